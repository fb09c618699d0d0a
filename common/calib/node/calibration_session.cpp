#include "calib/node/calibration_session.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <vector>

#include "calib/node/corners_message.h"
#include "calib/node/view_summary.h"
#include "calib/solver/corner_noise.h"
#include "lcm_io/channels.h"
#include "lcm_io/decode.h"
#include "lcm_io/lcm_log.h"
#include "runtime/atomic_file.h"
#include "runtime/escaped.h"
#include "runtime/wall_clock.h"

namespace ws::calib {
namespace {

namespace fs = std::filesystem;

// "20261201T195600.123456Z": the UTC time of `wall_us`, sorting as it runs.
std::string ArchiveTime(int64_t wall_us) {
  const std::time_t seconds = std::time_t(wall_us / 1000000);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  const size_t n = std::strftime(text, sizeof text, "%Y%m%dT%H%M%S", &utc);
  std::snprintf(text + n, sizeof text - n, ".%06lldZ", (long long)(wall_us % 1000000));
  return text;
}
constexpr size_t kArchiveTimeChars = 23;

// views.lcmlog -> views-<kind><time>.lcmlog, beside it.
fs::path ArchivePath(const fs::path& state, const std::string& kind, int64_t wall_us) {
  return state.parent_path() /
         (state.stem().string() + "-" + kind + ArchiveTime(wall_us) + state.extension().string());
}

// A damaged state file's archive says so, and is never taken for one of
// reset's (ArchiveFiles: their names are shorter).
constexpr const char* kDamaged = "damaged-";

bool IsCornersEvent(const std::string& channel, const uint8_t* data, size_t size) {
  if (channel != channel::kStereoCorners) return false;
  try {
    DecodeMessage<widestereo::stereo_corners_t>(data, int(size));
    return true;
  } catch (const DecodeError&) {
    return false;
  }
}

}  // namespace

CalibrationSession::CalibrationSession(SessionOptions options)
    : options_(std::move(options)),
      left_grid_(options_.grid_rows, options_.grid_cols),
      right_grid_(options_.grid_rows, options_.grid_cols) {}

CalibrationSession::~CalibrationSession() = default;

int CalibrationSession::Restore() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (options_.state_path.empty()) return 0;
  const int restored = ReadStateLocked(WallMicros());
  OpenStateForAppend();
  return restored;
}

int CalibrationSession::ReadStateLocked(int64_t wall_us) {
  const std::string& path = options_.state_path;
  state_events_ = 0;
  state_damage_.clear();
  if (!fs::exists(path)) return 0;
  const LcmLogRecovery log = RecoverLcmLog(path, IsCornersEvent);
  std::string archive, not_rewritten;
  if (!log.intact()) {
    // The damaged file is kept as it is, and the views continue in a new
    // one holding every intact event: what follows the damage is not lost.
    // Where the new one cannot be written (the disk that cut the old one
    // short is still full), the views continue after the damage, which the
    // next start passes over again: the process starts all the same.
    archive = ArchiveLocked(kDamaged, wall_us);
    try {
      WriteFileAtomically(path, EncodeLcmLog(log.events));
    } catch (const std::runtime_error& e) {
      not_rewritten = std::string("; it could not be written again without the damage (") + e.what() +
                      "): new views follow the damage";
    }
  }
  int restored = 0;
  for (const LcmLogEvent& event : log.events) {
    const auto msg = DecodeMessage<widestereo::stereo_corners_t>(event.data.data(), int(event.data.size()));
    if (AddLocked(msg, nullptr, false) == Outcome::kAccepted) ++restored;
  }
  state_events_ = int64_t(log.events.size());
  if (!log.intact())
    state_damage_ = "the views file " + Quoted(path) + " was damaged (" + log.first_damage + ") and is kept as " +
                    Quoted(archive) + ": intact events recovered: " + std::to_string(log.events.size()) + " (" +
                    std::to_string(restored) + " views restored); events lost: " + std::to_string(log.lost_events) +
                    " (" + std::to_string(log.lost_bytes) + " of " + std::to_string(log.file_bytes) + " bytes)" +
                    not_rewritten;
  return restored;
}

std::string CalibrationSession::StateDamage() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_damage_;
}

void CalibrationSession::OpenStateForAppend() {
  state_.reset();
  if (options_.state_path.empty()) return;
  const auto parent = std::filesystem::path(options_.state_path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  state_ = std::make_unique<lcm::LogFile>(options_.state_path, "a");
  if (!state_->good()) {
    state_.reset();
    throw std::runtime_error("cannot write the state file " + options_.state_path);
  }
}

CalibrationSession::Outcome CalibrationSession::Add(const widestereo::stereo_corners_t& msg,
                                                    std::string* why) {
  std::lock_guard<std::mutex> lock(mutex_);
  return AddLocked(msg, why, true);
}

CalibrationSession::Outcome CalibrationSession::AddLocked(const widestereo::stereo_corners_t& msg,
                                                          std::string* why, bool save) {
  if (msg.left.n <= 0 && msg.right.n <= 0) return Outcome::kNoBoard;
  if (data_.size() >= options_.max_views) {
    if (why)
      *why = "the session holds its maximum of " + std::to_string(options_.max_views) +
             " views (--max-views); 'reset' archives them and starts again";
    return Outcome::kRejected;
  }
  for (const auto* side : {&msg.left, &msg.right}) {
    if (side->n <= 0) continue;
    if (board_id_.empty()) board_id_ = side->board_id;
    if (side->board_id != board_id_) {
      if (why)
        *why = "board '" + side->board_id + "' differs from the board so far, '" + board_id_ + "'";
      return Outcome::kRejected;
    }
  }
  StereoData probe = data_;
  try {
    AddStereoCorners(probe, msg);
  } catch (const CalibrationError& e) {
    if (why) *why = e.what();
    return Outcome::kRejected;
  }
  const BoardView left = ToBoardView(msg.left), right = ToBoardView(msg.right);
  // A board held still moves its corners by about their noise (corner_noise.h).
  auto threshold = [&](const BoardView& view) {
    return options_.duplicate_px > 0 ? options_.duplicate_px : kStillBoard * CornerNoise(view);
  };
  const double left_px = threshold(left), right_px = threshold(right);
  // A view adds nothing when each camera's corners are absent or a near
  // duplicate of that camera's corners in one view already accepted.
  auto covered = [](const BoardView& view, const BoardView& old, double px) {
    return view.empty() || (!old.empty() && NearDuplicate(view, old, px));
  };
  for (int v = 0; v < data_.size(); ++v) {
    if (covered(left, data_.left.views[v], left_px) &&
        covered(right, data_.right.views[v], right_px)) {
      ++duplicates_;
      return Outcome::kDuplicate;
    }
  }
  data_ = std::move(probe);
  accepted_.push_back(msg);
  left_grid_.Add(left, data_.left.image_width, data_.left.image_height);
  right_grid_.Add(right, data_.right.image_width, data_.right.image_height);
  if (save && state_ && !WriteView(*state_, msg, state_events_++) && why)
    *why = "could not save the view to " + options_.state_path;
  return Outcome::kAccepted;
}

bool CalibrationSession::WriteView(lcm::LogFile& log, const widestereo::stereo_corners_t& msg, int64_t eventnum) {
  std::vector<uint8_t> bytes = EncodeMessage(msg);
  lcm::LogEvent event;
  event.eventnum = eventnum;
  event.timestamp = msg.utime;
  event.channel = channel::kStereoCorners;
  event.datalen = int32_t(bytes.size());
  event.data = bytes.data();
  return log.writeEvent(&event) == 0 && std::fflush(log.getFilePtr()) == 0;
}

std::string CalibrationSession::Remove(int64_t frame_id, std::optional<int64_t> utime) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<size_t> found;
  for (size_t i = 0; i < accepted_.size(); ++i)
    if (accepted_[i].frame_id == frame_id && (!utime || accepted_[i].utime == *utime)) found.push_back(i);
  const std::string name =
      "frame " + std::to_string(frame_id) + (utime ? " of utime " + std::to_string(*utime) : std::string());
  if (found.empty()) throw std::invalid_argument("no view of " + name);
  if (found.size() > 1)
    throw std::invalid_argument(std::to_string(found.size()) + " views of " + name + ": name its utime too");
  std::vector<widestereo::stereo_corners_t> kept = accepted_;
  kept.erase(kept.begin() + std::ptrdiff_t(found[0]));
  std::string removed_file;
  if (!options_.state_path.empty()) {
    // The view is kept first, then the state file replaced whole: a crash
    // in between leaves the view in both files, never in neither.
    const fs::path state(options_.state_path);
    removed_file = (state.parent_path() / (state.stem().string() + "-removed" + state.extension().string())).string();
    lcm::LogFile removed(removed_file, "a");
    if (!removed.good() || !WriteView(removed, accepted_[found[0]], 0))
      throw std::runtime_error("cannot keep the removed view in " + Quoted(removed_file));
    std::vector<LcmLogEvent> events;
    for (const auto& msg : kept) events.push_back({0, msg.utime, channel::kStereoCorners, EncodeMessage(msg)});
    state_.reset();
    try {
      WriteFileAtomically(options_.state_path, EncodeLcmLog(events));
    } catch (...) {
      OpenStateForAppend();
      throw;
    }
    OpenStateForAppend();
    state_events_ = int64_t(kept.size());
  }
  const int duplicates = duplicates_;
  ClearLocked();
  for (const auto& msg : kept) AddLocked(msg, nullptr, false);
  duplicates_ = duplicates;
  return removed_file;
}

std::string CalibrationSession::Reset(int64_t wall_us) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (accepted_.empty()) return "";
  std::string where = "memory";
  if (options_.state_path.empty()) {
    memory_archives_.push_back(accepted_);
  } else {
    where = ArchiveStateLocked(wall_us);
    OpenStateForAppend();
  }
  ClearLocked();
  return where;
}

std::string CalibrationSession::RestoreLastArchive(int64_t wall_us) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (options_.state_path.empty()) {
    if (memory_archives_.empty()) throw std::runtime_error("no archived views to restore (no reset yet)");
    const std::vector<widestereo::stereo_corners_t> views = std::move(memory_archives_.back());
    memory_archives_.pop_back();
    if (!accepted_.empty()) memory_archives_.push_back(accepted_);
    ClearLocked();
    for (const auto& msg : views) AddLocked(msg, nullptr, false);
    return "memory";
  }
  const std::vector<std::string> archives = ArchiveFiles();
  if (archives.empty()) throw std::runtime_error("no archive of " + options_.state_path + " to restore (no reset yet)");
  if (!accepted_.empty()) {
    ArchiveStateLocked(wall_us);
  } else {
    state_.reset();
    fs::remove(options_.state_path);
  }
  fs::rename(archives.back(), options_.state_path);
  ClearLocked();
  ReadStateLocked(wall_us);
  OpenStateForAppend();
  return archives.back();
}

void CalibrationSession::ClearLocked() {
  data_ = StereoData();
  board_id_.clear();
  left_grid_ = CoverageGrid(options_.grid_rows, options_.grid_cols);
  right_grid_ = CoverageGrid(options_.grid_rows, options_.grid_cols);
  duplicates_ = 0;
  accepted_.clear();
}

std::string CalibrationSession::ArchiveStateLocked(int64_t wall_us) {
  state_.reset();
  const std::string archive = ArchiveLocked("", wall_us);
  fs::remove(options_.state_path);
  state_events_ = 0;
  return archive;
}

// link(2) gives the file its archive's name without ever replacing a file
// that has it (an earlier archive), and leaves the state file in place until
// the caller replaces or removes it: a crash in between loses nothing.
std::string CalibrationSession::ArchiveLocked(const std::string& kind, int64_t wall_us) {
  for (;; ++wall_us) {
    const std::string archive = ArchivePath(options_.state_path, kind, wall_us).string();
    if (link(options_.state_path.c_str(), archive.c_str()) == 0) return archive;
    if (errno != EEXIST)
      throw std::runtime_error("cannot keep " + Quoted(options_.state_path) + " as " + Quoted(archive) + ": " +
                               std::strerror(errno));
  }
}

std::vector<std::string> CalibrationSession::ArchiveFiles() const {
  const fs::path state(options_.state_path);
  const fs::path folder = state.parent_path().empty() ? fs::path(".") : state.parent_path();
  const std::string prefix = state.stem().string() + "-", suffix = state.extension().string();
  std::vector<std::string> archives;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.size() == prefix.size() + kArchiveTimeChars + suffix.size() && name.rfind(prefix, 0) == 0 &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      archives.push_back((state.parent_path() / name).string());
  }
  std::sort(archives.begin(), archives.end());
  return archives;
}

StereoData CalibrationSession::Data(std::vector<int64_t>* frame_ids, std::vector<int64_t>* utimes) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& msg : accepted_) {
    if (frame_ids) frame_ids->push_back(msg.frame_id);
    if (utimes) utimes->push_back(msg.utime);
  }
  return data_;
}

widestereo::calibration_views_t CalibrationSession::Views(int64_t utime) const {
  std::lock_guard<std::mutex> lock(mutex_);
  widestereo::calibration_views_t msg{};
  msg.utime = utime;
  const CameraData* cameras[2] = {&data_.left, &data_.right};
  for (int c = 0; c < 2; ++c) {
    msg.image_width[c] = cameras[c]->image_width;
    msg.image_height[c] = cameras[c]->image_height;
  }
  for (const auto& view : accepted_) msg.views.push_back(ViewSummary(view));
  msg.nviews = int32_t(msg.views.size());
  return msg;
}

int CalibrationSession::views() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return data_.size();
}

int CalibrationSession::duplicates() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return duplicates_;
}

widestereo::calibration_status_t CalibrationSession::Status(int64_t utime, const std::string& state,
                                                            double rms) const {
  std::lock_guard<std::mutex> lock(mutex_);
  CoverageStatus c;
  for (int v = 0; v < data_.size(); ++v) {
    const bool l = !data_.left.views[v].empty(), r = !data_.right.views[v].empty();
    c.views_left += l;
    c.views_right += r;
    c.views_stereo += l && r;
  }
  c.left = left_grid_;
  c.right = right_grid_;
  widestereo::calibration_status_t msg;
  msg.utime = utime;
  msg.state = state;
  msg.views_left = c.views_left;
  msg.views_right = c.views_right;
  msg.views_stereo = c.views_stereo;
  msg.grid_rows = options_.grid_rows;
  msg.grid_cols = options_.grid_cols;
  for (const auto* grid : {&left_grid_, &right_grid_}) {
    auto& out = grid == &left_grid_ ? msg.coverage_left : msg.coverage_right;
    out.assign(options_.grid_rows, std::vector<int32_t>(options_.grid_cols, 0));
    for (int r = 0; r < options_.grid_rows; ++r)
      for (int col = 0; col < options_.grid_cols; ++col)
        out[r][col] = grid->count.empty() ? 0 : grid->count[r * options_.grid_cols + col];
  }
  msg.rms = rms;
  msg.heldout_rms = -1;  // the node's, after a solve
  msg.hint = CoverageHint(c, options_.min_views);
  return msg;
}

}  // namespace ws::calib
