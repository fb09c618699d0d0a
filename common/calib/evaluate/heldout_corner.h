// One held-out corner of a cross-validation (heldout.h): its squared
// residual (px^2) under its fold's step with its view's pose refitted.
#pragma once

namespace ws::calib {

struct HeldOutCorner {
  int camera = 0, view = 0, index = 0, fold = 0;
  double squared = 0;
};

}  // namespace ws::calib
