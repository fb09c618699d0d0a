// The project's default lens: a Theia-MY125M-like super-wide-angle lens
// (1.3 mm focal length, 1/3" sensor of 1280 x 960 pixels of 3.75 um, about
// 125 deg horizontal field), from the design table
// config/lenses/theia-my125m-like.csv (see config/lenses/README.md for where
// its shape comes from). The table is compiled into the library, so processes
// and tests find it wherever they run.
#pragma once

#include "models/camera_model.h"
#include "models/lens_table.h"

namespace ws {

// A sensor behind a lens whose design table is in mm.
struct LensSensor {
  double focal_length_mm = 1.3;
  double pixel_pitch_mm = 0.00375;
  int image_width = 1280;
  int image_height = 960;
};

// The shipped table (mm).
LensTable TheiaLikeLensTable();

// A "bspline" camera whose D(r) interpolates every row of `table_mm`
// (FitBsplineByCollocation on r = h / f, so the knots are in normalized
// radius), with fx = fy = f / pitch, the principal point at the image centre
// (width / 2, height / 2) and no tangential distortion.
CameraModel CameraFromLensTable(const LensTable& table_mm, const LensSensor& sensor, int degree = 3);

// CameraFromLensTable(TheiaLikeLensTable(), LensSensor{}): fx = fy = 346.67,
// c = (640, 480), 1280 x 960.
CameraModel TheiaLikeCamera();

}  // namespace ws
