// What a figure hangs from, when the prompt says so ("the sloth hangs from the branch and
// sways"): a long straight thing drawn across the figure's top (a branch, a bar, a wire) that the
// figure's motions leave where it is, the figure swinging about its grip as a pendulum. Without
// it the branch a sloth hung from swayed with the sloth, and its sway leant the sloth about its
// feet, as if it stood.
//
// Found from the drawing, not from the word: the prompt only says that there is a support (a
// noun after "from" that is not the figure's own, in a clause that is no launch: "takes off
// from the runway" leaves its ground, support_band.h). The support is the longest straight
// piece of the figure (its control points' extent along their main axis at least kStraight times
// that across, and at least kLong of the figure's size that way), with every straight piece on
// its line (a branch drawn in pieces behind the sloth, its outline and highlights), reaching
// across kAcross of the figure's extent along that line, with most of the rest of the figure
// below it (hanging). No such line, no support: nothing changes.
#pragma once

#include <string>
#include <vector>

#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"
#include "svgmotion/scene.h"

namespace svgm {

// "from the branch": the first noun after "from" that is not the figure's own (no "its", no
// named part of the figure), in a clause with no launch or landing; empty when none.
std::string hang_words(const ParsedPrompt& prompt, const Rig& rig);

struct HangSupport {
  std::vector<char> paths;  // per path of the scene: 1 on the support
  Vec2 grip;                // the point of the support the figure swings about
  bool found = false;
};
HangSupport hang_support(const Scene& scene, const Rig& rig);

// A hanging figure's sway or rock at time t: the whole of it turns about its grip, as a
// pendulum; leant about a hinge near its feet (as a standing figure sways), it bent away from
// what it hung from.
Affine pendulum(const PlannedAction& a, double amp, double t, Vec2 grip);

}  // namespace svgm
