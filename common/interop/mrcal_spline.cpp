#include "interop/mrcal_spline.h"

#include <cstdio>
#include <regex>
#include <stdexcept>

namespace ws {

std::string MrcalSplineConfig::LensModel() const {
  char name[160];
  std::snprintf(name, sizeof name, "LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=%d_Ny=%d_fov_x_deg=%d",
                nx, ny, fov_x_deg);
  return name;
}

MrcalSplineConfig MrcalSplineConfig::Parse(const std::string& lensmodel) {
  static const std::regex pattern(
      "LENSMODEL_SPLINED_STEREOGRAPHIC_order=([0-9]{1,4})_Nx=([0-9]{1,4})_Ny=([0-9]{1,4})_fov_x_deg=([0-9]{1,4})");
  std::smatch match;
  if (!std::regex_match(lensmodel, match, pattern))
    throw std::invalid_argument("'" + lensmodel +
                                "' is not LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=N_Ny=N_fov_x_deg=N");
  if (match[1] != "3")
    throw std::invalid_argument("'" + lensmodel + "': only order=3 (cubic) is read");
  MrcalSplineConfig config;
  config.nx = std::stoi(match[2]);
  config.ny = std::stoi(match[3]);
  config.fov_x_deg = std::stoi(match[4]);
  if (config.nx < 4 || config.ny < 4 || config.nx > 1000 || config.ny > 1000)
    throw std::invalid_argument("'" + lensmodel + "': Nx and Ny must be 4 to 1000");
  if (!(config.fov_x_deg > 0 && config.fov_x_deg < 360))
    throw std::invalid_argument("'" + lensmodel + "': fov_x_deg must be within (0, 360)");
  return config;
}

}  // namespace ws
