#include "view/audience.h"

#include <stdexcept>

namespace ws::view {
namespace {

constexpr size_t Index(PageView view) { return static_cast<size_t>(view); }

}  // namespace

Audience::Views Audience::Parse(const std::string& view) {
  if (view.empty()) return {};
  if (view == "calibration") return {true, false};
  if (view == "depth") return {false, true};
  throw std::invalid_argument("view is 'calibration' or 'depth' (or absent: both)");
}

void Audience::Join(Views views) {
  if (views.calibration) ++streams_[Index(PageView::kCalibration)];
  if (views.depth) ++streams_[Index(PageView::kDepth)];
}

void Audience::Leave(Views views) {
  if (views.calibration) --streams_[Index(PageView::kCalibration)];
  if (views.depth) --streams_[Index(PageView::kDepth)];
}

bool Audience::Watching(PageView view) const { return streams_[Index(view)].load() > 0; }

bool Audience::Watching(Views views) const {
  return (views.calibration && Watching(PageView::kCalibration)) || (views.depth && Watching(PageView::kDepth));
}

}  // namespace ws::view
