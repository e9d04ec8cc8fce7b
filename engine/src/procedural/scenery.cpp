// The scenery of a scene (scenery.h).
#include "procedural/scenery.h"

#include <algorithm>
#include <numeric>

#include "scene/backdrop.h"

namespace svgm {

namespace {

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  bool empty() const { return x1 < x0; }
  double area() const { return empty() ? 0 : (x1 - x0) * (y1 - y0); }
  void add(const Box& b) { x0 = std::min(x0, b.x0), y0 = std::min(y0, b.y0), x1 = std::max(x1, b.x1), y1 = std::max(y1, b.y1); }
  bool overlaps(const Box& b) const { return std::min(x1, b.x1) > std::max(x0, b.x0) && std::min(y1, b.y1) > std::max(y0, b.y0); }
};

int find(std::vector<int>& up, int i) {
  while (up[i] != i) i = up[i] = up[up[i]];
  return i;
}

}  // namespace

std::vector<char> scenery_paths(const Scene& scene) {
  const size_t n = scene.paths.size();
  std::vector<char> out(n, 0);
  if (n < 2) return out;
  std::vector<Box> box(n);
  for (size_t i = 0; i < n; ++i)
    for (const auto& sp : scene.paths[i].subpaths)
      for (const Vec2& q : sp.points) box[i].add({q.x, q.y, q.x, q.y});
  // The drawing's own canvas (Scene::room) and its edges' reach.
  const double f = 1 + 2 * scene.room, W = scene.width / f, H = scene.height / f;
  const double ox = scene.room * W, oy = scene.room * H, tx = kBackdropEdge * W, ty = kBackdropEdge * H;
  // A backdrop by its box (backdrop.h), and the frame's cut of it together with the other early
  // paths at the edges: a landscape drawn in layers (a sky with its mountains, the meadow, the
  // rails) runs along the frame as a whole, each layer for a part of a side (a carriage's sky and
  // mountains along 0.53 of the left side, with the meadow and rails 0.70).
  std::vector<char> inner(n, 0);  // no backdrop, reaching no edge
  std::vector<int> backdrops, at_edges;
  for (size_t i = 0; i < n; ++i) {
    const Box& b = box[i];
    if (b.empty()) continue;
    const double pos = static_cast<double>(i) / static_cast<double>(n);
    const bool edge = b.x0 - ox <= tx || b.y0 - oy <= ty || b.x1 - ox >= W - tx || b.y1 - oy >= H - ty;
    if (is_backdrop(b.x0 - ox, b.y0 - oy, b.x1 - ox, b.y1 - oy, pos, W, H)) {
      backdrops.push_back(static_cast<int>(i));
      continue;
    }
    if (edge && pos < kBackdropEarly) at_edges.push_back(static_cast<int>(i));
    inner[i] = !edge;
  }
  if (backdrops.empty()) return out;
  std::vector<int> layers = backdrops;
  layers.insert(layers.end(), at_edges.begin(), at_edges.end());
  if (frame_cut(scene, layers) < kBackdropCut) return out;
  std::vector<int> up(n);
  std::iota(up.begin(), up.end(), 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n && inner[i]; ++j)
      if (inner[j] && box[i].overlaps(box[j])) up[find(up, static_cast<int>(j))] = find(up, static_cast<int>(i));
  std::vector<Box> cluster(n);
  for (size_t i = 0; i < n; ++i)
    if (inner[i]) cluster[find(up, static_cast<int>(i))].add(box[i]);
  int subject = -1;
  for (size_t c = 0; c < n; ++c)
    if (!cluster[c].empty() && (subject < 0 || cluster[c].area() > cluster[subject].area())) subject = static_cast<int>(c);
  if (subject < 0 || cluster[subject].area() < kSubjectMin * W * H) return out;
  for (size_t i = 0; i < n; ++i) out[i] = !(inner[i] && find(up, static_cast<int>(i)) == subject) && !box[i].empty();
  return out;
}

bool edge_to_edge(const Scene& scene, const std::vector<int>& paths) {
  Box b;
  for (int pi : paths)
    for (const auto& sp : scene.paths[static_cast<size_t>(pi)].subpaths)
      for (const Vec2& q : sp.points) b.add({q.x, q.y, q.x, q.y});
  if (b.empty()) return false;
  const double f = 1 + 2 * scene.room, W = scene.width / f, H = scene.height / f;
  const double ox = scene.room * W, oy = scene.room * H, tx = kBackdropEdge * W, ty = kBackdropEdge * H;
  return (b.x0 - ox <= tx && b.x1 - ox >= W - tx) || (b.y0 - oy <= ty && b.y1 - oy >= H - ty);
}

}  // namespace svgm
