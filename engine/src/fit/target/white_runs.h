// A target's cleaned frames (TargetFrames::rgba) held losslessly while nothing reads them: the
// cleanup makes every pixel outside the figure's dilated mask exactly white (1, 1, 1, 1), so
// runs of those are kept as counts and only the other pixels' floats as they are. A fit's
// refinement reads its target's rgba once, to make the loss's constants Q and R, and again
// only after its iterations (the gate, the preview); between, the 16 bytes per pixel and
// keyframe (88 MB for the bundled example's 21 keyframes at 512 px) become 16 per figure pixel.
// Unpacking gives back the same floats, bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace svgm {

struct WhiteRuns {
  size_t pixels = 0;              // RGBA pixels packed
  std::vector<uint32_t> runs;     // alternating: white pixels, then other pixels, from the first
  std::vector<float> others;      // the other pixels' RGBA, in order
  size_t bytes() const { return runs.size() * sizeof(uint32_t) + others.size() * sizeof(float); }
};

// Packs `rgba` (a multiple of 4 floats) and empties it, its memory freed.
WhiteRuns pack_white_runs(std::vector<float>& rgba);
// Packs `pixels` more RGBA pixels onto the end of `packed`: appending a target's frames one by
// one as its load cleans them gives what pack_white_runs gives of them whole, run for run (a run
// goes on across a frame's end), so the load never holds every frame's floats.
void append_white_runs(WhiteRuns& packed, const float* rgba, size_t pixels);
// The floats pack_white_runs took, bit for bit; `packed` is emptied, its memory freed.
std::vector<float> unpack_white_runs(WhiteRuns& packed);
// Pixels first .. first + count - 1 of what `packed` holds, bit for bit, into `out` (4 * count
// floats), `packed` untouched: one frame read at a time while the rest stay packed.
void unpack_white_runs_range(const WhiteRuns& packed, size_t first, size_t count, float* out);

}  // namespace svgm
