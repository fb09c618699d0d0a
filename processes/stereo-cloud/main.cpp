// stereo-cloud: filters every point cloud on STEREO_CLOUD (depth pass-through,
// voxel grid, outlier removal, RANSAC plane) and publishes the result and
// per-stage statistics; writes PCD files every N clouds or on a save command.
#include <cstdio>

#include "cloud/cloud_filter_options.h"
#include "cloud/cloud_node.h"
#include "lcm_io/channels.h"
#include "runtime/process_cli.h"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-cloud",
                     "Filters the point clouds on STEREO_CLOUD with PCL (depth pass-through, voxel "
                     "grid, statistical outlier removal, RANSAC plane) and publishes "
                     "STEREO_CLOUD_FILTERED and CLOUD_STATS. Live, it filters the newest cloud waiting; "
                     "the clouds it skips, and the frames stereo-match did not make a cloud of, are counted as "
                     "skipped in PROCESS_STATUS. Writes PCD files every --save-every "
                     "clouds into --pcd-dir, and there on a 'save [path=NAME.pcd]' command on "
                     "STEREO_COMMAND.");
  ws::CloudFilterConfig filter;
  ws::CloudSaveConfig save;
  auto& app = cli.app();
  ws::AddCloudFilterOptions(app, &filter);
  auto* pcd_dir = app.add_option("--pcd-dir", save.pcd_dir,
                                 "Folder for PCD files cloud_<frame_id>.pcd (created if needed)");
  app.add_option("--save-every", save.save_every,
                 "With --pcd-dir: write every N-th filtered cloud (0: only on save commands)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str()
      ->needs(pcd_dir);
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    ws::SilencePclConsole();
    ws::Process process(cli.options());
    ws::CloudNode node(process, filter, save);
    process.SetProgress([&] { return node.Progress(); });
    // stereo-match makes a cloud of the newest pair only: the frame ids it
    // passed over are skipped by design, not lost (runtime/process.h).
    process.Subscribe<ws::PointCloud>(
        ws::channel::kStereoCloud, [&](auto& msg) { node.OnCloud(msg); }, 2, ws::Process::FrameGaps::skipped);
    process.Subscribe<widestereo::command_t>(
        ws::channel::kStereoCommand, [&](const auto& msg) { node.OnCommand(msg); });
    return process.Run();
  } catch (const std::exception& e) {
    const std::string& config = cli.options().config_file;
    std::fprintf(stderr, "stereo-cloud: %s%s\n", config.empty() ? "" : (config + ": ").c_str(),
                 e.what());
    return 1;
  }
}
