// A JSON document (a report: stereo-calibrate --report, stereo-health
// --report) written as a file, indented, atomically (runtime/atomic_file.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace ws {

// Writes `json` indented by 2 to a temporary file and renames it; throws
// std::runtime_error when it cannot.
void WriteJsonFile(const std::string& path, const nlohmann::ordered_json& json);

}  // namespace ws
