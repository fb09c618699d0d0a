#include "models/model_registry.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace ws {
namespace {

template <typename Model>
struct ModelType {
  using type = Model;
};

// Each alternative of AnyDistortionModel is its kind's row of the table.
template <size_t... I>
constexpr bool TableMatchesModels(std::index_sequence<I...>) {
  return ((std::variant_alternative_t<I, AnyDistortionModel>::kKind == static_cast<ModelKind>(I)) && ...);
}
static_assert(std::variant_size_v<AnyDistortionModel> == kNumModelKinds &&
                  TableMatchesModels(std::make_index_sequence<kNumModelKinds>()),
              "AnyDistortionModel's alternatives follow ModelKind's order (model_kind.h)");

// f(ModelType<Model>{}) for the alternative of AnyDistortionModel of `kind`.
template <size_t I = 0, typename F>
auto ForKind(ModelKind kind, const F& f) -> decltype(f(ModelType<BsplineDistortion>{})) {
  if constexpr (I == std::variant_size_v<AnyDistortionModel>) {
    throw std::invalid_argument("no distortion model of kind " + std::to_string(static_cast<int>(kind)));
  } else {
    using Model = std::variant_alternative_t<I, AnyDistortionModel>;
    if (kind == Model::kKind) return f(ModelType<Model>{});
    return ForKind<I + 1>(kind, f);
  }
}

}  // namespace

ModelKind KindOf(const AnyDistortionModel& model) { return static_cast<ModelKind>(model.index()); }

AnyDistortionModel MakeModel(const Distortion& data, Coefficients which) {
  return ForKind(data.kind, [&](auto type) -> AnyDistortionModel {
    return decltype(type)::type::FromData(data, which);
  });
}

AnyDistortionModel MakeCalibrationModel(ModelKind kind, const CalibrationSetup& setup) {
  return ForKind(kind, [&](auto type) -> AnyDistortionModel {
    return decltype(type)::type::ForCalibration(setup);
  });
}

}  // namespace ws
