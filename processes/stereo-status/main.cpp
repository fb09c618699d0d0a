// stereo-status: a live one-screen table of every widestereo process on the
// bus (rates, losses, skips, rejections, errors), the depth, the
// calibration's progress and its health.
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>

#include "lcm_io/channels.h"
#include "monitor/status_board.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "runtime/wall_clock.h"

namespace {

// The terminal's size, or no limit when the output is not a terminal.
ws::Screen TerminalScreen() {
  winsize size{};
  if (!isatty(STDOUT_FILENO) || ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) != 0) return {};
  return {size.ws_col, size.ws_row};
}

}  // namespace

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-status",
                     "Shows every widestereo process on the bus: message rates, frames lost (LOST) and "
                     "skipped for a newer one by design (SKIPPED), rejections, errors; a process "
                     "silent for 3 s as gone; the depth (stereo-cloud's points and plane), the "
                     "calibration's state and coverage, and its health (stereo-health's verdict and "
                     "median |dy|). The table fits the terminal.");
  double duration_s = 0;
  cli.app().add_option("--duration", duration_s, "Exit after this many seconds (0: run until Ctrl-C)");
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    ws::Process process(cli.options());
    ws::StatusBoard board;
    // Times of arrival: the board's clock, whatever the senders' clocks say
    // (the message clock when reading a log).
    auto received = [&] { return process.file_input() ? process.Now() : ws::WallMicros(); };
    process.Subscribe<widestereo::process_status_t>(
        ws::channel::kProcessStatus, [&](const auto& m) { board.Add(m, received()); });
    // CLOUD_STATS and CALIBRATION_HEALTH carry only the frames their senders
    // looked at: their frame-id gaps are skips by design, not losses.
    constexpr auto sparse = ws::Process::FrameGaps::skipped;
    process.Subscribe<widestereo::cloud_stats_t>(
        ws::channel::kCloudStats, [&](const auto& m) { board.Add(m, received()); }, 0, sparse);
    process.Subscribe<widestereo::calibration_status_t>(
        ws::channel::kCalibrationStatus, [&](const auto& m) { board.Add(m); });
    process.Subscribe<widestereo::calibration_health_t>(
        ws::channel::kCalibrationHealth, [&](const auto& m) { board.Add(m); }, 0, sparse);
    const bool tty = isatty(STDOUT_FILENO);
    auto show = [&] {
      std::printf("%s%s", tty ? "\033[H\033[2J" : "", board.Render(received(), TerminalScreen()).c_str());
      std::fflush(stdout);
    };
    const int64_t start = process.Now();
    if (!process.file_input()) {
      process.Every(1000000, [&] {
        show();
        if (duration_s > 0 && process.Now() - start >= duration_s * 1e6) process.Stop();
      });
    }
    const int rc = process.Run();
    show();
    return rc;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-status: %s\n", e.what());
    return 1;
  }
}
