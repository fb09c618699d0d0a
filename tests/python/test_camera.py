"""widestereo.Camera: project and unproject equal the C++ Camera's on every
model kind over the whole image; other tools' models equal their own
evaluation (mrcal.project and mrcal.unproject, python3-mrcal)."""
import glob
import os

import mrcal
import numpy as np
import pytest

import widestereo
from conftest import BUILD, run

KINDS = {"bspline", "poly6", "poly12", "kb4", "bspline_theta"}


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    folder = tmp_path_factory.mktemp("kinds")
    run(os.path.join(BUILD, "tests", "camera_reference"), folder)
    return folder


def rows(path, what):
    return np.array([[float(x) for x in line.split()[1:]] for line in open(path) if line.startswith(what)])


def test_the_reference_has_every_kind(reference):
    assert {os.path.basename(p)[:-4] for p in glob.glob(str(reference / "*.txt"))} == KINDS


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_python_equals_cpp_over_the_whole_image(reference, kind):
    camera = widestereo.Camera.load(str(reference / (kind + ".yaml")), "left")
    assert camera.model == kind
    unproject = rows(reference / (kind + ".txt"), "unproject")
    project = rows(reference / (kind + ".txt"), "project")
    assert len(unproject) == 16 * 12 and len(project) > 100
    rays = camera.unproject(unproject[:, :2])
    np.testing.assert_array_equal(np.isnan(rays), np.isnan(unproject[:, 2:]))
    assert np.nanmax(np.abs(rays - unproject[:, 2:])) <= 1e-12
    pixels = camera.project(project[:, :3])
    np.testing.assert_array_equal(np.isnan(pixels), np.isnan(project[:, 3:]))
    assert np.nanmax(np.abs(pixels - project[:, 3:])) <= 1e-12
    # One row at a time gives the same.
    np.testing.assert_array_equal(camera.project(project[0, :3]), pixels[0])


def test_bad_input_is_refused(reference):
    camera = widestereo.Camera.load(str(reference / "poly6.yaml"))
    with pytest.raises(ValueError, match="N x 3"):
        camera.project(np.zeros((4, 2)))
    with pytest.raises(ValueError, match="one camera only"):
        widestereo.Camera.load(str(reference / "poly6.yaml"), "right")
    with pytest.raises(RuntimeError, match="missing"):
        widestereo.Camera.load(str(reference / "absent.yaml"))


def mrcal_model(tmp_path, lensmodel, intrinsics):
    path = str(tmp_path / "camera.cameramodel")
    mrcal.cameramodel(intrinsics=(lensmodel, np.array(intrinsics)), imagersize=(800, 600),
                      extrinsics_rt_fromref=np.zeros(6)).write(path)
    return path, mrcal.cameramodel(path)  # both from the file (mrcal writes 10 digits)


def directions(n, max_deg):
    rng = np.random.default_rng(4)
    theta = np.radians(rng.uniform(0, max_deg, n))
    phi = rng.uniform(-np.pi, np.pi, n)
    return np.c_[np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)]


@pytest.mark.parametrize("lensmodel", ["LENSMODEL_OPENCV8", "LENSMODEL_OPENCV12",
                                       "LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=11_Ny=8_fov_x_deg=150"])
def test_mrcal_models_project_and_unproject_as_mrcal_does(tmp_path, lensmodel):
    rng = np.random.default_rng(1)
    count = mrcal.lensmodel_num_params(lensmodel) - 4
    distortion = rng.normal(size=count) * (0.03 if "SPLINED" in lensmodel else 0.002)
    if "OPENCV" in lensmodel:
        distortion[:2] = [-0.05, 0.002]
    path, model = mrcal_model(tmp_path, lensmodel, np.r_[320.0, 318.0, 401.5, 297.25, distortion])
    camera = widestereo.Camera.load(path)
    assert camera.model == "mrcal " + lensmodel and camera.image_size == (800, 600)
    p = directions(500, 60)
    ours = camera.project(p)
    theirs = mrcal.project(p, *model.intrinsics())
    assert np.abs(ours - theirs).max() < 1e-9
    rays = camera.unproject(theirs)
    expected = mrcal.unproject(theirs, *model.intrinsics(), normalize=True)
    assert np.abs(rays - expected).max() < 1e-9


def test_parameters_carry_the_tilt(tmp_path, sim_calibration):
    text = open(sim_calibration).read()
    tilted = text.replace("   views: 27\nright:", "   views: 27\n   nonradial:\n      tilt: [ 1.0e-02, -2.0e-02 ]\nright:", 1)
    assert tilted != text
    path = tmp_path / "tilted.yaml"
    path.write_text(tilted)
    camera = widestereo.Camera.load(str(path), "left")
    assert camera.parameters["nonradial"] == {"tilt": [0.01, -0.02]}
    assert "nonradial" not in widestereo.Camera.load(sim_calibration, "left").parameters
    ray = np.array([0.3, -0.2, 1.0])
    assert np.abs(camera.project(ray) - widestereo.Camera.load(sim_calibration, "left").project(ray)).max() > 0.1


@pytest.mark.parametrize("kind", ["poly6", "poly12", "kb4"])
def test_in_field_of_a_polynomial_is_what_its_image_holds(reference, kind):
    """A polynomial keeps no knots: its field is the rays it images inside
    the image before its radial map folds, not every ray it projects."""
    camera = widestereo.Camera.load(str(reference / (kind + ".yaml")), "left")
    w, h = camera.image_size
    grid = np.stack(np.meshgrid(np.linspace(0, w - 1, 9), np.linspace(0, h - 1, 7)), -1).reshape(-1, 2)
    rays = camera.unproject(grid)
    seen = ~np.isnan(rays).any(axis=1)
    assert seen.sum() > 50 and camera.in_field(rays[seen]).all()
    # A ray beyond the image's corner, in its azimuth: imaged outside the
    # image, or past a fold.
    corner = camera.unproject(np.array([0.0, 0.0]))
    theta, phi = np.arccos(corner[2]), np.arctan2(corner[1], corner[0])
    theta = theta * 1.3 if kind == "kb4" else (theta + np.pi / 2) / 2
    beyond = np.array([[np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)]])
    assert not camera.in_field(beyond).any()
    # Far outside the image: a ray where the model still inverts, never in the field.
    outside = camera.unproject(np.array([[-500.0, -500.0], [w + 300.0, h / 2]]))
    assert not camera.in_field(outside[~np.isnan(outside).any(axis=1)]).any()
    assert camera.in_field(np.array([[0.0, 0.0, 1.0]])).all()


def test_parameters_are_the_calibration_files_fields(sim_calibration):
    parameters = widestereo.Camera.load(sim_calibration, "left").parameters
    assert parameters["model"] == "bspline" and "alpha" in parameters and "knots" in parameters
    assert "coeffs" not in parameters  # the file names a model's coefficients by its own key
    left = open(sim_calibration).read().split("\nright:")[0]
    for key in set(parameters) - {"fx", "fy", "cx", "cy"}:  # the file holds those as camera_matrix
        assert f"\n   {key}:" in left, key
