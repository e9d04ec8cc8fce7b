// A figure seen from the front, by its pair of eyes (see front_face.h).
#include "procedural/front_face.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "procedural/eye_cue.h"
#include "procedural/motion_plan_internal.h"

namespace svgm {

FrontFace front_face(const Rig& rig) {
  FrontFace out;
  const RigBox& F = rig.figure;
  if (F.empty() || F.w() <= 0 || F.h() <= 0) return out;
  std::vector<const RigBox*> eyes;
  for (const RigElement& e : rig.elements)
    if (eye_like(e, F)) eyes.push_back(&e.box);
  const double mid = F.centre().x;
  double smallest = 0;  // of the pairs that meet the bounds, the smallest: a dog's dark ear insides are a pair too
  for (size_t i = 0; i < eyes.size(); ++i)
    for (size_t j = i + 1; j < eyes.size(); ++j) {
      const RigBox &a = *eyes[i], &b = *eyes[j];
      const Vec2 ca = a.centre(), cb = b.centre();
      const double apart = std::fabs(ca.x - cb.x);
      const double sa = std::max(a.w(), a.h()), sb = std::max(b.w(), b.h());
      if (std::fabs(ca.y - cb.y) > kFacePairLevel * F.h() || std::fabs(0.5 * (ca.x + cb.x) - mid) > kFacePairCentred * F.w() ||
          apart < kFacePairApartMin * F.w() || apart > kFacePairApartMax * F.w() || std::max(sa, sb) > kFacePairSize * std::min(sa, sb))
        continue;
      if (out.seen && sa + sb >= smallest) continue;
      smallest = sa + sb;
      out.seen = true;
      out.left = ca.x < cb.x ? ca : cb;
      out.right = ca.x < cb.x ? cb : ca;
      char buf[160];
      std::snprintf(buf, sizeof buf, "a pair of eye-like marks level at %.2f,%.2f and %.2f,%.2f of the figure", (out.left.x - F.x0) / F.w(),
                    (out.left.y - F.y0) / F.h(), (out.right.x - F.x0) / F.w(), (out.right.y - F.y0) / F.h());
      out.why = buf;
    }
  return out;
}

std::string tail_not_drawn(const Rig& rig) {
  if (rig.root < 0 || std::any_of(rig.limbs.begin(), rig.limbs.end(), [](const ArmLobe& l) {
        return motion_plan_internal::lobe_serves(l.kind, Target::Tail);
      }))
    return "";
  const FrontFace face = front_face(rig);
  return face.seen ? "no tail drawn: the figure is seen from the front (" + face.why + ")" : "";
}

}  // namespace svgm
