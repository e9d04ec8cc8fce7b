// Things that move by themselves (see self_movers.h).
#include "procedural/self_movers.h"

#include <algorithm>
#include <cmath>

#include "procedural/gait_travel.h"
#include "procedural/held_things.h"
#include "procedural/legged_crawl.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/rotor_blades.h"
#include "procedural/toss_and_stroke.h"

namespace svgm {

bool twinkle_of_fire(const Clause& c, bool lights) {
  const Verb* twinkle = find_verb_by_name("twinkle");
  if (std::find(c.verbs.begin(), c.verbs.end(), twinkle) == c.verbs.end()) return false;
  bool fire = c.figure == FigureClass::Flame;
  for (const auto& n : c.nouns)
    fire = fire || (!n.object_of_preposition && (n.figure == FigureClass::Flame || ((lights || n.figure == FigureClass::None) && n.motion == twinkle)));
  return fire;
}

// With no flame found and repeated sparks drawn, the twinkle stays theirs: a storm's lightning
// "strikes" (a flicker of fire) over its rain drops.
const Verb* flame_verb(const Verb* v, const Clause& c, const Rig& rig, const LocatedPart* located) {
  if (!v || v->name != "twinkle") return v;
  const bool flame = (located && located->shape == PartShape::Flames) || (rig.repeated.empty() && twinkle_of_fire(c, false));
  const Verb* f = flame ? find_verb_by_name("flicker") : nullptr;
  return f ? f : v;
}

const Verb* wheeled_travel(const Verb* v, const Clause& c) {
  if (!v || c.figure != FigureClass::Wheeled) return v;
  // A gait (legs in turn, not a pedalling rider's; the generic move) or a glide or a flight.
  const bool carried = is_gait(*v, c.figure) || v->name == "glide" || v->name == "soar" || v->name == "fly";
  const Verb* drive = carried ? find_verb_by_name("drive") : nullptr;
  return drive ? drive : v;
}

const std::string& verb_word(const Clause& c, size_t i) { return i < c.verb_words.size() ? c.verb_words[i] : c.verbs.at(i)->name; }

const Verb* insect_flight(const Verb* v, const Clause& c, const std::string& word) {
  if (!v || c.figure != FigureClass::Insect) return v;
  const bool flight = v->name == "fly" || v->name == "flutter" || v->name == "soar" || v->name == "glide" || v->name == "move";
  if (!flight) return v;
  const std::string said = word.substr(0, word.find_first_of(" -"));
  for (const char* legs : {"crawl", "creep", "crept", "inch"})
    if (word_matches(said, legs)) return v;
  for (const PromptNoun& n : c.nouns)
    if (n.after_verb && !n.object_of_preposition && !n.own_predicate && motion_plan_internal::is_limb_target(n.target)) return v;
  const Verb* buzz = find_verb_by_name("buzz");
  return buzz ? buzz : v;
}

std::vector<const Verb*> clause_verbs(const Clause& c, const Rig& rig, const LocatedPart* located) {
  // Several things tossed by a figure holding them up is a juggle; a swimmer's crawl a stroke
  // (toss_and_stroke.h): they stand for the throw, the swim and the crawl's move.
  const Verb* juggle = reads_as_juggling(c, rig) ? find_verb_by_name("juggle") : nullptr;
  const Verb* stroke = stroke_reading(c);
  std::vector<const Verb*> out;
  for (size_t i = 0; i < c.verbs.size(); ++i) {
    const Verb* v = c.verbs[i];
    const std::string& word = verb_word(c, i);
    const Verb* by = juggle && v->name == "throw" ? juggle
                     : stroke && (v->name == "swim" || v->name == "move")
                         ? stroke
                         : held_thing_reading(legged_crawl(insect_flight(wheeled_travel(flame_verb(v, c, rig, located), c), c, word), c, rig), c, rig);
    if (std::find(out.begin(), out.end(), by) == out.end()) out.push_back(by);
  }
  if (juggle && std::find(out.begin(), out.end(), juggle) == out.end()) out.insert(out.begin(), juggle);
  if (stroke && std::find(out.begin(), out.end(), stroke) == out.end()) out.insert(out.begin(), stroke);
  return out;
}

LocatedPart flames_of_light(const Clause& c, const Rig& rig) {
  if (rig.root < 0 || !twinkle_of_fire(c, true)) return {};
  return locate_part(rig, PartShape::Flames);
}

bool plume_rises(const LocatedPart* located, Primitive p) {
  return located && located->shape == PartShape::Jet && (p == Primitive::Bob || p == Primitive::Pulse || p == Primitive::Stretch || p == Primitive::Undulate);
}

std::string own_motion(const Rig& rig, const LocatedPart* located, Primitive& primitive, double& amp) {
  if (plume_rises(located, primitive)) {
    primitive = Primitive::Pulse, amp = plume_growth(rig, *located);
    return "a plume rises: it swells up from its base";
  }
  if (!located || located->shape != PartShape::Rotor) return "";
  rotor_motion(rig, *located, primitive, amp);
  return rotor_edge_on(rig, *located) ? "a rotor seen edge on: its blades' length along their line shrinks and grows about the hub"
                                 : "a rotor's blades spin about their hub";
}

double plume_growth(const Rig& rig, const LocatedPart& plume) {
  double reach = 0;
  for (const ArmLobe& l : plume.lobes) reach = std::max(reach, std::hypot(l.tip.x - l.pivot.x, l.tip.y - l.pivot.y));
  return std::clamp(kPlumeRise * rig.figure.h() / std::max(reach, 1e-9), kPlumeGrowMin, kPlumeGrowMax);
}

bool repeated_are_the_figure(const Rig& rig) {
  if (rig.repeated.empty() || rig.figure.empty()) return false;
  RigBox span;
  for (const auto& element : rig.repeated)
    for (const ElementPiece& piece : element)
      for (const RigElement& e : rig.elements)
        if (e.path == piece.path && (piece.subpath < 0 || e.subpath < 0 || e.subpath == piece.subpath)) span.add(e.box);
  return !span.empty() && span.w() >= kOneThingSpan * rig.figure.w() && span.h() >= kOneThingSpan * rig.figure.h();
}

}  // namespace svgm
