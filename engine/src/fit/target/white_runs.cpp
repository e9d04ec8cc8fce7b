// Runs of exact white in a target's frames (white_runs.h).
#include "fit/target/white_runs.h"

#include <algorithm>
#include <limits>
#include <string>

#include "svgmotion/error.h"

namespace svgm {

namespace {
// Exactly the cleanup's white: 1.0f compares equal to itself alone (no other float, no NaN).
bool is_white(const float* p) { return p[0] == 1.f && p[1] == 1.f && p[2] == 1.f && p[3] == 1.f; }
}  // namespace

WhiteRuns pack_white_runs(std::vector<float>& rgba) {
  if (rgba.size() % 4 != 0) throw Error("internal: packing " + std::to_string(rgba.size()) + " floats as RGBA");
  WhiteRuns out;
  out.pixels = rgba.size() / 4;
  size_t n_others = 0;
  for (size_t i = 0; i < out.pixels; ++i) n_others += !is_white(&rgba[4 * i]);
  out.others.reserve(4 * n_others);
  constexpr uint32_t kMaxRun = std::numeric_limits<uint32_t>::max();
  bool white = true;  // the kind of the run being counted: runs start with a white one
  uint32_t run = 0;
  for (size_t i = 0; i < out.pixels; ++i) {
    const float* p = &rgba[4 * i];
    if (is_white(p) != white || run == kMaxRun) {
      out.runs.push_back(run);  // a full run is followed by an empty one of the other kind
      white = !white;
      run = 0;
      if (is_white(p) != white) {
        out.runs.push_back(0);
        white = !white;
      }
    }
    ++run;
    if (!white) out.others.insert(out.others.end(), p, p + 4);
  }
  out.runs.push_back(run);
  out.runs.shrink_to_fit();
  std::vector<float>().swap(rgba);
  return out;
}

std::vector<float> unpack_white_runs(WhiteRuns& packed) {
  std::vector<float> rgba(packed.pixels * 4, 1.f);
  size_t at = 0, from = 0;
  bool white = true;
  for (const uint32_t run : packed.runs) {
    if (at + run > packed.pixels) throw Error("internal: white runs longer than their frames");
    if (!white) {
      if (from + 4 * size_t{run} > packed.others.size()) throw Error("internal: white runs without their pixels");
      std::copy_n(packed.others.begin() + static_cast<std::ptrdiff_t>(from), 4 * size_t{run},
                  rgba.begin() + static_cast<std::ptrdiff_t>(4 * at));
      from += 4 * size_t{run};
    }
    at += run;
    white = !white;
  }
  if (at != packed.pixels || from != packed.others.size()) throw Error("internal: white runs do not cover their frames");
  packed = WhiteRuns{};
  return rgba;
}

void unpack_white_runs_range(const WhiteRuns& packed, size_t first, size_t count, float* out) {
  if (first + count > packed.pixels) throw Error("internal: unpacking pixels past the white runs' frames");
  std::fill(out, out + 4 * count, 1.f);
  const size_t end = first + count;
  size_t at = 0, from = 0;  // the run's first pixel, and its first float in `others`
  bool white = true;
  for (size_t r = 0; r < packed.runs.size() && at < end; ++r, white = !white) {
    const size_t run = packed.runs[r], lo = std::max(at, first), hi = std::min(at + run, end);
    if (!white && lo < hi) {
      if (from + 4 * (hi - at) > packed.others.size()) throw Error("internal: white runs without their pixels");
      std::copy_n(packed.others.begin() + static_cast<std::ptrdiff_t>(from + 4 * (lo - at)), 4 * (hi - lo),
                  out + 4 * (lo - first));
    }
    if (!white) from += 4 * run;
    at += run;
  }
}

}  // namespace svgm
