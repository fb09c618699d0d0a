#!/usr/bin/env bash
# mrcal (Debian's mrcal 2.2, LENSMODEL_SPLINED_STEREOGRAPHIC) on the same
# corners as stereo-calibrate, per camera, beside stereo-calibrate's
# bspline_theta and kb4 and cv::fisheye (printed by tests/calib's
# RealFisheyeStereo test):
#   bench/mrcal/run.sh [IMAGES_DIR] [BOARD] [FOCAL_PX]
# defaults: ../shared/data/fisheye-stereo-ros, chessboard:8x6:0.04, 250.
# The spline's field (fov_x_deg) and knots (Nx x Ny) are mrcal's documented
# choices for a 180+ degree lens; mrcal rejects outliers itself.
set -euo pipefail
cd "$(dirname "$0")/../.."
IMAGES=${1:-../shared/data/fisheye-stereo-ros}
BOARD=${2:-chessboard:8x6:0.04}
FOCAL=${3:-250}
BIN=build/bin
OUT=$(mktemp -d /tmp/bench-mrcal-XXXX)
IFS=: read -r _ SIZE SQUARE <<<"$BOARD"
COLS=${SIZE%x*}; ROWS=${SIZE#*x}
file_url() { echo "file://$1"; }
$BIN/stereo-capture --source "dir:$IMAGES" --frame-clock --out-url "$(file_url "$OUT/images.lcmlog")?mode=w" --log-dir "$OUT" --quiet
$BIN/stereo-detect --board "$BOARD" --in-url "$(file_url "$OUT/images.lcmlog")?speed=0" \
  --out-url "$(file_url "$OUT/corners.lcmlog")?mode=w" --log-dir "$OUT" --quiet
build/bench/export_corners_vnl --in-url "$(file_url "$OUT/corners.lcmlog")?speed=0" --prefix "$OUT/corners" --log-dir "$OUT" --quiet
SIZE_PX=$(python3 -c "import sys,struct; f=open(sys.argv[1],'rb'); f.read(16); w,h=struct.unpack('>II', f.read(8)); print(w, h)" "$(ls "$IMAGES"/left*.png | head -1)")
for camera in left right; do
  mkdir -p "$OUT/$camera"
  mrcal-calibrate-cameras --corners-cache "$OUT/corners-$camera.vnl" \
    --lensmodel LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=16_Ny=12_fov_x_deg=200 \
    --focal "$FOCAL" --imagersize $SIZE_PX --object-spacing "$SQUARE" \
    --object-width-n "$COLS" --object-height-n "$ROWS" --outdir "$OUT/$camera" \
    "$camera-*.png" > "$OUT/$camera/mrcal.out" 2>&1 || { tail -20 "$OUT/$camera/mrcal.out"; exit 1; }
  echo "mrcal $camera: $(grep -E 'RMS reprojection error|Noutliers' "$OUT/$camera/mrcal.out" | tr '\n' ' ')"
done
echo "(work in $OUT)"
