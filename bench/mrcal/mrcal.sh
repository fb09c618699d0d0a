# mrcal 2.2 (Debian's mrcal, python3-mrcal) on the very corners widestereo
# calibrated: sourced by bench/fisheye/run.sh and bench/real/run.sh, from
# the project's root, with BENCH (build/bench) set.

# DIR/corners.lcmlog as DIR/corners.vnl (left-NNNN.png, right-NNNN.png) and
# one file a camera, DIR/corners-{left,right}.vnl; sets GRID_SIZE (COLSxROWS)
# and GRID_SPACING (metres).
export_vnl() {
  local grid
  grid=$($BENCH/export_corners_vnl --in-url "file://$1/corners.lcmlog?speed=0" \
    --out "$1/corners.vnl" --log-dir "$1" --quiet | tail -1)
  read -r _ GRID_SIZE _ GRID_SPACING <<<"$grid"
  for camera in left right; do grep -E "^(#|$camera-)" "$1/corners.vnl" > "$1/corners-$camera.vnl" || true; done
}

# VNL's views of even (0) or odd (1) frame ids (names ending NNNN.png).
every_other() { awk -v odd="$2" 'NR == 1 || (substr($1, length($1) - 4, 1) % 2 == odd)' "$1"; }

# mrcal-calibrate-cameras (its defaults: outlier rejection, board warp) into
# OUTDIR, its output in OUTDIR/mrcal.out and its wall-clock seconds in
# OUTDIR/seconds: VNL OUTDIR WIDTH HEIGHT FOCAL_PX LENSMODEL GLOB... (one
# glob a camera). Returns non-zero, saying why, when mrcal fails.
mrcal_solve() {
  local vnl=$1 outdir=$2 width=$3 height=$4 focal=$5 lensmodel=$6 start
  shift 6
  mkdir -p "$outdir"
  start=$(date +%s.%N)
  if ! mrcal-calibrate-cameras --corners-cache "$vnl" --lensmodel "$lensmodel" \
    --focal "$focal" --imagersize "$width" "$height" --object-spacing "$GRID_SPACING" \
    --object-width-n "${GRID_SIZE%x*}" --object-height-n "${GRID_SIZE#*x}" --outdir "$outdir" \
    "$@" > "$outdir/mrcal.out" 2>&1; then
    echo "mrcal $lensmodel $*: failed ($(tail -1 "$outdir/mrcal.out"))"
    return 1
  fi
  awk -v end="$(date +%s.%N)" -v start="$start" 'BEGIN { print end - start }' > "$outdir/seconds"
}

# mrcal's splined model for a lens of FOV_X_DEG horizontal field: its
# documented choice for wide lenses, 16 x 12 knots over the field.
splined() { echo "LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=16_Ny=12_fov_x_deg=$1"; }
