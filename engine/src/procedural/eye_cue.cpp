// The eye cue (see eye_cue.h): a figure's head end from a small dark round element.
#include "procedural/eye_cue.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace svgm {

bool eye_like(const RigElement& e, const RigBox& F) {
  const RigBox& b = e.box;
  if (e.lightness < 0 || e.lightness > kEyeDark || b.empty() || F.empty()) return false;
  const double D = std::max(F.w(), F.h());
  const double lo = std::min(b.w(), b.h()), hi = std::max(b.w(), b.h());
  if (hi > kEyeMaxSize * D || hi < kEyeMinSize * D || lo < kEyeRound * hi) return false;
  return e.area >= kEyeFilled * b.area() && b.centre().y <= F.y0 + kEyeHigh * F.h();
}

EyeCue find_eye(const Rig& rig) {
  EyeCue out;
  const RigBox& F = rig.figure;
  if (F.empty() || F.w() <= 0 || F.h() <= 0) return out;
  const double mid = F.centre().x;
  double sum_x = 0, sum_y = 0, weight = 0;
  int left = 0, right = 0;
  for (const RigElement& e : rig.elements) {
    if (!eye_like(e, F)) continue;
    const RigBox& b = e.box;
    const double off = b.centre().x - mid;
    // One near the middle says nothing of the ends, and breaks none.
    if (std::fabs(off) < kEyeOffCentre * F.w()) continue;
    (off < 0 ? left : right) += 1;
    const double w = std::max(e.area, 1e-12);
    sum_x += w * b.centre().x, sum_y += w * b.centre().y, weight += w;
  }
  if (weight == 0 || (left > 0 && right > 0)) return out;  // none, or at both ends (a face, spots)
  out.count = left + right;
  out.side = left > 0 ? -1 : 1;
  out.at = {sum_x / weight, sum_y / weight};
  char buf[160];
  std::snprintf(buf, sizeof buf, "its eye (%d small dark round element%s at %.2f,%.2f of the figure)", out.count,
                out.count > 1 ? "s" : "", (out.at.x - F.x0) / F.w(), (out.at.y - F.y0) / F.h());
  out.why = buf;
  return out;
}

int relabel_by_eye(Rig& rig, const EyeCue& eye) {
  if (eye.side == 0 || rig.figure.empty()) return 0;
  const double mid = rig.figure.centre().x, off = kEyeOffCentre * rig.figure.w();
  int changed = 0;
  for (ArmLobe& l : rig.limbs) {
    // The end a limb belongs to is where it leaves the body: its base, when that lies off the
    // middle; else its tip. A shrimp's antennae leave its head and sweep back over its body to
    // past the tail: by their tips they were the tail ("flicks its tail" waved the antennae).
    const double base = (l.pivot.x - mid) * eye.side;
    const double ahead = std::fabs(base) > off ? base : (l.tip.x - mid) * eye.side;  // > 0: towards the eye
    if (l.kind == LobeKind::Head && ahead < -off) l.kind = LobeKind::Tail, ++changed;
    else if (l.kind == LobeKind::Tail && ahead > off) l.kind = LobeKind::Head, ++changed;
  }
  return changed;
}

EyeCue apply_eye_cue(Rig& rig, const Scene& scene, const Scene& paint) {
  std::map<std::string, const Path*> by_id;
  for (const Path& p : paint.paths) by_id[p.id] = &p;
  for (RigElement& e : rig.elements) {
    e.lightness = -1;
    if (e.path < 0 || e.path >= static_cast<int>(scene.paths.size())) continue;
    const auto it = by_id.find(scene.paths[e.path].id);
    if (it == by_id.end()) continue;
    const Path& p = *it->second;
    if (p.has_fill && p.fill.a > 0 && p.opacity > 0) e.lightness = 0.299 * p.fill.r + 0.587 * p.fill.g + 0.114 * p.fill.b;
  }
  const EyeCue eye = find_eye(rig);
  rig.eye_side = eye.side;
  rig.eye = eye.at;
  rig.eye_why = eye.why;
  relabel_by_eye(rig, eye);
  return eye;
}

}  // namespace svgm
