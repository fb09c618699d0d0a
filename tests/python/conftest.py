"""Shared by the Python module's tests: where the build is, and running its
executables."""
import os
import subprocess

import pytest

SOURCE = os.environ.get("WS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("WS_BINARY_DIR", os.path.join(SOURCE, "build"))
BIN = os.path.join(BUILD, "bin")


def run(*argv):
    """Runs a command, failing the test with its output when it fails; its stdout."""
    done = subprocess.run([str(a) for a in argv], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, timeout=600)
    assert done.returncode == 0, "%s failed (%d):\n%s" % (" ".join(map(str, argv)), done.returncode, done.stdout)
    return done.stdout


@pytest.fixture(scope="session")
def sim_calibration():
    """The simulated default rig's calibration (1280 x 960, bspline)."""
    return os.path.join(SOURCE, "config", "calib", "sim-default.yaml")
