// ScalarPart(v): the value of a scalar without its derivatives.
//
// Templated model code must sometimes branch on a value (which knot span holds
// r, is Z > 0): it branches on ScalarPart(v), so that a ceres::Jet takes the
// same branch as the double it carries and its derivatives stay those of the
// chosen branch.
#pragma once

#include <ceres/jet.h>

namespace ws {

inline double ScalarPart(double value) { return value; }

template <typename T, int N>
double ScalarPart(const ceres::Jet<T, N>& value) {
  return ScalarPart(value.a);
}

}  // namespace ws
