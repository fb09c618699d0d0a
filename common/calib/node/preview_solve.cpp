#include "calib/node/preview_solve.h"

#include <optional>

#include "calib/node/result_message.h"
#include "models/model_registry.h"

namespace ws::calib {

ModelKind PreviewModel(const std::vector<ModelKind>& models) {
  for (ModelKind model : models)
    if (Traits(model).angle) return model;
  return models.front();
}

widestereo::calibration_result_t PreviewSolve(const StereoData& data, CalibrationOptions options, ModelKind model,
                                              int64_t utime) {
  options.model = model;
  options.spline.knots = options.spline.knots.value_or(kPreviewKnots);
  options.nonradial = FieldRule::kNone;
  options.board_warp = WarpRule::kFlat;
  options.cv_folds = 0;
  options.covariance = true;  // the map is the covariance's
  options.progress = nullptr;
  widestereo::calibration_result_t msg{};
  msg.utime = utime;
  msg.chosen = ModelName(model);
  widestereo::calibration_model_t line{ModelName(model), "", -1, -1, -1, -1, -1};
  std::string why;
  for (const CameraData* camera : {&data.left, &data.right}) {
    if (camera->image_width <= 0) continue;  // a one-camera rig's right
    try {
      const CameraCalibration solved = CalibrateCamera(*camera, options);
      (camera == &data.left ? line.left_rms : line.right_rms) = solved.rms_px;
      msg.cameras.push_back(ToMapsMessage(solved));
    } catch (const CalibrationError& e) {
      why += (why.empty() ? "" : "; ") + std::string(e.what());
    }
  }
  if (msg.cameras.empty()) throw CalibrationError("no camera could be solved yet: " + why);
  msg.models = {line};
  msg.nmodels = 1;
  msg.ncameras = int32_t(msg.cameras.size());
  return msg;
}

}  // namespace ws::calib
