#!/usr/bin/env bash
# widestereo against cv::fisheye and mrcal 2.2 on every real set in
# ../shared/data (a set that is absent is skipped, saying so):
#   - widestereo with its defaults (stereo-calibrate with no option; --model
#     all where the default is still one model), on stereo-detect's own
#     corners and on OpenCV's detections imported (stereo-detect
#     --chessboard-detector opencv, written to one corners.vnl and read
#     back by stereo-import-corners --pairs: the same corners every other
#     tool gets);
#   - cv::fisheye::calibrate on OpenCV's detections;
#   - mrcal-calibrate-cameras (its defaults: outlier rejection, board warp)
#     on the same corners.vnl, LENSMODEL_SPLINED_STEREOGRAPHIC and
#     LENSMODEL_OPENCV8, each camera alone and as one stereo solve of the
#     pairs (--pairs).
# Per camera: views, outliers and their share, fitted RMS per corner (mrcal
# prints it per coordinate; bench/mrcal/mrcal_rms.py gives it per corner),
# held-out RMS by BabelCalib's protocol (cameras fixed, each test pose
# fitted; trained on the even views and tested on the odd ones, babelcalib
# on its own split), and each solve's wall-clock seconds.
#   bench/real/run.sh [ros] [babelcalib]     (default: both)
# OTHER_TREE=DIR also runs another checkout's stereo-calibrate (built in
# DIR/build) on the same corners, its rows labelled "baseline": a before and
# after in the same run.
set -euo pipefail
cd "$(dirname "$0")/../.."
# The benchmarks are not in `make test`'s build (bench/CMakeLists.txt).
cmake --build build --target bench -j"$(nproc)" > /dev/null
BIN=build/bin
BENCH=build/bench
DATA=../shared/data
SETS=${*:-ros babelcalib}
OUT=$(mktemp -d /tmp/bench-real-XXXX)
url() { echo "file://$1?$2"; }
source bench/mrcal/mrcal.sh

DEFAULTS=()
if $BIN/stereo-calibrate --help | grep -qE -- '--model TEXT:\{[^}]*\}=(bspline|poly6|poly12|kb4|bspline_theta)( |$)'; then
  DEFAULTS=(--model all)
  echo "(stereo-calibrate's default is one model: --model all given)"
fi

# The seconds since START (date +%s.%N).
since() { awk -v end="$(date +%s.%N)" -v start="$1" 'BEGIN { printf "%.1f", end - start }'; }

# stereo-calibrate (BIN's) with the defaults on LOG into PREFIX.{yaml,json};
# prints the report's rows under LABEL and the seconds: LABEL LOG PREFIX [BIN]
ws_solve() {
  local start bin=${4:-$BIN}
  start=$(date +%s.%N)
  "$bin/stereo-calibrate" --once "${DEFAULTS[@]}" --in-url "$(url "$2" speed=0)" --out "$3.yaml" \
    --report "$3.json" --out-url "$(url "$3.lcmlog" mode=w)" --log-dir "$(dirname "$3")" --quiet 2> "$3.err" ||
    { cat "$3.err"; return 1; }
  /usr/bin/python3 bench/real/report_rows.py "$3.json" "$1"
  echo "$1 solve $(since "$start") s"
}

# widestereo trained on TRAIN and held out on TEST: LABEL TRAIN TEST PREFIX [BIN]
ws_heldout() {
  ws_solve "$1 (train)" "$2" "$4" "${5:-}" > /dev/null
  $BENCH/heldout --test "$3" --calib "$4.yaml" --report "$4.json" | sed "s/^/$1 /"
}

# ws_solve, then with OTHER_TREE the other checkout's on the same corners
# (PREFIX-baseline): LABEL LOG PREFIX
ws_solve_both() {
  ws_solve "$@"
  [ -z "${OTHER_TREE:-}" ] || ws_solve "baseline $1" "$2" "$3-baseline" "$OTHER_TREE/build/bin"
}

# The same for ws_heldout: LABEL TRAIN TEST PREFIX
ws_heldout_both() {
  ws_heldout "$@"
  [ -z "${OTHER_TREE:-}" ] || ws_heldout "baseline $1" "$2" "$3" "$4-baseline" "$OTHER_TREE/build/bin"
}

# A corners.vnl of a stereo set as a STEREO_CORNERS log, paired by frame:
# VNL LOG WIDTHxHEIGHT
import_pairs() {
  $BIN/stereo-import-corners --mrcal "$1" --board "chessboard:$GRID_SIZE:$GRID_SPACING" --image-size "$3" \
    --pairs 'left-*.png' 'right-*.png' --out-url "$(url "$2" mode=w)" --log-dir "$(dirname "$2")" --quiet
}

# mrcal with LENSMODEL on VNL, each camera alone and (stereo) together;
# trained on TRAIN.vnl, held out on TEST.vnl per camera:
# DIR VNL TRAIN TEST WIDTH HEIGHT FOCAL LENSMODEL CAMERA...
mrcal_rows() {
  local dir=$1 vnl=$2 train=$3 test=$4 width=$5 height=$6 focal=$7 model=$8 name out
  shift 8
  name=${model%%_order*}
  for camera in "$@"; do
    out=$dir/mrcal-$name-$camera
    mrcal_solve "$vnl" "$out" "$width" "$height" "$focal" "$model" "$camera-*.png" &&
      /usr/bin/python3 bench/mrcal/mrcal_rms.py "$out/camera-0.cameramodel" "$camera" &&
      echo "mrcal $name $camera solve $(cat "$out/seconds") s"
    grep -E "^(#|$camera-)" "$test" > "$out-test.vnl"
    if [ "$train" != "$vnl" ]; then  # else the solve above is the trained one
      grep -E "^(#|$camera-)" "$train" > "$out-train.vnl"
      mrcal_solve "$out-train.vnl" "$out-train" "$width" "$height" "$focal" "$model" "$camera-*.png" || continue
    else
      ln -sfn "$out" "$out-train"
    fi
    [ -f "$out-train/camera-0.cameramodel" ] &&
      /usr/bin/python3 bench/mrcal/mrcal_heldout.py "$out-train/camera-0.cameramodel" "$out-test.vnl" \
        "${GRID_SIZE%x*}" "${GRID_SIZE#*x}" "$GRID_SPACING" "$camera" | sed "s/^mrcal/mrcal $name/"
  done
  if (($# > 1)); then  # one stereo solve of the pairs (--pairs)
    out=$dir/mrcal-$name-stereo
    mrcal_solve "$vnl" "$out" "$width" "$height" "$focal" "$model" --pairs "${@/%/-*.png}" &&
      /usr/bin/python3 bench/mrcal/mrcal_rms.py "$out/camera0-0.cameramodel" "$@" | sed "s/^mrcal/mrcal stereo/" &&
      echo "mrcal $name stereo solve $(cat "$out/seconds") s"
  fi
  return 0
}

# A stereo set of images DIR/left-NNNN.png, right-NNNN.png:
# NAME IMAGES BOARD WIDTH HEIGHT FOV_X_DEG FOCAL_PX
stereo_set() {
  local name=$1 images=$2 board=$3 size=$4x$5 dir=$OUT/$1 detector
  mkdir -p "$dir/own" "$dir/opencv"
  $BIN/stereo-capture --source "dir:$images" --frame-clock --out-url "$(url "$dir/images.lcmlog" mode=w)" \
    --log-dir "$dir" --quiet
  for detector in own opencv; do
    $BIN/stereo-detect --board "$board" --chessboard-detector "$([ $detector = own ] && echo classic || echo opencv)" \
      --in-url "$(url "$dir/images.lcmlog" speed=0)" --out-url "$(url "$dir/$detector/corners.lcmlog" mode=w)" \
      --log-dir "$dir/$detector" --quiet
    echo "$detector corners: $(grep -o 'boards left [0-9]* right [0-9]* of [0-9]*' "$dir/$detector/stereo-detect.log" | tail -1)"
    export_vnl "$dir/$detector"
    every_other "$dir/$detector/corners.vnl" 0 > "$dir/$detector/train.vnl"
    every_other "$dir/$detector/corners.vnl" 1 > "$dir/$detector/test.vnl"
    for part in corners train test; do import_pairs "$dir/$detector/$part.vnl" "$dir/$detector/$part-imported.lcmlog" "$size"; done
  done
  ws_solve_both "widestereo (own corners)" "$dir/own/corners.lcmlog" "$dir/own/ws"
  ws_heldout_both "widestereo (own corners)" "$dir/own/train-imported.lcmlog" "$dir/own/test-imported.lcmlog" \
    "$dir/own/ws-train"
  ws_solve_both "widestereo (OpenCV's corners)" "$dir/opencv/corners-imported.lcmlog" "$dir/opencv/ws"
  ws_heldout_both "widestereo (OpenCV's corners)" "$dir/opencv/train-imported.lcmlog" "$dir/opencv/test-imported.lcmlog" \
    "$dir/opencv/ws-train"
  $BENCH/heldout --opencv-fisheye "$dir/opencv/corners-imported.lcmlog" --test "$dir/opencv/corners-imported.lcmlog" |
    grep "cv::fisheye RMS" || true
  $BENCH/heldout --opencv-fisheye "$dir/opencv/train-imported.lcmlog" --test "$dir/opencv/test-imported.lcmlog" |
    grep -v "cv::fisheye RMS" | sed "s/^/cv::fisheye /"
  for model in "$(splined "$6")" LENSMODEL_OPENCV8; do
    mrcal_rows "$dir/opencv" "$dir/opencv/corners.vnl" "$dir/opencv/train.vnl" "$dir/opencv/test.vnl" "$4" "$5" "$7" \
      "$model" left right
  done
}

# BabelCalib's ov_plane: one camera, its own corners (train and test);
# OpenCV's detector is tried on the images too.
babelcalib_set() {
  local data=$DATA/babelcalib-ov-plane dir=$OUT/babelcalib part
  mkdir -p "$dir/train" "$dir/test" "$dir/images"
  for part in train test; do
    $BIN/stereo-import-corners --babelcalib "$data/ov_plane.dsc" --log-dir "$dir/$part" --quiet \
      --out-url "$(url "$dir/$part/corners.lcmlog" mode=w)" "$data"/corners/$part/*.orpc
    export_vnl "$dir/$part"
  done
  cp "$data"/corners/*/*.png "$dir/images/"
  $BIN/stereo-capture --source "dir:$dir/images" --mono --frame-clock --out-url "$(url "$dir/images.lcmlog" mode=w)" \
    --log-dir "$dir" --quiet
  $BIN/stereo-detect --board "chessboard:22x22:0.0075" --chessboard-detector opencv --log-dir "$dir" --quiet \
    --in-url "$(url "$dir/images.lcmlog" speed=0)" --out-url "$(url "$dir/opencv-corners.lcmlog" mode=w)"
  echo "OpenCV's detector: $(grep -o 'boards left [0-9]*' "$dir/stereo-detect.log" | tail -1) of 25 images" \
    "(the tags in the board's squares break its quads): every tool gets BabelCalib's corners"
  ws_solve_both "widestereo (BabelCalib's corners)" "$dir/train/corners.lcmlog" "$dir/ws"
  for prefix in ws ${OTHER_TREE:+ws-baseline}; do
    $BENCH/heldout --test "$dir/test/corners.lcmlog" --calib "$dir/$prefix.yaml" --report "$dir/$prefix.json" |
      sed "s/^/$([ $prefix = ws ] || echo 'baseline ')widestereo (BabelCalib's corners) /"
  done
  $BENCH/heldout --opencv-fisheye "$dir/train/corners.lcmlog" --test "$dir/test/corners.lcmlog" | sed "s/^/cv::fisheye /"
  for model in "$(splined 200)" LENSMODEL_OPENCV8; do
    mrcal_rows "$dir" "$dir/train/corners.vnl" "$dir/train/corners.vnl" "$dir/test/corners.vnl" 1280 800 300 "$model" left
  done
}

for set in $SETS; do
  case $set in
    ros)
      [ -d "$DATA/fisheye-stereo-ros" ] || { echo "== ros: $DATA/fisheye-stereo-ros absent, skipped"; continue; }
      echo "== fisheye-stereo-ros (800 x 503, 46 pairs, chessboard 8x6)"
      stereo_set ros "$DATA/fisheye-stereo-ros" chessboard:8x6:0.04 800 503 200 250 ;;
    babelcalib)
      [ -d "$DATA/babelcalib-ov-plane" ] || { echo "== babelcalib: $DATA/babelcalib-ov-plane absent, skipped"; continue; }
      echo "== babelcalib-ov-plane (1280 x 800, one camera, 18 train and 7 test views)"
      babelcalib_set ;;
    *) echo "unknown set '$set' (ros, babelcalib)"; exit 2 ;;
  esac
done
echo "(work in $OUT)"
