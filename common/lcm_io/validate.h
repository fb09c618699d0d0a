// Checks of a decoded message's content beyond what LCM's decoder checks
// (LCM guarantees array lengths match their count fields; these check the
// meaning). Each throws DecodeError naming the type, field and reason.
#pragma once

#include "widestereo/calibration_health_t.hpp"
#include "widestereo/calibration_result_t.hpp"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/calibration_views_t.hpp"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/command_t.hpp"
#include "widestereo/disparity_t.hpp"
#include "widestereo/point_cloud_t.hpp"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

void Validate(const widestereo::image_t& msg);
void Validate(const widestereo::stereo_frame_t& msg);
void Validate(const widestereo::camera_corners_t& msg);
void Validate(const widestereo::stereo_corners_t& msg);
void Validate(const widestereo::camera_calibration_t& msg);
void Validate(const widestereo::stereo_calibration_t& msg);
void Validate(const widestereo::calibration_status_t& msg);
void Validate(const widestereo::calibration_health_t& msg);
void Validate(const widestereo::calibration_result_t& msg);
void Validate(const widestereo::calibration_views_t& msg);
void Validate(const widestereo::disparity_t& msg);
void Validate(const widestereo::point_cloud_t& msg);
void Validate(const widestereo::cloud_stats_t& msg);
void Validate(const widestereo::process_status_t& msg);
void Validate(const widestereo::command_t& msg);

}  // namespace ws
