// The head of a bust or of a head drawn alone (see bust_head.h).
#include "procedural/bust_head.h"

#include <algorithm>
#include <set>
#include <string>

namespace svgm {

namespace {

// Priors, in shares of the figure's box (F).
constexpr double kShouldersWide = 0.7;   // the shoulders span at least this share of F's width
constexpr double kShouldersLow = 0.45;   // their top below this share of F's height
constexpr double kOnBottom = 0.04;       // their bottom within this share of F's height of F's bottom
constexpr double kHeadTall = 0.35;       // the head above them at least this share of F's height
constexpr double kCompact = 1.5;         // a head alone: F no more than this times longer one way

bool has_limbs(const Rig& rig) {
  for (const RigPart& P : rig.parts)
    if (P.role == Role::UpperLimb || P.role == Role::LowerLimb || P.role == Role::Tail) return true;
  return false;
}

bool has_arms(const Rig& rig) {
  for (const RigPart& P : rig.parts)
    if (P.role == Role::UpperLimb || !P.arm_lobes.empty()) return true;
  return false;
}

// A head part whose middle is above the body's top: a head on a body, not hair over a face.
bool head_above_body(const Rig& rig) {
  if (rig.root < 0) return false;
  for (const RigPart& P : rig.parts)
    if (P.role == Role::Head && !P.box.empty() && P.box.centre().y < rig.parts[rig.root].box.y0) return true;
  return false;
}

LocatedPart turning_whole(const Rig& rig, const std::vector<int>& els, Vec2 pivot, const std::string& why) {
  LocatedPart out;
  out.lobes.push_back(lobe_over_elements(rig, els, pivot));
  // A head turns on its neck whole: bent from a ramp, the chin held and the face folded.
  out.lobes.back().rigid = true;
  out.lobes.back().kind = LobeKind::Head;
  std::set<int> paths;
  for (int e : els) paths.insert(rig.elements[e].path);
  out.paths.assign(paths.begin(), paths.end());
  out.why = why;
  return out;
}

}  // namespace

LocatedPart bust_head(const Rig& rig) {
  const RigBox& F = rig.figure;
  if (rig.elements.empty() || F.w() <= 0 || F.h() <= 0 || has_arms(rig)) return {};
  int shoulders = -1;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigBox& b = rig.elements[i].box;
    if (b.w() >= kShouldersWide * F.w() && b.y0 >= F.y0 + kShouldersLow * F.h() && b.y1 >= F.y1 - kOnBottom * F.h() &&
        (shoulders < 0 || b.w() > rig.elements[shoulders].box.w()))
      shoulders = static_cast<int>(i);
  }
  if (shoulders >= 0) {
    const double top = rig.elements[shoulders].box.y0;
    std::vector<int> head;
    RigBox hb;
    for (size_t i = 0; i < rig.elements.size(); ++i)
      if (static_cast<int>(i) != shoulders && rig.elements[i].box.centre().y < top) {
        head.push_back(static_cast<int>(i));
        hb.add(rig.elements[i].box);
      }
    if (head.empty() || top - hb.y0 < kHeadTall * F.h()) return {};
    return turning_whole(rig, head, {hb.centre().x, top},
                         std::to_string(head.size()) + " element" + (head.size() > 1 ? "s" : "") + " drawn above the shoulders (" +
                             fmt_box(rig, rig.elements[shoulders].box) + "), turning about the middle of their top");
  }
  // A head alone: a compact figure with no limbs (of its parts or its silhouette) and no head
  // set above its body is all head.
  if (has_limbs(rig) || !rig.limbs.empty() || head_above_body(rig) || std::max(F.w(), F.h()) > kCompact * std::min(F.w(), F.h()))
    return {};
  std::vector<int> all(rig.elements.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return turning_whole(rig, all, {F.centre().x, F.y1}, "a head drawn alone (no shoulders, no limbs): the whole figure, turning about its bottom");
}

}  // namespace svgm
