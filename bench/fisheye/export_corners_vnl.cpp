// export_corners_vnl: the board corners of a STEREO_CORNERS log as one
// mrcal corners.vnl (calib/node/corner_export.h), so that mrcal-calibrate-cameras
// solves the very corners stereo-calibrate did (bench/fisheye/run.sh,
// bench/real/run.sh). Images are named left-NNNN.png / right-NNNN.png by
// frame id (a one-camera log: left only), so mrcal's globs 'left-*.png'
// 'right-*.png' and stereo-import-corners --pairs pair them again. The last
// line on stdout gives the board: "grid COLSxROWS spacing S".
//   export_corners_vnl --in-url 'file://corners.lcmlog?speed=0' --out corners.vnl
#include <cstdio>
#include <fstream>

#include "calib/node/corner_export.h"
#include "calib/node/corners_message.h"
#include "lcm_io/channels.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "widestereo/stereo_corners_t.hpp"

int main(int argc, char** argv) {
  ws::ProcessCli cli("export_corners_vnl",
                     "Writes the board corners of a STEREO_CORNERS log as an mrcal corners.vnl "
                     "(left-NNNN.png and right-NNNN.png by frame id).");
  std::string path = "corners.vnl";
  cli.app().add_option("--out", path, "The corners.vnl to write")->capture_default_str();
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  try {
    ws::Process process(cli.options());
    std::vector<int64_t> frames;
    ws::calib::StereoData data;
    process.Subscribe<widestereo::stereo_corners_t>(ws::channel::kStereoCorners, [&](const auto& msg) {
      frames.push_back(msg.frame_id);
      ws::calib::AddStereoCorners(data, msg);
    });
    if (const int rc = process.Run()) return rc;
    const bool mono = data.right.image_width == 0;
    std::vector<ws::calib::BoardView> all = data.left.views;
    all.insert(all.end(), data.right.views.begin(), data.right.views.end());
    const ws::calib::BoardLattice lattice = ws::calib::LatticeOf(all);
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write " + path);
    ws::calib::WriteMrcalHeader(out);
    for (size_t v = 0; v < frames.size(); ++v)
      for (const ws::calib::CameraData* camera : {&data.left, &data.right}) {
        if (mono && camera == &data.right) continue;
        char name[64];
        std::snprintf(name, sizeof name, "%s-%04lld.png", camera->name.c_str(),
                      static_cast<long long>(frames[v]));
        ws::calib::WriteMrcalView(out, name, camera->views[v], lattice);
      }
    if (!out.flush()) throw std::runtime_error("cannot write " + path);
    std::printf("grid %dx%d spacing %.9g\n", lattice.cols, lattice.rows, lattice.spacing);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "export_corners_vnl: %s\n", e.what());
    return 1;
  }
}
