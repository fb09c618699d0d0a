// The one rule by which the plain command makes every choice
// (docs/calibration.md, "One rule for every choice"): the model, the
// B-spline's knots, the board's bow, the sensor tilt, the non-radial field.
//
// Each choice is a list of candidates in order of complexity, each solved
// and cross-validated on the same corners and the same folds (heldout.h;
// outliers are part of each candidate's fit, never a criterion between
// them). The rule is parsimony under held-out error: the simplest
// candidate is chosen first; each richer one, in order, takes its place
// only where it beats the one chosen so far by more than the folds' own
// spread: their mean held-out RMS difference, paired fold by fold (the
// pairing cancels what the folds share: which views, how noisy), larger
// than its standard error over the K folds,
//
//   mean_k(c_k - e_k) > sd_k(e_k - c_k) / sqrt(K).
#pragma once

#include <string>
#include <vector>

namespace ws::calib {

struct Candidate {
  std::string name;         // "kb4", "16 knots", "the bow", "a 16 x 10 field (smoothness 1.000)"
  int parameters = 0;       // its estimated parameters (the order of complexity)
  double heldout_rms_px = -1;
  std::vector<double> fold_rms_px;  // per fold, the same folds for every candidate
  int corners = 0;                  // held-out corners scored
  std::string failed;               // why it has no score ("" when scored)
  // Filled by Select: the candidate it was compared with (-1: none, the
  // first scored), its mean held-out RMS difference to it, fold by fold
  // (negative: better), and their spread (above).
  int against = -1;
  double excess_px = 0, spread_px = 0;
};

// One choice made: the candidates as solved, which scored best, which won
// and why.
struct Selection {
  std::string camera;  // "left", "right"; "" for the rig (both pooled)
  std::string choice;  // "model", "knots", "board bow", "sensor tilt", "field"
  std::vector<Candidate> candidates;  // in order of complexity
  int best = -1;       // the lowest mean held-out RMS; -1: none scored
  int chosen = -1;     // by the rule; -1: none scored
  std::string why;
};

// The rule above over `candidates` (in order of complexity); a candidate
// whose folds are fewer than the first scored one's is not comparable and
// counts as failed. None scored: chosen -1.
Selection Select(std::string camera, std::string choice, std::vector<Candidate> candidates);

// How finely a candidate's held-out RMS over n corners resolves a model's
// error at all, rms / (2 sqrt(n)) (|e|^2 of a Gaussian corner has a
// standard deviation equal to its mean: a gain below it could not be seen
// on a fresh set of as many corners); 0 without held-out corners.
double Resolution(const Candidate& candidate);

// The selection as lines for the terminal and the log: the candidates with
// their held-out RMS and fold spread, then the winner and why.
std::vector<std::string> SelectionLines(const Selection& selection);

}  // namespace ws::calib
