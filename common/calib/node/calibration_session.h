// What stereo-calibrate keeps while it runs: the accepted stereo views (near
// duplicates of views it already has are skipped), the coverage of each
// image, the CALIBRATION_STATUS it publishes, and the state file that makes
// the accepted views survive a crash.
//
// State file: an LCM log of every accepted STEREO_CORNERS message, appended
// and flushed as each is accepted, and read back when the session starts, so
// a process killed halfway loses nothing the person holding the board did.
// A damaged file (cut in the middle of an event by a kill during a write, a
// flipped byte) is never truncated: it is kept beside itself as
// STATE-damaged-<UTC time>.lcmlog, and every intact event, those after the
// damage too (lcm_io/lcm_log.h, RecoverLcmLog), goes to a new state file.
//
// Nothing is ever thrown away: Reset() archives the views (the state file is
// renamed STATE-<UTC time>.lcmlog beside it; without a state file they are
// kept in memory) and RestoreLastArchive() brings the newest archive back,
// archiving the views of the moment first if there are any. Remove() takes
// one view out, at a user's request: the state file is written again without
// it (whole, atomic_file.h) and the view appended to STATE-removed.lcmlog
// beside it.
//
// Thread-safe: the process's solve thread reads Data() while messages come in.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "calib/evaluate/coverage.h"
#include "calib/solver/calib_data.h"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/calibration_views_t.hpp"
#include "widestereo/stereo_corners_t.hpp"

namespace lcm {
class LogFile;
}

namespace ws::calib {

// A view is a near duplicate of an accepted one when its corners moved on
// average less than this many times their noise (corner_noise.h): a board
// held still moves them by about 1.8 noise levels (the mean distance of two
// noisy detections), a view someone chose by many pixels. So a replayed log
// or imported corners keep every distinct view, and a live stream does not
// count one still board many times.
inline constexpr double kStillBoard = 4.0;

struct SessionOptions {
  // Near-duplicate threshold: mean corner distance in pixels; 0 =
  // kStillBoard times the view's corner noise.
  double duplicate_px = 0;
  int grid_rows = 6, grid_cols = 8;
  int min_views = 3;
  // Views the session keeps at most: a flood of views (a peer's, a stream
  // left running) cannot grow it, its state file or every solve without
  // bound. Beyond it a view is rejected, saying so.
  int max_views = 300;
  std::string state_path;  // "" = no state file
};

class CalibrationSession {
 public:
  explicit CalibrationSession(SessionOptions options);
  ~CalibrationSession();

  // Reads the state file's views (if it exists) and opens it for appending;
  // returns how many views it restored. Throws std::runtime_error when the
  // file cannot be read or written.
  int Restore();
  // What the last read of the state file (Restore, RestoreLastArchive) found
  // damaged, where the damaged file was kept and what was recovered and
  // lost; "" when it was intact.
  std::string StateDamage() const;

  enum class Outcome { kAccepted, kDuplicate, kNoBoard, kRejected };
  // Adds a STEREO_CORNERS message: accepted (and saved), a near duplicate of
  // an accepted view, no board in either camera, or rejected (*why says why:
  // an image size that changed, a board id that changed).
  Outcome Add(const widestereo::stereo_corners_t& msg, std::string* why = nullptr);
  // Archives every view and starts with none; returns where they went (the
  // archive file, "memory", or "" when there was no view to archive).
  // `wall_us` (microseconds since the epoch) names the archive file.
  std::string Reset(int64_t wall_us);
  // Replaces the views with those of the newest archive (the current ones,
  // if any, are archived first); returns the archive it read. Throws
  // std::runtime_error when there is no archive or a file cannot be moved.
  std::string RestoreLastArchive(int64_t wall_us);

  // Takes the view of STEREO_CORNERS frame `frame_id` (of that `utime`
  // when given: frame ids start again when stereo-capture does) out of the
  // session and its state file; returns where the view was kept (the
  // removed-views file, or "" without a state file). Throws
  // std::invalid_argument when no view or several match, std::runtime_error
  // when a file cannot be written (then nothing changed).
  std::string Remove(int64_t frame_id, std::optional<int64_t> utime);

  // The views, and with `frame_ids` and `utimes` the STEREO_CORNERS frame
  // id and utime of each.
  StereoData Data(std::vector<int64_t>* frame_ids = nullptr, std::vector<int64_t>* utimes = nullptr) const;
  // CALIBRATION_VIEWS without RMS (calib/node/view_summary.h).
  widestereo::calibration_views_t Views(int64_t utime) const;
  int views() const;
  int duplicates() const;
  widestereo::calibration_status_t Status(int64_t utime, const std::string& state,
                                          double rms) const;

 private:
  Outcome AddLocked(const widestereo::stereo_corners_t& msg, std::string* why, bool save);
  // Adds the views of the state file; a damaged one is archived first and
  // replaced by its intact events (`wall_us` names the archive).
  int ReadStateLocked(int64_t wall_us);
  void OpenStateForAppend();
  // Appends `msg` to `log` as event `eventnum`; false when it could not be written.
  static bool WriteView(lcm::LogFile& log, const widestereo::stereo_corners_t& msg, int64_t eventnum);
  void ClearLocked();
  // Renames the state file to a new archive; returns the archive's path.
  std::string ArchiveStateLocked(int64_t wall_us);
  // Gives the state file a new archive's name too (STATE-<kind><time>);
  // returns it.
  std::string ArchiveLocked(const std::string& kind, int64_t wall_us);
  // The archives of the state file, oldest first.
  std::vector<std::string> ArchiveFiles() const;

  SessionOptions options_;
  mutable std::mutex mutex_;
  StereoData data_;
  std::string board_id_;
  CoverageGrid left_grid_, right_grid_;
  int duplicates_ = 0;
  std::unique_ptr<lcm::LogFile> state_;
  int64_t state_events_ = 0;
  std::string state_damage_;
  std::vector<widestereo::stereo_corners_t> accepted_;  // the views' messages, in order
  std::vector<std::vector<widestereo::stereo_corners_t>> memory_archives_;  // without a state file
};

}  // namespace ws::calib
