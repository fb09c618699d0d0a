"""stereo-export read back by each tool: OpenCV (cv2.FileStorage, its own
initUndistortRectifyMap for the models it has, cv2.remap against
stereo-match's --save-rectified), ROS camera_info and Kalibr's camchain by
their documented fields (evaluated with cv2's projection of the model they
name), mrcal (mrcal.cameramodel, mrcal.project); and stereo-compare of an
export against the calibration it came from."""
import glob
import json
import os
import re

import cv2
import mrcal
import numpy as np
import pytest
import yaml

import widestereo
from conftest import BIN, BUILD, SOURCE, run

KINDS = ["bspline", "poly6", "poly12", "kb4", "bspline_theta"]


@pytest.fixture(scope="module")
def kinds(tmp_path_factory):
    folder = tmp_path_factory.mktemp("kinds")
    run(os.path.join(BUILD, "tests", "camera_reference"), folder)
    return folder


def export(calibration, fmt, out):
    """stereo-export's output, and the error it printed (0 when exact)."""
    text = run(os.path.join(BIN, "stereo-export"), calibration, "--to", fmt, out)
    found = re.search(r"error up to ([0-9.eE+-]+) px", text)
    assert ("NOT EXACT" in text) == bool(found), text
    return text, float(found.group(1)) if found else 0.0


def image_pixels(camera, step=16, in_front=False):
    w, h = camera.image_size
    grid = np.stack(np.meshgrid(np.arange(0, w, step), np.arange(0, h, step)), -1).reshape(-1, 2).astype(float)
    rays = camera.unproject(grid)
    keep = ~np.isnan(rays).any(axis=1)
    keep[keep] = camera.in_field(rays[keep])
    if in_front:
        keep[keep] = rays[keep][:, 2] > 0.05
    return grid[keep], rays[keep]


def opencv_project(model, K, D, rays):
    """cv2's projection of unit rays in front of the camera (cv2 takes no
    other) through the model a file names."""
    points = rays.reshape(-1, 1, 3)
    project = cv2.fisheye.projectPoints if model in ("fisheye", "equidistant") else cv2.projectPoints
    return project(points, np.zeros(3), np.zeros(3), K, np.asarray(D, float))[0].reshape(-1, 2)


def matrix(node):
    return np.array(node["data"], float).reshape(node["rows"], node["cols"])


@pytest.mark.parametrize("kind", KINDS)
def test_opencv_stereo_reads_back_in_cv2(kinds, kind, tmp_path):
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    text, error = export(calibration, "opencv-stereo", tmp_path)
    rig = widestereo.Rig.load(calibration)
    fs = cv2.FileStorage(str(tmp_path / "stereo.yaml"), cv2.FILE_STORAGE_READ)
    np.testing.assert_array_equal(fs.getNode("R").mat(), rig.R)
    model = fs.getNode("distortion_model").string()
    maps = cv2.FileStorage(str(tmp_path / "maps.yml.gz"), cv2.FILE_STORAGE_READ)
    rect = rig.rectification("pinhole")
    map1, map2 = maps.getNode("map1_left").mat(), maps.getNode("map2_left").mat()
    np.testing.assert_array_equal(map1, rect.maps_left[0])
    np.testing.assert_array_equal(map2, rect.maps_left[1])
    if kind not in ("poly6", "kb4"):
        assert model == "none: widestereo " + kind and fs.getNode("D1").empty() and error > 0
        return
    # OpenCV's own maps from K, D, R1, P1 are ours, to the fixed point's 1/32 px.
    assert error == 0 and model == ("fisheye" if kind == "kb4" else "pinhole")
    K, D, R1, P1 = (fs.getNode(n).mat() for n in ("K1", "D1", "R1", "P1"))
    size = (fs.getNode("rectified_width").real(), fs.getNode("rectified_height").real())
    size = tuple(int(v) for v in size)
    init = cv2.fisheye.initUndistortRectifyMap if kind == "kb4" else cv2.initUndistortRectifyMap
    x, y = init(K, D, R1, P1, size, cv2.CV_32FC1)
    ours_x, ours_y = cv2.convertMaps(map1, map2, cv2.CV_32FC1)
    valid = rect.valid_left > 0
    assert valid.mean() > 0.5
    assert np.abs(x[valid] - ours_x[valid]).max() < 1 / 32 and np.abs(y[valid] - ours_y[valid]).max() < 1 / 32


def test_opencv_maps_rectify_as_stereo_match_saves(tmp_path, sim_calibration):
    export(sim_calibration, "opencv-stereo", tmp_path / "opencv")
    images = tmp_path / "images.lcmlog"
    events = widestereo.read_log(os.path.join(SOURCE, "logs", "sim-images.lcmlog"), {"STEREO_IMAGES"}, raw=True)
    widestereo.write_log(str(images), ((e.channel, e.message, e.utime) for _, e in zip(range(2), events)))
    saved = tmp_path / "rectified"
    run(os.path.join(BIN, "stereo-match"), "--calib", sim_calibration, "--rectification", "pinhole",
        "--save-rectified", saved, "--in-url", "file://%s?speed=0" % images,
        "--out-url", "file://%s?mode=w" % (tmp_path / "match.lcmlog"), "--log-dir", tmp_path, "--quiet")
    maps = cv2.FileStorage(str(tmp_path / "opencv" / "maps.yml.gz"), cv2.FILE_STORAGE_READ)
    frames = [e.message for e in widestereo.read_log(str(images))]
    pngs = {side: sorted(glob.glob(str(saved / ("%s_*.png" % side)))) for side in ("left", "right")}
    assert len(pngs["left"]) == len(frames) == 2
    for i, frame in enumerate(frames):
        for side in ("left", "right"):
            raw = widestereo.image_array(getattr(frame, side))
            mine = cv2.remap(raw, maps.getNode("map1_" + side).mat(), maps.getNode("map2_" + side).mat(),
                             cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT)
            theirs = cv2.imread(pngs[side][i], cv2.IMREAD_UNCHANGED)
            assert mine.shape == theirs.shape
            assert np.abs(mine.astype(int) - theirs.astype(int)).max() <= 1


@pytest.mark.parametrize("kind", KINDS)
def test_ros_export_loads_back(kinds, kind, tmp_path):
    """Camera.load and Rig.load read what stereo-export --to ros writes: the
    raw cameras where ROS has their model (projecting as the calibration
    does, R and T the same), the rectified pair where it has not."""
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    _, error = export(calibration, "ros", tmp_path)
    rig = widestereo.Rig.load(calibration)
    back = widestereo.Rig.load(str(tmp_path))
    for side in ("left", "right"):
        camera = widestereo.Camera.load(str(tmp_path / (side + ".yaml")))
        assert camera.parameters == getattr(back, side).parameters
        if error == 0:
            pixels, rays = image_pixels(getattr(rig, side), in_front=True)
            assert np.abs(camera.project(rays) - pixels).max() < 1e-6
    if error == 0:
        np.testing.assert_allclose(back.R, rig.R, atol=1e-12)
        np.testing.assert_allclose(back.T, rig.T, atol=1e-12)
    else:  # the rectified pair: side by side, the rig's baseline apart
        np.testing.assert_allclose(back.R, np.eye(3), atol=1e-12)
        assert abs(np.linalg.norm(back.T) - np.linalg.norm(rig.T)) < 1e-9 and back.T[0] < 0


def test_a_tilted_poly6_exports_to_opencv_exactly(kinds, tmp_path):
    """poly6 with a sensor tilt is OpenCV's 14-coefficient model
    (CALIB_TILTED_MODEL): cv2 projects with the exported K and D as the
    calibration does, and the file loads back as the same camera."""
    text = open(kinds / "rig-poly6.yaml").read()
    left, right = text.split("\nright:", 1)
    tilted = tmp_path / "tilted.yaml"
    tilted.write_text(left.replace("   views:", "   nonradial:\n      tilt: [ 1.0e-02, -2.0e-02 ]\n   views:", 1)
                      + "\nright:" + right)
    out = tmp_path / "opencv"
    _, error = export(str(tilted), "opencv-stereo", out)
    assert error == 0
    rig = widestereo.Rig.load(str(tilted))
    assert rig.left.parameters["nonradial"] == {"tilt": [0.01, -0.02]}
    fs = cv2.FileStorage(str(out / "stereo.yaml"), cv2.FILE_STORAGE_READ)
    K, D = fs.getNode("K1").mat(), fs.getNode("D1").mat().ravel()
    assert D.size == 14 and list(D[12:]) == [0.01, -0.02]
    pixels, rays = image_pixels(rig.left, in_front=True)
    assert np.abs(opencv_project("pinhole", K, D, rays) - pixels).max() < 1e-6
    back = widestereo.Rig.load(str(out / "stereo.yaml"))
    assert back.left.parameters["nonradial"] == {"tilt": [0.01, -0.02]}
    assert np.abs(back.left.project(rays) - pixels).max() < 1e-9


def test_a_damaged_ros_file_is_refused_naming_the_field(kinds, tmp_path):
    export(str(kinds / "rig-kb4.yaml"), "ros", tmp_path)
    text = open(tmp_path / "left.yaml").read()
    for old, new, field in [("cols: 4\n", "cols: 99\n", "distortion_coefficients.cols"),
                            ("equidistant", "rational_polynomial", "distortion_model"),
                            ("image_width: ", "image_width: -", "image_width")]:
        damaged = tmp_path / "damaged.yaml"
        damaged.write_text(text.replace(old, new, 1))
        with pytest.raises(RuntimeError, match=re.escape(str(damaged) + ": " + field + ": ")):
            widestereo.Camera.load(str(damaged))


@pytest.mark.parametrize("kind", KINDS)
def test_ros_camera_info_by_its_documented_fields(kinds, kind, tmp_path):
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    text, error = export(calibration, "ros", tmp_path)
    rig = widestereo.Rig.load(calibration)
    for side in ("left", "right"):
        info = yaml.safe_load(open(tmp_path / (side + ".yaml")))
        assert info["camera_name"] == side
        K, R, P = matrix(info["camera_matrix"]), matrix(info["rectification_matrix"]), matrix(info["projection_matrix"])
        D = matrix(info["distortion_coefficients"]).ravel()
        assert R.shape == (3, 3) and P.shape == (3, 4)
        camera = getattr(rig, side)
        if kind in ("poly6", "kb4"):
            assert error == 0 and info["distortion_model"] == ("equidistant" if kind == "kb4" else "plumb_bob")
            assert (info["image_width"], info["image_height"]) == camera.image_size
            pixels, rays = image_pixels(camera, in_front=True)
            assert np.abs(opencv_project(info["distortion_model"], K, D, rays) - pixels).max() < 1e-6
        else:
            assert error > 0 and info["distortion_model"] == "plumb_bob" and not D.any()
            assert "NOT THE RAW CAMERA" in open(tmp_path / (side + ".yaml")).read()
            np.testing.assert_array_equal(K, P[:, :3])
            rect = rig.rectification("pinhole")
            assert (info["image_width"], info["image_height"]) == rect.size
            assert os.path.exists(tmp_path / "maps.yml.gz")


@pytest.mark.parametrize("kind", KINDS)
def test_kalibr_camchain_by_its_documented_fields(kinds, kind, tmp_path):
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    text, error = export(calibration, "kalibr", tmp_path)
    rig = widestereo.Rig.load(calibration)
    chain = yaml.safe_load(open(tmp_path / "camchain.yaml"))
    T = np.array(chain["cam1"]["T_cn_cnm1"])
    np.testing.assert_array_equal(T[:3, :3], rig.R)
    np.testing.assert_array_equal(T[:3, 3], rig.T)
    for cam, side in (("cam0", "left"), ("cam1", "right")):
        c, camera = chain[cam], getattr(rig, side)
        assert c["camera_model"] == "pinhole" and tuple(c["resolution"]) == camera.image_size
        fu, fv, pu, pv = c["intrinsics"]
        K = np.array([[fu, 0, pu], [0, fv, pv], [0, 0, 1]])
        model = {"radtan": "plumb_bob", "equidistant": "equidistant"}[c["distortion_model"]]
        pixels, rays = image_pixels(camera, in_front=True)
        worst = np.abs(np.linalg.norm(opencv_project(model, K, c["distortion_coeffs"], rays) - pixels, axis=1)).max()
        if kind == "kb4":
            assert error == 0 and worst < 1e-6
        else:  # poly6's k3 is not 0: radtan has no k3
            assert error > 0 and worst <= error * 1.01 + 1e-6, (worst, error)


@pytest.mark.parametrize("kind", KINDS)
def test_mrcal_loads_and_projects_to_the_printed_error(kinds, kind, tmp_path):
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    text, error = export(calibration, "mrcal", tmp_path)
    rig = widestereo.Rig.load(calibration)
    models = [mrcal.cameramodel(str(tmp_path / ("camera-%d.cameramodel" % i))) for i in (0, 1)]
    r, t = models[1].extrinsics_rt_fromref()[:3], models[1].extrinsics_rt_fromref()[3:]
    np.testing.assert_allclose(mrcal.R_from_r(r), rig.R, atol=1e-12)
    np.testing.assert_allclose(t, rig.T, atol=1e-15)
    for model, side in zip(models, ("left", "right")):
        camera = getattr(rig, side)
        pixels, rays = image_pixels(camera, 4)
        worst = np.linalg.norm(mrcal.project(rays, *model.intrinsics()) - pixels, axis=1).max()
        if kind == "poly6":
            assert model.intrinsics()[0] == "LENSMODEL_OPENCV5" and error == 0 and worst < 1e-6
        else:
            assert model.intrinsics()[0].startswith("LENSMODEL_SPLINED_STEREOGRAPHIC_order=3")
            assert 0 < error < 0.01 and worst <= error * 1.01, (worst, error)


def test_an_export_compared_with_its_calibration_differs_by_at_most_its_error(kinds, tmp_path, sim_calibration):
    # The test rigs, and a calibration stereo-calibrate made (its mustache
    # lens took 128 knots across to come under 0.01 px).
    for calibration in (str(kinds / "rig-bspline_theta.yaml"), str(kinds / "rig-kb4.yaml"), sim_calibration):
        kind = os.path.basename(calibration)
        text, error = export(calibration, "mrcal", tmp_path / kind)
        assert 0 < error < 0.01, text
        run(os.path.join(BIN, "stereo-compare"), calibration, tmp_path / kind, "--no-rotation",
            "--report", tmp_path / "diff.json")
        report = json.load(open(tmp_path / "diff.json"))
        assert len(report["cameras"]) == 2
        for camera in report["cameras"]:
            assert camera["points"] > 1000 and camera["max_px"] <= error * 1.01, (camera["max_px"], error)
    # Exact exports compare to nothing.
    for fmt in ("kalibr", "opencv-stereo"):
        calibration = str(kinds / "rig-kb4.yaml")
        export(calibration, fmt, tmp_path / fmt)
        exported = tmp_path / fmt / ("camchain.yaml" if fmt == "kalibr" else "stereo.yaml")
        run(os.path.join(BIN, "stereo-compare"), calibration, exported, "--no-rotation", "--report", tmp_path / "diff.json")
        for camera in json.load(open(tmp_path / "diff.json"))["cameras"]:
            assert camera["max_px"] < 1e-6
