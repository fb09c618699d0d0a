#!/usr/bin/python3
# The per-corner RMS of a solved mrcal calibration, per camera (OpenCV's
# convention, as stereo-calibrate reports it: sqrt(mean |projected -
# observed|^2) over the inlier corners; mrcal itself prints the RMS over x
# and y separately, sqrt 2 smaller), its views and the corners it rejected
# as outliers.
#   mrcal_rms.py CAMERA.cameramodel NAME [NAME ...]    (one NAME a camera of the solve)
import sys

import mrcal
import numpy as np

model = mrcal.cameramodel(sys.argv[1])
names = sys.argv[2:]
inputs = model.optimization_inputs()
x = mrcal.optimizer_callback(**inputs, no_jacobian=True)[1]
observations = inputs["observations_board"]  # (views, rows, cols, 3): x, y, weight
per_view = observations.shape[1] * observations.shape[2]
residuals = x[: 2 * observations.shape[0] * per_view].reshape(observations.shape[0], per_view, 2)
weight = observations[..., 2].reshape(observations.shape[0], per_view)
# A corner the detector did not find is (-1, -1) with weight -1 (a "- - -"
# line); an outlier mrcal rejected keeps its pixel.
missing = ((observations[..., 0] == -1) & (observations[..., 1] == -1)).reshape(weight.shape) & (weight < 0)
camera_of_view = inputs["indices_frame_camintrinsics_camextrinsics"][:, 1]
warp = inputs.get("calobject_warp")
warp = "" if warp is None else ", board warp x2 %.3f y2 %.3f (board units x 1000)" % tuple(1e3 * warp)
for icam, name in enumerate(names):
    views = camera_of_view == icam
    r, w, m = residuals[views].reshape(-1, 2), weight[views].ravel(), missing[views].ravel()
    inlier = w > 0
    outliers = int(np.count_nonzero((w < 0) & ~m))
    rms = np.sqrt(np.mean(np.sum(r[inlier] ** 2, axis=1) / w[inlier] ** 2))
    print("mrcal %-5s %s: RMS %.4f px over %d views, %d outliers = %.1f %%%s"
          % (name, model.intrinsics()[0], rms, np.count_nonzero(views), outliers,
             100.0 * outliers / (outliers + np.count_nonzero(inlier)), warp))
