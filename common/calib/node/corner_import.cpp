#include "calib/node/corner_import.h"

#include <cmath>
#include <optional>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "calib/node/glob_captures.h"

namespace ws::calib {
namespace {

// Lines of a text file with their numbers; throws when it cannot be read.
class Lines {
 public:
  explicit Lines(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw CornerImportError(path + ": cannot be read");
  }
  bool Next(std::string* line) {
    if (!std::getline(in_, *line)) return false;
    ++number_;
    if (!line->empty() && line->back() == '\r') line->pop_back();
    return true;
  }
  [[noreturn]] void Fail(const std::string& why) const {
    throw CornerImportError(path_ + ":" + std::to_string(number_) + ": " + why);
  }

 private:
  std::string path_;
  std::ifstream in_;
  int number_ = 0;
};

// The comma-separated numbers of a line, exactly `count` of them, finite.
std::vector<double> Numbers(const Lines& lines, const std::string& line, size_t count) {
  std::vector<double> out;
  std::stringstream fields(line);
  for (std::string field; std::getline(fields, field, ',');) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(field, &used);
    } catch (const std::exception&) {
      lines.Fail("'" + field + "' is not a number");
    }
    if (field.find_first_not_of(" \t", used) != std::string::npos || !std::isfinite(value))
      lines.Fail("'" + field + "' is not a number");
    out.push_back(value);
  }
  if (out.size() != count)
    lines.Fail(std::to_string(count) + " comma-separated numbers expected, got " +
               std::to_string(out.size()));
  return out;
}

// Every corner of `view` inside the image of width x height (pixel centres
// at integer coordinates: [-0.5, width - 0.5] x [-0.5, height - 0.5]);
// throws naming `where` and the corner otherwise (x = 99999 or 1e308 would
// reach the solve as a "collinear" board).
void RequireInImage(const BoardView& view, int width, int height, const std::string& where) {
  for (size_t i = 0; i < view.image.size(); ++i) {
    const Eigen::Vector2d& p = view.image[i];
    if (!(p.x() >= -0.5 && p.x() <= width - 0.5 && p.y() >= -0.5 && p.y() <= height - 0.5))
      throw CornerImportError(where + ": corner " + std::to_string(view.ids[i]) + " at (" + std::to_string(p.x()) +
                              ", " + std::to_string(p.y()) + ") lies outside the " + std::to_string(width) + "x" +
                              std::to_string(height) + " image");
  }
}

int WholeNumber(const Lines& lines, double value, const char* what) {
  if (value != std::floor(value) || std::abs(value) > 1e6)
    lines.Fail(std::string(what) + " must be a whole number");
  return static_cast<int>(value);
}

// The fiducials of a .dsc target, in file order.
std::vector<Eigen::Vector3d> ReadTarget(const std::string& path) {
  Lines lines(path);
  std::string line;
  if (!lines.Next(&line)) lines.Fail("no board line");
  Numbers(lines, line, 4);
  if (!lines.Next(&line)) lines.Fail("no tag family line");
  std::vector<Eigen::Vector3d> target;
  while (lines.Next(&line)) {
    if (line.empty()) continue;
    const auto v = Numbers(lines, line, 6);
    target.emplace_back(v[3], v[4], v[5]);
  }
  if (target.empty()) lines.Fail("no fiducials");
  return target;
}

}  // namespace

CameraData ReadBabelCalibViews(const std::string& dsc_path,
                               const std::vector<std::string>& orpc_paths) {
  const auto target = ReadTarget(dsc_path);
  CameraData data;
  data.name = "left";
  for (const std::string& path : orpc_paths) {
    Lines lines(path);
    std::map<std::string, std::string> header;
    std::string line;
    BoardView view;
    while (lines.Next(&line)) {
      if (line.empty()) continue;
      const auto colon = line.find(':');
      if (colon != std::string::npos && line.find(',') == std::string::npos) {
        header[line.substr(0, colon)] = line.substr(line.find_first_not_of(' ', colon + 1));
        continue;
      }
      const auto v = Numbers(lines, line, 5);
      const int corner = WholeNumber(lines, v[1], "corner index");
      if (corner < 0 || corner >= static_cast<int>(target.size()))
        lines.Fail("corner " + std::to_string(corner) + " is not a fiducial of the target (0 to " +
                   std::to_string(target.size() - 1) + ")");
      view.ids.push_back(corner);
      view.object.push_back(target[corner]);
      view.image.emplace_back(v[3], v[4]);
    }
    int width = 0, height = 0;
    try {
      width = std::stoi(header.at("width"));
      height = std::stoi(header.at("height"));
    } catch (const std::exception&) {
      throw CornerImportError(path + ": no width and height in the header");
    }
    if (width <= 0 || height <= 0) throw CornerImportError(path + ": image size must be positive");
    if ((data.image_width && data.image_width != width) ||
        (data.image_height && data.image_height != height))
      throw CornerImportError(path + ": image size differs from the other files'");
    RequireInImage(view, width, height, path);
    data.image_width = width;
    data.image_height = height;
    data.views.push_back(std::move(view));
  }
  return data;
}

std::vector<NamedView> ReadMrcalViews(const std::string& vnl_path, int cols, int rows, double square) {
  if (cols < 2 || rows < 2 || !(square > 0))
    throw CornerImportError(vnl_path + ": the board must have at least 2 x 2 corners and a positive square");
  Lines lines(vnl_path);
  std::vector<NamedView> views;
  std::string line;
  int index = 0;           // corner of the current image
  bool no_board = false;   // the current image is one "NAME - - -" line
  auto complete = [&] { return index == cols * rows || (index == 1 && no_board); };
  auto require_complete = [&] {
    if (index != 0 && !complete())
      lines.Fail(views.back().name + " has " + std::to_string(index) + " corners, not " +
                 std::to_string(cols * rows));
  };
  while (lines.Next(&line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, x, y, level, extra;
    if (!(fields >> name >> x >> y >> level) || (fields >> extra))
      lines.Fail("four fields expected: filename x y level");
    if (views.empty() || name != views.back().name || index == cols * rows) {
      require_complete();
      no_board = x == "-" && y == "-";
      index = 0;
      views.push_back({name, {}});
    }
    const int id = index++;
    if (x == "-" || y == "-" || level == "-") continue;
    try {
      size_t ux = 0, uy = 0;
      const Eigen::Vector2d p(std::stod(x, &ux), std::stod(y, &uy));
      if (ux != x.size() || uy != y.size() || !p.allFinite()) throw std::invalid_argument(x);
      BoardView& view = views.back().view;
      view.ids.push_back(id);
      view.object.emplace_back((id % cols) * square, (id / cols) * square, 0.0);
      view.image.push_back(p);
    } catch (const std::exception&) {
      lines.Fail("x and y must be numbers or '-'");
    }
  }
  require_complete();
  return views;
}

CameraData ReadMrcalCorners(const std::string& vnl_path, int cols, int rows, double square,
                            int image_width, int image_height, std::vector<std::string>* names) {
  if (image_width <= 0 || image_height <= 0)
    throw CornerImportError(vnl_path + ": the image size must be positive");
  CameraData data;
  data.name = "left";
  data.image_width = image_width;
  data.image_height = image_height;
  for (NamedView& named : ReadMrcalViews(vnl_path, cols, rows, square)) {
    RequireInImage(named.view, image_width, image_height, vnl_path + ": " + named.name);
    if (names) names->push_back(named.name);
    data.views.push_back(std::move(named.view));
  }
  return data;
}

PairedViews PairMrcalViews(const std::vector<NamedView>& views, const std::string& left_glob,
                           const std::string& right_glob, int image_width, int image_height) {
  if (image_width <= 0 || image_height <= 0) throw CornerImportError("the image size must be positive");
  if (GlobStars(left_glob) != GlobStars(right_glob))
    throw CornerImportError("the globs '" + left_glob + "' and '" + right_glob +
                            "' must have as many '*' as each other: their matches name the frame");
  PairedViews paired;
  std::map<std::vector<std::string>, size_t> frame_of;  // the `*` texts -> frame index
  for (const NamedView& named : views) {
    const auto left = GlobCaptures(left_glob, named.name);
    const auto right = GlobCaptures(right_glob, named.name);
    if (left && right)
      throw CornerImportError(named.name + " matches both '" + left_glob + "' and '" + right_glob + "'");
    if (!left && !right) {
      ++paired.unmatched;
      continue;
    }
    const auto [at, added] = frame_of.emplace(left ? *left : *right, paired.data.size());
    if (added) {
      paired.data.Add({}, {});
      paired.left_names.emplace_back();
      paired.right_names.emplace_back();
    }
    std::string& slot = (left ? paired.left_names : paired.right_names)[at->second];
    if (!slot.empty())
      throw CornerImportError(named.name + " and " + slot + " fall in the same frame of the " +
                              (left ? "left" : "right") + " camera");
    slot = named.name;
    RequireInImage(named.view, image_width, image_height, named.name);
    (left ? paired.data.left : paired.data.right).views[at->second] = named.view;
  }
  for (CameraData* camera : {&paired.data.left, &paired.data.right}) {
    camera->image_width = image_width;
    camera->image_height = image_height;
  }
  return paired;
}

}  // namespace ws::calib
