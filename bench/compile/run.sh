#!/usr/bin/env bash
# bench/compile/run.sh [BUILD_DIR]: where a fresh build's time goes. Configures
# BUILD_DIR (default /tmp/ws-build-time, removed first) as `make test` does,
# with a compiler launcher that logs each compile's and link's wall seconds,
# builds `all` and `bench` with -j$(nproc), no ccache, and prints the time
# by part (library, tests, benchmarks, processes, fuzz targets, links) and
# the slowest units.
set -euo pipefail
cd "$(dirname "$0")/../.."
DIR=${1:-/tmp/ws-build-time}
LOG=$DIR.units.log
rm -rf "$DIR" "$LOG"
LAUNCHER=$DIR.launcher.sh
cat > "$LAUNCHER" <<EOS
#!/bin/bash
start=\$(date +%s.%N); "\$@"; rc=\$?; end=\$(date +%s.%N)
out=""; prev=""; for a in "\$@"; do [ "\$prev" = "-o" ] && out="\$a"; prev="\$a"; done
echo "\$(echo "\$end - \$start" | bc) \$out" >> "$LOG"; exit \$rc
EOS
chmod +x "$LAUNCHER"
CCACHE_DISABLE=1 cmake -S . -B "$DIR" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER="$LAUNCHER" \
  -DCMAKE_C_COMPILER_LAUNCHER="$LAUNCHER" -DCMAKE_CXX_LINKER_LAUNCHER="$LAUNCHER" > /dev/null
start=$(date +%s)
CCACHE_DISABLE=1 cmake --build "$DIR" -j"$(nproc)" --target all bench > "$DIR.build.log"
echo "build: $(( $(date +%s) - start )) s wall"
python3 - "$LOG" <<'EOP'
import sys, collections
part, count, units = collections.Counter(), collections.Counter(), []
for line in open(sys.argv[1]):
    seconds, out = line.split(None, 1)
    seconds, out = float(seconds), out.strip()
    if not out.endswith('.o'): name = 'links'
    elif '/widestereo_' in out: name = 'library'
    elif 'bench' in out or 'heldout.dir' in out: name = 'benchmarks'
    elif 'fuzz' in out: name = 'fuzz targets'
    elif 'stereo-' in out: name = 'processes'
    else: name = 'tests and the rest'
    part[name] += seconds; count[name] += 1; units.append((seconds, out))
total = sum(part.values())
for name, seconds in part.most_common():
    print(f"{name:20s} {seconds:7.0f} s  {100 * seconds / total:4.1f} %  {count[name]} units")
print("slowest units:")
for seconds, out in sorted(units, reverse=True)[:15]: print(f"  {seconds:6.1f} s  {out}")
EOP
