#!/usr/bin/python3
# BabelCalib's protocol for a solved mrcal camera: its intrinsics (and the
# board shape it estimated, calobject_warp) fixed, each test view's board
# pose seeded (mrcal.estimate_monocular_calobject_poses_Rt_tocam) and fitted,
# no outlier rejection; the per-corner RMS over every detected corner of the
# test views (as bench_fisheye_models --heldout reports ours).
#   mrcal_heldout.py CAMERA.cameramodel TEST.vnl COLS ROWS SPACING NAME
import sys

import mrcal
import numpy as np

model = mrcal.cameramodel(sys.argv[1])
cols, rows, spacing = int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5])
views = {}
for line in open(sys.argv[2]):
    if not line.startswith("#"):
        name, x, y, _ = line.split()
        views.setdefault(name, []).append((x, y))
observations = np.array([
    np.array([[float(x), float(y), 1.0] if x != "-" else [-1.0, -1.0, -1.0] for x, y in corners])
    .reshape(rows, cols, 3)
    for corners in views.values() if len(corners) == cols * rows])
n = len(observations)
inputs = dict(model.optimization_inputs())
poses = mrcal.estimate_monocular_calobject_poses_Rt_tocam(
    np.array([[i, 0] for i in range(n)], dtype=np.int32), observations, spacing, (model.intrinsics(),))
inputs.update(
    observations_board=observations,
    indices_frame_camintrinsics_camextrinsics=np.array([[i, 0, -1] for i in range(n)], dtype=np.int32),
    frames_rt_toref=mrcal.rt_from_Rt(poses),
    do_optimize_intrinsics_core=False, do_optimize_intrinsics_distortions=False,
    do_optimize_extrinsics=False, do_optimize_frames=True, do_optimize_calobject_warp=False,
    do_apply_outlier_rejection=False, do_apply_regularization=False)
mrcal.optimize(**inputs)
x = mrcal.optimizer_callback(**inputs, no_jacobian=True)[1]
residuals = x[: 2 * observations[..., 0].size].reshape(-1, 2)
detected = observations[..., 2].ravel() > 0
print("mrcal %-5s held out: test RMS %.4f px over %d views (%d corners)"
      % (sys.argv[6], np.sqrt(np.mean(np.sum(residuals[detected] ** 2, axis=1))), n, detected.sum()))
