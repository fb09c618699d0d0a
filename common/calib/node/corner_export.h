// Board corners written as mrcal's corners.vnl (corner_import.h reads it
// back), so that other tools solve the very corners calibrated here.
//
// mrcal wants every image as the full grid of its board in row-major order,
// a corner not seen as "NAME - - -", and an image whose board was not found
// as one "NAME - - -" line. The grid is the lattice of the views' object
// points: its spacing the smallest gap between two distinct x (or y), its
// size their extent over it (so boards of any tool export, BabelCalib's
// too). Pixels are written with every digit a double holds: reading the
// file back gives the same corners, bit for bit.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "calib/solver/calib_data.h"

namespace ws::calib {

struct BoardLattice {
  double x0 = 0, y0 = 0, spacing = 1;  // object-point units (metres)
  int cols = 0, rows = 0;
};

// The lattice of every object point of `views`; throws CalibrationError
// when they hold no corner or make no grid.
BoardLattice LatticeOf(const std::vector<BoardView>& views);

// The "# filename x y level" header line.
void WriteMrcalHeader(std::ostream& out);
// One image's lines.
void WriteMrcalView(std::ostream& out, const std::string& name, const BoardView& view,
                    const BoardLattice& lattice);

}  // namespace ws::calib
