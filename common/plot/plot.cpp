#include "plot/plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

extern char** environ;

namespace ws::plot {
namespace {

namespace fs = std::filesystem;

// Okabe & Ito's colour-blind-safe palette.
const char* const kPalette[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                "#e69f00", "#56b4e9", "#000000", "#f0e442"};

// A gnuplot string: single-quoted ('' stands for '), or double-quoted with
// \n for each line break when the text has several lines.
std::string Quote(const std::string& text) {
  if (text.find('\n') != std::string::npos) {
    std::string quoted = "\"";
    for (char c : text) {
      if (c == '\n')
        quoted += "\\n";
      else if (c == '"' || c == '\\')
        quoted += std::string("\\") + c;
      else
        quoted += c;
    }
    return quoted + "\"";
  }
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

// A fresh directory under the system's temporary directory, removed with
// everything in it when this goes out of scope.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "ws-plot-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw PlotError(std::string("cannot create a temporary directory: ") + std::strerror(errno));
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// Runs gnuplot with the arguments, its output going to log; its exit status.
int RunGnuplot(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<char*> argv{const_cast<char*>("gnuplot")};
  for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid;
  const int error = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error == ENOENT)
    throw PlotError("gnuplot is not on PATH; install it (Debian: apt-get install gnuplot-nox)");
  if (error != 0) throw PlotError(std::string("cannot run gnuplot: ") + std::strerror(error));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw PlotError(std::string("waiting for gnuplot: ") + std::strerror(errno));
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// "pngcairo" where gnuplot has it, else "png"; asked once per process.
const std::string& PngTerminal(const TempDir& dir) {
  static const std::string terminal =
      RunGnuplot({"-e", "set terminal pngcairo"}, dir / "probe.log") == 0 ? "pngcairo" : "png";
  return terminal;
}

std::string SeriesStyle(const Series& series, int index) {
  const std::string color =
      series.color.empty() ? kPalette[index % std::size(kPalette)] : series.color;
  std::ostringstream style;
  const bool lines = series.style != Style::kPoints, points = series.style != Style::kLines;
  style << "with " << (lines && points ? "linespoints" : lines ? "lines" : "points");
  if (lines) style << " lw " << series.line_width;
  if (points) style << " pt " << series.point_type << " ps " << series.point_size;
  style << " lc rgb " << Quote(color);
  style << (series.title.empty() ? " notitle" : " title " + Quote(series.title));
  return style.str();
}

void WriteData(const Series& series, const fs::path& path) {
  if (series.x.size() != series.y.size())
    throw PlotError("series '" + series.title + "' has " + std::to_string(series.x.size()) +
                    " x but " + std::to_string(series.y.size()) + " y values");
  std::ofstream out(path);
  out.precision(17);
  for (size_t i = 0; i < series.x.size(); ++i) out << series.x[i] << ' ' << series.y[i] << '\n';
  if (!out) throw PlotError("cannot write " + path.string());
}

bool HasMissing(const Heatmap& map) {
  return std::any_of(map.values.begin(), map.values.end(), [](double v) { return !std::isfinite(v); });
}

// The heat map's data file (gnuplot's `with image`: x y value, a blank
// line after each row) and its plot clause.
std::string HeatmapPlot(const Heatmap& map, const fs::path& path) {
  if (map.cols <= 0 || map.rows <= 0 || map.values.size() != size_t(map.cols) * map.rows)
    throw PlotError("heat map of " + std::to_string(map.cols) + " x " + std::to_string(map.rows) +
                    " cells has " + std::to_string(map.values.size()) + " values");
  std::ofstream out(path);
  out.precision(17);
  for (int j = 0; j < map.rows; ++j) {
    for (int i = 0; i < map.cols; ++i) {
      const double v = map.values[size_t(j) * map.cols + i];
      out << map.x0 + i * map.dx << ' ' << map.y0 + j * map.dy << ' ';
      if (std::isfinite(v))
        out << v << '\n';
      else
        out << "NaN\n";
    }
    out << '\n';
  }
  if (!out) throw PlotError("cannot write " + path.string());
  std::string plot = Quote(path.string()) + " using 1:2:3 with image notitle";
  if (HasMissing(map))
    plot += ", " + Quote(path.string()) + " using 1:($3 != $3 ? $2 : 1/0):(" + std::to_string(map.dx / 2) + "):(" +
            std::to_string(map.dy / 2) + ") with boxxyerror fill solid 1.0 noborder lc rgb '#9a9a9a' notitle";
  return plot;
}

// The gnuplot commands drawing one panel, writing its data files.
std::string PanelScript(const Panel& panel, int panel_index, const TempDir& dir) {
  std::ostringstream script;
  script << "set title " << Quote(panel.title) << "\n"
         << "set xlabel " << Quote(panel.x_label) << "\n"
         << "set ylabel " << Quote(panel.y_label) << "\n"
         << "set autoscale xy\nset xrange [*:*] noreverse\nset yrange [*:*] noreverse\n"
         << "unset colorbox\nset size noratio\n";
  if (panel.image_axes)  // the axes end where the data do (the image's edges)
    script << "set autoscale xfix\nset autoscale yfix\nset yrange [*:*] reverse\n"
           << "set size ratio -1\n";
  std::string plots;
  if (panel.heatmap) {
    const Heatmap& map = *panel.heatmap;
    script << "set colorbox\nset cblabel " << Quote(map.label + (HasMissing(map) ? "; grey: " + map.missing : ""))
           << "\n"
           << "set palette cubehelix negative\n"
           << "set cbrange [0:";
    if (std::isfinite(map.max) && map.max > 0)
      script << map.max;
    else
      script << "*";
    script << "]\n";
    plots = "plot " + HeatmapPlot(map, dir / ("panel" + std::to_string(panel_index) + "_map.dat"));
  }
  const long entries = std::count_if(panel.series.begin(), panel.series.end(),
                                     [](const Series& series) { return !series.title.empty(); });
  script << "set bmargin -1\n";
  if (panel.legend == "off" || entries == 0) {
    script << "unset key\n";
  } else if (panel.legend.find("below") != std::string::npos) {
    // Below the axis label, in two columns: the bottom margin made room for
    // its rows (gnuplot's own margin lets the key run over the x label).
    script << "set key below Left reverse box opaque samplen 3 spacing 1.2 maxcols 2\n"
           << "set bmargin " << 4 + int(std::ceil(1.3 * ((entries + 1) / 2))) << "\n";
  } else {
    script << "set key inside " << panel.legend << " Left reverse box opaque samplen 3 spacing 1.2\n";
  }
  script << (panel.zero_line ? "set xzeroaxis lt -1 lw 1\n" : "unset xzeroaxis\n");
  for (size_t i = 0; i < panel.series.size(); ++i) {
    const Series& series = panel.series[i];
    if (series.x.empty()) continue;
    const fs::path data = dir / ("panel" + std::to_string(panel_index) + "_series" +
                                 std::to_string(i) + ".dat");
    WriteData(series, data);
    plots += (plots.empty() ? "plot " : ", \\\n     ") + Quote(data.string()) + " using 1:2 " +
             SeriesStyle(series, static_cast<int>(i));
  }
  if (plots.empty()) throw PlotError("panel '" + panel.title + "' has no data");
  script << plots << "\n";
  return script.str();
}

}  // namespace

void WritePng(const Figure& figure, const std::string& png_path) {
  if (figure.panels.empty()) throw PlotError("figure '" + figure.title + "' has no panels");
  if (figure.columns < 1 || figure.width < 16 || figure.height < 16)
    throw PlotError("figure needs at least one column and a size of at least 16 x 16 pixels");
  const TempDir dir;
  const int rows = (static_cast<int>(figure.panels.size()) + figure.columns - 1) / figure.columns;
  std::ostringstream script;
  script << "set terminal " << PngTerminal(dir) << " size " << figure.width << ","
         << figure.height << " noenhanced font 'Sans,11'\n"
         << "set output " << Quote(png_path) << "\n"
         << "set encoding utf8\n"
         << "set grid lc rgb '#d0d0d0'\n"
         << "set tics out nomirror\n"
         << "set border 3\n"
         << "set multiplot layout " << rows << "," << figure.columns << " title "
         << Quote(figure.title) << " font ',14'\n";
  for (size_t i = 0; i < figure.panels.size(); ++i)
    script << PanelScript(figure.panels[i], static_cast<int>(i), dir);
  script << "unset multiplot\n";
  const fs::path script_path = dir / "figure.gp";
  if (!(std::ofstream(script_path) << script.str()))
    throw PlotError("cannot write " + script_path.string());
  std::error_code ignored;
  fs::remove(png_path, ignored);
  const fs::path log = dir / "gnuplot.log";
  if (RunGnuplot({script_path.string()}, log) != 0)
    throw PlotError("gnuplot failed drawing " + png_path + ":\n" + ReadText(log));
  if (!fs::exists(png_path) || fs::file_size(png_path) == 0)
    throw PlotError("gnuplot wrote no image to " + png_path + ":\n" + ReadText(log));
}

}  // namespace ws::plot
