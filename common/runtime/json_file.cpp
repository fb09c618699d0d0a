#include "runtime/json_file.h"

#include "runtime/atomic_file.h"

namespace ws {

void WriteJsonFile(const std::string& path, const nlohmann::ordered_json& json) {
  WriteFileAtomically(path, json.dump(2) + "\n");
}

}  // namespace ws
