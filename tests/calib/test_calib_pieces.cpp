// The calibration's pieces one at a time, on exact synthetic corners of a
// known camera and known board poses (tests/support/synthetic_rig.h with no
// noise): the homography and Zhang's closed form (start/homography.h,
// start/initialise.h), the board pose of one view with the camera fixed,
// pinhole and fisheye past 90 degrees (start/pose_fit.h, start/ray_pose.h),
// the angle models' start (start/angle_start.h),
// and the solver's problem (solver/problem.h): its shape and a solve from a
// perturbed start back to the truth; the progress lines' time left
// (solver/stage_log.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "calib/solver/camera_block.h"
#include "calib/solver/problem.h"
#include "calib/solver/stage_log.h"
#include "calib/start/angle_start.h"
#include "calib/start/homography.h"
#include "calib/start/initialise.h"
#include "calib/start/pose_fit.h"
#include "calib/start/ray_pose.h"
#include "synthetic_rig.h"

namespace ws::calib {
namespace {

constexpr int kWidth = 1280, kHeight = 960;
// The principal point at the image centre, where Zhang's centred form is exact.
constexpr double kPinholeFx = 800, kPinholeFy = 780;
constexpr double kPinholeCx = (kWidth - 1) / 2.0, kPinholeCy = (kHeight - 1) / 2.0;

SplineOptions Spline() {
  SplineOptions spline;
  spline.knots = 8;
  return spline;
}

// A distortion-free pinhole (poly6 with k = 0).
CameraBlock Pinhole() {
  return PinholeBlock(ModelKind::kPoly6, Spline(), kPinholeFx, kPinholeFy, kPinholeCx,
                      kPinholeCy);
}

// A barrel lens with an off-centre principal point and tangential terms,
// everything free.
CameraBlock Barrel() {
  CameraBlock camera = PinholeBlock(ModelKind::kPoly6, Spline(), 700, 690, 652.5, 471.0);
  camera.intrinsics[kP1] = 2e-4;
  camera.intrinsics[kP2] = -1e-4;
  camera.coeffs = {-0.2, 0.05, -0.005};
  camera.pinhole_only = false;
  return camera;
}

// Exact corners (no noise) of `views` boards seen by `camera`.
SyntheticRig ExactRig(const CameraBlock& camera, int views) {
  SyntheticRigOptions options;
  options.left = options.right = ToCameraModel(camera, kWidth, kHeight);
  options.stereo = false;
  options.views = views;
  options.noise_px = 0;
  return MakeSyntheticRig(options);
}

std::vector<Eigen::Vector2d> PlanePoints(const BoardView& view) {
  std::vector<Eigen::Vector2d> plane;
  for (const auto& X : view.object) plane.push_back(X.head<2>());
  return plane;
}

Eigen::Matrix3d K(double fx, double fy, double cx, double cy) {
  Eigen::Matrix3d k;
  k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
  return k;
}

// The K of Pinhole().
Eigen::Matrix3d TrueK() { return K(kPinholeFx, kPinholeFy, kPinholeCx, kPinholeCy); }

// The rotation angle (radians) between two poses' R.
double RotationError(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.R().transpose() * b.R()).angle();
}

std::vector<char> All(const BoardView& view) { return std::vector<char>(view.size(), 1); }

Pose Perturbed(const Pose& pose, double rad, double metres) {
  Pose out = pose;
  for (int k = 0; k < 3; ++k) out.data[k] += rad * (k == 1 ? -1 : 1);
  for (int k = 3; k < 6; ++k) out.data[k] += metres * (k == 4 ? -1 : 1);
  return out;
}

// ---------------------------------------------------------------- homography

TEST(Homography, MapsExactBoardPointsOntoTheirPixels) {
  const SyntheticRig rig = ExactRig(Pinhole(), 3);
  for (int v = 0; v < rig.data.size(); ++v) {
    const BoardView& view = rig.data.left.views[v];
    const auto H = EstimateHomography(PlanePoints(view), view.image);
    ASSERT_TRUE(H) << "view " << v;
    // The truth: H = K [r1 r2 t], scaled to H(2, 2) = 1.
    const Pose& pose = rig.left_poses[v];
    Eigen::Matrix3d truth;
    truth << pose.R().col(0), pose.R().col(1), pose.t();
    truth = TrueK() * truth;
    truth /= truth(2, 2);
    EXPECT_LT((*H - truth).norm(), 1e-9 * truth.norm()) << "view " << v;
    for (int i = 0; i < view.size(); ++i) {
      const Eigen::Vector2d mapped = (*H * view.object[i].head<2>().homogeneous()).hnormalized();
      EXPECT_LT((mapped - view.image[i]).norm(), 1e-9) << "view " << v << ", corner " << i;
    }
  }
}

TEST(Homography, WithNoisyPixelsStaysWithinTheNoiseOfTheTruth) {
  const SyntheticRig rig = ExactRig(Pinhole(), 1);
  const BoardView& view = rig.data.left.views[0];
  const double sigma = 0.5;  // px per coordinate
  std::mt19937 random(7);
  std::normal_distribution<double> gaussian(0.0, sigma);
  std::vector<Eigen::Vector2d> noisy = view.image;
  for (auto& p : noisy) p += Eigen::Vector2d(gaussian(random), gaussian(random));
  const auto H = EstimateHomography(PlanePoints(view), noisy);
  ASSERT_TRUE(H);
  double sum = 0, largest = 0;
  for (int i = 0; i < view.size(); ++i) {
    const Eigen::Vector2d mapped = (*H * view.object[i].head<2>().homogeneous()).hnormalized();
    const double e = (mapped - view.image[i]).norm();  // from the noise-free pixel
    sum += e * e;
    largest = std::max(largest, e);
  }
  // A fit of 8 parameters to ~100 corners averages the noise down: its error
  // against the truth is well under the noise of one corner.
  EXPECT_LT(std::sqrt(sum / view.size()), 0.5 * sigma);
  EXPECT_LT(largest, sigma);
}

TEST(Homography, IsRefusedForFewerThanFourPoints) {
  const std::vector<Eigen::Vector2d> plane{{0, 0}, {0.04, 0}, {0, 0.04}};
  const std::vector<Eigen::Vector2d> image{{100, 100}, {140, 101}, {99, 140}};
  EXPECT_FALSE(EstimateHomography(plane, image));
}

TEST(Homography, IsRefusedForCollinearPoints) {
  const CameraBlock camera = Pinhole();
  std::vector<Eigen::Vector2d> plane, image;
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector2d X(0.04 * i, 0.02 * i);  // one line on the board
    plane.push_back(X);
    image.push_back(*ProjectPoint(camera, Eigen::Vector3d(X.x() - 0.2, X.y() - 0.1, 0.6)));
  }
  EXPECT_FALSE(EstimateHomography(plane, image));
}

TEST(Homography, PoseFromTheExactHomographyIsTheTruePose) {
  const SyntheticRig rig = ExactRig(Pinhole(), 3);
  for (int v = 0; v < rig.data.size(); ++v) {
    const Pose& truth = rig.left_poses[v];
    Eigen::Matrix3d H;
    H << truth.R().col(0), truth.R().col(1), truth.t();
    H = -3.0 * TrueK() * H;  // any scale, even negative
    const Pose pose = PoseFromHomography(H, TrueK());
    EXPECT_LT(RotationError(pose, truth), 1e-9) << "view " << v;
    EXPECT_LT((pose.t() - truth.t()).norm(), 1e-9) << "view " << v;
  }
}

TEST(Homography, MaxNormalAngleIsTheAngleBetweenTheBoardNormals) {
  const Eigen::Vector3d t(0, 0, 1);
  const std::vector<Pose> poses{
      Pose::FromRt(Eigen::Matrix3d::Identity(), t),
      Pose::FromRt(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()).toRotationMatrix(), t),
      Pose::FromRt(Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitX()).toRotationMatrix(), t),
      Pose::FromRt(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix(), t)};
  EXPECT_NEAR(MaxNormalAngleDeg(poses), 0.7 * 180 / M_PI, 1e-9);
}

// ---------------------------------------------------------------- initialise

std::vector<Eigen::Matrix3d> Homographies(const SyntheticRig& rig) {
  std::vector<Eigen::Matrix3d> Hs;
  for (const BoardView& view : rig.data.left.views) {
    const auto H = EstimateHomography(PlanePoints(view), view.image);
    EXPECT_TRUE(H);
    if (H) Hs.push_back(*H);
  }
  return Hs;
}

TEST(ZhangIntrinsics, RecoversTheFocalLengthsFromExactViews) {
  const SyntheticRig rig = ExactRig(Pinhole(), 5);
  const PinholeInit init = ZhangIntrinsics(Homographies(rig), kWidth, kHeight);
  EXPECT_EQ(init.method, "zhang-centred");
  EXPECT_NEAR(init.fx, kPinholeFx, 1e-6 * kPinholeFx);
  EXPECT_NEAR(init.fy, kPinholeFy, 1e-6 * kPinholeFy);
  EXPECT_NEAR(init.cx, kPinholeCx, 1e-9);
  EXPECT_NEAR(init.cy, kPinholeCy, 1e-9);
}

TEST(ZhangIntrinsics, ThrowsForBoardsParallelToTheImage) {
  std::vector<Eigen::Matrix3d> Hs;
  for (double roll : {0.0, 0.7}) {
    Eigen::Matrix3d Rt;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    Rt << R.col(0), R.col(1), Eigen::Vector3d(-0.1, 0.05, 0.5 + roll);
    Hs.push_back(TrueK() * Rt);
  }
  EXPECT_THROW(ZhangIntrinsics(Hs, kWidth, kHeight), CalibrationError);
}

TEST(Initialize, GivesTheTrueIntrinsicsAndPosesOfExactPinholeViews) {
  const SyntheticRig rig = ExactRig(Pinhole(), 5);
  CalibrationOptions options;
  options.model = ModelKind::kPoly6;
  Prepared prepared = Prepare(rig.data.left, options);
  ASSERT_EQ(prepared.NumUsable(), 5);
  const Init init = Initialize(prepared, options, options.model);
  EXPECT_NEAR(init.pinhole.fx, kPinholeFx, 1e-6 * kPinholeFx);
  EXPECT_NEAR(init.pinhole.fy, kPinholeFy, 1e-6 * kPinholeFy);
  EXPECT_NEAR(init.pinhole.cx, kPinholeCx, 1e-9);
  EXPECT_NEAR(init.pinhole.cy, kPinholeCy, 1e-9);
  ASSERT_EQ(init.poses.size(), rig.left_poses.size());
  for (size_t v = 0; v < init.poses.size(); ++v) {
    EXPECT_LT(RotationError(init.poses[v], rig.left_poses[v]), 1e-6) << "view " << v;
    EXPECT_LT((init.poses[v].t() - rig.left_poses[v].t()).norm(), 1e-6) << "view " << v;
  }
}

// ------------------------------------------------------------------ pose fit

TEST(RefinePose, ReturnsTheTruePoseFromAPerturbedStart) {
  const CameraBlock camera = Barrel();
  const SyntheticRig rig = ExactRig(camera, 3);
  for (int v = 0; v < rig.data.size(); ++v) {
    const BoardView& view = rig.data.left.views[v];
    const Pose& truth = rig.left_poses[v];
    Pose pose = Perturbed(truth, 0.03, 0.02);
    const double rms = RefinePose(camera, view, All(view), &pose);
    EXPECT_LT(rms, 1e-9) << "view " << v;
    EXPECT_LT(RotationError(pose, truth), 1e-9) << "view " << v;
    EXPECT_LT((pose.t() - truth.t()).norm(), 1e-9) << "view " << v;
  }
}

TEST(PlanarPoseCandidates, IncludeTheTruePoseThroughADistortedLens) {
  const CameraBlock camera = Barrel();
  const SyntheticRig rig = ExactRig(camera, 3);
  for (int v = 0; v < rig.data.size(); ++v) {
    const BoardView& view = rig.data.left.views[v];
    const Pose& truth = rig.left_poses[v];
    const std::vector<Pose> candidates = PlanarPoseCandidates(camera, view, All(view));
    ASSERT_FALSE(candidates.empty()) << "view " << v;
    double best_R = INFINITY, best_t = INFINITY;
    for (const Pose& pose : candidates) {
      best_R = std::min(best_R, RotationError(pose, truth));
      best_t = std::min(best_t, (pose.t() - truth.t()).norm());
    }
    EXPECT_LT(best_R, 1e-8) << "view " << v;
    EXPECT_LT(best_t, 1e-8) << "view " << v;
  }
}

// An equidistant fisheye (r = f theta, kb4 with k = 0) and a board beside it,
// its corners from 60 to past 100 degrees off the axis.
struct FisheyeView {
  CameraBlock camera = PinholeBlock(ModelKind::kKb4, Spline(), 400, 400, kPinholeCx, kPinholeCy);
  Pose truth;
  BoardView view;
  std::vector<Eigen::Vector3d> rays;  // the unit rays of the pixels
  double max_theta_deg = 0;
};

FisheyeView Fisheye() {
  FisheyeView f;
  // Board centre 85 degrees off the axis, 0.3 m away, facing the camera
  // turned by 20 degrees.
  const double theta = 85 * M_PI / 180;
  const Eigen::Vector3d direction(std::sin(theta), 0, std::cos(theta));
  const Eigen::Vector3d z = direction;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
  Eigen::Matrix3d facing;
  facing << x, z.cross(x), z;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.35, Eigen::Vector3d(0.6, 0.8, 0)).toRotationMatrix() * facing;
  const Eigen::Vector3d centre(0.14, 0.1, 0);
  f.truth = Pose::FromRt(R, 0.3 * direction - R * centre);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 6; ++j) {
      const Eigen::Vector3d X(0.04 * i, 0.04 * j, 0);
      const Eigen::Vector3d Xc = f.truth * X;
      const auto pixel = ProjectPoint(f.camera, Xc);
      if (!pixel) continue;
      f.view.ids.push_back(i * 6 + j);
      f.view.object.push_back(X);
      f.view.image.push_back(*pixel);
      const auto ray = PixelRay(f.camera, *pixel);
      f.rays.push_back(ray ? *ray : Eigen::Vector3d(NAN, NAN, NAN));
      f.max_theta_deg = std::max(
          f.max_theta_deg, std::atan2(Xc.head<2>().norm(), Xc.z()) * 180 / M_PI);
    }
  return f;
}

TEST(PoseFromRays, RecoversTheTruePoseOfABoardPastNinetyDegrees) {
  const FisheyeView f = Fisheye();
  ASSERT_EQ(f.view.size(), 48);
  ASSERT_GT(f.max_theta_deg, 100.0);  // some corners behind the image plane
  for (const auto& ray : f.rays) ASSERT_TRUE(ray.allFinite());
  const auto pose = PoseFromRays(f.view.object, f.rays);
  ASSERT_TRUE(pose);
  EXPECT_LT(RotationError(*pose, f.truth), 1e-9);
  EXPECT_LT((pose->t() - f.truth.t()).norm(), 1e-9);
}

TEST(PoseFromRays, IsRefusedForFewPointsOrPointsOffTheBoardPlane) {
  const FisheyeView f = Fisheye();
  const std::vector<Eigen::Vector3d> three_object(f.view.object.begin(),
                                                  f.view.object.begin() + 3);
  const std::vector<Eigen::Vector3d> three_rays(f.rays.begin(), f.rays.begin() + 3);
  EXPECT_FALSE(PoseFromRays(three_object, three_rays));
  std::vector<Eigen::Vector3d> off_plane = f.view.object;
  off_plane[5].z() = 0.01;
  EXPECT_FALSE(PoseFromRays(off_plane, f.rays));
}

TEST(PlanarPoseCandidates, GiveTheTruePoseOfAFisheyeBoardPastNinetyDegrees) {
  const FisheyeView f = Fisheye();
  const std::vector<Pose> candidates = PlanarPoseCandidates(f.camera, f.view, All(f.view));
  ASSERT_FALSE(candidates.empty());
  double best_R = INFINITY, best_t = INFINITY;
  for (const Pose& pose : candidates) {
    best_R = std::min(best_R, RotationError(pose, f.truth));
    best_t = std::min(best_t, (pose.t() - f.truth.t()).norm());
  }
  EXPECT_LT(best_R, 1e-9);
  EXPECT_LT(best_t, 1e-9);
}

TEST(RefinePose, ReturnsTheTruePoseOfAFisheyeBoardPastNinetyDegrees) {
  const FisheyeView f = Fisheye();
  Pose pose = Perturbed(f.truth, 0.03, 0.02);
  const double rms = RefinePose(f.camera, f.view, All(f.view), &pose);
  EXPECT_LT(rms, 1e-9);
  EXPECT_LT(RotationError(pose, f.truth), 1e-9);
  EXPECT_LT((pose.t() - f.truth.t()).norm(), 1e-9);
}

TEST(AngleStart, FindsTheFocalLengthOfAnEquidistantFisheyeWithinItsGrid) {
  const double f = 400;  // r = f theta: 90 degrees at 628 px, the image corners past 110
  const CameraBlock camera = PinholeBlock(ModelKind::kKb4, Spline(), f, f, kPinholeCx, kPinholeCy);
  const SyntheticRig rig = ExactRig(camera, 5);
  CalibrationOptions options;
  options.model = ModelKind::kKb4;
  const Prepared prepared = Prepare(rig.data.left, options);
  ASSERT_EQ(prepared.NumUsable(), 5);
  const AngleStartFit start = AngleStart(prepared, 3);
  const PinholeInit& init = start.pinhole;
  const std::vector<Pose>& poses = start.poses;
  const std::vector<bool>& posed = start.posed;
  // The search steps by 1 % about the best of a 10 % grid: within half a step.
  EXPECT_EQ(start.lens, StartLens::kEquidistant);
  EXPECT_EQ(init.method, "equidistant");
  EXPECT_NEAR(init.fx, f, 0.006 * f);
  EXPECT_EQ(init.fy, init.fx);
  EXPECT_EQ(init.cx, kPinholeCx);
  EXPECT_EQ(init.cy, kPinholeCy);
  ASSERT_EQ(posed.size(), 5u);
  for (int v = 0; v < 5; ++v) {
    ASSERT_TRUE(posed[v]) << "view " << v;
    // Off only as far as f is: a few milliradians and millimetres.
    EXPECT_LT(RotationError(poses[v], rig.left_poses[v]), 5e-3) << "view " << v;
    EXPECT_LT((poses[v].t() - rig.left_poses[v].t()).norm(), 5e-3) << "view " << v;
  }
  std::printf("equidistant start: f %.3f px (truth %.1f)\n", init.fx, f);
}

// A wide pinhole (f 500 px: 104 degrees across the 1280 px image), far
// from any equidistant f.
constexpr double kWideF = 500;

TEST(AngleStart, ChoosesThePerspectiveLensForAWidePinhole) {
  const CameraBlock camera =
      PinholeBlock(ModelKind::kPoly6, Spline(), kWideF, kWideF, kPinholeCx, kPinholeCy);
  const SyntheticRig rig = ExactRig(camera, 5);
  CalibrationOptions options;
  options.model = ModelKind::kKb4;
  const AngleStartFit start = AngleStart(Prepare(rig.data.left, options), 3);
  EXPECT_EQ(start.lens, StartLens::kPerspective);
  EXPECT_EQ(start.pinhole.method, "perspective");
  EXPECT_NEAR(start.pinhole.fx, kWideF, 0.006 * kWideF);
  for (int v = 0; v < 5; ++v) EXPECT_LT(RotationError(start.poses[v], rig.left_poses[v]), 5e-3);
}

TEST(StartCamera, PutsAnAngleModelOnThePerspectiveLens) {
  Init init;
  init.pinhole = PinholeInit{kWideF, kWideF, kPinholeCx, kPinholeCy, "perspective"};
  init.lens = StartLens::kPerspective;
  Prepared prepared;
  prepared.width = kWidth;
  prepared.height = kHeight;
  const double corner = std::atan(0.5 * std::hypot(kWidth, kHeight) / kWideF);
  for (ModelKind kind : {ModelKind::kKb4, ModelKind::kBsplineTheta}) {
    const CameraBlock camera = StartCamera(init, prepared, kind, Spline());
    EXPECT_TRUE(camera.pinhole_only);
    double worst = 0;  // pixels, against r = f tan(theta), out to the image's corner
    for (double theta = 0.01; theta <= corner; theta += 0.01) {
      const Eigen::Vector3d X(std::sin(theta), 0, std::cos(theta));
      const auto pixel = ProjectPoint(camera, X);
      ASSERT_TRUE(pixel) << ModelName(kind) << " theta " << theta;
      worst = std::max(worst, std::abs(pixel->x() - kPinholeCx - kWideF * std::tan(theta)));
    }
    EXPECT_LT(worst, 1.0) << ModelName(kind);
    std::printf("%s on the perspective lens: within %.3f px of f tan(theta) up to %.1f deg\n",
                ModelName(kind).c_str(), worst, corner * 180 / M_PI);
  }
}

// ------------------------------------------------------------------- problem

struct BarrelProblem {
  SyntheticRig rig;
  Inliers inliers;
  std::vector<Pose> poses;
  Problem problem;

  BarrelProblem(const CameraBlock& start, int views) : rig(ExactRig(Barrel(), views)) {
    poses = rig.left_poses;
    problem.cameras = {start};
    for (int v = 0; v < rig.data.size(); ++v)
      inliers.push_back(All(rig.data.left.views[v]));
    for (int v = 0; v < rig.data.size(); ++v)
      problem.observations.push_back({0, v, &rig.data.left.views[v], &inliers[v], &poses[v]});
  }
  BarrelProblem(const BarrelProblem&) = delete;
};

TEST(Problem, LinearisedAtTheTruthHasOneBlockPerViewAndZeroResiduals) {
  const int views = 4;
  BarrelProblem p(Barrel(), views);
  const Linearisation lin = Linearise(p.problem, "barrel");
  EXPECT_TRUE(p.problem.left_out.empty());
  EXPECT_EQ(lin.free_size, kNumIntrinsics + 3);  // fx fy cx cy p1 p2, k1 k2 k3
  ASSERT_EQ(int(lin.blocks.size()), views);
  for (int b = 0; b < views; ++b) {
    const auto& block = lin.blocks[b];
    EXPECT_EQ(block.observation, b);
    EXPECT_EQ(block.pose, b);
    EXPECT_EQ(block.r.size(), 2 * p.rig.data.left.views[b].size()) << "view " << b;
    EXPECT_EQ(block.J_free.rows(), block.r.size());
    // Without a field a view's corners are one block, in order.
    std::vector<int> all(size_t(p.rig.data.left.views[b].size()));
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(block.corners, all) << "view " << b;
    // Without a field every view reads every free parameter.
    ASSERT_EQ(int(block.columns.size()), lin.free_size);
    for (int c = 0; c < lin.free_size; ++c) EXPECT_EQ(block.columns[size_t(c)], c);
    EXPECT_EQ(block.J_free.cols(), lin.free_size);
    EXPECT_EQ(block.J_pose.cols(), 6);
    EXPECT_LT(block.r.cwiseAbs().maxCoeff(), 1e-9) << "view " << b;
  }
}

TEST(Problem, WithAFieldAViewIsLinearisedInBlocksOfCornersThatReadTheSameSegments) {
  // The same normal equations as one block per view, in blocks that each
  // read a few of the field's segments: a view's blocks hold each of its
  // inlier corners once, and each block reads fewer parameters than the view.
  CameraBlock start = Barrel();
  start.field = NonRadialField(16, 12, {-1.0, 1.0, -0.75, 0.75});
  start.coeffs.resize(start.coeffs.size() + size_t(start.field.NumCoeffs()), 0.0);
  BarrelProblem p(start, 3);
  for (int i = 0; i < 5; ++i) p.inliers[0][size_t(i)] = 0;
  const Linearisation lin = Linearise(p.problem, "barrel with a field");
  std::vector<std::vector<int>> seen(3);
  std::vector<std::set<int>> view_columns(3);
  for (const Linearisation::Block& block : lin.blocks) {
    EXPECT_EQ(block.r.size(), 2 * Eigen::Index(block.corners.size()));
    EXPECT_TRUE(std::is_sorted(block.corners.begin(), block.corners.end()));
    EXPECT_LT(block.columns.size(), size_t(lin.free_size));
    seen[size_t(block.observation)].insert(seen[size_t(block.observation)].end(), block.corners.begin(),
                                           block.corners.end());
    view_columns[size_t(block.observation)].insert(block.columns.begin(), block.columns.end());
  }
  for (int v = 0; v < 3; ++v) {
    std::vector<int> inliers;
    for (int i = 0; i < p.rig.data.left.views[v].size(); ++i)
      if (p.inliers[size_t(v)][size_t(i)]) inliers.push_back(i);
    std::sort(seen[size_t(v)].begin(), seen[size_t(v)].end());
    EXPECT_EQ(seen[size_t(v)], inliers) << "view " << v;
    EXPECT_GT(std::count_if(lin.blocks.begin(), lin.blocks.end(),
                            [&](const Linearisation::Block& b) { return b.observation == v; }),
              1)
        << "view " << v;
    for (const Linearisation::Block& block : lin.blocks)
      if (block.observation == v) {
        EXPECT_LT(block.columns.size(), view_columns[size_t(v)].size());
      }
  }
}

TEST(Problem, HeldOutCornersLeaveTheResiduals) {
  BarrelProblem p(Barrel(), 2);
  for (int i = 0; i < 10; ++i) p.inliers[1][i] = 0;
  const Linearisation lin = Linearise(p.problem, "barrel");
  ASSERT_EQ(lin.blocks.size(), 2u);
  EXPECT_EQ(lin.blocks[0].r.size(), 2 * p.rig.data.left.views[0].size());
  EXPECT_EQ(lin.blocks[1].r.size(), 2 * (p.rig.data.left.views[1].size() - 10));
}

TEST(Problem, SolveFromAPerturbedStartConvergesToTheTruth) {
  const CameraBlock truth = Barrel();
  CameraBlock start = truth;
  start.intrinsics = {truth.intrinsics[kFx] * 1.03, truth.intrinsics[kFy] * 0.98,
                      truth.intrinsics[kCx] + 8, truth.intrinsics[kCy] - 6, 0, 0};
  start.coeffs = {0, 0, 0};
  BarrelProblem p(start, 6);
  for (Pose& pose : p.poses) pose = Perturbed(pose, 0.02, 0.01);
  SolveSettings settings;
  settings.what = "barrel";
  Solve(p.problem, settings);
  EXPECT_TRUE(p.problem.left_out.empty());
  const CameraBlock& solved = p.problem.cameras[0];
  for (int k : {kFx, kFy, kCx, kCy})
    EXPECT_NEAR(solved.intrinsics[k], truth.intrinsics[k], 1e-6 * truth.intrinsics[k])
        << "intrinsic " << k;
  for (int k : {kP1, kP2})
    EXPECT_NEAR(solved.intrinsics[k], truth.intrinsics[k], 1e-9) << "intrinsic " << k;
  ASSERT_EQ(solved.coeffs.size(), truth.coeffs.size());
  for (size_t k = 0; k < truth.coeffs.size(); ++k)
    EXPECT_NEAR(solved.coeffs[k], truth.coeffs[k], 1e-6) << "k" << k + 1;
  for (int v = 0; v < p.rig.data.size(); ++v) {
    EXPECT_LT(RotationError(p.poses[v], p.rig.left_poses[v]), 1e-8) << "view " << v;
    EXPECT_LT((p.poses[v].t() - p.rig.left_poses[v].t()).norm(), 1e-8) << "view " << v;
  }
}

}  // namespace
// The seconds so far per item done, times the items to go: 10 s for 2 of 5
// leaves about 15 s; nothing done yet says nothing.
TEST(StageLog, TimeLeftIsTheTimePerItemTimesTheItemsToGo) {
  const auto ten_seconds_ago = std::chrono::steady_clock::now() - std::chrono::seconds(10);
  EXPECT_EQ(TimeLeft(ten_seconds_ago, 2, 5), "about 15 s left");
  EXPECT_EQ(TimeLeft(ten_seconds_ago, 5, 5), "about 0 s left");
  EXPECT_EQ(TimeLeft(ten_seconds_ago, 0, 5), "");
}

}  // namespace ws::calib
