#include "runtime/niceness_option.h"

#include <sys/resource.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace ws {

void AddNicenessOption(CLI::App& app, int& niceness) {
  niceness = 0;
  app.add_option("--nice", niceness,
                 "Niceness of every thread of this process (0: as started, 19: lowest): a stage that "
                 "yields its core to the stages after it when the cores are full")
      ->check(CLI::Range(0, 19))
      ->capture_default_str();
}

void ApplyNiceness(int niceness) {
  if (niceness == 0) return;
  // PRIO_PROCESS with who = 0 is the calling thread on Linux, not the process.
  if (setpriority(PRIO_PROCESS, 0, niceness) != 0)
    throw std::runtime_error("--nice " + std::to_string(niceness) + ": " + std::strerror(errno));
}

}  // namespace ws
