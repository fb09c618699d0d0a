#include "calib/table2.h"

#include <cstdio>

namespace ws::calib {

std::vector<TableRow> TableRows(const std::vector<StereoCalibration>& calibrations) {
  std::vector<TableRow> rows;
  for (const auto& c : calibrations)
    rows.push_back({c.model, c.left.rms_px, c.mono ? -1 : c.right.rms_px, c.mono ? -1 : c.rms_px});
  return rows;
}

std::string FormatTableII(const std::vector<TableRow>& rows, const std::string& title) {
  auto cell = [](double v) {
    char buf[32];
    if (v < 0)
      std::snprintf(buf, sizeof buf, "%10s", "-");
    else
      std::snprintf(buf, sizeof buf, "%10.4f", v);
    return std::string(buf);
  };
  std::string out = title + "\n";
  char head[96];
  std::snprintf(head, sizeof head, "%-22s%10s%10s%10s\n", "model", "left", "right", "stereo");
  out += head;
  for (const auto& r : rows) {
    char name[32];
    std::snprintf(name, sizeof name, "%-22s", r.model.c_str());
    out += name + cell(r.left_rms) + cell(r.right_rms) + cell(r.stereo_rms) + "\n";
  }
  return out;
}

}  // namespace ws::calib
