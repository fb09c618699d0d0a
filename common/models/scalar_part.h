// ScalarPart(v): the value of a scalar without its derivatives.
//
// Templated model code must sometimes branch on a value (which knot span holds
// r, is Z > 0): it branches on ScalarPart(v), so that a ceres::Jet takes the
// same branch as the double it carries and its derivatives stay those of the
// chosen branch. A Jet is any type with its value in `.a`, so that the
// models' headers need no Ceres header of their own.
#pragma once

#include <utility>

namespace ws {

inline double ScalarPart(double value) { return value; }

template <typename Jet, typename = decltype(std::declval<const Jet&>().a)>
double ScalarPart(const Jet& value) {
  return ScalarPart(value.a);
}

}  // namespace ws
