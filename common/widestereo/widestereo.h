// widestereo's public interface, one header for a program that uses a
// calibration (docs/library.md):
//
//   #include <widestereo/widestereo.h>
//
//   const ws::StereoRig rig = ws::StereoRigFromFile("calib.yaml");
//   const ws::Camera left(rig.left);
//   std::optional<Eigen::Vector3d> ray = left.Unproject({640, 480});
//
// Installed, CMake's find_package(widestereo) gives the target
// widestereo::widestereo and pkg-config the package widestereo.
#pragma once

#include "calib/calib_file.h"            // ReadCalibrationFile, WriteCalibrationFile
#include "interop/any_rig.h"             // LoadAnyRig: mrcal, Kalibr, OpenCV calibrations
#include "models/camera_model.h"         // CameraModel, Camera: Project, Unproject
#include "rectify/pair_triangulation.h"  // TriangulatePixels: a point from two raw pixels
#include "rectify/ray_triangulation.h"   // TriangulateDisparity, RangeChange
#include "rectify/rectification.h"       // BuildRectification: pinhole and lat-lon maps
#include "rectify/stereo_rig.h"          // StereoRig from a file or a message
#include "widestereo/messages.hpp"       // every LCM message type (lcm-gen)
