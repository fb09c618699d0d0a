#include "calib/node/corner_export.h"

#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace ws::calib {
namespace {

// The smallest gap between two distinct values of `values`.
double SmallestGap(const std::set<double>& values) {
  double gap = std::numeric_limits<double>::infinity();
  for (auto a = values.begin(), b = std::next(a); b != values.end(); ++a, ++b)
    if (*b - *a > 1e-9) gap = std::min(gap, *b - *a);
  return gap;
}

}  // namespace

BoardLattice LatticeOf(const std::vector<BoardView>& views) {
  std::set<double> xs, ys;
  for (const auto& view : views)
    for (const auto& X : view.object) {
      xs.insert(X.x());
      ys.insert(X.y());
    }
  if (xs.empty()) throw CalibrationError("no board corners to export");
  BoardLattice lattice;
  lattice.spacing = std::min(SmallestGap(xs), SmallestGap(ys));
  if (!std::isfinite(lattice.spacing)) throw CalibrationError("the board corners make no grid");
  lattice.x0 = *xs.begin();
  lattice.y0 = *ys.begin();
  lattice.cols = int(std::lround((*xs.rbegin() - lattice.x0) / lattice.spacing)) + 1;
  lattice.rows = int(std::lround((*ys.rbegin() - lattice.y0) / lattice.spacing)) + 1;
  return lattice;
}

void WriteMrcalHeader(std::ostream& out) { out << "# filename x y level\n"; }

void WriteMrcalView(std::ostream& out, const std::string& name, const BoardView& view,
                    const BoardLattice& lattice) {
  if (view.empty()) {
    out << name << " - - -\n";
    return;
  }
  std::map<int, Eigen::Vector2d> at;  // lattice index -> pixel
  for (int i = 0; i < view.size(); ++i) {
    const int col = int(std::lround((view.object[i].x() - lattice.x0) / lattice.spacing));
    const int row = int(std::lround((view.object[i].y() - lattice.y0) / lattice.spacing));
    at[row * lattice.cols + col] = view.image[i];
  }
  const auto precision = out.precision(std::numeric_limits<double>::max_digits10);
  for (int k = 0; k < lattice.cols * lattice.rows; ++k) {
    const auto it = at.find(k);
    if (it == at.end())
      out << name << " - - -\n";
    else
      out << name << " " << it->second.x() << " " << it->second.y() << " 0\n";
  }
  out.precision(precision);
}

}  // namespace ws::calib
