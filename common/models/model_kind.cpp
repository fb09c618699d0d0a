#include "models/model_kind.h"

#include <ostream>
#include <stdexcept>

namespace ws {

std::ostream& operator<<(std::ostream& out, ModelKind kind) { return out << Traits(kind).name; }

std::vector<ModelKind> ModelKinds() {
  std::vector<ModelKind> kinds;
  for (int i = 0; i < kNumModelKinds; ++i) kinds.push_back(static_cast<ModelKind>(i));
  return kinds;
}

std::vector<std::string> ModelNames() {
  std::vector<std::string> names;
  for (const ModelTraits& traits : kModelTraits) names.push_back(traits.name);
  return names;
}

std::string KnownModelNames() {
  std::string known;
  for (const ModelTraits& traits : kModelTraits) known += (known.empty() ? "" : ", ") + std::string(traits.name);
  return known;
}

ModelKind ParseModelKind(const std::string& name) {
  for (const ModelKind kind : ModelKinds())
    if (name == Traits(kind).name) return kind;
  throw std::invalid_argument("unknown distortion model '" + name + "' (known: " + KnownModelNames() + ")");
}

}  // namespace ws
