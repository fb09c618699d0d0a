// A camera's intrinsics as one array {fx, fy, cx, cy, p1, p2}: the focal
// lengths and principal point in pixels and the tangential terms
// (camera_model.h), one parameter block in a Ceres problem (projection.h).
#pragma once

namespace ws {

// Indices into the intrinsics array, and its size.
constexpr int kFx = 0, kFy = 1, kCx = 2, kCy = 3, kP1 = 4, kP2 = 5, kNumIntrinsics = 6;

}  // namespace ws
