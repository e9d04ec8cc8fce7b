// Which limb covers which part of the drawing (limbs.h): the skeleton's Voronoi regions, each
// skeleton point owned by a limb or by the core, and a point of the drawing given to the owner
// whose inscribed disc's edge is nearest (|p - q| - r(q)). Subtracting the radius keeps the
// body's flesh with the body: a point between a thick torso and a thin arm's axis belongs to
// the torso unless it lies nearer the arm's own outline. A limb's stretch inside the body (from
// its joint on the core's axis out to its base) is the core's.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "motion/limbs.h"

namespace svgm::motion {

namespace {

struct Owned {
  Vec2 p;
  double r;
  int owner;  // limb index, -1 for the core
};

std::vector<Owned> owned_points(const Skeleton& s, const Figure& f) {
  std::vector<Owned> out;
  // A limb with a stalk (limbs.cpp's with_stalk: its path's first points lie on the core's
  // edges, on none of its own) owns that stretch of the trunk and the neck's disc.
  const auto on_edges = [&](const std::vector<int>& edges, Vec2 p) {
    for (int e : edges)
      for (const Vec2& q : s.edges[e].points)
        if (q.x == p.x && q.y == p.y) return true;
    return false;
  };
  std::vector<size_t> stalk(f.limbs.size(), 0);
  std::vector<char> neck(s.nodes.size(), 0);
  std::vector<Vec2> stalks;
  for (size_t l = 0; l < f.limbs.size(); ++l) {
    const Limb& L = f.limbs[l];
    while (stalk[l] < L.path.size() && on_edges(f.core_edges, L.path[stalk[l]]) && !on_edges(L.edges, L.path[stalk[l]])) ++stalk[l];
    if (stalk[l] > 0) neck[L.joint] = 1, stalks.insert(stalks.end(), L.path.begin(), L.path.begin() + static_cast<long>(stalk[l]));
  }
  const auto on_stalk = [&](Vec2 p) { return std::any_of(stalks.begin(), stalks.end(), [&](Vec2 q) { return q.x == p.x && q.y == p.y; }); };
  for (int e : f.core_edges)
    for (size_t i = 0; i < s.edges[e].points.size(); ++i)
      if (!on_stalk(s.edges[e].points[i])) out.push_back({s.edges[e].points[i], s.edges[e].radius[i], -1});
  for (int n : f.core_nodes)
    if (!neck[n]) out.push_back({s.nodes[n].pos, s.nodes[n].radius, -1});
  for (size_t l = 0; l < f.limbs.size(); ++l) {
    for (size_t i = 0; i < stalk[l]; ++i) out.push_back({f.limbs[l].path[i], f.limbs[l].radius[i], static_cast<int>(l)});
    SkeletonNode joint = s.nodes[f.limbs[l].joint];
    if (stalk[l] > 0) joint.radius = 0;  // the neck's disc is the limb's
    const auto& standing = f.limbs[l].standing_edges;
    // A tail's stretch through a foot, before its base, is the body's (limbs.h).
    const auto& path = f.limbs[l].path;
    const auto through_foot = [&](Vec2 p) {
      return std::any_of(path.begin(), path.begin() + static_cast<long>(std::min(f.limbs[l].body_until, path.size())),
                         [&](Vec2 q) { return q.x == p.x && q.y == p.y; });
    };
    for (int e : f.limbs[l].edges) {
      // A fork standing on the ground off a limb that does not is the body's leg (limbs.h).
      const bool leg = std::find(standing.begin(), standing.end(), e) != standing.end();
      for (size_t i = 0; i < s.edges[e].points.size(); ++i) {
        const Vec2 p = s.edges[e].points[i];
        const bool inside = std::hypot(p.x - joint.pos.x, p.y - joint.pos.y) < joint.radius;
        // A tail's thick stretch before its base is the rump it runs through (limbs.h).
        const Limb& L = f.limbs[l];
        const bool rump = L.body_radius > 0 && s.edges[e].radius[i] >= L.body_radius &&
                          std::hypot(p.x - joint.pos.x, p.y - joint.pos.y) < std::hypot(L.base.x - joint.pos.x, L.base.y - joint.pos.y);
        out.push_back({p, s.edges[e].radius[i], inside || leg || rump || through_foot(p) ? -1 : static_cast<int>(l)});
      }
    }
  }
  return out;
}

int nearest_owner(const std::vector<Owned>& owned, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  int owner = -1;
  for (const auto& o : owned) {
    const double d = std::hypot(p.x - o.p.x, p.y - o.p.y) - o.r;
    if (d < best) best = d, owner = o.owner;
  }
  return owner;
}

}  // namespace

std::vector<int> assign_points(const Skeleton& s, const Figure& f, const std::vector<Vec2>& points) {
  const std::vector<Owned> owned = owned_points(s, f);
  std::vector<int> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(nearest_owner(owned, p));
  return out;
}

std::vector<int> assign_paths(const Skeleton& s, const Figure& f, const std::vector<Vec2>& points,
                              const std::vector<int>& path_of_point, int paths) {
  const std::vector<int> owner = assign_points(s, f, points);
  std::vector<std::map<int, int>> votes(std::max(0, paths));
  for (size_t i = 0; i < owner.size() && i < path_of_point.size(); ++i)
    if (path_of_point[i] >= 0 && path_of_point[i] < paths) ++votes[path_of_point[i]][owner[i]];
  std::vector<int> out(votes.size(), -1);
  for (size_t p = 0; p < votes.size(); ++p) {
    int most = 0;
    for (const auto& [limb, n] : votes[p])  // map order: ties go to the core, then the lower limb
      if (n > most) most = n, out[p] = limb;
  }
  return out;
}

cv::Mat limb_regions(const Skeleton& s, const Figure& f) {
  cv::Mat out(s.height, s.width, CV_32S, cv::Scalar(-2));
  const std::vector<Owned> owned = owned_points(s, f);
  if (owned.empty()) return out;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      if (s.labels.at<int>(y, x) == f.component) out.at<int>(y, x) = nearest_owner(owned, {double(x), double(y)});
  return out;
}

std::vector<int> assign_path_masks(const cv::Mat& regions, int limbs, const std::vector<cv::Mat>& path_masks) {
  std::vector<int> out;
  for (const auto& m : path_masks) {
    std::vector<int> count(limbs + 1, 0);  // [0] the core, [l + 1] limb l
    if (m.size() == regions.size() && m.type() == CV_8U)
      for (int y = 0; y < m.rows; ++y)
        for (int x = 0; x < m.cols; ++x) {
          const int r = regions.at<int>(y, x);
          if (m.at<uchar>(y, x) && r >= -1 && r < limbs) ++count[r + 1];
        }
    const auto most = std::max_element(count.begin(), count.end());
    out.push_back(*most > 0 ? static_cast<int>(most - count.begin()) - 1 : -1);
  }
  return out;
}

}  // namespace svgm::motion
