// The separate pieces of a figure (figure_pieces.h).
#include "procedural/figure_pieces.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace svgm {

namespace {

int find(std::vector<int>& up, int i) {
  while (up[i] != i) i = up[i] = up[up[i]];
  return i;
}

}  // namespace

std::vector<int> figure_pieces(const Rig& rig) {
  const int G = static_cast<int>(rig.parts.size());
  std::vector<int> out(G, -1);
  auto figure_part = [&](int g) { return rig.parts[g].role != Role::Background && !rig.parts[g].box.empty(); };
  const double gap = kPieceGap * std::hypot(rig.figure.w(), rig.figure.h());
  auto near = [&](const RigBox& a, const RigBox& b) {
    return std::min(a.x1, b.x1) + gap >= std::max(a.x0, b.x0) && std::min(a.y1, b.y1) + gap >= std::max(a.y0, b.y0);
  };
  std::vector<int> up(G);
  std::iota(up.begin(), up.end(), 0);
  for (int i = 0; i < G; ++i)
    for (int j = i + 1; j < G && figure_part(i); ++j)
      if (figure_part(j) && near(rig.parts[i].box, rig.parts[j].box)) up[find(up, j)] = find(up, i);
  // Number the pieces in part order, with each piece's box.
  std::vector<int> id(G, -1);
  std::vector<RigBox> box;
  for (int g = 0; g < G; ++g) {
    if (!figure_part(g)) continue;
    int& k = id[find(up, g)];
    if (k < 0) k = static_cast<int>(box.size()), box.emplace_back();
    box[k].add(rig.parts[g].box);
    out[g] = k;
  }
  RigBox all;
  for (const RigBox& b : box) all.add(b);
  const bool apart = box.size() >= 2 && std::all_of(box.begin(), box.end(), [&](const RigBox& b) { return b.area() >= kPieceMin * all.area(); });
  if (!apart)
    for (int& k : out)
      if (k > 0) k = 0;
  return out;
}

int piece_count(const std::vector<int>& pieces) {
  return pieces.empty() ? 0 : *std::max_element(pieces.begin(), pieces.end()) + 1;
}

}  // namespace svgm
