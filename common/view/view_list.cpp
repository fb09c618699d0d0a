#include "view/view_list.h"

#include <nlohmann/json.hpp>

#include "view/page_events.h"

namespace ws::view {
namespace {

using nlohmann::json;

json Outline(const float (&outline)[4][2]) {
  json points = json::array();
  for (const auto& p : outline) points.push_back({p[0], p[1]});
  return points;
}

json Rms(double rms) { return rms < 0 ? json(nullptr) : json(rms); }

}  // namespace

void ViewList::Found(const widestereo::stereo_frame_t& thumbnail) {
  const Key key{thumbnail.frame_id, thumbnail.utime};
  if (candidates_.count(key) || thumbnails_.count(key)) return;
  candidates_[key] = std::make_shared<const Blob>(ImageJpeg(thumbnail.left, kThumbnailWidth));
  candidate_order_.push_back(key);
  if (candidate_order_.size() > kCandidatesKept) {
    candidates_.erase(candidate_order_.front());
    candidate_order_.pop_front();
  }
}

std::string ViewList::Thumbnail(const Key& key) {
  if (const auto found = thumbnails_.find(key); found != thumbnails_.end()) return found->second;
  const auto candidate = candidates_.find(key);
  if (candidate == candidates_.end()) return "";
  const std::string src = blobs_.Put("thumbnail", kThumbnailsKept, *candidate->second);
  candidates_.erase(candidate);  // its order entry goes in turn, finding nothing
  thumbnails_[key] = src;
  made_.emplace_back(key, src);
  if (made_.size() > kThumbnailsKept) {  // the store has just forgotten it
    const auto& [oldest, oldest_src] = made_.front();
    if (const auto found = thumbnails_.find(oldest); found != thumbnails_.end() && found->second == oldest_src)
      thumbnails_.erase(found);
    made_.pop_front();
  }
  return src;
}

std::optional<ViewList::Update> ViewList::Event(const widestereo::calibration_views_t& views) {
  const json header = {{"solve_utime", views.solve_utime},
                       {"width", {views.image_width[0], views.image_width[1]}},
                       {"height", {views.image_height[0], views.image_height[1]}}};
  json whole = header, change = header;
  whole["views"] = json::array();
  change["put"] = json::array();
  change["gone"] = json::array();
  std::map<Key, std::string> sent;
  for (const auto& view : views.views) {  // oldest first
    const Key key{view.frame_id, view.frame_utime};
    const std::string thumbnail = Thumbnail(key);
    json item = {{"frame_id", view.frame_id},
                 {"utime", view.frame_utime},
                 {"left_corners", view.left_corners},
                 {"right_corners", view.right_corners},
                 {"left_outline", Outline(view.left_outline)},
                 {"right_outline", Outline(view.right_outline)},
                 {"left_rms", Rms(view.left_rms)},
                 {"right_rms", Rms(view.right_rms)},
                 {"thumbnail", thumbnail.empty() ? json(nullptr) : json(thumbnail)}};
    std::string text = item.dump();
    if (const auto last = last_views_.find(key); last == last_views_.end() || last->second != text)
      change["put"].push_back(item);
    whole["views"].insert(whole["views"].begin(), std::move(item));
    sent[key] = std::move(text);
  }
  for (const auto& [key, text] : last_views_)
    if (!sent.count(key)) {
      change["gone"].push_back({key.first, key.second});
      thumbnails_.erase(key);  // removed, or reset: not shown again
    }
  const std::string header_text = header.dump();
  if (change["put"].empty() && change["gone"].empty() && header_text == last_header_) return std::nullopt;
  last_header_ = header_text;
  last_views_ = std::move(sent);
  return Update{whole.dump(), change.dump()};
}

}  // namespace ws::view
