// Bench tool: what the backdrop rule (scene/backdrop.h) sees in a drawing, path by path and part
// by part (the rig's parts, procedural/part_rig.h), to tell scenery from a figure filling its
// canvas.  backdrop_probe X.svg ...   (a run's grouped.svg keeps its groups and its room)
// Per path and per part: box share of the drawing's own canvas, edges reached, paint position,
// frame cut (sides), the rule's verdict; per part its role and why.
#include <cstdio>
#include <exception>

#include "procedural/part_rig.h"
#include "procedural/scenery.h"
#include "scene/backdrop.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

void line(const Scene& s, const char* what, int index, const std::vector<int>& paths, double pos) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (int pi : paths)
    for (const auto& sp : s.paths[pi].subpaths)
      for (const Vec2& q : sp.points) x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
  const double f = 1 + 2 * s.room, W = s.width / f, H = s.height / f, ox = s.room * W, oy = s.room * H;
  const double tx = kBackdropEdge * W, ty = kBackdropEdge * H;
  const int edges = (x0 - ox <= tx) + (y0 - oy <= ty) + (x1 - ox >= W - tx) + (y1 - oy >= H - ty);
  // The cut of the largest path alone (by its box), beside the cut of them all.
  int big = paths.front();
  double big_area = -1;
  for (int pi : paths) {
    double a0 = 1e300, b0 = 1e300, a1 = -1e300, b1 = -1e300;
    for (const auto& sp : s.paths[pi].subpaths)
      for (const Vec2& q : sp.points) a0 = std::min(a0, q.x), b0 = std::min(b0, q.y), a1 = std::max(a1, q.x), b1 = std::max(b1, q.y);
    if ((a1 - a0) * (b1 - b0) > big_area) big_area = (a1 - a0) * (b1 - b0), big = pi;
  }
  std::printf("%s %d\tpaths %zu\tbox %.2f\tedges %d\tpos %.2f\tcut %.2f\tbigcut %.2f\t%s", what, index, paths.size(),
              (x1 - x0) * (y1 - y0) / (W * H), edges, pos, frame_cut(s, paths), frame_cut(s, {big}),
              is_backdrop(s, paths, x0, y0, x1, y1, pos) ? "BACKDROP" : "-");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    for (int a = 1; a < argc; ++a) {
      const Scene s = read_svg_file(argv[a]);
      std::printf("== %s (room %.2f)\n", argv[a], s.room);
      const size_t n = s.paths.size();
      const std::vector<char> scenery = scenery_paths(s);
      for (size_t i = 0; i < n; ++i) {
        line(s, "path", static_cast<int>(i), {static_cast<int>(i)}, static_cast<double>(i) / n);
        std::printf("\t%s\t%s\n", scenery[i] ? "scenery" : "", s.paths[i].id.c_str());
      }
      const Rig rig = build_rig(s, {});
      for (size_t g = 0; g < rig.parts.size(); ++g) {
        std::vector<int> paths;
        double pos = 0;
        for (size_t i = 0; i < n; ++i)
          if (rig.part_of_path[i] == static_cast<int>(g)) paths.push_back(static_cast<int>(i)), pos += static_cast<double>(i);
        if (paths.empty()) continue;
        line(s, "part", static_cast<int>(g), paths, pos / paths.size() / n);
        std::printf("\t%s\t%s\t%s\n", role_name(rig.parts[g].role), rig.parts[g].name.c_str(), rig.parts[g].why.c_str());
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "backdrop_probe: %s\n", e.what());
    return 1;
  }
  return 0;
}
