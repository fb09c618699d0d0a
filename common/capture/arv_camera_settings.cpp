#include "capture/arv_camera_settings.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/pixel_format.h"
#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

constexpr char kSection[] = "aravis";

[[noreturn]] void FieldError(const std::string& name, const std::string& reason) {
  throw RigConfigError("field '" + name + "': " + reason);
}

std::string Show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Reads typed fields of one YAML map, remembering the names asked for so that
// the others can be reported as unknown.
class FieldReader {
 public:
  FieldReader(const cv::FileNode& map, std::string prefix)
      : map_(map), prefix_(std::move(prefix)) {}

  double Number(const char* name) {
    const cv::FileNode node = Find(name);
    if (!node.isInt() && !node.isReal()) Fail(name, "must be a number");
    return double(node);
  }

  int Integer(const char* name) {
    const cv::FileNode node = Find(name);
    if (!node.isInt()) Fail(name, "must be an integer");
    return int(node);
  }

  // OpenCV's YAML reader keeps a comment after unquoted text in the value
  // (and makes a map of it when the comment holds ": "); quoted text is fine.
  std::string Text(const char* name) {
    const cv::FileNode node = Find(name);
    constexpr char kQuote[] = "; quote the text when a comment follows it";
    if (!node.isString()) Fail(name, std::string("must be text") + kQuote);
    const std::string text = node.string();
    if (text.find('#') != std::string::npos) Fail(name, "'" + text + "' holds a comment" + kQuote);
    return text;
  }

  // Throws for a field no reader asked for, or one given twice (OpenCV would
  // silently use the first).
  void RejectUnknownAndRepeated() const {
    std::vector<std::string> seen;
    for (const cv::FileNode& node : map_) {
      const std::string name = node.name();
      if (std::find(known_.begin(), known_.end(), name) == known_.end())
        Fail(name, "unknown field");
      if (std::find(seen.begin(), seen.end(), name) != seen.end())
        Fail(name, "given more than once");
      seen.push_back(name);
    }
  }

  [[noreturn]] void Fail(const std::string& name, const std::string& reason) const {
    FieldError(prefix_ + name, reason);
  }

 private:
  cv::FileNode Find(const char* name) {
    known_.emplace_back(name);
    const cv::FileNode node = map_[name];
    if (node.empty()) Fail(name, "missing");
    return node;
  }

  const cv::FileNode map_;
  const std::string prefix_;
  std::vector<std::string> known_;
};

// The value of enumeration field `name` whose ...Name() is `text`.
template <class Enum, class NameOf>
Enum ParseChoice(const char* name, const std::string& text, std::initializer_list<Enum> values,
                 NameOf name_of, const FieldReader& fields) {
  std::string choices;
  for (Enum value : values) {
    if (text == name_of(value)) return value;
    choices += (choices.empty() ? "'" : " or '") + name_of(value) + "'";
  }
  fields.Fail(name, "must be " + choices + ", got '" + text + "'");
}

cv::FileNode OpenSection(cv::FileStorage& storage, const std::string& path) {
  try {
    OpenOpenCvYaml(storage, path);
  } catch (const YamlFileError& e) {
    throw RigConfigError(e.what());
  }
  if (!storage.root().isMap()) throw RigConfigError("the file must be a YAML map");
  const cv::FileNode section = storage[kSection];
  if (!section.isMap()) throw RigConfigError(std::string("no map '") + kSection + "'");
  return section;
}

// Throws RigConfigError for the first bad value, naming the field `prefix` + name.
void Validate(const ArvCameraSettings& settings, const std::string& prefix) {
  const auto fail = [&](const std::string& name, const std::string& reason) {
    FieldError(prefix + name, reason);
  };
  const auto require_positive = [&](const char* name, double value) {
    if (!std::isfinite(value) || value <= 0)
      fail(name, "must be a finite number > 0, got " + Show(value));
  };
  const auto& formats = SupportedPixelFormats();
  if (std::find(formats.begin(), formats.end(), settings.pixel_format) == formats.end()) {
    std::string list;
    for (const std::string& name : formats) list += (list.empty() ? "" : ", ") + name;
    fail("pixel_format", "'" + settings.pixel_format + "' is not one of " + list);
  }
  require_positive("exposure_us", settings.exposure_us);
  if (!std::isfinite(settings.gain_db))
    fail("gain_db", "must be a finite number, got " + Show(settings.gain_db));
  require_positive("frame_rate_hz", settings.frame_rate_hz);
  if (settings.packet_size != 0 && (settings.packet_size < 576 || settings.packet_size > 65535))
    fail("packet_size",
         "must be 0 (negotiate) or 576..65535 bytes, got " + std::to_string(settings.packet_size));
  require_positive("pairing_tolerance_ms", settings.pairing_tolerance_ms);
  const double half_period_ms = 500.0 / settings.frame_rate_hz;
  if (settings.pairing_tolerance_ms >= half_period_ms)
    fail("pairing_tolerance_ms", "must be under half a frame period (" + Show(half_period_ms) +
                                     " ms at " + Show(settings.frame_rate_hz) + " Hz), got " +
                                     Show(settings.pairing_tolerance_ms));
}

}  // namespace

std::string TriggerModeName(TriggerMode mode) {
  return mode == TriggerMode::software ? "software" : "free-run";
}

std::string PairingClockName(PairingClock clock) {
  return clock == PairingClock::host ? "host" : "camera";
}

void ValidateArvCameraSettings(const ArvCameraSettings& settings) { Validate(settings, ""); }

ArvCameraSettings LoadArvCameraSettings(const std::string& path) {
  try {
    cv::FileStorage storage;
    FieldReader fields(OpenSection(storage, path), std::string(kSection) + ".");
    ArvCameraSettings settings;
    settings.pixel_format = fields.Text("pixel_format");
    settings.exposure_us = fields.Number("exposure_us");
    settings.gain_db = fields.Number("gain_db");
    settings.frame_rate_hz = fields.Number("frame_rate_hz");
    settings.packet_size = fields.Integer("packet_size");
    settings.trigger =
        ParseChoice("trigger", fields.Text("trigger"),
                    {TriggerMode::software, TriggerMode::free_run}, TriggerModeName, fields);
    settings.pairing_tolerance_ms = fields.Number("pairing_tolerance_ms");
    settings.pairing_clock =
        ParseChoice("pairing_clock", fields.Text("pairing_clock"),
                    {PairingClock::host, PairingClock::camera}, PairingClockName, fields);
    fields.RejectUnknownAndRepeated();
    Validate(settings, std::string(kSection) + ".");
    return settings;
  } catch (const RigConfigError& e) {
    throw RigConfigError(path + ": " + e.what());
  }
}

}  // namespace ws
