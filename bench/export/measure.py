"""One camera of a stereo-export --to mrcal folder against its calibration,
with mrcal itself: mrcal.project of the calibration's ray of every 2nd
pixel of the observed field against that pixel, worst and RMS, within the
lens circle (RADIUS px about the principal point: where the export was
fitted) and over the whole observed field; and the worst angle between
mrcal.unproject of those pixels and the calibration's rays, within the
circle (180 where mrcal gives none).

  python3 measure.py CALIBRATION.yaml FOLDER left|right RADIUS

Prints one line: Nx file_kB in_worst in_rms whole_worst whole_rms unproject_deg
(Nx 0: an exact mrcal model)."""
import os
import re
import sys

import mrcal
import numpy as np
import widestereo

calibration, folder, side, radius = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
camera = widestereo.Camera.load(calibration, side)
path = os.path.join(folder, "camera-%d.cameramodel" % ("left", "right").index(side))
lensmodel, intrinsics = mrcal.cameramodel(path).intrinsics()
nx = re.search(r"_Nx=(\d+)_", lensmodel)

w, h = camera.image_size
pixels = np.stack(np.meshgrid(np.arange(0, w, 2.0), np.arange(0, h, 2.0)), -1).reshape(-1, 2)
rays = camera.unproject(pixels)
keep = ~np.isnan(rays).any(axis=1)
keep[keep] = camera.in_field(rays[keep])
pixels, rays = pixels[keep], rays[keep]
inside = np.linalg.norm(pixels - [camera.parameters["cx"], camera.parameters["cy"]], axis=1) <= radius

off = np.linalg.norm(mrcal.project(rays, lensmodel, intrinsics) - pixels, axis=1)
back = mrcal.unproject(pixels[inside], lensmodel, intrinsics, normalize=True)
angle = np.degrees(np.arccos(np.clip((back * rays[inside]).sum(axis=1), -1, 1)))
angle[np.isnan(angle)] = 180
print("%d %.0f %.3g %.2g %.3g %.2g %.2g" % (int(nx.group(1)) if nx else 0, os.path.getsize(path) / 1e3,
                                           off[inside].max(), np.sqrt((off[inside] ** 2).mean()),
                                           off.max(), np.sqrt((off ** 2).mean()), angle.max()))
