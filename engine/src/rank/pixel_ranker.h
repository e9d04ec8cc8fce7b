// The pixel ranker: scores candidate target videos for fitting suitability from their pixels
// and the palette of the recoloured image they were generated from (palette.json).
//
// Five signals, each a value in [0, 1] (0 = fine, 1 = bad) with a one-line reason:
//   colour_drift      per frame, the median over the foreground of each pixel's distance to
//                     the nearest palette colour (an edge pixel, not 3x3 all foreground: or to
//                     a palette colour's blend with white), capped at far_distance;
//                     mean over frames and growth last - first: max((mean - 0.02) / 0.1,
//                     growth / 0.08) (0.02: what H.264 alone costs a flat colour)
//   invented_content  8-connected blobs of foreground pixels farther than far_distance from
//                     every palette colour and from every palette colour's blend with white
//                     (anti-aliased edges) and from every colour the first frame already shows
//                     off the palette (a translucent shape's blend with what lies under it),
//                     with at least one pixel whose 3x3 neighbourhood is all far (so 1-2 px
//                     seams between shapes do not count), as a fraction f of the foreground,
//                     max over frames: (f - 0.005) / 0.03
//   continuity        per palette colour, its soft area per frame (colour_coverage.h: each
//                     pixel shared among the colours it is a mixture of, so a stroke thinner
//                     than a pixel keeps its area; a seam where two other shapes meet is no
//                     area of the colour between them): a colour present in frame 0 that
//                     (almost) vanishes, one absent in frame 0 that appears, or a big relative
//                     jump between consecutive frames: max of (0.3 - min/first) / 0.25,
//                     (0.3 - first/max) / 0.25 and (jump - 0.35) / 0.4, each change in the
//                     direction of the whole figure's (its foreground spread x rho) taken
//                     beyond rho^2 only (a flat turn narrows and overlaps its parts)
//   out_of_plane      relative std s of the total foreground area, counted only when no colour
//                     appears or vanishes: (s - 0.08) / 0.22 * (1 - appear/vanish value), and
//                     only for the frames that are no flat change of the first (its box
//                     stretched, or its foreground's spread changed with every colour keeping
//                     its share: a turn while it twists in the plane)
//   motion            over the pixels that are foreground in either frame: r = largest share of
//                     them whose colour differs from the first frame's by more than 0.15, m =
//                     mean absolute difference of consecutive frames, each shifted by the
//                     whole-frame shift (up to 20 % of the frame) that matches the one before
//                     best when the plain mean is above 0.25 (a figure shaken or carried
//                     rigidly is no chaos). (0.005 - r) / 0.004 below r = 0.5% ("no motion"),
//                     (m - 0.25) / 0.3 above m = 0.25 ("chaotic motion"), else 0
// every value clamped to [0, 1]. Score (lower = better, in [0, 1]):
//   score = (1.0 drift + 1.5 invented + 1.2 continuity + 0.8 out_of_plane + 1.0 motion) / 5.5
// A signal >= defect_threshold (0.5) names a defect: "colour drift", "invented content",
// "continuity", "out-of-plane motion", "no motion" or "chaotic motion". rank() puts clean
// candidates first and charges a clean one that moves less than the most moving clean one
// (kMotionPreference).
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "svgmotion/scene.h"
#include "svgmotion/target_video.h"

namespace svgm {

// The continuity signal's floor: a palette colour whose area falls below this share of its
// first frame's (or whose first frame's is below this share of its largest) starts to count as
// vanishing (appearing). The procedural video keeps a turning figure at least this wide
// (motion_plan_internal.h, kTurnEdgeWidth).
inline constexpr double kRankVanishRatio = 0.3;

struct PixelRankOptions {
  double white_threshold = 0.97;  // foreground: darkest channel < this, and farther than
                                  // 1 - this (any channel) from the frame's border median when
                                  // that is near white (an off-white drifting background)
  double far_distance = 0.25;     // RGB (Euclidean, channels in [0,1]) distance "off palette"
  double defect_threshold = 0.5;  // a signal at least this names a defect
  int analysis_width = 128;       // rank_directory: frames are resized to at most this width
  int keyframes = 16;             // rank_directory: at most this many uniformly sampled frames
};

struct RankSignal {
  double value = 0;  // [0, 1], 1 = bad
  std::string reason;
};

struct CandidateScore {
  std::string name;
  double score = 0;  // lower = better; +inf when the candidate could not be read
  RankSignal colour_drift, invented_content, continuity, out_of_plane, motion;
  std::vector<std::string> defects;
  double mean_motion = 0;     // the motion signal's mean frame difference on the foreground
  double motion_penalty = 0;  // rank(): what moving less than the most moving clean candidate costs
  std::string error;  // non-empty: unreadable, not ranked
  nlohmann::json to_json() const;
};

// The signal weights of the score, in the order drift, invented, continuity, out-of-plane,
// motion.
inline constexpr double kPixelRankWeights[5] = {1.0, 1.5, 1.2, 0.8, 1.0};

// Scores one candidate from its frames (`raw` is analysed: straight RGB in [0,1], K*H*W*4).
// `palette` holds the palette's colours (duplicates are harmless; alpha ignored). Throws
// svgm::Error for an empty palette or frames whose buffers do not match their size.
CandidateScore score_candidate(const TargetFrames& frames, const std::vector<Rgba>& palette,
                               const PixelRankOptions& options = {});

// Scores one candidate video file (or folder of PNG frames) as rank_directory does: frames
// resized to at most options.analysis_width, options.keyframes of them sampled uniformly.
// Throws svgm::Error when it cannot be read. The procedural video checks its own candidates
// with it before they reach the ranker.
CandidateScore score_candidate_file(const std::filesystem::path& video, const std::vector<Rgba>& palette,
                                    const PixelRankOptions& options = {});

// The frames a candidate is sampled at when the fitter will take `fitter_keyframes` keyframes
// of it: at least options.keyframes, and one more than the fitter's (0: options.keyframes).
inline int frames_to_rank(const PixelRankOptions& options, int fitter_keyframes) {
  return fitter_keyframes + 1 > options.keyframes ? fitter_keyframes + 1 : options.keyframes;
}

struct Ranking {
  std::vector<CandidateScore> candidates;  // best first (score, then name); unreadable last
  std::string chosen;                      // name of candidates.front()
  std::string reason;
  nlohmann::json to_json() const;  // {"chosen", "reason", "candidates": [...]}
};

// What a clean candidate's ranking pays for moving less than the most moving clean one: this
// times 1 - its mean frame difference / the largest. A viewer asked for motion sees the motion,
// not a colour's area wavering by a third: on the suite of session 54 the ranker chose an
// ambulance "speeding away" that moved 0.46 of its most moving sibling (0.002 against 0.065,
// a continuity value of 0.24 on the others); half the motion pays 0.075, what a continuity
// value of 0.34 costs (1.2 / 5.5 of it). Candidates with defects are never ranked above a clean
// one, nor charged.
inline constexpr double kMotionPreference = 0.15;

// Orders scored candidates and picks the best: readable before unreadable, clean before
// flagged, then by score plus motion_penalty (kMotionPreference), then by name. Fills each
// clean candidate's motion_penalty. Throws svgm::Error when none is readable.
Ranking rank(std::vector<CandidateScore> scores);

// Scores every entry of `dir` (video files or folders of PNG frames, by name order) and ranks
// them. Unreadable candidates are kept with their error and never chosen. `keyframes_of(name)`,
// when given and positive, samples that candidate at that many frames instead of
// options.keyframes (a procedural candidate, at the keyframes its motion asks of the fitter). `progress(fraction,
// note)` is called before each candidate; returning false cancels (svgm::Error "cancelled").
Ranking rank_directory(const std::filesystem::path& dir, const std::vector<Rgba>& palette,
                       const PixelRankOptions& options = {},
                       const std::function<bool(double, const std::string&)>& progress = {},
                       const std::function<int(const std::string&)>& keyframes_of = {});

}  // namespace svgm
