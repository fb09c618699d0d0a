#!/usr/bin/env bash
# Issue #13's table on the real fisheye sets and the simulated 200-degree rig:
# per camera RMS, views and outliers of bspline, poly12, kb4, bspline_theta
# (bench_fisheye_models: stereo-calibrate's solver by default and with
# --outlier-sigma 6 --board-warp), beside cv::fisheye::calibrate and mrcal
# 2.2's LENSMODEL_SPLINED_STEREOGRAPHIC (mrcal-calibrate-cameras, its own
# outlier rejection and board warp) on the very same corners, and
# BabelCalib's train/test RMS (the RealBabelCalib test); and held out
# (BabelCalib's protocol, the same for both tools): trained on the even
# views and tested on the odd ones (babelcalib: its own train / test split).
#   bench/fisheye/run.sh [ros] [babelcalib] [sim]     (default: all three)
# The real sets are read from ../shared/data (absent: that set is skipped).
# mrcal's spline: its documented choice for a 180+ degree lens, 16 x 12
# knots over fov_x_deg (the lens's horizontal field).
set -euo pipefail
cd "$(dirname "$0")/../.."
# The benchmarks are not in `make test`'s build (bench/CMakeLists.txt).
cmake --build build --target bench -j"$(nproc)" > /dev/null
BIN=build/bin
BENCH=build/bench
DATA=../shared/data
SETS=${*:-ros babelcalib sim}
OUT=$(mktemp -d /tmp/bench-fisheye-XXXX)
url() { echo "file://$1?$2"; }
source bench/mrcal/mrcal.sh

# mrcal on every view of DIR's corners, then trained on TRAIN.vnl and tested
# on TEST.vnl: DIR WIDTH HEIGHT FOV FOCAL CAMERA TRAIN TEST
mrcal_fit() {
  local dir=$1 camera=$6 model
  model=$(splined "$4")
  mrcal_solve "$dir/corners-$camera.vnl" "$dir/mrcal-$camera" "$2" "$3" "$5" "$model" "$camera-*.png" &&
    /usr/bin/python3 bench/mrcal/mrcal_rms.py "$dir/mrcal-$camera/camera-0.cameramodel" "$camera" &&
    /usr/bin/python3 bench/fisheye/mrcal_uncertainty.py "$dir/mrcal-$camera/camera-0.cameramodel" \
      "$dir/corners-$camera.vnl" "$camera"
  mrcal_solve "$7" "$dir/mrcal-train-$camera" "$2" "$3" "$5" "$model" "$camera-*.png" &&
    /usr/bin/python3 bench/mrcal/mrcal_heldout.py "$dir/mrcal-train-$camera/camera-0.cameramodel" "$8" \
      "${GRID_SIZE%x*}" "${GRID_SIZE#*x}" "$GRID_SPACING" "$camera"
}

# A stereo set's table (with held-out), then mrcal on each camera, trained
# on the even views and tested on the odd ones: DIR WIDTH HEIGHT FOV FOCAL
stereo_set() {
  local dir=$1
  table "$dir" --heldout
  export_vnl "$dir"
  for camera in left right; do
    every_other "$dir/corners-$camera.vnl" 0 > "$dir/train-$camera.vnl"
    every_other "$dir/corners-$camera.vnl" 1 > "$dir/test-$camera.vnl"
    mrcal_fit "$dir" "${@:2:4}" $camera "$dir/train-$camera.vnl" "$dir/test-$camera.vnl"
  done
}

table() {
  $BENCH/bench_fisheye_models --in-url "$(url "$1/corners.lcmlog" speed=0)" --log-dir "$1" --quiet "${@:2}" 2> >(grep "cv::fisheye" || true)
}

for set in $SETS; do
  dir=$OUT/$set
  mkdir -p "$dir"
  case $set in
    ros)
      [ -d $DATA/fisheye-stereo-ros ] || { echo "== ros: $DATA/fisheye-stereo-ros absent, skipped"; continue; }
      echo "== fisheye-stereo-ros (800 x 503, 46 pairs, chessboard 8x6)"
      $BIN/stereo-capture --source dir:$DATA/fisheye-stereo-ros --frame-clock --out-url "$(url "$dir/images.lcmlog" mode=w)" --log-dir "$dir" --quiet
      $BIN/stereo-detect --board chessboard:8x6:0.04 --in-url "$(url "$dir/images.lcmlog" speed=0)" \
        --out-url "$(url "$dir/corners.lcmlog" mode=w)" --log-dir "$dir" --quiet
      stereo_set "$dir" 800 503 200 250 ;;
    babelcalib)
      [ -d $DATA/babelcalib-ov-plane ] || { echo "== babelcalib: $DATA/babelcalib-ov-plane absent, skipped"; continue; }
      echo "== babelcalib-ov-plane, train views (1280 x 800, one camera)"
      $BIN/stereo-import-corners --babelcalib $DATA/babelcalib-ov-plane/ov_plane.dsc --log-dir "$dir" --quiet \
        --out-url "$(url "$dir/corners.lcmlog" mode=w)" $DATA/babelcalib-ov-plane/corners/train/*.orpc
      table "$dir"
      mkdir -p "$dir/test"
      $BIN/stereo-import-corners --babelcalib $DATA/babelcalib-ov-plane/ov_plane.dsc --log-dir "$dir/test" --quiet \
        --out-url "$(url "$dir/test/corners.lcmlog" mode=w)" $DATA/babelcalib-ov-plane/corners/test/*.orpc
      build/tests/test_calib_real_fisheye --gtest_filter='RealBabelCalib.TrainTest*' | grep -E "^(kb4|bspline_theta) "
      export_vnl "$dir/test"
      export_vnl "$dir"
      mrcal_fit "$dir" 1280 800 200 300 left "$dir/corners-left.vnl" "$dir/test/corners-left.vnl" ;;
    sim)
      echo "== simulated 200-degree knee-lens rig (config/sim/fisheye.yaml, rendered and detected)"
      $BIN/stereo-capture --source sim:config/sim/fisheye.yaml --frame-clock --rate 5 \
        --out-url "$(url "$dir/images.lcmlog" mode=w)" --log-dir "$dir" --quiet
      $BIN/stereo-detect --board chessboard:9x6:0.05 --in-url "$(url "$dir/images.lcmlog" speed=0)" \
        --out-url "$(url "$dir/corners.lcmlog" mode=w)" --log-dir "$dir" --quiet
      rm -f "$dir/images.lcmlog"
      stereo_set "$dir" 1280 960 200 300 ;;
    *) echo "unknown set '$set' (ros, babelcalib, sim)"; exit 2 ;;
  esac
done
echo "(work in $OUT)"
