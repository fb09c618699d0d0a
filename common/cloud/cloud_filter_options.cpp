#include "cloud/cloud_filter_options.h"

namespace ws {

void AddCloudFilterOptions(CLI::App& app, CloudFilterConfig* c) {
  const std::string group = "Filter chain";
  auto add = [&](const char* name, auto* field, const char* help) {
    app.add_option(name, *field, help)->capture_default_str()->group(group);
  };
  add("--z-min", &c->z_min,
      "Pass-through: nearest depth (z, along the left rectified axis) kept, metres; negative keeps points "
      "behind the image plane (a lat-lon cloud of lenses past 180 degrees)");
  add("--z-max", &c->z_max,
      "Pass-through: farthest depth kept, metres (OpenCV puts missing disparities at Z = 10000)");
  add("--voxel", &c->voxel_enabled, "Voxel-grid downsampling (true/false)");
  add("--voxel-leaf", &c->voxel_leaf, "Voxel edge, metres (coarsened when the grid would overflow)");
  add("--outliers", &c->outliers_enabled, "Statistical outlier removal (true/false)");
  add("--outliers-mean-k", &c->outliers_mean_k, "Outlier removal: neighbours per point");
  add("--outliers-stddev-mul", &c->outliers_stddev_mul,
      "Outlier removal: drop points whose mean neighbour distance exceeds mean + this * stddev");
  add("--plane", &c->plane_enabled, "RANSAC plane fit (true/false)");
  add("--plane-distance", &c->plane_distance, "Plane: RANSAC inlier threshold, metres");
  add("--plane-max-iterations", &c->plane_max_iterations, "Plane: RANSAC iterations");
  add("--plane-min-inliers", &c->plane_min_inliers, "Plane: fewer inliers than this is no plane");
  add("--plane-ransac-points", &c->plane_ransac_points,
      "Plane: RANSAC on at most this many points (every k-th), refit on the whole cloud (0: all)");
}

}  // namespace ws
