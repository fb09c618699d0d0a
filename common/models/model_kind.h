// The distortion model kinds and one table of their properties (as mrcal's
// MRCAL_LENSMODEL_META_LIST): what r is, spline or polynomial, the name of
// the coefficients, which of them a calibration can identify.
//
// A kind's name is read once, where it enters (command line, calibration
// file, message: ParseModelKind); past that code asks Traits(kind), never
// the name. The model classes (bspline_distortion.h, poly_distortion.h) take
// their properties from this table, and model_registry.cpp checks at compile
// time that the table and the classes agree.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace ws {

// In the order of AnyDistortionModel's alternatives (model_registry.h).
enum class ModelKind { kBspline, kPoly6, kPoly12, kKb4, kBsplineTheta };

struct ModelTraits {
  const char* name;       // in files, messages, reports and on the command line
  bool angle;             // r is the incidence angle theta, else tan(theta) (radial_coordinate.h)
  bool spline;            // a B-spline over stored knots and degree; else a polynomial
  bool tangential;        // p1, p2 apply (Kannala-Brandt has none)
  const char* coeff_key;  // the coefficients' name in files and reports, their parameters' prefix
  int terms;              // a polynomial's coefficients k1..kN; 0: a spline's follow its knots
  int gauge_fixed;        // leading stored coefficients a calibration fixes at 0 (alpha_0, alpha_1):
                          // identifiable = stored - gauge_fixed
};

// Indexed by ModelKind.
inline constexpr ModelTraits kModelTraits[] = {
    {"bspline", false, true, true, "alpha", 0, 2},
    {"poly6", false, false, true, "k", 3, 0},
    {"poly12", false, false, true, "k", 6, 0},
    {"kb4", true, false, false, "k", 4, 0},
    {"bspline_theta", true, true, true, "alpha", 0, 2},
};
inline constexpr int kNumModelKinds = sizeof kModelTraits / sizeof kModelTraits[0];

constexpr const ModelTraits& Traits(ModelKind kind) { return kModelTraits[static_cast<int>(kind)]; }
inline std::string ModelName(ModelKind kind) { return Traits(kind).name; }
std::ostream& operator<<(std::ostream& out, ModelKind kind);

// Every kind, in the table's order.
std::vector<ModelKind> ModelKinds();
// Their names, in that order.
std::vector<std::string> ModelNames();
// "bspline, poly6, poly12, kb4, bspline_theta".
std::string KnownModelNames();

// The kind named `name`; throws std::invalid_argument("unknown distortion
// model 'NAME' (known: ...)") for any other.
ModelKind ParseModelKind(const std::string& name);

}  // namespace ws
