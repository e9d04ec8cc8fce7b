// Repeated small elements: paths and subpath pieces of similar size, gathered into elements and
// sets (see repeated_elements.h).
#include "procedural/repeated_elements.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

// An item joins an element whose box holds its middle when its box is under this share of the
// element's (a highlight in a drop), or when this share of its box lies on the element's (a
// snowflake's arms cross, a drop's outline is drawn over its fill as a second path).
constexpr double kPartOfShare = 0.5;
constexpr double kLiesOnShare = 0.5;
// Members of a set overlap each other by at most this share of the smaller box.
constexpr double kSetClash = 0.3;

bool holds(const RigBox& b, Vec2 c) { return c.x >= b.x0 && c.x <= b.x1 && c.y >= b.y0 && c.y <= b.y1; }

double overlap_area(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

RigBox padded(RigBox b, const Path& p) {
  if (b.empty() || !p.has_stroke) return b;
  const double r = 0.5 * p.stroke.width;
  b.x0 -= r, b.y0 -= r, b.x1 += r, b.y1 += r;
  return b;
}

RigBox subpath_box(const Subpath& sp) {
  RigBox b;
  for (const Vec2& q : sp.points) b.add(q);
  return b;
}

struct Item {
  RigBox box;
  std::vector<ElementPiece> pieces;
};

}  // namespace

std::vector<std::vector<int>> subpath_pieces(const Path& p) {
  const int n = static_cast<int>(p.subpaths.size());
  std::vector<RigBox> box(n);
  std::vector<int> order;
  for (int s = 0; s < n; ++s) {
    box[s] = subpath_box(p.subpaths[s]);
    if (!box[s].empty()) order.push_back(s);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return box[a].area() > box[b].area(); });
  std::vector<std::vector<int>> pieces;
  for (int s : order) {
    bool joined = false;
    for (auto& piece : pieces)
      if (holds(box[piece.front()], box[s].centre())) {
        piece.push_back(s);
        joined = true;
        break;
      }
    if (!joined) pieces.push_back({s});
  }
  for (auto& piece : pieces) std::sort(piece.begin(), piece.end());
  return pieces;
}

RepeatedElements find_repeated_elements(const Scene& scene, const std::vector<char>& skip) {
  const double max_area = kRepeatedArea * scene.width * scene.height;
  std::vector<Item> items;
  bool of_subpaths = false;
  for (size_t i = 0; i < scene.paths.size(); ++i) {
    if (i < skip.size() && skip[i]) continue;
    const Path& p = scene.paths[i];
    const int pi = static_cast<int>(i);
    const auto pieces = subpath_pieces(p);
    if (pieces.size() >= 2) {
      // Each piece is an item of its own (drops drawn as the subpaths of one path).
      for (const auto& piece : pieces) {
        Item it;
        for (int s : piece) {
          it.box.add(subpath_box(p.subpaths[s]));
          it.pieces.push_back({pi, s});
        }
        it.box = padded(it.box, p);
        if (it.box.area() > 0 && it.box.area() <= max_area) items.push_back(std::move(it));
      }
      continue;
    }
    Item it;
    for (const auto& sp : p.subpaths) it.box.add(subpath_box(sp));
    it.box = padded(it.box, p);
    it.pieces.push_back({pi, -1});
    if (!it.box.empty() && it.box.area() > 0 && it.box.area() <= max_area) items.push_back(std::move(it));
  }
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.box.area() > b.box.area(); });

  std::vector<Item> elems;
  for (Item& it : items) {
    const Vec2 c = it.box.centre();
    bool attached = false;
    for (auto& e : elems) {
      if (!holds(e.box, c)) continue;
      const double a = it.box.area();
      if (a < kPartOfShare * e.box.area() || overlap_area(e.box, it.box) > kLiesOnShare * a) {
        e.pieces.insert(e.pieces.end(), it.pieces.begin(), it.pieces.end());
        attached = true;
        break;
      }
    }
    if (!attached) elems.push_back(std::move(it));
  }

  std::vector<std::vector<int>> clusters;  // indices into elems
  auto similar = [](const RigBox& a, const RigBox& b) {
    const double rw = std::max(a.w(), b.w()) / std::max(std::min(a.w(), b.w()), 1e-9);
    const double rh = std::max(a.h(), b.h()) / std::max(std::min(a.h(), b.h()), 1e-9);
    return rw <= kRepeatedSimilar && rh <= kRepeatedSimilar;
  };
  for (size_t e = 0; e < elems.size(); ++e) {
    bool placed = false;
    for (auto& c : clusters) {
      if (!similar(elems[c.front()].box, elems[e].box)) continue;
      bool clash = false;  // members of a set do not overlap each other much
      for (int o : c)
        clash = clash || overlap_area(elems[o].box, elems[e].box) > kSetClash * std::min(elems[o].box.area(), elems[e].box.area());
      if (clash) continue;
      c.push_back(static_cast<int>(e));
      placed = true;
      break;
    }
    if (!placed) clusters.push_back({static_cast<int>(e)});
  }
  size_t best = clusters.size();
  for (size_t c = 0; c < clusters.size(); ++c)
    if (clusters[c].size() >= kRepeatedMin && (best == clusters.size() || clusters[c].size() > clusters[best].size())) best = c;
  RepeatedElements out;
  if (best == clusters.size()) return out;
  for (int e : clusters[best]) {
    std::vector<ElementPiece> ps = elems[e].pieces;
    std::sort(ps.begin(), ps.end(), [](const ElementPiece& a, const ElementPiece& b) {
      return a.path != b.path ? a.path < b.path : a.subpath < b.subpath;
    });
    for (const auto& q : ps) of_subpaths = of_subpaths || q.subpath >= 0;
    out.elements.push_back(std::move(ps));
  }
  out.why = std::to_string(out.elements.size()) +
            (of_subpaths ? " small shapes of similar size (the subpaths of a path drawing several)" : " small paths of similar size");
  return out;
}

}  // namespace svgm
