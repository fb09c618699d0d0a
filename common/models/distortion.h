// A radial distortion model as data, and the concept every model class follows.
//
// A camera model (see projection.h) is a pinhole with a distortion model
//
//   x_d = (1 + D(r)) x + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = (1 + D(r)) y + p1 (r^2 + 2 y^2) + 2 p2 x y        (paper Eqs. 6, 18, 19)
//
// on ideal normalized coordinates x = X/Z, y = Y/Z, r = sqrt(x^2 + y^2).
// The models differ only in D(r), the radial distortion curve
// (r' = (1 + D(r)) r is the distorted radius):
//   "bspline"  D = B(r) = sum_i alpha_i N_{i,K}(r)      bspline_distortion.h
//   "poly6"    D = k1 r^2 + k2 r^4 + k3 r^6             poly_distortion.h
//   "poly12"   D = k1 r^2 + ... + k6 r^12               poly_distortion.h
//
// The model concept. A model class holds only FIXED data (knots, degree) and
// takes the ESTIMATED coefficients as `const T* coeffs`, Ceres-style:
//
//   static constexpr ModelKind kKind;                // its row of model_kind.h's table
//   static Model FromData(const Distortion&, Coefficients);
//   static Model ForCalibration(const CalibrationSetup&);
//   int NumCoeffs() const;                           // estimated coefficients
//   std::string CoeffName(int i) const;              // "alpha2", "k1", ...
//   Distortion ToData(const double* coeffs) const;   // fixed data + stored coefficients
//   std::vector<double> EstimatedCoeffs(const std::vector<double>& stored) const;
//   template <typename T> T RadialDistortion(const T* coeffs, const T& r) const;   // D(r)
//   template <typename T> void Distort(const T* coeffs, const T& p1, const T& p2,
//                                      const T& x, const T& y, T* xd, T* yd) const;
//   // Local support: Distort at the ideal point (x, y) reads only
//   // coeffs[FirstLocalCoeff(x, y) + j], 0 <= j < NumLocalCoeffs() (those of
//   // them in [0, NumCoeffs())), so that a solver differentiates a corner's
//   // residual by those few (calib/solver/residuals.h). A spline: its degree + 1.
//   static constexpr int kMaxLocalCoeffs;            // bound of NumLocalCoeffs()
//   int NumLocalCoeffs() const;
//   int FirstLocalCoeff(double x, double y) const;
//
// A new model is a new header with such a class, one row of model_kind.h's
// table and one entry in model_registry.h; solvers and processes only use the
// concept and the table.
#pragma once

#include <string>
#include <vector>

#include "models/model_kind.h"

namespace ws {

// The distortion part of a camera model as stored in files and messages:
// everything needed to evaluate D(r).
struct Distortion {
  ModelKind kind = ModelKind::kBspline;  // model_kind.h
  int degree = 0;               // B-spline degree K; 0 for the polynomials
  std::vector<double> knots;    // clamped knot vector in the unit of r (bspline); else empty
  std::vector<double> coeffs;   // all of alpha_0..alpha_{n-1} (bspline) or k_1..k_N
};

// Which coefficients a model instance takes as `coeffs`.
enum class Coefficients {
  kAll,           // every stored coefficient: curve fitting, evaluating stored models
  kIdentifiable,  // calibration: those the gauge pins (bspline: alpha_0 = alpha_1 = 0) are left out
};

// What a fresh calibration model needs to know: the largest ideal normalized
// radius the image reaches and, for splines, the knot layout.
struct CalibrationSetup {
  double r_max = 0;
  int knot_intervals = 8;
  int degree = 3;
};

}  // namespace ws
