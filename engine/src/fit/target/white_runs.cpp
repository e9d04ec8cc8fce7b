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

void append_white_runs(WhiteRuns& packed, const float* rgba, size_t pixels) {
  constexpr uint32_t kMaxRun = std::numeric_limits<uint32_t>::max();
  if (packed.runs.empty()) packed.runs.push_back(0);  // runs start with a white one
  // The run being counted is the last; its kind alternates from white at index 0.
  bool white = packed.runs.size() % 2 == 1;
  for (size_t i = 0; i < pixels; ++i) {
    const float* p = rgba + 4 * i;
    if (is_white(p) != white || packed.runs.back() == kMaxRun) {
      packed.runs.push_back(0);  // a full run is followed by an empty one of the other kind
      white = !white;
      if (is_white(p) != white) {
        packed.runs.push_back(0);
        white = !white;
      }
    }
    ++packed.runs.back();
    if (!white) packed.others.insert(packed.others.end(), p, p + 4);
  }
  packed.pixels += pixels;
}

WhiteRuns pack_white_runs(std::vector<float>& rgba) {
  if (rgba.size() % 4 != 0) throw Error("internal: packing " + std::to_string(rgba.size()) + " floats as RGBA");
  WhiteRuns out;
  const size_t pixels = rgba.size() / 4;
  size_t n_others = 0;
  for (size_t i = 0; i < pixels; ++i) n_others += !is_white(&rgba[4 * i]);
  out.others.reserve(4 * n_others);
  append_white_runs(out, rgba.data(), pixels);
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
