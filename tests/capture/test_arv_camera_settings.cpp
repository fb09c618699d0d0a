#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "capture/arv_camera_settings.h"
#include "test_support.h"

namespace {

const char kValid[] = R"(%YAML:1.0
other_section:
  anything: 1
aravis:
  pixel_format: Mono16
  exposure_us: 2500
  gain_db: 3.5
  frame_rate_hz: 15
  packet_size: 8192
  trigger: "free-run"   # quoted text may have a comment: after it
  pairing_tolerance_ms: 5
  pairing_clock: "camera"
)";

std::string WriteRig(const std::string& name, const std::string& text) {
  const std::string path = ws::test::TempDir("rig") + "/" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The error message of loading `text`, "" if it loads.
std::string LoadError(const std::string& name, const std::string& text) {
  try {
    ws::LoadArvCameraSettings(WriteRig(name, text));
  } catch (const ws::RigConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ArvCameraSettings, LoadsEveryFieldAndIgnoresOtherSections) {
  const auto s = ws::LoadArvCameraSettings(WriteRig("valid", kValid));
  EXPECT_EQ(s.pixel_format, "Mono16");
  EXPECT_EQ(s.exposure_us, 2500);
  EXPECT_EQ(s.gain_db, 3.5);
  EXPECT_EQ(s.frame_rate_hz, 15);
  EXPECT_EQ(s.packet_size, 8192);
  EXPECT_EQ(s.trigger, ws::TriggerMode::free_run);
  EXPECT_EQ(s.pairing_tolerance_ms, 5);
  EXPECT_EQ(s.pairing_clock, ws::PairingClock::camera);
}

TEST(ArvCameraSettings, ShippedRigFilesLoad) {
  for (const char* name : {"default", "fake-gige"}) {
    const std::string path = ws::test::SourceDir() + "/config/rig/" + name + ".yaml";
    EXPECT_NO_THROW(ws::LoadArvCameraSettings(path)) << path;
  }
  const auto s = ws::LoadArvCameraSettings(ws::test::SourceDir() + "/config/rig/default.yaml");
  const ws::ArvCameraSettings defaults;
  EXPECT_EQ(s.pixel_format, defaults.pixel_format);
  EXPECT_EQ(s.packet_size, defaults.packet_size);
  EXPECT_EQ(s.trigger, defaults.trigger);
  EXPECT_EQ(s.pairing_clock, defaults.pairing_clock);
}

TEST(ArvCameraSettings, ErrorsNameFileFieldAndReason) {
  const std::string missing = LoadError("missing", Replace(kValid, "  gain_db: 3.5\n", ""));
  EXPECT_NE(missing.find("missing.yaml: field 'aravis.gain_db': missing"), std::string::npos)
      << missing;
  EXPECT_NE(LoadError("type", Replace(kValid, "packet_size: 8192", "packet_size: big"))
                .find("field 'aravis.packet_size': must be an integer"),
            std::string::npos);
  EXPECT_NE(LoadError("unknown", Replace(kValid, "  trigger:", "  exposure: 1\n  trigger:"))
                .find("field 'aravis.exposure': unknown field"),
            std::string::npos);
  EXPECT_NE(LoadError("trigger", Replace(kValid, "free-run", "hardware"))
                .find("field 'aravis.trigger': must be 'software' or 'free-run', got 'hardware'"),
            std::string::npos);
  EXPECT_NE(LoadError("clock", Replace(kValid, "\"camera\"", "ptp"))
                .find("field 'aravis.pairing_clock': must be 'host' or 'camera', got 'ptp'"),
            std::string::npos);
  EXPECT_NE(
      LoadError("format", Replace(kValid, "Mono16", "Mono12"))
          .find("field 'aravis.pixel_format': 'Mono12' is not one of Mono8, Mono16, RGB8, BGR8"),
      std::string::npos);
  EXPECT_NE(LoadError("packet", Replace(kValid, "8192", "100"))
                .find("field 'aravis.packet_size': must be 0 (negotiate) or 576..65535"),
            std::string::npos);
  EXPECT_NE(LoadError("exposure", Replace(kValid, "2500", "-1"))
                .find("field 'aravis.exposure_us': must be a finite number > 0"),
            std::string::npos);
  EXPECT_NE(LoadError("comment", Replace(kValid, "Mono16", "Mono16  # or Mono8"))
                .find("field 'aravis.pixel_format': 'Mono16  # or Mono8' holds a comment; quote "
                      "the text when a comment follows it"),
            std::string::npos);
  EXPECT_NE(LoadError("section", "%YAML:1.0\ncamera:\n  a: 1\n").find("no map 'aravis'"),
            std::string::npos);
  try {
    ws::LoadArvCameraSettings("/nonexistent/rig.yaml");
    ADD_FAILURE() << "loaded a file that does not exist";
  } catch (const ws::RigConfigError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/rig.yaml: cannot open the file");
  }
}

// Found by tests/fuzz: OpenCV 4.6's YAML reader never returns on the first
// file (a line indented less than the first one, then "xyz-"), throws
// std::length_error on an empty key at the end of the file, and a file that
// is a list made it throw its own assertion.
TEST(ArvCameraSettings, FilesOpenCvCannotReadAreErrorsNotHangs) {
  EXPECT_NE(LoadError("hang", "%YAML:1.0\n  aravis: 1\nxyz-\n")
                .find("hang.yaml: line 3: indented less than line 2, where the top level starts"),
            std::string::npos);
  EXPECT_NE(LoadError("end", "%YAML:1.0\naravis: 1\n...\n-\n")
                .find("end.yaml: line 3: '...' (the end of a YAML document) is not supported"),
            std::string::npos);
  EXPECT_NE(LoadError("list", "%YAML:1.0\n- 1\n").find("list.yaml: the file must be a YAML map"),
            std::string::npos);
  EXPECT_NE(LoadError("key", "%YAML:1.0\n  t: c\n  :").find("key.yaml: not YAML that OpenCV reads"),
            std::string::npos);
}

TEST(ArvCameraSettings, ToleranceMustStayUnderHalfAFramePeriod) {
  const std::string error = LoadError(
      "tolerance", Replace(kValid, "pairing_tolerance_ms: 5", "pairing_tolerance_ms: 40"));
  EXPECT_NE(error.find("field 'aravis.pairing_tolerance_ms': must be under half a frame period "
                       "(33.3333 ms at 15 Hz), got 40"),
            std::string::npos)
      << error;
  ws::ArvCameraSettings settings;
  settings.pairing_tolerance_ms = 49;
  EXPECT_NO_THROW(ws::ValidateArvCameraSettings(settings));  // 10 Hz: under 50 ms
  settings.pairing_tolerance_ms = 50;
  EXPECT_THROW(ws::ValidateArvCameraSettings(settings), ws::RigConfigError);
}

}  // namespace
