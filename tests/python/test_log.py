"""LCM logs from Python without LCM's binding: a log written by
stereo-calibrate decodes to the calibration its file holds; stereo-match's
disparity and clouds decode into numpy; a log read and written again is the
same file."""
import os

import numpy as np
import pytest

import widestereo
from conftest import BIN, SOURCE, run


def url(path, options):
    return "file://%s?%s" % (path, options)


@pytest.fixture(scope="module")
def calibrated(tmp_path_factory):
    folder = tmp_path_factory.mktemp("calibrate")
    out = folder / "calibration.lcmlog"
    run(os.path.join(BIN, "stereo-calibrate"), "--once", "--model", "poly6", "--cv-folds", "0",
        "--in-url", url(os.path.join(SOURCE, "logs", "sim-corners.lcmlog"), "speed=0"),
        "--out-url", url(out, "mode=w"), "--out", folder / "calib.yaml",
        "--report", folder / "report.json", "--log-dir", folder, "--quiet")
    return folder


def test_stereo_calibrates_log_decodes_to_its_file(calibrated):
    events = list(widestereo.read_log(str(calibrated / "calibration.lcmlog"), channels={"STEREO_CALIBRATION"}))
    assert len(events) == 1
    message = events[0].message
    assert isinstance(message, widestereo.stereo_calibration_t)
    from_message = widestereo.rig_from_message(message)
    from_file = widestereo.Rig.load(str(calibrated / "calib.yaml"))
    np.testing.assert_allclose(from_message.R, from_file.R, rtol=0, atol=1e-15)
    np.testing.assert_allclose(from_message.T, from_file.T, rtol=0, atol=1e-15)
    for side in ("left", "right"):
        a, b = getattr(from_message, side), getattr(from_file, side)
        assert a.parameters == b.parameters
        grid = np.stack(np.meshgrid(np.linspace(0, 1279, 33), np.linspace(0, 959, 25)), -1).reshape(-1, 2)
        np.testing.assert_array_equal(a.unproject(grid), b.unproject(grid))
    assert message.left.model == "poly6" and message.left.fx == from_file.left.parameters["fx"]


def test_a_log_read_and_written_again_is_the_same_file(calibrated, tmp_path):
    source = str(calibrated / "calibration.lcmlog")
    copy = str(tmp_path / "copy.lcmlog")
    widestereo.write_log(copy, ((e.channel, e.message, e.utime) for e in widestereo.read_log(source, raw=True)))
    # Event numbers restart at 0 in the copy; everything else is byte for byte.
    a, b = list(widestereo.read_log(source, raw=True)), list(widestereo.read_log(copy, raw=True))
    assert [(e.utime, e.channel, e.message) for e in a] == [(e.utime, e.channel, e.message) for e in b]
    assert os.path.getsize(source) == os.path.getsize(copy)


def test_a_damaged_log_is_refused_where_it_breaks(calibrated, tmp_path):
    data = open(calibrated / "calibration.lcmlog", "rb").read()
    damaged = tmp_path / "damaged.lcmlog"
    damaged.write_bytes(data[:-5])
    with pytest.raises(ValueError, match="exceed the file"):
        list(widestereo.read_log(str(damaged)))
    with pytest.raises(ValueError, match="not a widestereo message"):
        widestereo.decode(b"\0" * 16)


def test_disparity_and_clouds_decode_into_numpy(tmp_path, sim_calibration):
    # Three image pairs of the recorded log, written by the module itself.
    images = tmp_path / "images.lcmlog"
    events = widestereo.read_log(os.path.join(SOURCE, "logs", "sim-images.lcmlog"), {"STEREO_IMAGES"}, raw=True)
    widestereo.write_log(str(images), ((e.channel, e.message, e.utime) for _, e in zip(range(3), events)))
    out = tmp_path / "match.lcmlog"
    run(os.path.join(BIN, "stereo-match"), "--calib", sim_calibration, "--in-url", url(images, "speed=0"),
        "--out-url", url(out, "mode=w"), "--log-dir", tmp_path, "--quiet")
    disparities = [e.message for e in widestereo.read_log(str(out), channels={"STEREO_DISPARITY"})]
    clouds = [e.message for e in widestereo.read_log(str(out), channels={"STEREO_CLOUD"})]
    assert len(disparities) == 3 and len(clouds) == 3
    d = widestereo.disparity_array(disparities[0])
    assert d.dtype == np.float32 and d.shape == (disparities[0].disparity.height, disparities[0].disparity.width)
    valid = d >= disparities[0].min_disparity
    assert valid.mean() > 0.05
    xyz = widestereo.cloud_array(clouds[0])
    assert xyz.shape == (clouds[0].npoints, 3) and clouds[0].npoints > 1000
    # The board is about 1 to 3 m in front of the rig.
    assert 0.5 < np.median(np.linalg.norm(xyz, axis=1)) < 5
