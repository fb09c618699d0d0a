#include "models/model_registry.h"

#include <stdexcept>

namespace ws {
namespace {

template <typename Model>
struct ModelType {
  using type = Model;
};

// f(ModelType<Model>{}) for the alternative of AnyDistortionModel whose
// Kind() is kind.
template <size_t I = 0, typename F>
auto ForKind(const std::string& kind, const F& f) -> decltype(f(ModelType<BsplineDistortion>{})) {
  if constexpr (I == std::variant_size_v<AnyDistortionModel>) {
    std::string known;
    for (const auto& name : ModelKinds()) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown distortion model '" + kind + "' (known: " + known + ")");
  } else {
    using Model = std::variant_alternative_t<I, AnyDistortionModel>;
    if (kind == Model::Kind()) return f(ModelType<Model>{});
    return ForKind<I + 1>(kind, f);
  }
}

template <size_t... I>
std::vector<std::string> KindsOf(std::index_sequence<I...>) {
  return {std::variant_alternative_t<I, AnyDistortionModel>::Kind()...};
}

}  // namespace

std::vector<std::string> ModelKinds() {
  return KindsOf(std::make_index_sequence<std::variant_size_v<AnyDistortionModel>>());
}

AnyDistortionModel MakeModel(const Distortion& data, Coefficients which) {
  return ForKind(data.kind, [&](auto type) -> AnyDistortionModel {
    return decltype(type)::type::FromData(data, which);
  });
}

AnyDistortionModel MakeCalibrationModel(const std::string& kind, const CalibrationSetup& setup) {
  return ForKind(kind, [&](auto type) -> AnyDistortionModel {
    return decltype(type)::type::ForCalibration(setup);
  });
}

bool IsAngleModel(const AnyDistortionModel& model) {
  return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::Coordinate::kAngle; },
                    model);
}

bool HasTangential(const AnyDistortionModel& model) {
  return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::kTangential; }, model);
}

std::string CoefficientKey(const std::string& kind) {
  return ForKind(kind, [](auto type) -> std::string { return decltype(type)::type::kCoeffKey; });
}

}  // namespace ws
