// Optical flow between consecutive target keyframes, for the fitter's warm starts: the
// `tracker flow` stage computes it (dense Farnebäck flow, forward and backward, the
// forward-backward disagreement as the certainty) and writes tracks.json; the fitter reads it
// and moves each control point of keyframe k-1 by the flow at its position.
#pragma once

#include <filesystem>
#include <vector>

#include "svgmotion/target_video.h"

namespace svgm {

// Flow from keyframe k-1 to k sampled on a grid x grid lattice over the frame (cell centres),
// in pixels of the frame it was computed on (width x height), and a certainty in [0, 1].
struct FlowField {
  int grid = 0, width = 0, height = 0;
  std::vector<float> dx, dy, certainty;  // grid * grid each, row-major
  // Bilinear sample at a pixel position (x, y) of a frame of size (w, h): displacement scaled
  // to that size, and the certainty.
  void sample(double x, double y, int w, int h, double* ox, double* oy, double* weight) const;
};

// flows[k] is the flow into keyframe k (flows[0] is empty).
std::vector<FlowField> compute_flows(const TargetFrames& target, int grid = 32);

void write_tracks(const std::filesystem::path& file, const std::vector<FlowField>& flows);
// Throws svgm::Error "<file>: <problem>".
std::vector<FlowField> read_tracks(const std::filesystem::path& file);

}  // namespace svgm
