// The channels of the widestereo bus (DESIGN.md, "Processes").
#pragma once

namespace ws::channel {

inline constexpr const char* kStereoImages = "STEREO_IMAGES";
inline constexpr const char* kStereoCorners = "STEREO_CORNERS";
inline constexpr const char* kStereoThumbnails = "STEREO_THUMBNAILS";
inline constexpr const char* kStereoCommand = "STEREO_COMMAND";
inline constexpr const char* kCalibrationStatus = "CALIBRATION_STATUS";
inline constexpr const char* kCalibrationHealth = "CALIBRATION_HEALTH";
inline constexpr const char* kStereoCalibration = "STEREO_CALIBRATION";
inline constexpr const char* kCalibrationResult = "CALIBRATION_RESULT";
inline constexpr const char* kCalibrationViews = "CALIBRATION_VIEWS";
inline constexpr const char* kCalibrationPreview = "CALIBRATION_PREVIEW";
inline constexpr const char* kStereoDisparity = "STEREO_DISPARITY";
inline constexpr const char* kStereoCloud = "STEREO_CLOUD";
inline constexpr const char* kStereoCloudFiltered = "STEREO_CLOUD_FILTERED";
inline constexpr const char* kCloudStats = "CLOUD_STATS";
inline constexpr const char* kProcessStatus = "PROCESS_STATUS";

}  // namespace ws::channel
