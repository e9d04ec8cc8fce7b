// Which elements a plume is (see plume_stacks.h).
#include "procedural/plume_stacks.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

// The element of most drawn area, of those whose middle is in the figure's lower half with `low`.
int source_of(const Rig& rig, bool low) {
  int best = -1;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigElement& e = rig.elements[i];
    if ((!low || e.box.centre().y > rig.figure.centre().y) && (best < 0 || e.area > rig.elements[best].area)) best = static_cast<int>(i);
  }
  return best;
}

}  // namespace

std::vector<int> plume_stack(const Rig& rig, const std::vector<int>& els) {
  const double tol = kStackTouch * rig.figure.h();
  std::vector<int> out;
  for (int e : els) {
    const RigBox& E = rig.elements[e].box;
    bool carries = false;
    for (int o : els) {
      const RigBox& O = rig.elements[o].box;
      carries = carries || (o != e && std::fabs(O.y1 - E.y0) <= tol && O.centre().x > E.x0 && O.centre().x < E.x1 && O.centre().y < E.centre().y);
    }
    if (carries) out.push_back(e);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> plume_elements(const Rig& rig, size_t& stacked) {
  std::vector<int> els;
  stacked = 0;
  for (int low = 0; low < 2 && els.empty(); ++low) {
    const int source = source_of(rig, low == 1);
    if (source < 0) continue;
    const RigBox& B = rig.elements[source].box;
    std::vector<int> above;
    for (size_t i = 0; i < rig.elements.size(); ++i) {
      const RigBox& E = rig.elements[i].box;
      // Across the source's top, reaching below it, as wide as most of it: the source's own top
      // (a cup's rim, the coffee in it, a pot's lid), not what rises from it.
      const bool own_top = E.y1 > B.y0 && E.w() >= kRimSpan * B.w();
      if (static_cast<int>(i) != source && E.centre().y < B.y0 && !own_top) above.push_back(static_cast<int>(i));
    }
    const std::vector<int> stack = plume_stack(rig, above);
    for (int pass = 0; pass < 2 && els.empty(); ++pass)
      for (int i : above)
        if (!std::binary_search(stack.begin(), stack.end(), i) && (pass == 1 || rig.elements[i].box.y1 < B.y0 - kJetGap * rig.figure.h()))
          els.push_back(i);
    stacked = els.empty() ? 0 : stack.size();
  }
  return els;
}

}  // namespace svgm
