"""widestereo from Python (docs/python.md).

    import widestereo
    camera = widestereo.Camera.load("calib.yaml", "left")
    pixels = camera.project(points)          # N x 3 -> N x 2, NaN where none
    rays = camera.unproject(pixels)          # N x 2 -> N x 3 unit rays
    rig = widestereo.Rig.load("calib.yaml")  # rig.R, rig.T, rig.left, rig.right
    rect = rig.rectification("latlon")       # rect.maps_left, rect.rectify(left, right)
    points = rig.triangulate(left_pixels, right_pixels)
    for event in widestereo.read_log("run.lcmlog", channels={"STEREO_CLOUD"}):
        xyz = widestereo.cloud_array(event.message)

Camera, Rig and Rectification are the C++ library's own code (pybind11); a
calibration may be widestereo's file or another tool's (an mrcal
.cameramodel or output folder, a Kalibr camchain, OpenCV calibration YAML).
The LCM message classes are the ones lcm-gen -p generates for the
package widestereo (widestereo.stereo_calibration_t, ...), so logs are read
and written without LCM's Python binding.
"""
import importlib as _importlib
import pkgutil as _pkgutil

from ._widestereo import Camera, Rectification, Rig


def _import_message_classes():
    # lcm-gen's classes refer to one another as widestereo.TYPE, the class
    # (its own __init__.py did `from .TYPE import TYPE`): import every
    # module first, then put the classes in their place.
    names = [m.name for m in _pkgutil.iter_modules(__path__) if m.name.endswith("_t")]
    modules = [_importlib.import_module("." + name, __name__) for name in names]
    classes = {name: getattr(module, name) for name, module in zip(names, modules)}
    globals().update(classes)
    return classes


MESSAGE_TYPES = _import_message_classes()

from .lcm_log import Event, decode, read_log, write_log  # noqa: E402
from .messages import cloud_array, disparity_array, image_array, rig_from_message  # noqa: E402

__all__ = ["Camera", "Rectification", "Rig", "MESSAGE_TYPES", "Event", "decode", "read_log",
           "write_log", "cloud_array", "disparity_array", "image_array", "rig_from_message"]
__all__ += sorted(MESSAGE_TYPES)
