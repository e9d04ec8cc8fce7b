// Where a figure is held while it waves or bends: a pole at one of its sides (a flag's, drawn
// thin or as the figure's one upright bar), else its base when it stands upright or is a plant.
// The motion plan (motion_plan.cpp) anchors a whole-figure ripple or bend there, and the frames
// (motion_frames.cpp) hold the pole still.
#include <algorithm>
#include <utility>
#include <vector>

#include "procedural/motion_plan_internal.h"

namespace svgm::motion_plan_internal {

// The pole's parts at `side` of the figure (1 left, 2 right, 3 top, 4 bottom): the thin parts
// (at most kPoleWidth of the figure's extent across that side) lying within kPoleEnd of it, or
// upright bars drawn thick (kPoleWidthMax, kPoleAspect) starting there.
std::vector<int> pole_parts(const Rig& rig, int side, bool thick) {
  const RigBox& F = rig.figure;
  const bool across_x = side <= 2;  // a left or right pole: thin in x, spanning y
  const double L = std::max(across_x ? F.w() : F.h(), 1e-9);
  // Upright bars of the figure: a thick one is its pole only when it is the only one (of three
  // stalks, the leftmost is no pole).
  auto upright_bar = [&](const RigBox& b) { return b.h() >= kPoleAspect * b.w() && b.h() >= 0.5 * F.h() && b.w() <= kPoleWidthMax * F.w(); };
  int bars = 0;
  for (const RigPart& P : rig.parts) bars += P.role != Role::Background && !P.box.empty() && upright_bar(P.box);
  std::vector<int> out;
  for (size_t i = 0; i < rig.parts.size(); ++i) {
    const RigPart& P = rig.parts[i];
    if (P.role == Role::Background || P.box.empty()) continue;
    const double a0 = across_x ? P.box.x0 : P.box.y0, a1 = across_x ? P.box.x1 : P.box.y1;
    const double s0 = across_x ? F.x0 : F.y0, s1 = across_x ? F.x1 : F.y1;
    const bool near = side % 2 == 1 ? a1 <= s0 + kPoleEnd * L : a0 >= s1 - kPoleEnd * L;
    // A pole drawn thick (an emoji's flagpole is a sixth of the flag's width) is still a pole
    // when it stands upright, thin for its own length, from the left or right side. Not along
    // the top or bottom: a thin bar lying there is a ski, a board or the ground.
    const double length = across_x ? P.box.h() : P.box.w();
    const bool starts = side % 2 == 1 ? a0 <= s0 + kPoleEnd * L : a1 >= s1 - kPoleEnd * L;
    const bool thick_pole = thick && across_x && bars == 1 && starts && a1 - a0 <= kPoleWidthMax * L && length >= kPoleAspect * (a1 - a0);
    if ((near && a1 - a0 <= kPoleWidth * L) || thick_pole) out.push_back(static_cast<int>(i));
  }
  return out;
}

// The side of the figure a pole holds (PlannedAction::anchored: 1 left, 2 right, 3 top, 4
// bottom), 0 for none: where the pole's parts together span kPoleSpan of the figure. `thick`
// counts the bars drawn thick (pole_parts) too: for the wave or the bend of the whole figure,
// never to turn a limb's verb into a ripple (an arm raised high is such a bar: "he raises his
// hand and waves it" rippled the whole man).
int anchored_side(const Rig& rig, bool thick) {
  const RigBox& F = rig.figure;
  for (int side = 1; side <= 4; ++side) {
    const bool across_x = side <= 2;
    const double span = std::max(across_x ? F.h() : F.w(), 1e-9);
    std::vector<std::pair<double, double>> spans;
    for (int p : pole_parts(rig, side, thick)) {
      const RigBox& b = rig.parts[p].box;
      spans.push_back(across_x ? std::make_pair(b.y0, b.y1) : std::make_pair(b.x0, b.x1));
    }
    std::sort(spans.begin(), spans.end());
    double covered = 0, lo = 0, hi = -1e300;
    for (const auto& [b0, b1] : spans) {
      if (b0 > hi) {
        covered += std::max(0.0, hi - lo);
        lo = b0;
        hi = b1;
      } else {
        hi = std::max(hi, b1);
      }
    }
    covered += std::max(0.0, hi - lo);
    if (covered >= kPoleSpan * span) return side;
  }
  return 0;
}

// Where a bend of the whole figure is held: at a pole (a banner), else at the figure's base
// when it stands (a plant, a standing figure: upright, or named a plant), 0 when it is free
// (a fish, a bird, a snake, a figure lying along its length bends about its middle). Bent
// about its middle, rice stalks swung their roots five times as far as their ears.
int bend_anchor(const Rig& rig, FigureClass figure) {
  if (const int side = anchored_side(rig, true)) return side;
  if (figure == FigureClass::FishOrSnake || figure == FigureClass::Bird || figure == FigureClass::Insect) return 0;
  if (figure == FigureClass::Flame) return 4;  // a flame burns up from its base, however wide
  return figure == FigureClass::Plant || rig.figure.h() >= kUpright * rig.figure.w() ? 4 : 0;
}

}  // namespace svgm::motion_plan_internal
