"""widestereo.Rig: R and T as the file holds them, triangulation of raw pixel
pairs, and both rectifications' maps as cv2.remap uses them."""
import os

import cv2
import numpy as np
import pytest

import widestereo


@pytest.fixture(scope="module")
def rig(sim_calibration):
    return widestereo.Rig.load(sim_calibration)


def test_r_and_t_are_the_files(rig, sim_calibration):
    fs = cv2.FileStorage(sim_calibration, cv2.FILE_STORAGE_READ)
    np.testing.assert_array_equal(rig.R, fs.getNode("stereo").getNode("R").mat())
    np.testing.assert_array_equal(rig.T, fs.getNode("stereo").getNode("T").mat().ravel())
    assert rig.left.parameters["model"] == "bspline"
    assert rig.left.image_size == (1280, 960)


def test_triangulate_gives_back_the_points_seen(rig):
    rng = np.random.default_rng(2)
    points = np.c_[rng.uniform(-2, 2, 200), rng.uniform(-1.5, 1.5, 200), rng.uniform(1, 6, 200)]
    left = rig.left.project(points)
    right = rig.right.project(points @ rig.R.T + rig.T)
    found = rig.triangulate(left, right)
    seen = ~np.isnan(left).any(axis=1) & ~np.isnan(right).any(axis=1)
    assert seen.sum() > 150
    assert np.abs(found[seen] - points[seen]).max() < 1e-7
    # A match whose rays meet behind the cameras has no point.
    assert np.isnan(rig.triangulate(left[:1], left[:1] + [400, 0])).all()


@pytest.mark.parametrize("mode", ["pinhole", "latlon"])
def test_maps_rectify_with_cv2_remap_as_the_library_does(rig, mode):
    rect = rig.rectification(mode)
    assert rect.mode == mode and rect.baseline == pytest.approx(np.linalg.norm(rig.T))
    rng = np.random.default_rng(3)
    image = cv2.GaussianBlur(rng.integers(0, 255, (960, 1280), dtype=np.uint8), (5, 5), 1.5)
    left, right = rect.rectify(image, image)
    map1, map2 = rect.maps_left
    assert map1.dtype == np.int16 and map1.shape == (rect.size[1], rect.size[0], 2)
    np.testing.assert_array_equal(cv2.remap(image, map1, map2, cv2.INTER_LINEAR), left)
    np.testing.assert_array_equal(cv2.remap(image, *rect.maps_right, cv2.INTER_LINEAR), right)


def test_disparity_triangulation_meets_the_raw_pixel_one(rig):
    rect = rig.rectification("pinhole")
    point = np.array([0.3, -0.2, 3.0])  # left camera frame
    in_rect = rect.R_left @ point
    u, v = rect.f * in_rect[:2] / in_rect[2] + [rect.cx, rect.cy]
    d = rect.f * rect.baseline / in_rect[2]
    found = rect.triangulate([u, v, d])
    np.testing.assert_allclose(rect.R_left.T @ found, point, atol=1e-9)


def test_bad_input_is_refused_before_any_work(rig, sim_calibration, tmp_path):
    rect = rig.rectification("pinhole")
    with pytest.raises(ValueError, match="an image of 640x480, where the cameras' are 1280x960"):
        rect.rectify(np.zeros((480, 640), np.uint8), np.zeros((480, 640), np.uint8))
    with pytest.raises(ValueError, match="size must be two positive numbers"):
        rig.rectification("pinhole", size=(-5, -5))
    with pytest.raises(ValueError, match="NUL"):
        widestereo.Rig.load(sim_calibration + "\0.ignored")
    fifo = str(tmp_path / "calib.yaml")
    os.mkfifo(fifo)
    for path in (fifo, "/dev/zero"):  # a FIFO blocked the reader; /dev/zero was read for 2 GB
        with pytest.raises(RuntimeError, match="not a regular file"):
            widestereo.Camera.load(path)
