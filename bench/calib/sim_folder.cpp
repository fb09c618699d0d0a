// The simulator's board frames as a folder of image pairs, the way a user
// hands one to `stereo-calibrate --images`: DIR/leftNN.png, DIR/rightNN.png
// (bench/calib/folder.sh times the one command on it).
//
//   build/bench/sim_folder CONFIG.yaml DIR
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "sim/simulator.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s CONFIG.yaml DIR (the simulator's board frames as DIR/leftNN.png, "
                         "DIR/rightNN.png)\n", argv[0]);
    return 2;
  }
  ws::Simulator sim(ws::LoadSimConfig(argv[1]));
  const std::string dir = argv[2];
  std::filesystem::create_directories(dir);
  int pairs = 0;
  for (int i = 0; i < sim.frame_count(); ++i) {
    if (sim.frames()[size_t(i)].kind != ws::SimFrame::Kind::board) continue;
    const auto [left, right] = sim.Render(i);
    char name[32];
    std::snprintf(name, sizeof name, "%02d.png", pairs++);
    if (!cv::imwrite(dir + "/left" + name, left) || !cv::imwrite(dir + "/right" + name, right)) {
      std::fprintf(stderr, "cannot write %s/left%s\n", dir.c_str(), name);
      return 1;
    }
  }
  std::printf("%d pairs in %s\n", pairs, dir.c_str());
  return 0;
}
