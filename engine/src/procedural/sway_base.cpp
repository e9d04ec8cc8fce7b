// Where a sway leans from (a plant's pot mouth or stem foot) and the lean (see sway_base.h).
#include "procedural/sway_base.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "procedural/motion_plan_internal.h"

namespace svgm {

using namespace motion_plan_internal;

namespace {

// A general sway's lean grows over this share of the figure's height above its hinge
// (motion_frames.cpp's region bends ramp the same way).
constexpr double kLeanRamp = 0.25;
// A holder's mouth is flat: its points within kMouthBand of its height from its top span at
// least kMouthSpan of its width (a pot's rim; a leaf standing at the bottom comes to a point).
constexpr double kMouthBand = 0.15, kMouthSpan = 0.5;
// A band stacked on the holder (a rim) is at least kBandWide of its width and lies within
// kBandOver of its width beyond either side.
constexpr double kBandWide = 0.8, kBandOver = 0.25;
// A holder stands under the plant: its middle within kHolderOffCentre of the figure's width of
// the figure's middle (a hibiscus's leaf at its bottom left, flat where the bloom covers it,
// was taken for a pot and the bloom swayed about the leaf).
constexpr double kHolderOffCentre = 0.15;

bool solid(const RigElement& e) { return !e.thin && e.box.area() > 0 && e.area >= kHolderSolid * e.box.area(); }

bool flat_top(const RigElement& e) {
  double lo = 1e300, hi = -1e300;
  for (const Vec2& p : e.points)
    if (p.y <= e.box.y0 + kMouthBand * e.box.h()) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  return hi - lo >= kMouthSpan * e.box.w();
}

Vec2 turned(Vec2 q, Vec2 c, double deg) {
  const double r = deg * M_PI / 180, cs = std::cos(r), sn = std::sin(r);
  const Vec2 d = q - c;
  return c + Vec2{cs * d.x - sn * d.y, sn * d.x + cs * d.y};
}

}  // namespace

PlantBase plant_base(const Rig& rig) {
  const RigBox& F = rig.figure;
  const double W = std::max(F.w(), 1e-9), H = std::max(F.h(), 1e-9);
  const std::vector<RigElement>& els = rig.elements;
  // The holder: the widest solid element with a flat top standing on the figure's bottom.
  int seed = -1;
  for (size_t i = 0; i < els.size(); ++i) {
    const RigBox& b = els[i].box;
    if (solid(els[i]) && b.y1 >= F.y1 - kFootBand * H && b.w() >= kHolderWide * W && b.h() <= kHolderTall * H && flat_top(els[i]) &&
        std::fabs(b.centre().x - F.centre().x) <= kHolderOffCentre * W && (seed < 0 || b.w() > els[static_cast<size_t>(seed)].box.w()))
      seed = static_cast<int>(i);
  }
  char why[160];
  if (seed >= 0) {
    RigBox holder = els[static_cast<size_t>(seed)].box;
    // The solid bands stacked on it (a rim), while the holder stays under kHolderTall of the figure.
    for (bool grew = true; grew;) {
      grew = false;
      for (const RigElement& e : els) {
        const RigBox& b = e.box;
        const double over = kBandOver * holder.w();
        if (solid(e) && b.y0 < holder.y0 && b.y1 >= holder.y0 && b.w() >= kBandWide * holder.w() && b.x0 >= holder.x0 - over &&
            b.x1 <= holder.x1 + over && holder.y1 - b.y0 <= kHolderTall * H) {
          holder.add(b);
          grew = true;
        }
      }
    }
    std::snprintf(why, sizeof why, "held at the mouth of what it stands in (y %.1f): it moves from there", holder.y0);
    return {{holder.centre().x, holder.y0}, true, why};
  }
  // The stem's foot: the middle of what is drawn at the figure's bottom.
  double lo = 1e300, hi = -1e300;
  for (const RigElement& e : els)
    for (const Vec2& p : e.points)
      if (p.y >= F.y1 - kFootBand * H) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  const double x = hi >= lo ? 0.5 * (lo + hi) : F.centre().x;
  std::snprintf(why, sizeof why, "held at its stem's foot (%.1f, %.1f): it moves from there", x, F.y1);
  return {{x, F.y1}, false, why};
}

std::string root_plant(PlannedAction& a, const Rig& rig, FigureClass figure) {
  if (figure != FigureClass::Plant || a.target != Target::Whole || !a.parts.empty() ||
      !(a.primitive == Primitive::Sway || (a.primitive == Primitive::Bend && a.anchored == 4)))
    return "";
  const PlantBase base = plant_base(rig);
  a.rooted = true;
  a.root = base.root;
  return base.why;
}

Vec2 sway_lean(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q) {
  const double turn = a.direction * amp * oscillation(a, a.cycles * t);
  if (a.rooted) {
    // Each point turns about the root by its height above it over the plant's (sway_base.h).
    if (q.y >= a.root.y) return q;
    const double v = std::min((a.root.y - q.y) / std::max(a.root.y - box.y0, 1e-9), 1.0);
    return turned(q, a.root, turn * v);
  }
  // Above the hinge the points lean about the hinge's middle, the lean growing smoothly over
  // kLeanRamp of the height (the shape stays in one piece); below it they hold.
  const double H = std::max(box.h(), 1e-9), hinge = box.y0 + kSwayHinge * H;
  if (q.y >= hinge) return q;
  const double x = std::clamp((hinge - q.y) / (kLeanRamp * H), 0.0, 1.0);
  return turned(q, {box.centre().x, hinge}, turn * (x * x * (3 - 2 * x)));
}

}  // namespace svgm
