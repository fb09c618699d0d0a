#include "calib/evaluate/selection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "calib/solver/stage_log.h"

namespace ws::calib {
namespace {

double Mean(const std::vector<double>& x) {
  return x.empty() ? 0.0 : std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
}

// A candidate's held-out RMS as the lines show it: its pooled RMS, or why
// it has none.
std::string Score(const Candidate& c) {
  return c.failed.empty() ? Fixed(c.heldout_rms_px) + " px" : "not scored: " + c.failed;
}

}  // namespace

double Resolution(const Candidate& c) {
  return c.corners > 0 ? c.heldout_rms_px / (2.0 * std::sqrt(double(c.corners))) : 0.0;
}

Selection Select(std::string camera, std::string choice, std::vector<Candidate> candidates) {
  Selection s;
  s.camera = std::move(camera);
  s.choice = std::move(choice);
  s.candidates = std::move(candidates);
  std::vector<Candidate>& c = s.candidates;
  size_t folds = 0;
  for (const Candidate& candidate : c)
    if (candidate.failed.empty() && !candidate.fold_rms_px.empty()) {
      folds = candidate.fold_rms_px.size();
      break;
    }
  for (Candidate& candidate : c)
    if (candidate.failed.empty() && (folds == 0 || candidate.fold_rms_px.size() != folds))
      candidate.failed = "not every fold could be solved";
  for (size_t i = 0; i < c.size(); ++i)
    if (c[i].failed.empty() && (s.best < 0 || Mean(c[i].fold_rms_px) < Mean(c[s.best].fold_rms_px)))
      s.best = int(i);
  if (s.best < 0) {
    s.why = "no candidate could be scored";
    return s;
  }
  // Each candidate against the one chosen so far, the simplest first: a
  // richer one takes its place only where it beats it by more than the
  // spread of the two.
  auto compare = [&](int rich, int simple) {
    std::vector<double> d(folds);
    for (size_t k = 0; k < folds; ++k) d[k] = c[rich].fold_rms_px[k] - c[simple].fold_rms_px[k];
    const double m = Mean(d);
    double var = 0;
    for (double x : d) var += (x - m) * (x - m);
    const double se = folds > 1 ? std::sqrt(var / double(folds - 1) / double(folds)) : 0.0;
    c[rich].excess_px = m;  // negative: better than the one it was compared with
    c[rich].spread_px = se;
    return -m > c[rich].spread_px;
  };
  for (size_t i = 0; i < c.size(); ++i) {
    if (!c[i].failed.empty()) continue;
    if (s.chosen < 0) {
      s.chosen = int(i);
      continue;
    }
    const int against = s.chosen;
    if (compare(int(i), against)) s.chosen = int(i);
    c[i].against = against;
  }
  const Candidate& chosen = c[s.chosen];
  const Candidate& best = c[s.best];
  if (chosen.against < 0)
    s.why = chosen.name + " is the simplest, and no richer candidate beats it by more than the spread";
  else
    s.why = chosen.name + " beats " + c[chosen.against].name + " by " + Fixed(-chosen.excess_px) +
            " px, more than the spread " + Fixed(chosen.spread_px) + " px, and no richer candidate beats it by more";
  if (s.best != s.chosen)
    s.why += " (the lowest held-out RMS is " + best.name + "'s, " + Fixed(best.heldout_rms_px) + " px)";
  return s;
}

std::vector<std::string> SelectionLines(const Selection& s) {
  const std::string head = (s.camera.empty() ? "" : s.camera + " camera, ") + s.choice;
  std::vector<std::string> lines;
  for (size_t i = 0; i < s.candidates.size(); ++i) {
    const Candidate& c = s.candidates[i];
    std::string line = head + ": " + c.name +
                       (c.parameters > 0 ? " (" + std::to_string(c.parameters) + " parameters)" : "") +
                       ": held-out " + Score(c);
    if (c.failed.empty() && c.against >= 0)
      line += ", " + std::string(c.excess_px < 0 ? "" : "+") + Fixed(c.excess_px) + " px against " +
              s.candidates[size_t(c.against)].name + ", spread " + Fixed(c.spread_px) + " px";
    if (int(i) == s.chosen) line += "  <- chosen";
    lines.push_back(line);
  }
  lines.push_back(head + ": " + (s.chosen >= 0 ? s.candidates[s.chosen].name + " chosen: " : "") +
                  s.why);
  return lines;
}

}  // namespace ws::calib
