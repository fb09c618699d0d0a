#include "interop/ros_camera_info.h"

#include <sstream>
#include <stdexcept>

#include "interop/number_text.h"
#include "runtime/atomic_file.h"

namespace ws {
namespace {

std::string Matrix(int rows, int cols, const double* data) {
  return "\n  rows: " + std::to_string(rows) + "\n  cols: " + std::to_string(cols) + "\n  data: [" +
         NumberList(data, rows * cols) + "]";
}

}  // namespace

void WriteRosCameraInfo(const std::string& path, const RosCameraInfo& info,
                        const std::vector<std::string>& comments) {
  std::ostringstream out;
  for (const std::string& line : comments) out << "# " << line << "\n";
  out << "image_width: " << info.width << "\nimage_height: " << info.height
      << "\ncamera_name: " << info.name << "\ncamera_matrix:" << Matrix(3, 3, info.K.val)
      << "\ndistortion_model: " << info.distortion_model
      << "\ndistortion_coefficients:" << Matrix(1, int(info.D.size()), info.D.data())
      << "\nrectification_matrix:" << Matrix(3, 3, info.R.val)
      << "\nprojection_matrix:" << Matrix(3, 4, info.P.val) << "\n";
  WriteFileAtomically(path, out.str());
}

}  // namespace ws
