#include "runtime/stop_request.h"

#include <atomic>

namespace ws {
namespace {

std::atomic<bool> g_stop{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

}  // namespace

bool StopRequested() { return g_stop.load(); }

void RequestStop() { g_stop.store(true); }

void ThrowIfStopRequested() {
  if (StopRequested()) throw Stopped();
}

}  // namespace ws
