// Paths with one outline fitted as one: see coincident_paths.h for why.
#include "fit/coincident_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace svgm {

namespace {

// A path's outline as a polyline per subpath (each cubic sampled at eight steps) and its box.
struct Outline {
  std::vector<std::vector<Vec2>> lines;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
};

constexpr int kSteps = 8;

Vec2 cubic_at(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double t) {
  const double u = 1 - t;
  return {u * u * u * a.x + 3 * u * u * t * b.x + 3 * u * t * t * c.x + t * t * t * d.x,
          u * u * u * a.y + 3 * u * u * t * b.y + 3 * u * t * t * c.y + t * t * t * d.y};
}

Outline outline_of(const Path& p) {
  Outline o;
  for (const Subpath& s : p.subpaths) {
    if (s.points.empty()) continue;
    std::vector<Vec2> line{s.points[0]};
    for (size_t k = 0; k < s.segment_count(); ++k)
      for (int i = 1; i <= kSteps; ++i)
        line.push_back(cubic_at(s.points[3 * k], s.points[3 * k + 1], s.points[3 * k + 2], s.points[3 * k + 3],
                                static_cast<double>(i) / kSteps));
    if (s.closed) line.push_back(s.points[0]);
    for (const Vec2& v : line) o.x0 = std::min(o.x0, v.x), o.y0 = std::min(o.y0, v.y), o.x1 = std::max(o.x1, v.x), o.y1 = std::max(o.y1, v.y);
    o.lines.push_back(std::move(line));
  }
  return o;
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Every sample of `a` lies within `tol` of `b`'s polylines.
bool within(const Outline& a, const Outline& b, double tol) {
  for (const auto& line : a.lines)
    for (const Vec2& p : line) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& other : b.lines) {
        if (other.size() == 1) best = std::min(best, std::hypot(p.x - other[0].x, p.y - other[0].y));
        for (size_t i = 1; i < other.size() && best > tol; ++i) best = std::min(best, distance_to_segment(p, other[i - 1], other[i]));
        if (best <= tol) break;
      }
      if (best > tol) return false;
    }
  return true;
}

bool coincide(const Outline& a, const Outline& b, double tol) {
  if (a.lines.empty() || b.lines.empty()) return false;
  if (std::fabs(a.x0 - b.x0) > tol || std::fabs(a.y0 - b.y0) > tol || std::fabs(a.x1 - b.x1) > tol ||
      std::fabs(a.y1 - b.y1) > tol)
    return false;
  return within(a, b, tol) && within(b, a, tol);
}

}  // namespace

Scene merge_coincident_paths(const Scene& scene, std::vector<std::string>* notes) {
  const double tol = kCoincidentShare * std::max(scene.width, scene.height);
  const size_t n = scene.paths.size();
  std::vector<Outline> outlines;
  outlines.reserve(n);
  for (const Path& p : scene.paths) outlines.push_back(outline_of(p));
  // A path alone in its unit (no group, or a group of its own: the reader gives each top-level
  // path one) may join another's; a path among others stays with them.
  auto alone = [&](size_t q) {
    const int g = scene.paths[q].group;
    return g < 0 || scene.groups[static_cast<size_t>(g)].paths.size() == 1;
  };
  Scene out = scene;
  std::vector<int> moved_to(n, -1);  // the path whose unit each path joined
  for (size_t q = 0; q < n; ++q) {
    if (!alone(q)) continue;
    for (size_t p = 0; p < q; ++p)
      if (coincide(outlines[q], outlines[p], tol)) {
        moved_to[q] = moved_to[p] >= 0 ? moved_to[p] : static_cast<int>(p);
        break;
      }
  }
  if (std::none_of(moved_to.begin(), moved_to.end(), [](int v) { return v >= 0; })) return scene;

  // Units rebuilt in scene order: each group less the paths that left it, and the joiners added
  // to the unit of the path they cover (a new group named after it when it had none).
  std::vector<Group> groups = scene.groups;
  for (Group& g : groups) g.paths.clear();
  std::vector<int> group_of(n, -1);
  for (size_t q = 0; q < n; ++q)
    if (moved_to[q] < 0) group_of[q] = scene.paths[q].group;
  std::map<int, std::vector<std::string>> joined;  // host path -> ids that joined its unit
  for (size_t q = 0; q < n; ++q) {
    if (moved_to[q] < 0) continue;
    const size_t host = static_cast<size_t>(moved_to[q]);
    if (group_of[host] < 0) {
      group_of[host] = static_cast<int>(groups.size());
      groups.push_back(Group{scene.paths[host].id, {}, ""});
    }
    group_of[q] = group_of[host];
    joined[static_cast<int>(host)].push_back(scene.paths[q].id);
  }
  for (size_t q = 0; q < n; ++q)
    if (group_of[q] >= 0) groups[static_cast<size_t>(group_of[q])].paths.push_back(static_cast<int>(q));
  // Groups emptied by the move go; the rest keep their order.
  std::vector<int> renumber(groups.size(), -1);
  out.groups.clear();
  for (size_t g = 0; g < groups.size(); ++g)
    if (!groups[g].paths.empty()) {
      renumber[g] = static_cast<int>(out.groups.size());
      out.groups.push_back(std::move(groups[g]));
    }
  for (size_t q = 0; q < n; ++q) out.paths[q].group = group_of[q] >= 0 ? renumber[static_cast<size_t>(group_of[q])] : -1;
  if (notes)
    for (const auto& [host, ids] : joined) {
      std::string names;
      for (const std::string& id : ids) names += (names.empty() ? "" : ", ") + id;
      notes->push_back(out.groups[static_cast<size_t>(out.paths[static_cast<size_t>(host)].group)].id + ": " + names +
                       " fit with " + scene.paths[static_cast<size_t>(host)].id + ", whose outline " +
                       (ids.size() == 1 ? "it shares" : "they share"));
    }
  return out;
}

}  // namespace svgm
