#include "calib/solver/field_blocks.h"

#include <algorithm>

#include "models/projection.h"

namespace ws::calib {

FieldBlocks::FieldBlocks(const NonRadialField& field)
    : field_(&field),
      cols_(field.grid() ? field.cols() : 0),
      rows_(field.grid() ? field.rows() : 0),
      per_row_(field.grid() ? (field.cols() + kSegment - 1) / kSegment : 0) {}

int FieldBlocks::Offset(int segment) const {
  const int q = segment % per_row_, row = segment / per_row_;  // row: c rows + j
  return row * cols_ + q * kSegment;
}

int FieldBlocks::Size(int segment) const {
  const int q = segment % per_row_;
  return std::min(kSegment, cols_ - q * kSegment);
}

void FieldBlocks::MarkSupport(double s, double t, std::vector<char>* used) const {
  const NonRadialField::Local local = field_->LocalBasis(s, t);
  // The patch's first and last control point in each direction, one more
  // each side.
  const int col0 = local.index[0] % cols_, row0 = local.index[0] / cols_;
  const int d = NonRadialField::kDegree;
  for (int j = std::max(0, row0 - 1); j <= std::min(rows_ - 1, row0 + d + 1); ++j)
    for (int i = std::max(0, col0 - 1); i <= std::min(cols_ - 1, col0 + d + 1); ++i)
      for (int c = 0; c < 2; ++c) (*used)[size_t(SegmentOf(c, j * cols_ + i))] = 1;
}

std::vector<int> FieldSupport(const NonRadialField& field, const double* intrinsics,
                              const std::vector<double>& pixels) {
  if (!field.grid()) return {};
  const FieldBlocks blocks(field);
  std::vector<char> used(size_t(blocks.count()), 0);
  for (size_t i = 0; i + 1 < pixels.size(); i += 2)
    blocks.MarkSupport((pixels[i] - intrinsics[kCx]) / intrinsics[kFx],
                       (pixels[i + 1] - intrinsics[kCy]) / intrinsics[kFy], &used);
  std::vector<int> segments;
  for (int s = 0; s < blocks.count(); ++s)
    if (used[size_t(s)]) segments.push_back(s);
  return segments;
}

}  // namespace ws::calib
