// Codec noise averaged away over time: each sampled frame of the target is replaced by the
// average of itself and its R neighbours on either side, each neighbour first warped onto it by
// dense optical flow.
//
// The fitter sees only the K keyframes (15 of a clip's 49 frames, say), so blocking, ringing and
// the smeared colour of a heavily compressed video land on the fitted shapes unfiltered: one
// frame's noise moves one keyframe's edges. The frames between keyframes show the same drawing a
// moment apart, with noise of their own (the content moves against the codec's fixed block grid,
// and every frame is quantised afresh). Aligned onto the keyframe and averaged, they cut that
// noise's variance by up to 2R + 1 while the drawing, moved back into place, stays as sharp as
// the flow is accurate. Where the flow is wrong (occlusion, a part too fast or too thin for it)
// the warped neighbour disagrees with the keyframe by far more than noise, and a per-pixel weight
// exp(-(d / tau)^2) on the largest channel difference d leaves it out.
//
// Measured on the non-rigid bench targets (tests/bench/fit_nonrigid.sh): see
// third_party_notes.md for the idea's sources and README's "Real videos" for the figures.
#pragma once

#include <opencv2/core.hpp>

#include <deque>
#include <utility>
#include <vector>

namespace svgm {

// Frames arrive in increasing order of their index (the ones `needs` asks for, at least); each
// wanted frame comes back, averaged, once its R later neighbours have arrived (or the clip has
// ended: `finish`). Frames are straight RGB float in [0, 1], all of one size.
class TemporalDenoiser {
 public:
  // `wanted`: the sampled frames' indices, increasing. `radius` 0 hands frames back unchanged.
  TemporalDenoiser(int radius, std::vector<int> wanted);

  // Seconds spent aligning and averaging so far.
  double seconds() const { return seconds_; }

  // Frame i is a wanted one or one of a wanted one's neighbours.
  bool needs(int i) const;

  // Frame i (i greater than any pushed before). Returns the wanted frames completed by it, as
  // (index, averaged frame), in increasing index order.
  std::vector<std::pair<int, cv::Mat>> push(int i, cv::Mat rgb);

  // The clip has ended: the wanted frames still waiting for later neighbours.
  std::vector<std::pair<int, cv::Mat>> finish();

 private:
  std::vector<std::pair<int, cv::Mat>> complete(int last_index, bool ended);

  int radius_;
  std::vector<int> wanted_;
  double seconds_ = 0;
  size_t next_ = 0;                           // the first wanted frame not yet handed back
  std::deque<std::pair<int, cv::Mat>> window_;  // recent frames, oldest first
};

// The average of `centre` and `neighbours` aligned onto it (the class above, for one frame).
cv::Mat average_aligned(const cv::Mat& centre, const std::vector<const cv::Mat*>& neighbours);

}  // namespace svgm
