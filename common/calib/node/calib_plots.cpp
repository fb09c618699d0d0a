#include "calib/node/calib_plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plot/plot.h"

namespace ws::calib {
namespace {

std::string Format(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

const CameraCalibration& Side(const StereoCalibration& s, int side) {
  return side == 0 ? s.left : s.right;
}

// Values on a grid of image points as a heat map, clipped at `max`; NaN
// values are `missing`.
plot::Heatmap ImageGridHeatmap(const ImageGrid& grid, std::vector<double> values,
                               const std::string& label, double max, const std::string& missing) {
  plot::Heatmap map;
  map.cols = grid.cols;
  map.rows = grid.rows;
  map.x0 = grid.Pixel(0, 0).x();
  map.y0 = grid.Pixel(0, 0).y();
  map.dx = grid.step_x;
  map.dy = grid.step_y;
  for (double& v : values) v = std::min(v, max);
  map.values = std::move(values);
  map.label = label;
  map.missing = missing;
  map.max = max;
  return map;
}

}  // namespace

void WriteDistortionCurvesPng(const std::vector<StereoCalibration>& calibrations,
                              const std::string& rig, const std::string& png_path) {
  // One row of panels per radial coordinate: the pinhole models over
  // r = tan(theta), the angle models over theta in degrees.
  std::vector<bool> families;
  for (bool angle : {false, true})
    for (const auto& c : calibrations)
      if (Traits(c.left.model.distortion.kind).angle == angle) {
        families.push_back(angle);
        break;
      }
  plot::Figure figure(rig + ": recovered radial distortion D = r'/r - 1 of each model", 2, 1400,
                      650 * static_cast<int>(families.size()));
  for (bool angle : families)
    for (int side = 0; side < 2; ++side) {
      const std::string name = side == 0 ? "left" : "right";
      const double unit = angle ? 180 / M_PI : 1.0;  // degrees on the axis
      plot::Panel& panel = figure.panels.emplace_back(
          name + " camera, " + (angle ? "angle models" : "pinhole models"),
          angle ? "incidence angle theta [deg]" : "ideal radius r = |(X/Z, Y/Z)| = tan(theta)",
          angle ? "D(theta) [%]" : "D(r) [%]");
      panel.zero_line = true;
      panel.legend = "below";
      // To the end of the B-spline's knots (which the calibration puts at
      // the image's corners), else a fifth past the largest observed radius.
      double r_end = 0, r_seen = 0;
      std::vector<const StereoCalibration*> drawn;
      for (const auto& c : calibrations) {
        if ((c.mono && side == 1) || Traits(Side(c, side).model.distortion.kind).angle != angle) continue;
        drawn.push_back(&c);
        const Distortion& d = Side(c, side).model.distortion;
        if (!d.knots.empty()) r_end = std::max(r_end, d.knots.back());
        r_seen = std::max(r_seen, Side(c, side).max_observed_radius);
      }
      if (!(r_end > r_seen)) r_end = 1.2 * r_seen;
      if (!(r_end > 0)) r_end = 1.0;
      double lo = 0, hi = 0;
      for (const StereoCalibration* c : drawn) {
        const Camera camera(Side(*c, side).model);
        std::vector<double> r, d;
        for (int k = 0; k <= 300; ++k) {
          const double at = r_end * k / 300.0;
          r.push_back(unit * at);
          d.push_back(100.0 * camera.DistortionCurve(at));
          lo = std::min(lo, d.back());
          hi = std::max(hi, d.back());
        }
        panel.series.emplace_back(
            ModelName(c->model) + " (RMS " + Format("%.3f", Side(*c, side).rms_px) + " px)", r, d);
      }
      if (r_seen > 0) {
        plot::Series& mark = panel.series.emplace_back(
            std::string("largest observed ") + (angle ? "angle " : "radius ") +
                Format(angle ? "%.1f deg" : "%.2f", unit * r_seen),
            std::vector<double>{unit * r_seen, unit * r_seen}, std::vector<double>{lo, hi},
            plot::Style::kLines, "#808080");
        mark.line_width = 1;
      }
    }
  plot::WritePng(figure, png_path);
}

void WriteResidualMapPng(const std::vector<StereoCalibration>& calibrations,
                         const std::string& rig, const std::string& png_path) {
  const int rows = static_cast<int>(calibrations.size());
  plot::Figure figure(rig + ": mean reprojection residual per image cell (arrows scaled)", 2,
                      1400, std::max(500, 450 * rows));
  for (const auto& c : calibrations)
    for (int side = 0; side < (c.mono ? 1 : 2); ++side) {
      const CameraCalibration& cam = Side(c, side);
      const ResidualGrid& g = cam.grid;
      double largest = 0;
      for (int cell = 0; cell < g.rows * g.cols; ++cell)
        if (g.count[cell]) largest = std::max(largest, g.mean[cell].norm());
      const double cell_size = g.cols > 0 ? double(g.image_width) / g.cols : 1.0;
      const double scale = largest > 0 ? 0.45 * cell_size / largest : 1.0;
      plot::Panel& panel = figure.panels.emplace_back(
          cam.name + " camera, " + ModelName(c.model) + ": RMS " + Format("%.3f", cam.rms_px) +
              " px, arrows x" + Format("%.0f", scale) + " (longest " + Format("%.3f", largest) +
              " px)",
          "u [px]", "v [px]");
      panel.legend = "off";
      panel.image_axes = true;
      std::vector<double> ax, ay, px, py, ex, ey;
      for (int cell = 0; cell < g.rows * g.cols; ++cell) {
        const Eigen::Vector2d centre = g.CellCentre(cell);
        if (!g.count[cell]) {
          ex.push_back(centre.x());
          ey.push_back(centre.y());
          continue;
        }
        const Eigen::Vector2d tip = centre + scale * g.mean[cell];
        ax.insert(ax.end(), {centre.x(), tip.x(), NAN});
        ay.insert(ay.end(), {centre.y(), tip.y(), NAN});
        px.push_back(centre.x());
        py.push_back(centre.y());
      }
      // The image outline.
      const double w = g.image_width - 0.5, h = g.image_height - 0.5;
      panel.series.emplace_back("", std::vector<double>{-0.5, w, w, -0.5, -0.5},
                                std::vector<double>{-0.5, -0.5, h, h, -0.5}, plot::Style::kLines,
                                "#c0c0c0");
      if (!ax.empty())
        panel.series.emplace_back("residual", ax, ay, plot::Style::kLines, "#d55e00");
      if (!px.empty()) {
        plot::Series& dots =
            panel.series.emplace_back("cell", px, py, plot::Style::kPoints, "#0072b2");
        dots.point_size = 0.5;
      }
      if (!ex.empty()) {
        plot::Series& empty =
            panel.series.emplace_back("no corners", ex, ey, plot::Style::kPoints, "#808080");
        empty.point_type = 2;
        empty.point_size = 0.8;
      }
    }
  plot::WritePng(figure, png_path);
}

bool WriteKnotCurvePng(const std::vector<StereoCalibration>& calibrations,
                       const std::string& rig, const std::string& png_path) {
  plot::Figure figure(
      rig + ": cross-validated choice of the B-spline's coefficients (--knots auto)", 2, 1400,
      650);
  bool any = false;
  for (int side = 0; side < 2; ++side) {
    plot::Panel& panel = figure.panels.emplace_back(
        (side == 0 ? "left" : "right") + std::string(" camera: RMS per coefficient count"),
        "estimated coefficients (--knots)", "RMS [px]");
    panel.legend = "below";
    for (const auto& c : calibrations) {
      if (c.mono && side == 1) continue;
      const CameraCalibration& camera = Side(c, side);
      if (camera.knot_curve.empty()) continue;
      any = true;
      std::vector<double> n, heldout, fitted;
      for (const KnotTrial& t : camera.knot_curve) {
        n.push_back(t.knots);
        heldout.push_back(t.heldout_rms_px);
        fitted.push_back(t.rms_px);
      }
      panel.series.emplace_back(ModelName(c.model) + " held-out", n, heldout, plot::Style::kLinesPoints);
      panel.series.emplace_back(ModelName(c.model) + " fitted", n, fitted, plot::Style::kLinesPoints);
      const double chosen = double(camera.param_names.size()) - 6;
      for (const KnotTrial& t : camera.knot_curve)
        if (t.knots == chosen)
          panel.series
              .emplace_back(ModelName(c.model) + " chosen: " + Format("%.0f", chosen),
                                    std::vector<double>{chosen},
                                    std::vector<double>{t.heldout_rms_px}, plot::Style::kPoints)
              .point_size = 2.5;
    }
  }
  if (!any) return false;
  plot::WritePng(figure, png_path);
  return true;
}

bool WriteUncertaintyPng(const std::vector<StereoCalibration>& calibrations,
                         const std::string& rig, const std::string& png_path) {
  std::vector<const CameraCalibration*> cameras;
  std::vector<std::string> models;
  for (const auto& c : calibrations)
    for (int side = 0; side < (c.mono ? 1 : 2); ++side)
      if (!Side(c, side).uncertainty.empty()) {
        cameras.push_back(&Side(c, side));
        models.push_back(ModelName(c.model));
      }
  if (cameras.empty()) return false;
  const int rows = (static_cast<int>(cameras.size()) + 1) / 2;
  plot::Figure figure(rig + ": projection uncertainty, 1 sigma in the worst direction, of a "
                            "fixed camera-frame ray",
                      2, 1400, 560 * rows);
  for (size_t k = 0; k < cameras.size(); ++k) {
    const CameraCalibration& camera = *cameras[k];
    const ProjectionUncertainty& u = camera.uncertainty;
    plot::Panel& panel = figure.panels.emplace_back(
        camera.name + " camera, " + models[k] + ": median " + Format("%.4f", u.median_px) +
            " px, worst " + Format("%.4f", u.worst_px) + " px\nover the cells with corners; "
            "colours clipped at twice the worst",
        "u [px]", "v [px]");
    panel.image_axes = true;
    panel.legend = "below";
    // The scale of the observed field (the unobserved corners can be far larger).
    panel.heatmap = ImageGridHeatmap(u.grid, u.sigma_px, "1-sigma [px]", 2 * u.worst_px, "no ray");
    std::vector<double> x, y;
    for (int j = 0; j < u.grid.rows; ++j)
      for (int i = 0; i < u.grid.cols; ++i)
        if (u.observed[j * u.grid.cols + i]) {
          x.push_back(u.grid.Pixel(i, j).x());
          y.push_back(u.grid.Pixel(i, j).y());
        }
    plot::Series& seen = panel.series.emplace_back("cells with corners",
                                                   x, y, plot::Style::kPoints, "#009e73");
    seen.point_size = 0.4;
  }
  plot::WritePng(figure, png_path);
  return true;
}

void WriteProjectionDiffPng(const std::vector<std::pair<std::string, ProjectionDiff>>& cameras,
                            const std::string& title, const std::string& png_path) {
  plot::Figure figure(title, int(std::min<size_t>(2, cameras.size())),
                      cameras.size() > 1 ? 1600 : 800, 600);
  for (const auto& [name, d] : cameras) {
    plot::Panel& panel = figure.panels.emplace_back(
        name + " camera: RMS " + Format("%.3f", d.rms_px) + ", median " +
            Format("%.3f", d.median_px) + ", max " + Format("%.3f", d.max_px) + " px\nafter a " +
            Format("%.4f", d.rotation_deg) + " deg turn; colours clipped at 3x the median",
        "u [px]", "v [px]");
    panel.image_axes = true;
    panel.legend = "off";
    // Clipped at 3x the median, so the field's structure shows; NaN: not compared.
    const double top = std::max(d.median_px > 0 ? 3 * d.median_px : d.max_px, 1e-6);
    panel.heatmap = ImageGridHeatmap(d.grid, d.diff_px, "difference [px]", top, "no ray");
  }
  plot::WritePng(figure, png_path);
}

}  // namespace ws::calib
