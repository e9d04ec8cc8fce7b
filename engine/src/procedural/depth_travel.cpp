// A thing seen head-on that goes away or comes nearer (see depth_travel.h).
#include "procedural/depth_travel.h"

#include <algorithm>
#include <cstdio>

#include "motion/lexicon.h"
#include "procedural/flight_axis.h"
#include "procedural/gait_travel.h"
#include "procedural/support_band.h"
#include "procedural/travel_profile.h"
#include "procedural/travel_words.h"

namespace svgm {

bool seen_head_on(const Rig& rig, std::string* why) {
  const UprightMirror m = upright_mirror(rig);
  const bool head_on = m.cover >= kHeadOnMirror && m.wide <= kHeadOnWide;
  if (why) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s (mirrored about its vertical %.2f of it, %.2f times as wide as tall)",
                  head_on ? "seen head-on" : "not seen head-on", m.cover, m.wide);
    *why = buf;
  }
  return head_on;
}

int depth_way(const ParsedPrompt& prompt, const Clause& c, const Rig& rig, std::string* why) {
  if (c.mods.travel != 0 || is_creature(c.figure)) return 0;
  if (!std::any_of(c.verbs.begin(), c.verbs.end(), [](const Verb* v) { return v && (locomotes(*v) || v->name == "move"); })) return 0;
  for (const Clause& other : prompt.clauses)
    if (stays_put(other.text)) return 0;
  if (c.mods.depth > 0) {
    if (why) *why = "it comes towards the viewer: it grows from far off on its horizon to its size, slowing, and stays";
    return 1;
  }
  if (c.mods.depth == 0 && !says_leaving(c)) return 0;
  std::string view;
  if (!seen_head_on(rig, &view)) return 0;
  if (why) *why = "it goes away, " + view + ": it shrinks towards its horizon, gathering speed, and settles back";
  return -1;
}

Vec2 vanishing_point(const Rig& rig) {
  const std::vector<char> band = support_paths(rig);
  RigBox figure, ground;
  for (const RigElement& e : rig.elements) {
    if (e.path < 0 || e.box.empty()) continue;
    (static_cast<size_t>(e.path) < band.size() && band[e.path] ? ground : figure).add(e.box);
  }
  if (figure.empty()) figure = rig.figure;
  // The sea's surface, the track's far end: where the ground the figure goes on meets the sky.
  const double horizon = !ground.empty() && ground.y0 > figure.y0 ? ground.y0 : figure.y1 - kHorizonRise * figure.h();
  return {figure.centre().x, horizon};
}

void travel_in_depth(MotionPlan& plan, size_t from, int way, const Rig& rig, const std::string& verb, const std::string& words,
                     const std::string& why) {
  // Its sideways slides (a glide's own, a leaving's) have no place: it goes along the line of sight.
  plan.actions.erase(std::remove_if(plan.actions.begin() + static_cast<long>(std::min(from, plan.actions.size())), plan.actions.end(),
                                    [](const PlannedAction& a) { return a.primitive == Primitive::Slide && a.parts.empty(); }),
                     plan.actions.end());
  PlannedAction a;
  a.verb = verb;
  // Measured with the clause's other motions (fit_plan groups a clause by verb and words): apart,
  // a car's drive jitter "coming towards us" was raised 12 times to the visible floor alone.
  for (size_t i = from; i < plan.actions.size(); ++i)
    if (plan.actions[i].words == words) {
      a.verb = plan.actions[i].verb;
      break;
    }
  a.words = words;
  a.primitive = Primitive::Pulse;
  a.target = Target::Whole;
  a.amp = 1 - kFarScale;
  a.direction = way;
  a.goes = true;
  a.vanish = vanishing_point(rig);
  a.why = "'" + words + "': " + why;
  plan.actions.push_back(a);
}

double depth_scale(const PlannedAction& a, double amp, double u) {
  return 1 - amp * (a.direction > 0 ? land_at(u) : launch_at(u));
}

}  // namespace svgm
