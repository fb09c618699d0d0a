#!/usr/bin/python3
# mrcal-stereo's lat-lon rectification (mrcal.rectified_system +
# rectification_maps, mrcal 2.2) of a stereo set against stereo-match's, on
# the same images and with the same detector: the chessboard is looked for
# in every rectified pair (cv2.findChessboardCorners + cornerSubPix), and
# corners found in both images of a pair should share a row. Prints, per
# rectification, the boards found, the row error RMS and median, and the
# median over the pairs of the RMS about each pair's own mean row difference
# (hand-held pairs not triggered together are off by a row shift each).
#
#   mrcal_latlon_rows.py LEFT.cameramodel RIGHT.cameramodel IMAGE_DIR OURS_DIR \
#       AZ_FOV_DEG EL_FOV_DEG PIXELS_PER_DEG COLS ROWS
# IMAGE_DIR holds left-NNNN.png / right-NNNN.png; OURS_DIR stereo-match
# --save-rectified's left_NNNNNN.png / right_NNNNNN.png of the same pairs in
# the same order.
import glob
import sys

import cv2
import mrcal
import numpy as np


def find(image, size):
    flags = cv2.CALIB_CB_ADAPTIVE_THRESH | cv2.CALIB_CB_NORMALIZE_IMAGE
    found, corners = cv2.findChessboardCorners(image, size, flags=flags)
    if not found:
        return None
    criteria = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 30, 0.01)
    return cv2.cornerSubPix(image, corners, (5, 5), (-1, -1), criteria).reshape(-1, 2)


def rows(pairs, size):
    """Row differences over the pairs (half-turned numbering allowed) and per-pair scatter."""
    all_rows, scatter, boards = [], [], 0
    for left, right in pairs:
        l, r = find(left, size), find(right, size)
        if l is None or r is None:
            continue
        boards += 1
        d = min((l[:, 1] - r[:, 1], l[:, 1] - r[::-1, 1]), key=lambda x: np.abs(x).mean())
        all_rows.append(d)
        scatter.append(np.std(d))
    d = np.concatenate(all_rows) if all_rows else np.zeros(0)
    return boards, len(pairs), np.sqrt(np.mean(d * d)), np.median(np.abs(d)), np.median(scatter)


def main():
    left_model, right_model, image_dir, ours_dir = sys.argv[1:5]
    az, el, ppd = (float(x) for x in sys.argv[5:8])
    size = (int(sys.argv[8]), int(sys.argv[9]))
    models = [mrcal.cameramodel(left_model), mrcal.cameramodel(right_model)]
    rectified = mrcal.rectified_system(models, az_fov_deg=az, el_fov_deg=el, pixels_per_deg_az=ppd,
                                       pixels_per_deg_el=ppd, rectification_model='LENSMODEL_LATLON')
    maps = mrcal.rectification_maps(models, rectified)
    lefts = sorted(glob.glob(image_dir + '/left-*.png'))
    mrcal_pairs = []
    for left in lefts:
        images = [cv2.imread(p, cv2.IMREAD_GRAYSCALE) for p in (left, left.replace('/left-', '/right-'))]
        mrcal_pairs.append([cv2.remap(im, m[..., 0], m[..., 1], cv2.INTER_LINEAR) for im, m in zip(images, maps)])
    ours = sorted(glob.glob(ours_dir + '/left_*.png'))
    our_pairs = [[cv2.imread(p, cv2.IMREAD_GRAYSCALE) for p in (left, left.replace('/left_', '/right_'))]
                 for left in ours]
    print('rectified size: mrcal %dx%d, ours %dx%d' % (mrcal_pairs[0][0].shape[1], mrcal_pairs[0][0].shape[0],
                                                       our_pairs[0][0].shape[1], our_pairs[0][0].shape[0]))
    for name, pairs in (('mrcal latlon', mrcal_pairs), ('stereo-match latlon', our_pairs)):
        print('%-20s boards %d of %d, row error RMS %.3f px, median %.3f px, scatter within a pair %.3f px'
              % ((name,) + rows(pairs, size)))


main()
