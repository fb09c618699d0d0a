#!/usr/bin/env bash
# The installed package as a user meets it: `cmake --install` of the library
# (component dev: the layers' libraries, headers, CMake package, .pc files)
# into a temporary prefix; examples/ copied out of the source tree,
# configured, built and run against that prefix with find_package(widestereo
# COMPONENTS core) and widestereo::core, its compile and link lines checked
# to hold the core's dependencies only (Eigen, OpenCV, yaml-cpp: nothing of
# Ceres, LCM, Aravis, GLib, libsodium); the same program compiled and checked
# so with `pkg-config --cflags --libs widestereo-core`, and built against
# everything (widestereo::widestereo, widestereo.pc) as before the layers;
# the Python module (component python) imported from the prefix. Nothing
# from the build tree: no installed text file names the build or source
# folder.
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
test -f "$prefix/include/widestereo/lcm.h"
if grep -rlI -e "$build" -e "$source" "$prefix"; then
  echo "FAIL: the installed files above name $build or $source"
  exit 1
fi
cp -r "$source/examples" "$work/examples"
calibration=$work/calibration.yaml
cp "$source/config/calib/sim-default.yaml" "$calibration"

# only_core WHAT FLAGS...: fails unless FLAGS (a compile or link line, the
# prefix's path left out) name the core's libraries only, and the core's
# library when they link.
only_core() {
  local what=$1 line
  shift
  line=$(echo "$*" | sed "s|$work|PREFIX|g")
  echo "$what: $line"
  if echo "$line" | grep -Eio 'ceres|glog|gflags|suitesparse|cholmod|spqr|cxsparse|tbb|lapack|blas|atlas|aravis|glib|gobject|gio-|libxml|libusb|lcm|sodium|nlohmann|cli11|widestereo_(calib|lcm|capture|runtime)|opencv_(imgcodecs|aruco|video|highgui|dnn)' |
    sort -u | tr '\n' ' ' | grep .; then
    echo "FAIL: $what names the libraries above, which the core does not use"
    exit 1
  fi
  if [[ $what == *link* ]] && ! echo "$line" | grep -q 'widestereo_core'; then
    echo "FAIL: $what does not link the core library"
    exit 1
  fi
}

# Unix Makefiles: the compile and link lines are in flags.make and link.txt.
cmake -S "$work/examples" -B "$work/build" -G "Unix Makefiles" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/build" -j2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }
echo "== find_package(widestereo COMPONENTS core): examples/use_calibration"
only_core "widestereo::core's compile line" "$(grep "^CXX_" "$work/build/CMakeFiles/use_calibration.dir/flags.make")"
only_core "widestereo::core's link line" "$(cat "$work/build/CMakeFiles/use_calibration.dir/link.txt")"
"$work/build/use_calibration" "$calibration"
echo "use_calibration against widestereo::core: $(stat -c %s "$work/build/use_calibration") bytes"

export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
echo "== pkg-config widestereo-core $(pkg-config --modversion widestereo-core)"
only_core "widestereo-core's compile flags" "$(pkg-config --cflags widestereo-core)"
only_core "widestereo-core's link flags" "$(pkg-config --libs widestereo-core)"
# -O0: these compiles only prove the flags; the CMake build above is the optimised one.
c++ -std=c++17 -O0 "$work/examples/use_calibration.cpp" -o "$work/use_calibration_pc" \
  $(pkg-config --cflags --libs widestereo-core)
"$work/use_calibration_pc" "$calibration"
# The headers it reads: the core's own and its packages', nothing of Ceres
# (the core compiles without libceres-dev's headers).
headers=$(c++ -std=c++17 -M "$work/examples/use_calibration.cpp" $(pkg-config --cflags widestereo-core) |
  tr ' \\' '\n\n' | grep '\.h')
grep -q "include/widestereo/models/camera_model.h" <<< "$headers" ||
  { echo "FAIL: the header list does not hold the core's camera_model.h"; exit 1; }
if grep ceres <<< "$headers"; then
  echo "FAIL: the core's headers include the Ceres headers above"
  exit 1
fi

# A component the package has not: find_package says which it has.
mkdir "$work/nosuch"
printf 'cmake_minimum_required(VERSION 3.19)\nproject(nosuch LANGUAGES CXX)\nfind_package(widestereo REQUIRED COMPONENTS core nosuch)\n' \
  > "$work/nosuch/CMakeLists.txt"
if cmake -S "$work/nosuch" -B "$work/nosuch/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/nosuch.log" 2>&1; then
  echo "FAIL: find_package(widestereo COMPONENTS nosuch) succeeded"
  exit 1
fi
grep -q "widestereo has no component 'nosuch' (core, calib, lcm, capture, runtime)" "$work/nosuch.log" ||
  { cat "$work/nosuch.log"; echo "FAIL: find_package did not name the components"; exit 1; }

# The message layer on top: a rig as its message, with widestereo-lcm's flags.
echo "== pkg-config widestereo-lcm: a rig as its message"
cat > "$work/rig_message.cpp" <<'CPP'
#include <cstdio>
#include <widestereo/lcm.h>
int main(int, char** argv) {
  const widestereo::stereo_calibration_t msg = ws::MessageFromRig(ws::StereoRigFromFile(argv[1]), 1);
  ws::Validate(msg);
  std::printf("STEREO_CALIBRATION of %s: %d bytes\n", argv[1], msg.getEncodedSize());
  return ws::RigFromMessage(msg).T == ws::StereoRigFromFile(argv[1]).T ? 0 : 1;
}
CPP
c++ -std=c++17 -O0 "$work/rig_message.cpp" -o "$work/rig_message" $(pkg-config --cflags --libs widestereo-lcm)
"$work/rig_message" "$calibration"

# A program of before the layers: everything, widestereo::widestereo and widestereo.pc.
echo "== find_package(widestereo): widestereo::widestereo, every layer"
mkdir "$work/whole"
sed 's/COMPONENTS core//; s/widestereo::core/widestereo::widestereo/' "$work/examples/CMakeLists.txt" \
  > "$work/whole/CMakeLists.txt"
cp "$work/examples/use_calibration.cpp" "$work/whole/"
grep -q 'widestereo::widestereo' "$work/whole/CMakeLists.txt"
cmake -S "$work/whole" -B "$work/whole/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$work/configure-whole.log"
cmake --build "$work/whole/build" -j2 > "$work/build-whole.log" || { cat "$work/build-whole.log"; exit 1; }
"$work/whole/build/use_calibration" "$calibration"
echo "== pkg-config widestereo $(pkg-config --modversion widestereo), every layer"
c++ -std=c++17 -O0 "$work/examples/use_calibration.cpp" -o "$work/use_calibration_all" \
  $(pkg-config --cflags --libs widestereo)
"$work/use_calibration_all" "$calibration"
echo "== the Python module from the prefix"
cd "$work"  # not the source tree
PYTHONPATH=$prefix/lib/python3/dist-packages /usr/bin/python3 -c "
import sys, widestereo
assert widestereo.__file__.startswith('$prefix'), widestereo.__file__
rig = widestereo.Rig.load(sys.argv[1])
print('widestereo from', widestereo.__file__, '- left camera', rig.left.model, rig.left.image_size)
" "$calibration"
echo "install_example: passed"
