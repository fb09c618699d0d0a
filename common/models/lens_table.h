// Lens distortion tables from a lens design: ideal image height r_i against
// real (distorted) image height r'_i, in one unit (typically mm).
//
// File format: CSV with one header line, then one row per height, two
// columns: ideal height and real height, or (TableColumns::kPercent) ideal
// height and distortion in percent, 100 (r'/r - 1). Blank lines and lines
// starting with '#' are ignored. Ideal heights are >= 0 and strictly
// increasing, real heights strictly increasing (r' = 0 exactly where r = 0),
// at least 3 rows.
#pragma once

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ws {

struct LensTable {
  std::vector<double> ideal;  // r_i
  std::vector<double> real;   // r'_i
};

enum class TableColumns { kRealHeight, kPercent };

// Its message names the file and line: "lens.csv:7: real height 1.2 is not
// greater than 1.3 on the previous row (r' must increase with r)".
struct LensTableError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

LensTable ReadLensTable(const std::string& path, TableColumns columns);
// `source` names the stream in error messages.
LensTable ParseLensTable(std::istream& in, const std::string& source, TableColumns columns);

// Both heights times factor, e.g. 1 / focal length for normalized radii.
LensTable ScaleLensTable(const LensTable& table, double factor);

// D_i = r'_i / r_i - 1 for every row. At r = 0 the ratio is 0/0 and D_0 is
// its limit, taken from the next two rows with D even in r
// (D ~ D_0 + c r^2): D_0 = (r_2^2 D_1 - r_1^2 D_2) / (r_2^2 - r_1^2).
std::vector<double> TableDistortion(const LensTable& table);

}  // namespace ws
