// Board corners refined to their saddle points (saddle_point.h) at a scale
// each corner's own image chooses, for every detector.
//
// The scale trades the image noise (a small window averages few pixels)
// against the bias of curved edges, perspective and uneven light (a large
// window is no longer symmetric about the corner); which wins depends on
// the lens, the board and the sensor, so it is chosen per corner by
// Lepski's rule (Lepski, Mammen & Spokoiny, Ann. Statist. 1997), the
// standard way to pick a smoothing scale from the data alone:
//   - the fit is made at scales 1, sqrt 2, 2, 2 sqrt 2, ... px up to the
//     corner's largest scale (below: 0.15 of the distance to the nearest
//     corner, so that the window, two scales, covers less than a third of
//     the way there; 16 px at most), each with its standard error from the
//     image's noise (saddle_point.h);
//   - going up, a scale is taken while its point lies within three standard
//     errors of the point at every smaller scale: the larger window then
//     adds no bias the noise does not already hide. The first scale that
//     disagrees, or fits poorly, ends the climb. Three, not fewer: a bias
//     that varies smoothly over the image the lens model absorbs, the noise
//     it cannot (on the simulator's sharp-knee rig the calibration's error
//     against the truth was 0.087 / 0.086 px with one standard error,
//     0.069 / 0.071 with two, 0.038 / 0.046 with three; the real sets'
//     kb4 RMS moved by under 0.003 px).
// A fit is poor where the quadratic explains less than three quarters of
// its window's variance (an ideal junction explains 0.85 or more:
// saddle_point.h), where it finds no saddle, or where its point wanders
// farther than its window's half-width; a corner with no good fit at any
// scale falls back to cv::cornerSubPix's position.
//
// The noise is measured once per board on the image's own pixels
// (Immerkaer, "Fast noise variance estimation", CVIU 1996, with the median
// of the absolute response for robustness to the board's edges), together
// with the 8-bit rounding's 1/12 grey level squared.
//
// A corner that ends at whole-pixel coordinates (x and y both integers) has
// failed its refinement, and the detectors drop it (DropUnrefined): the
// saddle fits found no good saddle, and cv::cornerSubPix returned its start
// unchanged, as it does where its system is singular (a window inside one
// square) or its point leaves the window, and the detectors' starts are
// often whole pixels (a quad's vertices). On a real image (its noise breaks
// any exact symmetry) a fit that moves a point never lands it on whole
// pixels. Such a corner can be pixels off (one was 5.85 px off, inside a
// black square), and both refinements have already been tried from the
// detector's point: there is nothing left to redo it with.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace ws {

// cv::cornerSubPix for each of `points` in a window of 0.4 of its spacing
// (its distance to the nearest other corner), 2 to 11 px a side of the
// centre: the window stays inside the four squares around the corner.
void CornerSubPix(const cv::Mat& gray, std::vector<cv::Point2f>& points, const std::vector<double>& spacing);

// The standard deviation (grey levels) of the noise of the 8-bit image
// within `region`, the rounding included.
double ImageNoise(const cv::Mat& gray, cv::Rect region);

// Moves each of `points` (the detector's, where each fit starts) to its
// saddle point as described above, or, with no good fit, to fallback[i]
// (cornerSubPix's); `spacing[i]` is point i's distance (pixels) to the
// nearest other corner of the board. Returns how many fell back.
int RefineCorners(const cv::Mat& gray, std::vector<cv::Point2f>& points, const std::vector<double>& spacing,
                  const std::vector<cv::Point2f>& fallback);

// Whether refinement left `point` at whole-pixel coordinates (above).
bool Unrefined(cv::Point2f point);

// Removes the unrefined corners from `points` and their ids from `ids` (of
// the same length); returns how many.
int DropUnrefined(std::vector<int>& ids, std::vector<cv::Point2f>& points);

}  // namespace ws
