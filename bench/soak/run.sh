#!/usr/bin/env bash
# bench/soak/run.sh [SECONDS [RATE_HZ]]: the soak run (bench_soak) of the whole
# simulated pipeline at the camera rate, from frames of config/sim/default.yaml
# rendered once into a folder (the simulator renders slower than 10 Hz on a
# busy 2-core machine). Prints resident memory per process and the counters
# per quarter of the run; everything is kept in logs/soak-<time>/.
set -euo pipefail
cd "$(dirname "$0")/../.."
# The benchmarks are not in `make test`'s build (bench/CMakeLists.txt).
cmake --build build --target bench -j"$(nproc)" > /dev/null
DURATION=${1:-1800}
RATE=${2:-10}
RUN=logs/soak-$(date +%Y%m%d-%H%M%S)
mkdir -p "$RUN/frames"
build/bench/bench_transport --prepare "$RUN/frames" --sim config/sim/default.yaml --log-dir "$RUN" --quiet
build/bench/bench_soak --duration "$DURATION" --rate "$RATE" --sim config/sim/default.yaml \
  --source "dir:$RUN/frames" --calib "$RUN/frames/calibration.yaml" --out "$RUN"
