#!/usr/bin/env bash
# Transport benchmark (issue #7): 2 x 1280x960 GRAY8 pairs at RATE Hz
# (default 15) over udpm on this host, through stereo-match and stereo-cloud,
# for DURATION seconds (default 60): frames lost in transit, latency from
# capture to STEREO_CLOUD_FILTERED, each process's CPU share and the latency
# budget (each stage's time per frame). Then the same again with stereo-view
# and its depth view read as a browser on another machine would
# (transport-view-remote.yaml, page_reader.py), and with one headless Chromium
# on this host showing it (transport-view.yaml): the first run is the others'
# baseline. Uses the receive-buffer size the launch files ask for; the kernel
# grants at most net.core.rmem_max (see docs/launch.md).
#   bench/transport/run.sh [DURATION] [RATE] [OTHER_TREE]
# OTHER_TREE: another checkout, built in its build/: its stereo-* processes
# run with its own config/ files instead (a baseline measured in the same
# session), with this tree's listener.
# VARIANTS="transport" runs the first launch only. ROUNDS=N (default 1)
# runs the variants N times in turn (A B A B ...: a machine whose speed
# drifts over minutes slows them alike) and ends with each figure's median
# and range over the rounds, per variant (summary.py). BOTH=1 with
# OTHER_TREE runs each launch in both trees in turn. SETTINGS="PROCESS.OPTION=VALUE ..."
# changes the processes' settings (scripts/launch --set), say a filter
# slower than the matcher: SETTINGS=stereo-cloud.voxel-leaf=0.02.
set -euo pipefail
cd "$(dirname "$0")/../.."
# The benchmarks are not in `make test`'s build (bench/CMakeLists.txt).
cmake --build build --target bench -j"$(nproc)" > /dev/null
DURATION=${1:-60}
RATE=${2:-15}
OTHER=${3:-}
VARIANTS=${VARIANTS:-transport transport-view-remote transport-view}
ROUNDS=${ROUNDS:-1}
RUN=logs/bench-transport-$(date +%Y%m%d-%H%M%S)${OTHER:+-other}
mkdir -p "$RUN/frames"
echo "net.core.rmem_max = $(sysctl -n net.core.rmem_max)"
build/bench/bench_transport --prepare "$RUN/frames" --sim config/sim/wall.yaml --log-dir "$RUN" --quiet
mv "$RUN/frames/calibration.yaml" "$RUN/calibration.yaml"
PORT=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
# The launches' bus on a UDP port of this run's own: processes of another
# launch on the host (the default bus: 7667) neither reach the chain nor
# are counted by the listener.
BUS_PORT=$(python3 -c 'import socket; s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("", 0)); print(s.getsockname()[1])')
# With BOTH=1 (and OTHER_TREE), each launch runs in this tree, then in the
# other, before the next: the baseline in turn with the change ("VARIANT"
# and "VARIANT-other" in the summary).
TREES=("${OTHER}")
[ -n "$OTHER" ] && [ "${BOTH:-0}" = 1 ] && TREES=("" "$OTHER")
for round in $(seq "$ROUNDS"); do
for variant in $VARIANTS; do
for tree in "${TREES[@]}"; do
  dir=$variant${tree:+-other}
  [ "$ROUNDS" = 1 ] || dir=round-$round/$dir
  mkdir -p "$RUN/$dir"
  ln -sfn "$PWD/$RUN/frames" "$RUN/$dir/frames"
  ln -sfn "$PWD/$RUN/calibration.yaml" "$RUN/$dir/calibration.yaml"
  python3 - "bench/transport/$variant.yaml" "$RUN/$dir/launch.yaml" "$tree" "$BUS_PORT" <<'PY'
import re, sys, yaml
launch_file, out, other, bus_port = sys.argv[1:]
launch = yaml.safe_load(open(launch_file))
launch["lcm_url"] = re.sub(r":\d+\?", f":{bus_port}?", launch["lcm_url"], count=1)
for p in launch["processes"]:
    if other and p["name"].startswith("stereo-"):
        p["executable"] = f"{other}/build/bin/{p['name']}"
        if "config" in p:
            p["config"] = f"{other}/{p['config']}"
yaml.safe_dump(launch, open(out, "w"), sort_keys=False)
PY
  extra=()
  for setting in ${SETTINGS:-}; do extra+=(--set "$setting"); done
  case $variant in
    transport-view) extra=(--append "stereo-view=--port=$PORT" --append "browser=http://127.0.0.1:$PORT/") ;;
    transport-view-remote) extra=(--append "stereo-view=--port=$PORT" --append "page_reader=http://127.0.0.1:$PORT/") ;;
  esac
  load=$(uptime)  # whatever else runs on the host slows the chain alike
  scripts/launch "$RUN/$dir/launch.yaml" --run-dir "$RUN/$dir" --no-record \
    --set "stereo-capture.rate=$RATE" --append "bench_transport=--duration=$DURATION" "${extra[@]}" \
    > "$RUN/$dir/launch.out"
  echo "== $variant.yaml, ${tree:-this tree}: capture at $RATE Hz for $DURATION s"
  echo "   load before the run (uptime): $load"
  [ "$ROUNDS" = 1 ] || echo "   round $round of $ROUNDS"
  cat "$RUN/$dir/bench_transport.out"
  grep -h "^browser: Chromium" "$RUN/$dir/browser.out" 2>/dev/null || true
  grep -h "^page reader: [0-9]" "$RUN/$dir/page_reader.out" 2>/dev/null || true
done
done
done
names=()
for variant in $VARIANTS; do for tree in "${TREES[@]}"; do names+=("$variant${tree:+-other}"); done; done
[ "$ROUNDS" = 1 ] || python3 bench/transport/summary.py "$RUN" "${names[@]}"
