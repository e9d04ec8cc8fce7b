// Flight that carries the whole figure (issue 35): a hover is the body held up in the air by the
// beat of its wings or its rotor, a buzz its body darting about a small area. The whole
// figure's motion is then what the verb says, not an accent of the limbs' beat: a prompt naming
// the wings ("the hummingbird hovers, its wings a blur") or the rotor in another clause ("the
// helicopter hovers, its rotor whirring") left the bob out as it leaves out a wave's hop, and
// the body hung still; measured with the wings, whose beat alone passes the visible floor, the
// bob stays at the verb's 4 % of the figure's height (2.2 % of the test helicopter's diagonal,
// 1.4 % of the test bird's), too little to read as a hover.
#pragma once

#include <string>

#include "motion/motion_verbs.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"

namespace svgm {

// Whether verb `v` carries the whole figure (the verb table's hover and buzz).
bool carries_figure(const Verb& v);

// Whether `v`'s whole-figure actions in clause `c` stay, whatever limbs the prompt names: `v`
// carries the figure and is not said of a part. A part after the verb ("hovers, its wings a
// blur") is how the figure does it; before it ("its rotor whirring", "its wings buzzing": a
// possessive before the verb, the part found or not) it is the verb's subject and moves alone.
// `part_word`: the part the clause names, empty when none.
bool keeps_whole(const Verb& v, const Clause& c, const std::string& part_word);

// Whether `a` is a carrying verb's motion of the whole figure: fit_plan measures it against the
// visible floor by itself (not with the wings' beat of the same words) and never scales it down
// with the limbs (motion_fit.cpp).
bool carried_whole(const PlannedAction& a);

}  // namespace svgm
