// Flames around what burns (see flame_core.h).
#include "procedural/flame_core.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "procedural/flame_lick.h"

namespace svgm {

bool blunt_top(const RigElement& e, double top) {
  const RigBox& b = e.box;
  double lo = 1e300, hi = -1e300;
  for (Vec2 q : e.points)
    if (q.y <= b.y0 + top * b.h()) lo = std::min(lo, q.x), hi = std::max(hi, q.x);
  return hi >= lo && hi - lo >= kBluntSpread * b.w();
}

LocatedPart flames_over_core(const Rig& rig, int body) {
  LocatedPart out;
  const RigElement& blaze = rig.elements[body];
  const RigBox& B = blaze.box;
  // A blaze ends in a tip (its top kTipTop, where a fire's side tongues do not reach yet): a
  // flag's field, a box or a cup is blunt (the corpus scan: 123 of 7991 drawings had a stripe or
  // a band across their bottom that passed for a thing burning).
  if (blunt_top(blaze, kTipTop)) return out;
  int core = -1;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigElement& e = rig.elements[i];
    // Drawn over the blaze (a later path), inside its box, low in it down to its bottom, across
    // it, blunt (a band across a lantern reaches neither its bottom nor a flame's tip).
    if (static_cast<int>(i) == body || e.path <= blaze.path || !e.box.within(B) || e.box.y0 < B.y0 + kCoreBelow * B.h() ||
        e.box.y1 < B.y1 - kCoreBottom * B.h() || e.box.w() < kCoreSpan * B.w() || !blunt_top(e))
      continue;
    if (core < 0 || e.box.area() > rig.elements[core].box.area()) core = static_cast<int>(i);
  }
  if (core < 0) return out;
  const RigBox& C = rig.elements[core].box;
  std::vector<Vec2> pts;
  std::set<int> paths, holds;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigElement& e = rig.elements[i];
    // The thing's outline and what is drawn on it hold: their boxes within its own, grown a
    // little (an outline's arcs bulge past its fill's top).
    if (static_cast<int>(i) == core || e.box.within(C, kCoreGrow * std::hypot(C.w(), C.h()))) holds.insert(e.path);
    if (static_cast<int>(i) == core || e.box.within(C, kCoreGrow * std::hypot(C.w(), C.h())) || e.box.y0 >= C.y0) continue;
    for (Vec2 q : e.points)
      if (q.y <= C.y0) pts.push_back(q);
    paths.insert(e.path);
  }
  if (pts.empty()) return out;
  // Its tongues lick, each column by its own phase (flame_lick.h): turned as one lobe, the
  // blaze's sides folded its mesh.
  out.lobes.push_back(lobe_over_point_set(rig, pts, {C.centre().x, C.y0}));
  out.lobes.back().kind = LobeKind::Blaze;
  out.lobes.back().tongue_spacing = tongue_spacing(pts);
  out.paths.assign(paths.begin(), paths.end());
  // A path both (a subpath in the blaze, another on the thing) moves.
  for (int p : paths) holds.erase(p);
  out.holds.assign(holds.begin(), holds.end());
  out.why = "nothing drawn above the blaze's top; a thing burning drawn over its lower part (path " +
            std::to_string(rig.elements[core].path + 1) + " at " + fmt_box(rig, C) + "): the flames are the stretch above it, licking up tongue by tongue";
  return out;
}

}  // namespace svgm
