// The non-radial field's coefficients (models/nonradial_field.h) as many
// small Ceres parameter blocks instead of one.
//
// A corner reads 16 control points of 4 rows (a bicubic patch); a view
// reaches a fraction of the field. Ceres holds each parameter block's
// Jacobian, and its share of the Schur complement, dense: with the field
// in one block of 2 cols rows coefficients every view added a dense
// (2 cols rows)^2 outer product to the reduced system, most of it zeros
// (on a 16 x 10 field, 320^2 per view per iteration). In segments of
// kSegment control points along a row, per component, a view adds only the
// segments its corners reach: the sparsity of the B-spline basis becomes
// the solver's.
//
// Segment s covers, of component c (0: x, 1: y), row j, the control points
// (j, q kSegment) .. (j, min(cols, (q + 1) kSegment) - 1), at offset
// c half + j cols + q kSegment of the field's coefficients (half = cols
// rows); s = (c rows + j) segments_per_row + q, in the coefficients' order.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "models/nonradial_field.h"

namespace ws::calib {

class FieldBlocks {
 public:
  static constexpr int kSegment = 4;

  explicit FieldBlocks(const NonRadialField& field);

  int count() const { return 2 * rows_ * per_row_; }  // 0 without a grid
  int Offset(int segment) const;  // into the field's coefficients (field_x_0_0 first)
  int Size(int segment) const;
  // The segment holding component c of control point `index` (row cols + col).
  int SegmentOf(int component, int index) const {
    return (component * rows_ + index / cols_) * per_row_ + (index % cols_) / kSegment;
  }
  // Its position within that segment.
  int PositionOf(int index) const { return (index % cols_) % kSegment; }

  // Marks in *used (count() entries) the segments a corner whose tilted
  // point is (s, t) reads, and those of the control points next to them: a
  // solve moves the point by much less than the control points' spacing.
  void MarkSupport(double s, double t, std::vector<char>* used) const;

 private:
  const NonRadialField* field_;
  int cols_ = 0, rows_ = 0, per_row_ = 0;
};

// The segments a view's corners may read (FieldBlocks::MarkSupport), in
// order; each corner's tilted point taken as its observed pixel's normalized
// point under `intrinsics` (fx fy cx cy ...), the field and the tilt moving
// it by far less than a control point's spacing. Empty without a grid.
std::vector<int> FieldSupport(const NonRadialField& field, const double* intrinsics,
                              const std::vector<double>& pixels);

}  // namespace ws::calib
