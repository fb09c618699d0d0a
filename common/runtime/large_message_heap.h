// Megabyte messages (image pairs, disparities, clouds), received or built
// 15 to 30 times a second and freed after each, kept in the heap instead of
// mapped and unmapped one by one. Each process of the bus calls this once at
// start, before its threads (Process's constructor does).
#pragma once

namespace ws {

// glibc maps every block above its mmap threshold afresh and gives the
// heap's free top back to the kernel above its trim threshold; a freshly
// mapped page is zeroed by the kernel on first touch. With 2.4 MB image
// pairs that is ~600 page faults a frame per receiver; in stereo-view they
// were a quarter of its CPU (bench/transport). Blocks up to 32 MiB (glibc's
// largest dynamic threshold on 64-bit) come from the heap, and up to 128 MiB
// of free heap is kept for the next message: resident memory stays at the
// process's peak, which its bounded queues bound. A MALLOC_MMAP_THRESHOLD_
// or MALLOC_TRIM_THRESHOLD_ in the environment is left as the user set it.
void KeepLargeMessagesInHeap();

}  // namespace ws
