// Juggling and swimming strokes, read and planned (see toss_and_stroke.h).
#include "procedural/toss_and_stroke.h"

#include <algorithm>
#include <cmath>

#include "procedural/motion_plan_internal.h"
#include "procedural/tossed_things.h"

namespace svgm {

using namespace motion_plan_internal;

namespace {

std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> out(1);
  for (char ch : text)
    if (ch == ' ') { if (!out.back().empty()) out.emplace_back(); }
    else out.back() += ch;
  if (out.back().empty()) out.pop_back();
  return out;
}

// The way the figure faces, as the viewer sees it: its eye's side, else its head's side of the
// root's middle; 0 when neither shows it.
int facing(const Rig& rig) {
  if (rig.eye_side != 0) return rig.eye_side;
  if (rig.root < 0) return 0;
  const RigBox& B = rig.parts[static_cast<size_t>(rig.root)].box;
  double sum = 0, weight = 0;
  for (const RigPart& P : rig.parts)
    if (P.role == Role::Head && !P.box.empty()) sum += P.box.area() * P.box.centre().x, weight += P.box.area();
  if (weight <= 0) return 0;
  const double dx = sum / weight - B.centre().x;
  return std::fabs(dx) < kHeadOffCentre * B.w() ? 0 : dx < 0 ? -1 : 1;
}

// The direction (radians) part p points from its pivot at rest.
double pointing(const Rig& rig, int p) {
  const RigBox b = chain_box(rig, p);
  const Vec2 c = b.centre(), pv = rig.parts[static_cast<size_t>(p)].pivot;
  return std::atan2(c.y - pv.y, c.x - pv.x);
}

std::optional<PlannedAction> plan_toss(const Rig& rig, const Verb& verb, const Action& base, const Modifiers& mods, const std::string& words,
                                       Action& instead, std::string& why) {
  std::vector<TossedThing> things = find_tossed_things(rig);
  if (things.size() < 2) {
    instead = {Primitive::Swing, Target::Arms, 20, 2, Pairing::Alternating};
    why = "no tossed things (two or more small round things held up) found: the arms toss in turn";
    return std::nullopt;
  }
  PlannedAction a;
  a.verb = verb.name;
  a.words = words;
  a.primitive = Primitive::Toss;
  a.target = Target::Whole;
  a.amp = base.amp * std::min(mods.size, 1.0);
  a.cycles = std::max(1, static_cast<int>(std::lround(base.cycles * mods.speed)));
  a.arc = cascade_arc(rig, things);
  a.tossed = std::move(things);
  char line[200];
  std::snprintf(line, sizeof line, "'%s': %s tosses the %zu round things held up from hand to hand (a cascade, each a %.0f%% of a cycle "
                "after the last; the arcs rise %.0f px over the hands)", words.c_str(), verb.name.c_str(), a.tossed.size(),
                100.0 / static_cast<double>(a.tossed.size()), a.arc.rise);
  a.why = line;
  return a;
}

std::optional<PlannedAction> plan_windmill(const Rig& rig, const Verb& verb, const Modifiers& mods,
                                           const std::string& words, uint32_t coin, Action& instead, std::string& why) {
  std::string note;
  std::vector<int> arms = parts_for(rig, Target::Arms, "", &note);
  const bool together = verb.name == "butterfly";
  if (arms.empty() || !note.empty()) {
    instead = {Primitive::Swing, Target::Arms, kStrokeSwingDeg, 1, together ? Pairing::Mirrored : Pairing::Alternating};
    why = "no arms of their own to turn over: they swing wide" + std::string(together ? " together" : " in turn");
    return std::nullopt;
  }
  std::sort(arms.begin(), arms.end(), [&](int x, int y) { return rig.parts[x].box.centre().x < rig.parts[y].box.centre().x; });
  PlannedAction a;
  a.verb = verb.name;
  a.words = words;
  a.primitive = Primitive::Windmill;
  a.target = Target::Arms;
  a.parts = arms;
  a.amp = mods.speed > 1 ? 2 : 1;
  a.cycles = 1;
  // Over the top the way it faces: clockwise on the screen facing right; a backstroke back.
  int face = facing(rig);
  const bool told = face != 0;
  if (face == 0) face = (coin & 1) ? 1 : -1;
  a.direction = verb.name == "backstroke" ? -face : face;
  // In turn: half a turn apart, unless drawn more than a quarter turn apart already.
  double apart = 0;
  if (arms.size() >= 2) {
    apart = std::fabs(std::remainder(pointing(rig, arms.front()) - pointing(rig, arms.back()), 2 * M_PI));
  }
  const bool drawn_apart = apart > M_PI / 2;
  for (size_t i = 0; i < arms.size(); ++i) {
    a.sign.push_back(a.direction);
    a.phase.push_back(!together && !drawn_apart && i % 2 == 1 ? 0.5 : 0);
  }
  std::vector<std::string> names;
  for (int p : arms) names.push_back(rig.parts[p].name);
  a.why = "'" + words + "': " + verb.name + " turns the arms (" + join(names, ", ") + ") over about the shoulders, whole turns" +
          (together ? ", together" : drawn_apart ? ", in turn as drawn (apart already)" : ", in turn, half a turn apart") +
          (told ? "" : "; facing not known: the seed's way");
  return a;
}

}  // namespace

const Verb* stroke_reading(const Clause& c) {
  bool swims = false, crawl = false, butterfly = false, back = false, stroke = false;
  for (const Verb* v : c.verbs) swims = swims || v->name == "swim";
  for (const std::string& w : words_of(c.text)) {
    swims = swims || w.rfind("swim", 0) == 0 || w.rfind("swam", 0) == 0;
    crawl = crawl || word_matches(w, "crawl") || word_matches(w, "freestyl");
    butterfly = butterfly || w == "butterfly";
    back = back || word_matches(w, "backstrok");
    stroke = stroke || word_matches(w, "strok");
  }
  if (back) return find_verb_by_name("backstroke");
  if (!swims && !crawl) return nullptr;
  if (swims && butterfly) return find_verb_by_name("butterfly");
  if (crawl && swims) return find_verb_by_name("stroke");
  for (const Verb* v : c.verbs)
    if (v->name == "stroke") return v;
  return swims && stroke ? find_verb_by_name("stroke") : nullptr;
}

std::optional<PlannedAction> plan_round_motion(const Rig& rig, const Verb& verb, const Action& base, const Modifiers& mods,
                                               const std::string& words, uint32_t coin, Action& instead, Target& target, std::string& why) {
  std::optional<PlannedAction> own = base.primitive == Primitive::Toss ? plan_toss(rig, verb, base, mods, words, instead, why)
                                                                        : plan_windmill(rig, verb, mods, words, coin, instead, why);
  if (!own) target = instead.target;
  return own;
}

}  // namespace svgm
