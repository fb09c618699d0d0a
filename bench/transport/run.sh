#!/usr/bin/env bash
# Transport benchmark (issue #7): 2 x 1280x960 GRAY8 pairs at RATE Hz
# (default 15) over udpm on this host, through stereo-match and stereo-cloud,
# for DURATION seconds (default 60): frames lost in transit, latency from
# capture to STEREO_CLOUD_FILTERED, and the latency budget (each stage's time
# per frame). Uses the receive-buffer size the launch files ask for; the
# kernel grants at most net.core.rmem_max (see docs/launch.md).
#   bench/transport/run.sh [DURATION] [RATE] [OTHER_TREE]
# OTHER_TREE: another checkout, built in its build/: its stereo-capture,
# stereo-match and stereo-cloud run with its own config/ files instead (a
# baseline measured in the same session), with this tree's listener.
set -euo pipefail
cd "$(dirname "$0")/../.."
DURATION=${1:-60}
RATE=${2:-15}
OTHER=${3:-}
RUN=logs/bench-transport-$(date +%Y%m%d-%H%M%S)${OTHER:+-other}
mkdir -p "$RUN/frames"
echo "net.core.rmem_max = $(sysctl -n net.core.rmem_max)"
build/bench/bench_transport --prepare "$RUN/frames" --sim config/sim/wall.yaml --log-dir "$RUN" --quiet
mv "$RUN/frames/calibration.yaml" "$RUN/calibration.yaml"
python3 - "$RUN/transport.yaml" "$OTHER" <<'PY'
import sys, yaml
out, other = sys.argv[1], sys.argv[2]
launch = yaml.safe_load(open("bench/transport/transport.yaml"))
for p in launch["processes"]:
    if other and p["name"].startswith("stereo-"):
        p["executable"] = f"{other}/build/bin/{p['name']}"
        if "config" in p:
            p["config"] = f"{other}/{p['config']}"
yaml.safe_dump(launch, open(out, "w"), sort_keys=False)
PY
echo "${OTHER:-this tree}: capture at $RATE Hz for $DURATION s"
scripts/launch "$RUN/transport.yaml" --run-dir "$RUN" --no-record \
  --set "stereo-capture.rate=$RATE" --append "bench_transport=--duration=$DURATION" > "$RUN/launch.out"
cat "$RUN/bench_transport.out"
