#include "models/lens_table.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

namespace ws {
namespace {

std::string Trim(const std::string& text) {
  const char* space = " \t\r\n";
  const size_t first = text.find_first_not_of(space);
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(space) - first + 1);
}

std::vector<std::string> SplitCommas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(Trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// The whole field as a finite number, or false.
bool ParseNumber(const std::string& field, double* value) {
  if (field.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *value = std::strtod(field.c_str(), &end);
  return errno == 0 && *end == '\0' && std::isfinite(*value);
}

std::string Number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

class RowChecker {
 public:
  RowChecker(std::string source, TableColumns columns)
      : source_(std::move(source)), columns_(columns) {}

  [[noreturn]] void Fail(int line, const std::string& reason) const {
    throw LensTableError(source_ + ":" + std::to_string(line) + ": " + reason);
  }

  void Add(int line, const std::vector<std::string>& fields, LensTable* table) const {
    if (fields.size() != 2)
      Fail(line, "expected 2 comma-separated columns, found " + std::to_string(fields.size()));
    double ideal, second;
    if (!ParseNumber(fields[0], &ideal)) Fail(line, "ideal height '" + fields[0] + "' is not a number");
    if (!ParseNumber(fields[1], &second))
      Fail(line, std::string(columns_ == TableColumns::kPercent ? "distortion" : "real height") +
                     " '" + fields[1] + "' is not a number");
    if (ideal < 0) Fail(line, "ideal height " + Number(ideal) + " is negative");
    if (!table->ideal.empty() && !(ideal > table->ideal.back()))
      Fail(line, "ideal height " + Number(ideal) + " is not greater than " +
                     Number(table->ideal.back()) + " on the previous row");
    if (columns_ == TableColumns::kPercent && !(second > -100))
      Fail(line, "distortion " + Number(second) + " % would put the point behind the axis");
    const double real = columns_ == TableColumns::kPercent ? ideal * (1 + second / 100) : second;
    if (ideal == 0 && real != 0)
      Fail(line, "real height " + Number(real) + " at ideal height 0 (must be 0 on the axis)");
    if (ideal > 0 && !(real > 0)) Fail(line, "real height " + Number(real) + " is not positive");
    if (!table->real.empty() && !(real > table->real.back()))
      Fail(line, "real height " + Number(real) + " is not greater than " +
                     Number(table->real.back()) + " on the previous row (r' must increase with r)");
    table->ideal.push_back(ideal);
    table->real.push_back(real);
  }

 private:
  std::string source_;
  TableColumns columns_;
};

}  // namespace

LensTable ParseLensTable(std::istream& in, const std::string& source, TableColumns columns) {
  const RowChecker checker(source, columns);
  LensTable table;
  bool have_header = false;
  int line_number = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string text = Trim(line);
    if (text.empty() || text[0] == '#') continue;
    const std::vector<std::string> fields = SplitCommas(text);
    if (!have_header) {
      double number;
      if (ParseNumber(fields[0], &number))
        checker.Fail(line_number, "expected a header line (column names) before the numbers");
      have_header = true;
      continue;
    }
    checker.Add(line_number, fields, &table);
  }
  if (in.bad()) checker.Fail(line_number, "read error");
  if (table.ideal.size() < 3)
    checker.Fail(line_number, "a lens table needs at least 3 rows, found " +
                                  std::to_string(table.ideal.size()));
  return table;
}

LensTable ReadLensTable(const std::string& path, TableColumns columns) {
  std::ifstream in(path);
  if (!in) throw LensTableError(path + ": cannot open: " + std::strerror(errno));
  return ParseLensTable(in, path, columns);
}

LensTable ScaleLensTable(const LensTable& table, double factor) {
  LensTable scaled = table;
  for (double& r : scaled.ideal) r *= factor;
  for (double& r : scaled.real) r *= factor;
  return scaled;
}

std::vector<double> TableDistortion(const LensTable& table) {
  std::vector<double> distortion(table.ideal.size());
  for (size_t i = 0; i < distortion.size(); ++i)
    if (table.ideal[i] > 0) distortion[i] = table.real[i] / table.ideal[i] - 1;
  if (table.ideal[0] == 0) {
    const double r1 = table.ideal[1] * table.ideal[1], r2 = table.ideal[2] * table.ideal[2];
    distortion[0] = (r2 * distortion[1] - r1 * distortion[2]) / (r2 - r1);
  }
  return distortion;
}

}  // namespace ws
