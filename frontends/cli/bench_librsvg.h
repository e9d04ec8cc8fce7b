// librsvg's time to render the same frames `bench raster` renders and differentiates: the
// figure the differentiable rasteriser is judged against, measured in the same run (the same
// machine load). librsvg and cairo are loaded with dlopen when present (Debian: librsvg2-2,
// libcairo2, runtime packages only), so they are no build or product dependency: without them
// the bench just leaves the comparison out.
#pragma once

#include <optional>
#include <string>

namespace svgm::cli {

// librsvg's time per frame: wall milliseconds, and the CPU milliseconds of the process (user +
// sys) over the same span, each the median over the runs. librsvg renders on this thread alone,
// so on a machine shared with other jobs its CPU time is its work and the wall time that work
// plus the time it waited for a core.
struct LibrsvgTimes {
  double ms_per_frame = 0, cpu_ms_per_frame = 0;
};

// Medians over `repeat` runs of the time per frame librsvg takes to render `svg` `frames` times
// at `width` px wide (height from its intrinsic aspect) onto a fresh white ARGB32 cairo surface
// each time, as /work/shared/tools/rsvg_time.py measures. Nothing when librsvg cannot be loaded
// or the file not read.
std::optional<LibrsvgTimes> librsvg_ms_per_frame(const std::string& svg, int width, int frames, int repeat);

}  // namespace svgm::cli
