"""widestereo's messages as numpy arrays and rigs."""
import numpy as np

from ._widestereo import Rig

_RAW = {  # image_t.PIXEL_FORMAT_*: (dtype, channels)
    1497715271: (np.uint8, 1),    # GRAY
    909199180: ("<u2", 1),        # LE_GRAY16
    859981650: (np.uint8, 3),     # RGB
    861030210: (np.uint8, 3),     # BGR
    842221382: ("<f4", 1),        # FLOAT_GRAY32 (native: little-endian here)
}


def image_array(image):
    """An image_t as an H x W (x C) array: raw formats directly, PNG and MJPEG
    through cv2.imdecode (python3-opencv)."""
    if image.pixelformat not in _RAW:
        import cv2
        decoded = cv2.imdecode(np.frombuffer(image.data, np.uint8), cv2.IMREAD_UNCHANGED)
        if decoded is None or decoded.shape[:2] != (image.height, image.width):
            raise ValueError("image_t: a compressed payload that does not decode to %dx%d"
                             % (image.width, image.height))
        return decoded
    dtype, channels = _RAW[image.pixelformat]
    row = image.width * channels * np.dtype(dtype).itemsize
    if image.width <= 0 or image.height <= 0 or image.row_stride < row or \
            len(image.data) < image.row_stride * image.height:
        raise ValueError("image_t: width, height, row_stride and data disagree")
    rows = np.frombuffer(bytes(image.data), np.uint8)[: image.row_stride * image.height]
    rows = rows.reshape(image.height, image.row_stride)[:, :row]
    shape = (image.height, image.width) + ((channels,) if channels > 1 else ())
    return np.ascontiguousarray(rows).view(dtype).reshape(shape)


def disparity_array(message):
    """A disparity_t's disparity image (pixels, float32; invalid below
    message.min_disparity)."""
    return image_array(message.disparity)


def cloud_array(message):
    """A point_cloud_t's points as N x 3 float32 (metres, in message.frame)."""
    return np.asarray(message.xyz, dtype=np.float32).reshape(message.npoints, 3)


def rig_from_message(message):
    """The Rig of a stereo_calibration_t (decoded by the library's own C++)."""
    return Rig.from_message(message.encode())
