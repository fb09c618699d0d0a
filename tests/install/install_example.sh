#!/usr/bin/env bash
# The installed package as a user meets it: `cmake --install` of the library
# (component dev: library, headers, CMake package, widestereo.pc) into a
# temporary prefix; examples/ copied out of the source tree, configured,
# built and run against that prefix with find_package(widestereo); the same
# program compiled with `pkg-config --cflags --libs widestereo`; the Python
# module (component python) imported from the prefix. Nothing from the build
# tree: no installed text file names the build or source folder.
#   install_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
work=$(mktemp -d /tmp/ws-install-XXXX)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" --component dev > "$work/install.log"
cmake --install "$build" --prefix "$prefix" --component python >> "$work/install.log"
test -f "$prefix/include/widestereo/widestereo.h"
if grep -rlI -e "$build" -e "$source" "$prefix"; then
  echo "FAIL: the installed files above name $build or $source"
  exit 1
fi
cp -r "$source/examples" "$work/examples"
calibration=$work/calibration.yaml
cp "$source/config/calib/sim-default.yaml" "$calibration"

cmake -S "$work/examples" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/build" -j2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }
echo "== find_package(widestereo): examples/use_calibration"
"$work/build/use_calibration" "$calibration"

export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
echo "== pkg-config widestereo $(pkg-config --modversion widestereo)"
# -O0: this compile only proves the flags; the CMake build above is the optimised one.
c++ -std=c++17 -O0 "$work/examples/use_calibration.cpp" -o "$work/use_calibration_pc" \
  $(pkg-config --cflags --libs widestereo)
"$work/use_calibration_pc" "$calibration"
echo "== the Python module from the prefix"
cd "$work"  # not the source tree
PYTHONPATH=$prefix/lib/python3/dist-packages /usr/bin/python3 -c "
import sys, widestereo
assert widestereo.__file__.startswith('$prefix'), widestereo.__file__
rig = widestereo.Rig.load(sys.argv[1])
print('widestereo from', widestereo.__file__, '- left camera', rig.left.model, rig.left.image_size)
" "$calibration"
echo "install_example: passed"
