#include "calib/node/table2.h"

#include <cstdio>

namespace ws::calib {

namespace {

int Coeffs(const CameraCalibration& camera) { return int(camera.param_names.size()) - 6; }

}  // namespace

std::vector<TableRow> TableRows(const std::vector<StereoCalibration>& calibrations, int chosen) {
  std::vector<TableRow> rows;
  for (size_t i = 0; i < calibrations.size(); ++i) {
    const StereoCalibration& c = calibrations[i];
    rows.push_back({ModelName(c.model), c.left.rms_px, c.mono ? -1 : c.right.rms_px, c.mono ? -1 : c.rms_px,
                    c.left.heldout_rms_px, c.mono ? -1 : c.right.heldout_rms_px,
                    std::to_string(Coeffs(c.left)) +
                        (c.mono ? "" : "/" + std::to_string(Coeffs(c.right))),
                    int(i) == chosen});
  }
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
  std::snprintf(head, sizeof head, "%-22s%10s%10s%10s%10s%10s%9s\n", "model", "left", "right",
                "stereo", "left CV", "right CV", "coeffs");
  out += head;
  for (const auto& r : rows) {
    char name[40], coeffs[16];
    std::snprintf(name, sizeof name, "%-22s", (r.model + (r.chosen ? " *" : "")).c_str());
    std::snprintf(coeffs, sizeof coeffs, "%9s", r.coeffs.c_str());
    out += name + cell(r.left_rms) + cell(r.right_rms) + cell(r.stereo_rms) +
           cell(r.left_heldout) + cell(r.right_heldout) + coeffs + "\n";
  }
  return out;
}

}  // namespace ws::calib
