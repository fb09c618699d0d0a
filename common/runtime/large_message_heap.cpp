#include "runtime/large_message_heap.h"

#include <malloc.h>

#include <cstdlib>

namespace ws {

void KeepLargeMessagesInHeap() {
  constexpr int kMiB = 1 << 20;
  if (!std::getenv("MALLOC_MMAP_THRESHOLD_")) mallopt(M_MMAP_THRESHOLD, 32 * kMiB);
  if (!std::getenv("MALLOC_TRIM_THRESHOLD_")) mallopt(M_TRIM_THRESHOLD, 128 * kMiB);
}

}  // namespace ws
