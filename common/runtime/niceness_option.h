// --nice, for a stage of a pipeline that should yield its core to the stages
// after it (stereo-match to stereo-cloud): when the cores are full, the frame
// nearest to being published runs first, and the next frame's first stage
// takes what is left, instead of both frames finishing late.
#pragma once

#include <CLI/CLI.hpp>

namespace ws {

void AddNicenessOption(CLI::App& app, int& niceness);

// Lowers the calling thread's priority to `niceness` (0: leaves it), before
// the process starts any other thread: Linux keeps a niceness per thread, and
// a new thread takes its creator's. Throws std::runtime_error naming why.
void ApplyNiceness(int niceness);

}  // namespace ws
