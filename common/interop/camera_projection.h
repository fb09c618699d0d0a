// A camera of any tool's model, as far as comparing two calibrations needs:
// its image size and its projection both ways. widestereo's own models
// (models/camera_model.h) and the models of other tools that ours cannot
// hold exactly (mrcal's splined stereographic, OpenCV's rational model:
// foreign_camera.h) are both one.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "models/camera_model.h"

namespace ws {

class CameraProjection {
 public:
  virtual ~CameraProjection() = default;

  virtual int image_width() const = 0;
  virtual int image_height() const = 0;
  // The model's name, e.g. "bspline_theta" or "mrcal LENSMODEL_OPENCV8".
  virtual std::string Name() const = 0;
  // The pixel of a camera-frame point or direction; nullopt where the model
  // has none.
  virtual std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& point) const = 0;
  // The unit ray seen at a pixel; nullopt where the model cannot be inverted.
  virtual std::optional<Eigen::Vector3d> Unproject(const Eigen::Vector2d& pixel) const = 0;
  // Whether a direction lies in the field the model was calibrated over
  // (Camera::InField; another tool's model: imaged inside the image, before
  // a fold, foreign_camera.h).
  virtual bool InField(const Eigen::Vector3d& direction) const = 0;
  // The camera as widestereo's own model when it is one (then it can be
  // rectified, exported, ...); nullptr for another tool's model.
  virtual const Camera* AsCamera() const { return nullptr; }
};

// widestereo's own camera (Camera::Project, Camera::Unproject).
class WidestereoProjection final : public CameraProjection {
 public:
  explicit WidestereoProjection(const CameraModel& model) : camera_(model) {}

  int image_width() const override { return camera_.model().image_width; }
  int image_height() const override { return camera_.model().image_height; }
  std::string Name() const override { return ModelName(camera_.model().distortion.kind); }
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& point) const override {
    return camera_.Project(point);
  }
  std::optional<Eigen::Vector3d> Unproject(const Eigen::Vector2d& pixel) const override {
    return camera_.Unproject(pixel);
  }
  bool InField(const Eigen::Vector3d& direction) const override { return camera_.InField(direction); }
  const Camera* AsCamera() const override { return &camera_; }

 private:
  Camera camera_;
};

}  // namespace ws
