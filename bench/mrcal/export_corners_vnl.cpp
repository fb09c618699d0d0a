// export_corners_vnl: the board corners of a STEREO_CORNERS log as mrcal's
// corners.vnl, one file per camera (PREFIX-left.vnl, PREFIX-right.vnl), so
// that mrcal-calibrate-cameras solves the very corners stereo-calibrate did
// (bench/mrcal/run.sh). Images are named left-NNNN.png / right-NNNN.png by
// frame id; a view whose board was not found is one "NAME - - -" line.
//   export_corners_vnl --in-url 'file://corners.lcmlog?speed=0' --prefix out/corners
#include <cstdio>
#include <fstream>
#include <map>

#include "calib/calib_data.h"
#include "detect/board_spec.h"
#include "lcm_io/channels.h"
#include "runtime/process.h"
#include "widestereo/stereo_corners_t.hpp"

int main(int argc, char** argv) {
  ws::ProcessCli cli("export_corners_vnl",
                     "Writes the board corners of a STEREO_CORNERS log as mrcal corners.vnl files, "
                     "one per camera.");
  std::string prefix = "corners";
  cli.app().add_option("--prefix", prefix, "Output: PREFIX-left.vnl and PREFIX-right.vnl");
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  try {
    ws::Process process(cli.options());
    std::ofstream out[2] = {std::ofstream(prefix + "-left.vnl"), std::ofstream(prefix + "-right.vnl")};
    for (auto& file : out) {
      if (!file) throw std::runtime_error("cannot write " + prefix + "-*.vnl");
      file << "# filename x y level\n";
    }
    process.Subscribe<widestereo::stereo_corners_t>(ws::channel::kStereoCorners, [&](const auto& msg) {
      const widestereo::camera_corners_t* cameras[2] = {&msg.left, &msg.right};
      for (int c = 0; c < 2; ++c) {
        char name[64];
        std::snprintf(name, sizeof name, "%s-%04lld.png", c == 0 ? "left" : "right",
                      static_cast<long long>(msg.frame_id));
        const ws::calib::BoardView view = ws::calib::ToBoardView(*cameras[c]);
        if (view.empty()) {
          out[c] << name << " - - -\n";
          continue;
        }
        const ws::BoardSpec board = ws::ParseBoardSpec(cameras[c]->board_id);
        std::map<int, Eigen::Vector2d> by_id;
        for (int i = 0; i < view.size(); ++i) by_id[view.ids[i]] = view.image[i];
        for (int id = 0; id < board.corner_count(); ++id) {
          const auto it = by_id.find(id);
          if (it == by_id.end())
            out[c] << name << " - - -\n";
          else
            out[c] << name << " " << it->second.x() << " " << it->second.y() << " 0\n";
        }
      }
    });
    return process.Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "export_corners_vnl: %s\n", e.what());
    return 1;
  }
}
