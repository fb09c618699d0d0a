#!/usr/bin/python3
# mrcal's projection uncertainty of a solved camera on the grid widestereo's
# report uses (calib/evaluate/projection_uncertainty.h): 32 x 24 points over the
# image, each pixel's ray at infinity, mrcal.projection_uncertainty's
# worst-direction 1-sigma; median and worst over the cells holding a corner
# of CORNERS.vnl (as the report's median_px and worst_px).
#   mrcal_uncertainty.py CAMERA.cameramodel CORNERS.vnl NAME
import sys

import mrcal
import numpy as np

model = mrcal.cameramodel(sys.argv[1])
width, height = model.imagersize()
cols, rows = 32, 24
step = np.array([width / cols, height / rows])
observed = np.zeros((rows, cols), bool)
for line in open(sys.argv[2]):
    if line.startswith("#"):
        continue
    _, x, y, _ = line.split()
    if x == "-":
        continue
    i, j = (np.array([float(x), float(y)]) + 0.5) // step
    if 0 <= i < cols and 0 <= j < rows:
        observed[int(j), int(i)] = True
jj, ii = np.mgrid[0:rows, 0:cols]
pixels = np.stack(((ii + 0.5) * step[0] - 0.5, (jj + 0.5) * step[1] - 0.5), axis=-1)
rays = mrcal.unproject(pixels, *model.intrinsics())
sigma = mrcal.projection_uncertainty(rays, model=model, atinfinity=True,
                                     what="worstdirection-stdev")
seen = sigma[observed & np.isfinite(sigma)]
print(f"mrcal {sys.argv[3]}: projection uncertainty (1 sigma, worst direction) median "
      f"{np.median(seen):.4f} px, worst {np.max(seen):.4f} px over the {seen.size} observed "
      f"cells of {cols} x {rows}")
