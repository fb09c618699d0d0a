#include "lcm_io/image_codec.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lcm_io/compressed_size.h"

namespace ws {
namespace {

using widestereo::image_t;

struct RawLayout {
  int cv_type;
  int bytes_per_pixel;
};

// The raw (uncompressed) formats we accept; false for compressed or unknown.
bool RawLayoutOf(int32_t pixelformat, RawLayout* layout) {
  switch (pixelformat) {
    case image_t::PIXEL_FORMAT_GRAY: *layout = {CV_8UC1, 1}; return true;
    case image_t::PIXEL_FORMAT_LE_GRAY16: *layout = {CV_16UC1, 2}; return true;
    case image_t::PIXEL_FORMAT_RGB:
    case image_t::PIXEL_FORMAT_BGR: *layout = {CV_8UC3, 3}; return true;
    case image_t::PIXEL_FORMAT_FLOAT_GRAY32: *layout = {CV_32FC1, 4}; return true;
    default: return false;
  }
}

bool IsCompressed(int32_t pixelformat) {
  return pixelformat == image_t::PIXEL_FORMAT_MJPEG || pixelformat == image_t::PIXEL_FORMAT_PNG;
}

[[noreturn]] void Reject(const std::string& what) { throw DecodeError("image_t: " + what); }

// A compressed payload's size, from its header or decoded, must be the message's.
void RequireCompressedSize(const image_t& msg, int64_t width, int64_t height) {
  if (width != msg.width || height != msg.height)
    Reject("compressed payload is " + std::to_string(width) + "x" + std::to_string(height) +
           ", header says " + std::to_string(msg.width) + "x" + std::to_string(msg.height));
}

}  // namespace

void RequireAtMostPixels(int64_t width, int64_t height, int64_t max_pixels) {
  if (width * height > max_pixels)
    Reject("a " + std::to_string(width) + "x" + std::to_string(height) + " image is " +
           std::to_string(width * height) + " pixels, more than --max-image-pixels " +
           std::to_string(max_pixels));
}

Compression ParseCompression(const std::string& name) {
  if (name == "none") return Compression::none;
  if (name == "jpeg") return Compression::jpeg;
  if (name == "png") return Compression::png;
  throw std::invalid_argument("compression must be none, jpeg or png, not '" + name + "'");
}

bool IsNoImage(const image_t& msg) {
  return msg.width == 0 && msg.height == 0 && msg.size == 0 && msg.data.empty();
}

image_t NoImage(int64_t utime) {
  image_t msg;
  msg.utime = utime;
  msg.width = msg.height = msg.row_stride = msg.size = 0;
  msg.pixelformat = image_t::PIXEL_FORMAT_GRAY;
  msg.nmetadata = 0;
  return msg;
}

void ValidateImage(const image_t& msg) {
  if (!ImageSizeAcceptable(msg.width, msg.height))
    Reject("bad image size " + std::to_string(msg.width) + "x" + std::to_string(msg.height));
  if (msg.size < 0 || size_t(msg.size) != msg.data.size())
    Reject("size field " + std::to_string(msg.size) + " but payload of " +
           std::to_string(msg.data.size()) + " bytes");
  if (IsCompressed(msg.pixelformat)) {
    const auto announced = CompressedImageSize(msg.data.data(), msg.data.size());
    if (!announced) Reject("compressed payload is neither a JPEG nor a PNG with its size");
    RequireCompressedSize(msg, announced->width, announced->height);
    return;
  }
  RawLayout layout{};
  if (!RawLayoutOf(msg.pixelformat, &layout))
    Reject("unsupported pixel format " + std::to_string(msg.pixelformat));
  const int64_t min_stride = int64_t(msg.width) * layout.bytes_per_pixel;
  if (msg.row_stride < min_stride)
    Reject("row_stride " + std::to_string(msg.row_stride) + " shorter than a row of " +
           std::to_string(min_stride) + " bytes");
  if (int64_t(msg.height) * msg.row_stride != int64_t(msg.size))
    Reject("height x row_stride = " + std::to_string(int64_t(msg.height) * msg.row_stride) +
           " but size is " + std::to_string(msg.size));
}

cv::Mat ImageToMat(const image_t& msg, int64_t max_pixels) {
  const cv::Mat image = ImageView(msg, max_pixels);
  return image.data == msg.data.data() ? image.clone() : image;
}

cv::Mat ImageView(const image_t& msg, int64_t max_pixels) {
  ValidateImage(msg);
  RequireAtMostPixels(msg.width, msg.height, max_pixels);
  if (IsCompressed(msg.pixelformat)) {
    cv::Mat decoded;
    try {
      decoded = cv::imdecode(cv::Mat(1, msg.size, CV_8UC1, const_cast<uint8_t*>(msg.data.data())),
                             cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception& e) {
      Reject(std::string("compressed payload does not decode: ") + e.what());
    }
    if (decoded.empty()) Reject("compressed payload does not decode");
    RequireCompressedSize(msg, decoded.cols, decoded.rows);
    if (decoded.type() == CV_8UC4) cv::cvtColor(decoded, decoded, cv::COLOR_BGRA2BGR);
    return decoded;
  }
  RawLayout layout{};
  RawLayoutOf(msg.pixelformat, &layout);
  cv::Mat view(msg.height, msg.width, layout.cv_type, const_cast<uint8_t*>(msg.data.data()),
               size_t(msg.row_stride));
  if (msg.pixelformat != image_t::PIXEL_FORMAT_RGB) return view;
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

image_t MatToImage(const cv::Mat& mat, int64_t utime, Compression compression, int jpeg_quality) {
  image_t msg;
  msg.utime = utime;
  msg.width = mat.cols;
  msg.height = mat.rows;
  msg.nmetadata = 0;
  if (compression != Compression::none) {
    std::vector<int> params;
    std::string ext = ".png";
    msg.pixelformat = image_t::PIXEL_FORMAT_PNG;
    if (compression == Compression::jpeg) {
      if (mat.depth() != CV_8U) throw std::invalid_argument("JPEG needs an 8-bit image");
      ext = ".jpg";
      msg.pixelformat = image_t::PIXEL_FORMAT_MJPEG;
      params = {cv::IMWRITE_JPEG_QUALITY, jpeg_quality};
    }
    cv::imencode(ext, mat, msg.data, params);
    msg.row_stride = 0;
  } else {
    switch (mat.type()) {
      case CV_8UC1: msg.pixelformat = image_t::PIXEL_FORMAT_GRAY; break;
      case CV_16UC1: msg.pixelformat = image_t::PIXEL_FORMAT_LE_GRAY16; break;
      case CV_8UC3: msg.pixelformat = image_t::PIXEL_FORMAT_BGR; break;
      case CV_32FC1: msg.pixelformat = image_t::PIXEL_FORMAT_FLOAT_GRAY32; break;
      default: throw std::invalid_argument("unsupported cv::Mat type " + std::to_string(mat.type()));
    }
    msg.row_stride = int32_t(mat.cols * mat.elemSize());
    msg.data.resize(size_t(msg.row_stride) * mat.rows);
    for (int y = 0; y < mat.rows; ++y)
      std::memcpy(msg.data.data() + size_t(y) * msg.row_stride, mat.ptr(y), msg.row_stride);
  }
  msg.size = int32_t(msg.data.size());
  return msg;
}

}  // namespace ws
