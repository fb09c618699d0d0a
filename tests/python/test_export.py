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
import subprocess

import cv2
import mrcal
import numpy as np
import pytest
import yaml

import widestereo
from conftest import BIN, BUILD, SOURCE, run

KINDS = ["bspline", "poly6", "poly12", "kb4", "bspline_theta"]
TILT = [0.01, -0.02]
FORMATS = ["opencv-stereo", "ros", "kalibr", "mrcal"]


@pytest.fixture(scope="module")
def kinds(tmp_path_factory):
    """The test rigs of every kind, and rig-poly6-tilt.yaml: rig-poly6's with a
    sensor tilt on its left camera."""
    folder = tmp_path_factory.mktemp("kinds")
    run(os.path.join(BUILD, "tests", "camera_reference"), folder)
    left, right = open(folder / "rig-poly6.yaml").read().split("\nright:", 1)
    (folder / "rig-poly6-tilt.yaml").write_text(
        left.replace("   views:", "   nonradial:\n      tilt: [ %r, %r ]\n   views:" % tuple(TILT), 1)
        + "\nright:" + right)
    return folder


def export(calibration, fmt, out, *options):
    """stereo-export's output, and the error it printed (0 when exact)."""
    text = run(os.path.join(BIN, "stereo-export"), calibration, "--to", fmt, out, *options)
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


def test_a_tilted_poly6_exports_to_opencv_and_ros_exactly(kinds, tmp_path):
    """poly6 with a sensor tilt is OpenCV's 14-coefficient model
    (CALIB_TILTED_MODEL), and ROS's rational_polynomial with the same D
    (image_geometry hands D to OpenCV as it stands): cv2 projects with the
    exported K and D as the calibration does."""
    tilted = str(kinds / "rig-poly6-tilt.yaml")
    rig = widestereo.Rig.load(tilted)
    assert rig.left.parameters["nonradial"] == {"tilt": TILT}
    pixels, rays = image_pixels(rig.left, in_front=True)
    _, error = export(tilted, "opencv-stereo", tmp_path / "opencv")
    fs = cv2.FileStorage(str(tmp_path / "opencv" / "stereo.yaml"), cv2.FILE_STORAGE_READ)
    K, D = fs.getNode("K1").mat(), fs.getNode("D1").mat().ravel()
    assert error == 0 and D.size == 14 and list(D[12:]) == TILT
    assert np.abs(opencv_project("pinhole", K, D, rays) - pixels).max() < 1e-6
    _, error = export(tilted, "ros", tmp_path / "ros")
    info = yaml.safe_load(open(tmp_path / "ros" / "left.yaml"))
    D = matrix(info["distortion_coefficients"]).ravel()
    assert error == 0 and info["distortion_model"] == "rational_polynomial" and list(D[12:]) == TILT
    assert np.abs(opencv_project("pinhole", matrix(info["camera_matrix"]), D, rays) - pixels).max() < 1e-6


def fitted_circles(text):
    """The lens circle radius each camera's fitted model (mrcal's spline,
    Kalibr's closest model) was fitted within, as stereo-export printed it
    (inf: the model does not fold)."""
    found = re.findall(r"^(left|right): .*?(?:lens circle \(r = ([0-9.]+) px|no lens circle)", text, re.M)
    return {side: float(r) if r else np.inf for side, r in found}


def rectified_pair_is_the_maps(rig, back, maps):
    """A camera the format has no model of loads as the rectified pair the
    exported maps make: side by side, the rig's baseline apart, and each
    loaded camera's ray of a rectified pixel is the calibration's ray of the
    raw pixel the map takes it from, to the maps' fixed point (1/32 px)."""
    np.testing.assert_allclose(back.R, np.eye(3), atol=1e-12)
    assert abs(np.linalg.norm(back.T) - np.linalg.norm(rig.T)) < 1e-9 and back.T[0] < 0
    rect = rig.rectification("pinhole")
    assert back.left.image_size == rect.size
    for side, R in (("left", rect.R_left), ("right", rect.R_right)):
        x, y = cv2.convertMaps(maps.getNode("map1_" + side).mat(), maps.getNode("map2_" + side).mat(), cv2.CV_32FC1)
        valid = getattr(rect, "valid_" + side) > 0
        v, u = np.nonzero(valid)
        pick = np.arange(0, u.size, max(1, u.size // 4000))
        rectified = np.stack([u[pick], v[pick]], 1).astype(float)
        raw = np.stack([x[v[pick], u[pick]], y[v[pick], u[pick]]], 1)
        rays = getattr(back, side).unproject(rectified) @ R  # R^T ray, row by row
        assert np.linalg.norm(getattr(rig, side).project(rays) - raw, axis=1).max() < 1 / 32


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("kind", KINDS + ["poly6-tilt"])
def test_every_export_loads_back(kinds, kind, fmt, tmp_path):
    """Rig.load and Camera.load read every folder stereo-export writes: a
    camera the format holds exactly projects as the calibration does (1e-9
    px, R and T the same); a fitted one (Kalibr's closest model, mrcal's
    spline) within the error printed, where it was fitted; one the format
    has no model of (OpenCV, ROS) is the rectified pair of the maps."""
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    text, error = export(calibration, fmt, tmp_path)
    rig, back = widestereo.Rig.load(calibration), widestereo.Rig.load(str(tmp_path))
    assert back.format == {"opencv-stereo": "opencv"}.get(fmt, fmt)
    for side in ("left", "right"):
        assert widestereo.Camera.load(str(tmp_path), side).parameters == getattr(back, side).parameters
    rectified = fmt in ("opencv-stereo", "ros") and error > 0
    if rectified:
        rectified_pair_is_the_maps(rig, back, cv2.FileStorage(str(tmp_path / "maps.yml.gz"), cv2.FILE_STORAGE_READ))
        return
    np.testing.assert_allclose(back.R, rig.R, atol=1e-12)
    np.testing.assert_allclose(back.T, rig.T, atol=1e-12)
    circles = fitted_circles(text)
    for side in ("left", "right"):
        camera = getattr(rig, side)
        pixels, rays = image_pixels(camera, 8)
        if fmt in ("mrcal", "kalibr") and error > 0:  # where the model was fitted
            if not re.search(r"^%s: .*, exactly$" % side, text, re.M):  # a fitted camera names its region
                assert side in circles, text
            inside = np.linalg.norm(pixels - [camera.parameters["cx"], camera.parameters["cy"]], axis=1) < circles.get(side, np.inf) - 0.1
            pixels, rays = pixels[inside], rays[inside]
        worst = np.linalg.norm(getattr(back, side).project(rays) - camera.project(rays), axis=1).max()
        assert worst <= (error * 1.01 if error > 0 else 1e-9), (side, worst, error)


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
    """mrcal reads the export; mrcal.project of the calibration's rays, and
    mrcal.unproject of its pixels, agree with the calibration to the printed
    error where the spline was fitted: on a knot grid mrcal's users use
    when one comes within 0.01 px, else on a finer one, saying so beside
    the best of theirs."""
    calibration = str(kinds / ("rig-%s.yaml" % kind))
    text, error = export(calibration, "mrcal", tmp_path)
    rig = widestereo.Rig.load(calibration)
    models = [mrcal.cameramodel(str(tmp_path / ("camera-%d.cameramodel" % i))) for i in (0, 1)]
    r, t = models[1].extrinsics_rt_fromref()[:3], models[1].extrinsics_rt_fromref()[3:]
    np.testing.assert_allclose(mrcal.R_from_r(r), rig.R, atol=1e-12)
    np.testing.assert_allclose(t, rig.T, atol=1e-15)
    circles = fitted_circles(text)
    for model, side in zip(models, ("left", "right")):
        camera = getattr(rig, side)
        pixels, rays = image_pixels(camera, 4)
        lensmodel, intrinsics = model.intrinsics()
        if kind == "poly6":
            worst = np.linalg.norm(mrcal.project(rays, lensmodel, intrinsics) - pixels, axis=1).max()
            assert lensmodel == "LENSMODEL_OPENCV5" and error == 0 and worst < 1e-6
            continue
        nx = int(re.match(r"LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=(\d+)_Ny=(\d+)_fov_x_deg=(\d+)$",
                          lensmodel).group(1))
        finer = re.search(r"^%s: .*no grid mrcal's users calibrate with \(Nx 16 to 30\) follows it within 0.01 px: "
                          r"the best of them, Nx (\d+), is ([0-9.e-]+) px off .*; this is Nx %d \(--mrcal-nx \1 " % (side, nx),
                          text, re.M)
        side_error = float(re.search(r"^%s: .*?worst projection difference ([0-9.e-]+) px" % side, text, re.M).group(1))
        if nx in (16, 20, 24, 30):
            assert not finer and 0 < side_error < 0.01, (lensmodel, side_error)
        else:  # a finer grid, for a lens theirs do not follow
            assert finer and int(finer.group(1)) in (16, 20, 24, 30) and float(finer.group(2)) >= 0.01, text
            assert 0 < side_error < float(finer.group(2)), (lensmodel, side_error)
        inside = np.linalg.norm(pixels - [camera.parameters["cx"], camera.parameters["cy"]], axis=1) < circles[side] - 0.1
        assert inside.mean() > 0.5
        pixels, rays = pixels[inside], rays[inside]
        worst = np.linalg.norm(mrcal.project(rays, lensmodel, intrinsics) - pixels, axis=1).max()
        assert worst <= error * 1.01, (worst, error)
        # mrcal's own inverse lands on the calibration's ray of each pixel:
        # the calibration projects it back within the printed error.
        back = mrcal.unproject(pixels, lensmodel, intrinsics, normalize=True)
        worst = np.linalg.norm(camera.project(back) - pixels, axis=1).max()
        assert worst <= error * 1.01 + 1e-6, (worst, error)


def test_the_calibrations_report_bounds_the_fitted_region(kinds, tmp_path):
    """With the calibration's report (--report) the spline is fitted out to
    each camera's outermost calibrated corner only: a kb4 that never folds
    gets a lens circle there, on a finer grid than over its whole image; a
    report of another calibration is refused."""
    calibration = tmp_path / "rig.yaml"
    calibration.write_text(open(kinds / "rig-kb4.yaml").read())
    _, whole = export(str(calibration), "mrcal", tmp_path / "whole")
    rig = widestereo.Rig.load(str(calibration))
    report = {"model": "kb4", "cameras": [{"name": side, "fx": getattr(rig, side).parameters["fx"],
                                           "max_observed_radius": 1.2} for side in ("left", "right")]}
    (tmp_path / "rig.report.json").write_text(json.dumps(report))
    assert export(str(calibration), "mrcal", tmp_path / "default")[1] == whole  # only when asked
    text, error = export(str(calibration), "mrcal", tmp_path / "bounded", "--report", tmp_path / "rig.report.json")
    assert "the calibrated field, from %s" % (tmp_path / "rig.report.json") in text
    circles = fitted_circles(text)
    for side in ("left", "right"):
        camera = getattr(rig, side)
        phi = np.radians(np.arange(0, 360, 2.5))  # the azimuths FindLensCircle walks, each to a quarter degree
        ring = np.stack([np.sin(1.2) * np.cos(phi), np.sin(1.2) * np.sin(phi), np.full_like(phi, np.cos(1.2))], 1)
        edge = np.linalg.norm(camera.project(ring) - [camera.parameters["cx"], camera.parameters["cy"]], axis=1).min()
        assert edge - camera.parameters["fx"] * np.radians(0.25) - 0.1 < circles[side] <= edge + 0.1, (circles, edge)
    assert error < whole
    report["cameras"][0]["fx"] *= 1.001
    (tmp_path / "other.json").write_text(json.dumps(report))
    done = subprocess.run([os.path.join(BIN, "stereo-export"), str(calibration), "--to", "mrcal", str(tmp_path / "other"),
                           "--report", str(tmp_path / "other.json")], capture_output=True, text=True)
    assert done.returncode == 1 and "the report of another calibration" in done.stderr


def test_an_export_compared_with_its_calibration_differs_by_at_most_its_error(kinds, tmp_path, sim_calibration):
    # The test rigs, and a calibration stereo-calibrate made (its mustache
    # lens's steep corners need a finer grid than mrcal's users' to come
    # within 0.01 px).
    for calibration, bound in ((str(kinds / "rig-bspline_theta.yaml"), 0.05), (str(kinds / "rig-kb4.yaml"), 0.05),
                               (sim_calibration, 0.01)):
        kind = os.path.basename(calibration)
        text, error = export(calibration, "mrcal", tmp_path / kind)
        assert 0 < error < bound, text
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


def test_mrcal_nx_writes_that_grid_whatever_its_error(kinds, tmp_path):
    """--mrcal-nx N writes N knots across, even where mrcal's users' grids
    or a finer one would come closer, and prints its error all the same."""
    text, error = export(str(kinds / "rig-bspline.yaml"), "mrcal", tmp_path, "--mrcal-nx", "20")
    for i in (0, 1):
        lensmodel = mrcal.cameramodel(str(tmp_path / ("camera-%d.cameramodel" % i))).intrinsics()[0]
        assert "_Nx=20_" in lensmodel, lensmodel
    assert error > 0 and "no grid mrcal's users" not in text, text
