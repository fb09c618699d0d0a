// widestereo's public interface, one header for a program that uses a
// calibration (docs/library.md):
//
//   #include <widestereo/widestereo.h>
//
//   const ws::Rig rig = ws::StereoRigFromFile("calib.yaml");
//   const ws::Camera left(rig.left);
//   std::optional<Eigen::Vector3d> ray = left.Unproject({640, 480});
//
// It is the core layer's: installed, CMake's find_package(widestereo
// COMPONENTS core) gives the target widestereo::core and pkg-config the
// package widestereo-core, with Eigen, OpenCV and yaml-cpp only. The LCM
// message types and their codecs are <widestereo/lcm.h>'s.
#pragma once

#include "interop/any_rig.h"             // LoadAnyRig: mrcal, Kalibr, OpenCV calibrations
#include "models/camera_model.h"         // CameraModel, Camera: Project, Unproject
#include "rectify/pair_triangulation.h"  // TriangulatePixels: a point from two raw pixels
#include "rectify/ray_triangulation.h"   // TriangulateDisparity, RangeChange
#include "rectify/rectification.h"       // BuildRectification: pinhole and lat-lon maps
#include "rig/rig.h"                   // Rig: the calibrated rig, its cameras, R, T
#include "rig/rig_file.h"              // ReadCalibrationFile, StereoRigFromFile, WriteCalibrationFile
