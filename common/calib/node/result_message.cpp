#include "calib/node/result_message.h"

#include <cmath>

#include "calib/node/table2.h"

namespace ws::calib {

widestereo::camera_maps_t ToMapsMessage(const CameraCalibration& camera) {
  widestereo::camera_maps_t maps{};
  maps.name = camera.name;
  maps.image_width = camera.model.image_width;
  maps.image_height = camera.model.image_height;
  const ResidualGrid& grid = camera.grid;
  maps.residual_rows = grid.rows;
  maps.residual_cols = grid.cols;
  maps.residual_rms_px.assign(size_t(grid.rows), std::vector<double>(size_t(grid.cols), -1));
  for (int cell = 0; cell < grid.rows * grid.cols; ++cell)
    if (grid.count[size_t(cell)] > 0)
      maps.residual_rms_px[size_t(cell / grid.cols)][size_t(cell % grid.cols)] = grid.rms[size_t(cell)];
  const ProjectionUncertainty& u = camera.uncertainty;
  maps.uncertainty_rows = u.empty() ? 0 : u.grid.rows;
  maps.uncertainty_cols = u.empty() ? 0 : u.grid.cols;
  maps.uncertainty_px.assign(size_t(maps.uncertainty_rows), std::vector<double>(size_t(maps.uncertainty_cols), -1));
  for (int cell = 0; cell < maps.uncertainty_rows * maps.uncertainty_cols; ++cell) {
    const double sigma = u.sigma_px[size_t(cell)];
    if (std::isfinite(sigma))
      maps.uncertainty_px[size_t(cell / maps.uncertainty_cols)][size_t(cell % maps.uncertainty_cols)] = sigma;
  }
  return maps;
}

widestereo::calibration_result_t ToResultMessage(const ModelCalibrations& results, int64_t utime) {
  widestereo::calibration_result_t msg{};
  msg.utime = utime;
  const StereoCalibration& chosen = Chosen(results);
  msg.chosen = ModelName(chosen.model);
  for (const TableRow& row : TableRows(results.solved, results.chosen))
    msg.models.push_back({row.model, "", row.left_rms, row.left_heldout, row.right_rms,
                          row.right_heldout, row.stereo_rms});
  for (const ModelFailure& failure : results.failed)
    msg.models.push_back({failure.model, failure.error, -1, -1, -1, -1, -1});
  msg.nmodels = int32_t(msg.models.size());
  msg.cameras.push_back(ToMapsMessage(chosen.left));
  if (!chosen.mono) msg.cameras.push_back(ToMapsMessage(chosen.right));
  msg.ncameras = int32_t(msg.cameras.size());
  return msg;
}

}  // namespace ws::calib
