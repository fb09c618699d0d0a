#!/usr/bin/python3
# The per-corner RMS of a solved mrcal camera (OpenCV's convention, as
# stereo-calibrate reports it: sqrt(mean |projected - observed|^2) over the
# inlier corners; mrcal itself prints the RMS over x and y separately), its
# views and the corners it rejected as outliers.
#   mrcal_rms.py CAMERA.cameramodel NAME
import sys

import mrcal
import numpy as np

model = mrcal.cameramodel(sys.argv[1])
inputs = model.optimization_inputs()
x = mrcal.optimizer_callback(**inputs, no_jacobian=True)[1]
observations = inputs["observations_board"]  # (views, rows, cols, 3): x, y, weight
corners = observations.shape[0] * observations.shape[1] * observations.shape[2]
residuals = x[: 2 * corners].reshape(-1, 2)
weight = observations[..., 2].ravel()
# A corner the detector did not find is (-1, -1) with weight -1 (a "- - -"
# line); an outlier mrcal rejected keeps its pixel.
missing = (observations[..., 0].ravel() == -1) & (observations[..., 1].ravel() == -1) & (weight < 0)
inlier = weight > 0
outliers = int(np.count_nonzero((weight < 0) & ~missing))
rms = np.sqrt(np.mean(np.sum(residuals[inlier] ** 2, axis=1) / weight[inlier] ** 2))
warp = inputs.get("calobject_warp")
warp = "" if warp is None else ", board warp x2 %.3f y2 %.3f (board units x 1000)" % tuple(1e3 * warp)
print("mrcal %-5s %s: RMS %.4f px over %d views, %d outliers = %.1f %%%s"
      % (sys.argv[2], model.intrinsics()[0], rms, observations.shape[0], outliers,
         100.0 * outliers / (outliers + np.count_nonzero(inlier)), warp))
