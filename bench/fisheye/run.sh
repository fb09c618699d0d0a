#!/usr/bin/env bash
# Issue #13's table on the real fisheye sets and the simulated 200-degree rig:
# per camera RMS, views and outliers of bspline, poly12, kb4, bspline_theta
# (bench_fisheye_models: stereo-calibrate's solver by default and with
# --outlier-sigma 6 --board-warp), beside cv::fisheye::calibrate and mrcal
# 2.2's LENSMODEL_SPLINED_STEREOGRAPHIC (mrcal-calibrate-cameras, its own
# outlier rejection and board warp) on the very same corners, and
# BabelCalib's train/test RMS (the RealBabelCalib test).
#   bench/fisheye/run.sh [ros] [babelcalib] [sim]     (default: all three)
# The real sets are read from ../shared/data (absent: that set is skipped).
# mrcal's spline: its documented choice for a 180+ degree lens, 16 x 12
# knots over fov_x_deg (the lens's horizontal field).
set -euo pipefail
cd "$(dirname "$0")/../.."
BIN=build/bin
BENCH=build/bench
DATA=../shared/data
SETS=${*:-ros babelcalib sim}
OUT=$(mktemp -d /tmp/bench-fisheye-XXXX)
url() { echo "file://$1?$2"; }

# mrcal on DIR/corners.lcmlog: WIDTH HEIGHT FOV_X_DEG FOCAL_PX CAMERAS...
mrcal_fit() {
  local dir=$1 width=$2 height=$3 fov=$4 focal=$5; shift 5
  local grid
  grid=$($BENCH/export_corners_vnl --in-url "$(url "$dir/corners.lcmlog" speed=0)" \
    --prefix "$dir/corners" --log-dir "$dir" --quiet | tail -1)
  read -r _ size _ spacing <<<"$grid"
  for camera in "$@"; do
    mkdir -p "$dir/mrcal-$camera"
    if mrcal-calibrate-cameras --corners-cache "$dir/corners-$camera.vnl" \
      --lensmodel "LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=16_Ny=12_fov_x_deg=$fov" \
      --focal "$focal" --imagersize "$width" "$height" --object-spacing "$spacing" \
      --object-width-n "${size%x*}" --object-height-n "${size#*x}" --outdir "$dir/mrcal-$camera" \
      "$camera-*.png" > "$dir/mrcal-$camera/mrcal.out" 2>&1; then
      /usr/bin/python3 bench/fisheye/mrcal_rms.py "$dir/mrcal-$camera/camera-0.cameramodel" "$camera"
    else
      echo "mrcal $camera: failed ($(tail -1 "$dir/mrcal-$camera/mrcal.out"))"
    fi
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
      table "$dir"
      mrcal_fit "$dir" 800 503 200 250 left right ;;
    babelcalib)
      [ -d $DATA/babelcalib-ov-plane ] || { echo "== babelcalib: $DATA/babelcalib-ov-plane absent, skipped"; continue; }
      echo "== babelcalib-ov-plane, train views (1280 x 800, one camera)"
      $BIN/stereo-import-corners --babelcalib $DATA/babelcalib-ov-plane/ov_plane.dsc --log-dir "$dir" --quiet \
        --out-url "$(url "$dir/corners.lcmlog" mode=w)" $DATA/babelcalib-ov-plane/corners/train/*.orpc
      table "$dir"
      mrcal_fit "$dir" 1280 800 200 300 left ;;
    sim)
      echo "== simulated 200-degree knee-lens rig (config/sim/fisheye.yaml, rendered and detected)"
      $BIN/stereo-capture --source sim:config/sim/fisheye.yaml --frame-clock --rate 5 \
        --out-url "$(url "$dir/images.lcmlog" mode=w)" --log-dir "$dir" --quiet
      $BIN/stereo-detect --board chessboard:9x6:0.05 --in-url "$(url "$dir/images.lcmlog" speed=0)" \
        --out-url "$(url "$dir/corners.lcmlog" mode=w)" --log-dir "$dir" --quiet
      rm -f "$dir/images.lcmlog"
      table "$dir"
      mrcal_fit "$dir" 1280 960 200 300 left right ;;
    *) echo "unknown set '$set' (ros, babelcalib, sim)"; exit 2 ;;
  esac
done
echo "(work in $OUT)"
