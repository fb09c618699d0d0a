// export_corners_vnl: the board corners of a STEREO_CORNERS log as mrcal's
// corners.vnl, one file per camera (PREFIX-left.vnl, PREFIX-right.vnl), so
// that mrcal-calibrate-cameras solves the very corners stereo-calibrate did
// (bench/fisheye/run.sh). Images are named left-NNNN.png / right-NNNN.png by
// frame id; a view whose board was not found is one "NAME - - -" line.
//
// mrcal wants every view as the full grid of its board in row-major order.
// The grid is the lattice of the object points the log holds: its spacing
// the smallest gap between two distinct x (or y), its size their extent over
// it (so boards of any tool import, BabelCalib's too). The last line on
// stdout says it: "grid COLSxROWS spacing S".
//   export_corners_vnl --in-url 'file://corners.lcmlog?speed=0' --prefix out/corners
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include "calib/calib_data.h"
#include "lcm_io/channels.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "widestereo/stereo_corners_t.hpp"

namespace {

struct Grid {
  double x0 = 0, y0 = 0, spacing = 1;
  int cols = 0, rows = 0;
};

// The smallest gap between two distinct values of `values`.
double SmallestGap(const std::set<double>& values) {
  double gap = std::numeric_limits<double>::infinity();
  for (auto a = values.begin(), b = std::next(a); b != values.end(); ++a, ++b)
    if (*b - *a > 1e-9) gap = std::min(gap, *b - *a);
  return gap;
}

Grid LatticeOf(const std::vector<ws::calib::BoardView>& views) {
  std::set<double> xs, ys;
  for (const auto& view : views)
    for (const auto& X : view.object) {
      xs.insert(X.x());
      ys.insert(X.y());
    }
  if (xs.empty()) throw std::runtime_error("the log holds no board corners");
  Grid g;
  g.spacing = std::min(SmallestGap(xs), SmallestGap(ys));
  if (!std::isfinite(g.spacing)) throw std::runtime_error("the board corners make no grid");
  g.x0 = *xs.begin();
  g.y0 = *ys.begin();
  g.cols = int(std::lround((*xs.rbegin() - g.x0) / g.spacing)) + 1;
  g.rows = int(std::lround((*ys.rbegin() - g.y0) / g.spacing)) + 1;
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  ws::ProcessCli cli("export_corners_vnl",
                     "Writes the board corners of a STEREO_CORNERS log as mrcal corners.vnl files, "
                     "one per camera.");
  std::string prefix = "corners";
  cli.app().add_option("--prefix", prefix, "Output: PREFIX-left.vnl and PREFIX-right.vnl");
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  try {
    ws::Process process(cli.options());
    std::vector<int64_t> frames;
    std::vector<ws::calib::BoardView> views[2];
    process.Subscribe<widestereo::stereo_corners_t>(ws::channel::kStereoCorners, [&](const auto& msg) {
      frames.push_back(msg.frame_id);
      views[0].push_back(ws::calib::ToBoardView(msg.left));
      views[1].push_back(ws::calib::ToBoardView(msg.right));
    });
    if (const int rc = process.Run()) return rc;
    std::vector<ws::calib::BoardView> all = views[0];
    all.insert(all.end(), views[1].begin(), views[1].end());
    const Grid grid = LatticeOf(all);
    for (int c = 0; c < 2; ++c) {
      std::ofstream out(prefix + (c == 0 ? "-left.vnl" : "-right.vnl"));
      if (!out) throw std::runtime_error("cannot write " + prefix + "-*.vnl");
      out << "# filename x y level\n";
      for (size_t v = 0; v < frames.size(); ++v) {
        char name[64];
        std::snprintf(name, sizeof name, "%s-%04lld.png", c == 0 ? "left" : "right",
                      static_cast<long long>(frames[v]));
        const ws::calib::BoardView& view = views[c][v];
        if (view.empty()) {
          out << name << " - - -\n";
          continue;
        }
        std::map<int, Eigen::Vector2d> at;  // grid index -> pixel
        for (int i = 0; i < view.size(); ++i) {
          const int col = int(std::lround((view.object[i].x() - grid.x0) / grid.spacing));
          const int row = int(std::lround((view.object[i].y() - grid.y0) / grid.spacing));
          at[row * grid.cols + col] = view.image[i];
        }
        for (int k = 0; k < grid.cols * grid.rows; ++k) {
          const auto it = at.find(k);
          if (it == at.end())
            out << name << " - - -\n";
          else
            out << name << " " << it->second.x() << " " << it->second.y() << " 0\n";
        }
      }
    }
    std::printf("grid %dx%d spacing %.9g\n", grid.cols, grid.rows, grid.spacing);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "export_corners_vnl: %s\n", e.what());
    return 1;
  }
}
