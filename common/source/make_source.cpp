#include "source/make_source.h"

#include <stdexcept>

#include "source/aravis_source.h"
#include "source/sim_source.h"
#include "source/dir_source.h"

namespace ws {

std::unique_ptr<StereoSource> MakeStereoSource(const std::string& spec, const SourceOptions& options) {
  const size_t colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  const std::string arg = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (arg.empty())
    throw std::invalid_argument("--source must be aravis:LEFT_ID,RIGHT_ID, dir:PATH or sim:CONFIG.yaml, not '" +
                                spec + "'");
  if (kind == "aravis") {
    if (options.rig_config.empty())
      throw std::invalid_argument("aravis: needs the cameras' settings: --rig config/rig/NAME.yaml");
    return std::make_unique<AravisSource>(arg, options.rig_config);
  }
  if (options.mono && kind != "dir")
    throw std::invalid_argument("--mono is for dir: sources (a folder of one camera's images)");
  if (kind == "dir") return std::make_unique<DirSource>(arg, options.loop, options.mono);
  if (kind == "sim") return MakeSimSource(arg, options.loop);
  throw std::invalid_argument("unknown source kind '" + kind +
                              "' (use aravis:LEFT_ID,RIGHT_ID, dir:PATH or sim:CONFIG.yaml)");
}

}  // namespace ws
