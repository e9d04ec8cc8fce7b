// Which way a figure goes on its gait when the prompt does not say (see gait_travel.h).
#include "procedural/gait_travel.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

#include "procedural/limb_qualifiers.h"
#include "procedural/motion_plan_internal.h"

namespace svgm {

bool stays_put(const std::string& text) {
  std::vector<std::string> w;
  std::istringstream in(text);
  for (std::string x; in >> x;) w.push_back(x);
  for (size_t i = 0; i + 1 < w.size(); ++i)
    if ((w[i] == "on" || w[i] == "in") && (w[i + 1] == "place" || w[i + 1] == "spot" || (i + 2 < w.size() && w[i + 2] == "spot")))
      return true;
  return false;
}

bool gets_somewhere(const Verb& v) {
  for (const Action& a : v.actions)
    if ((a.target == Target::Legs && a.pairing == Pairing::Alternating) || a.primitive == Primitive::Hop ||
        a.primitive == Primitive::Undulate)
      return true;
  return false;
}

bool locomotes(const Verb& v) {
  if (gets_somewhere(v) || v.name == "fly" || v.name == "soar" || v.name == "float") return true;
  // A slide of the whole figure of its own (a drive, a glide, a buzz's dart): told a way, it
  // goes there as far as a gait does. Looped at its own 10 % or 4 %, "the locomotive chugs
  // along to the right" and "the ship sails to the right" moved a few pixels and back.
  return std::any_of(v.actions.begin(), v.actions.end(), [](const Action& a) { return a.primitive == Primitive::Slide && a.target == Target::Whole; });
}

bool is_gait(const Verb& v, FigureClass figure) {
  if (v.name == "move") return true;
  bool legs = false, wave = false, wheels = false;
  for (const Action& a : v.actions) {
    legs = legs || (a.target == Target::Legs && a.pairing == Pairing::Alternating);
    wave = wave || a.primitive == Primitive::Undulate;
    wheels = wheels || a.primitive == Primitive::Spin;
  }
  const bool thing = figure != FigureClass::None && !is_creature(figure);
  return (legs && !wheels) || (wave && !thing);
}

int untold_travel(const ParsedPrompt& prompt, const Clause& c, const Rig& rig, std::string* why) {
  if (c.mods.travel != 0 || c.mods.vertical != 0 || c.mods.depth != 0) return 0;
  for (const Clause& other : prompt.clauses) {
    if (stays_put(other.text)) return 0;
    for (const PromptNoun& n : other.nouns)
      if (!n.object_of_preposition && motion_plan_internal::is_limb_target(n.target)) return 0;
  }
  std::string how;
  const int facing = facing_side(rig, c.figure, &how);
  if (facing != 0) {
    if (why) *why = std::string("no direction said: the figure faces ") + (facing < 0 ? "left" : "right") + " (" + how + ") and goes that way";
    return facing;
  }
  // Facing not known: a person drawn so faces the viewer and walks on the spot; any other figure
  // is drawn in profile more often than not, and its travel goes both ways about where it stands
  // (a slide's loop), so the way it goes first matters little: to the right, as a reader reads.
  if (c.figure == FigureClass::Biped) return 0;
  if (why) *why = "no direction said and its facing not known: the figure goes to the right first and back";
  return 1;
}

ParsedPrompt travel_across(const ParsedPrompt& prompt, const Rig& rig) {
  ParsedPrompt out = prompt;
  for (Clause& c : out.clauses)
    if (c.mods.across && c.mods.travel == 0) {
      const int facing = facing_side(rig, c.figure, nullptr);
      c.mods.travel = facing != 0 ? facing : 1;
    }
  return out;
}

bool goes_against_facing(const Rig& rig, FigureClass figure, int travel, std::string* why) {
  if (travel == 0) return false;
  // Only a facing the drawing shows plainly turns it: its eye or its head parts. The skeleton's
  // cues (a head limb ahead of the legs, legs gathered at one end) took a fish's tail for its head
  // (twemoji 1f41f, its fins for legs), and a fish told its own way turned round and swam tail first.
  // A vehicle's outline (shape_facing.h) is plain too: its low front.
  std::string how;
  const int facing = facing_side(rig, figure, &how);
  if (facing == 0 || facing == travel || (how != "its eye" && how != "its head" && how.rfind("its shape", 0) != 0)) return false;
  if (why)
    *why = std::string("it faces ") + (facing < 0 ? "left" : "right") + " (" + how + "): it turns round to go " + (travel < 0 ? "left" : "right") +
           " and turns back to come home facing its own way";
  return true;
}

void turn_round_to_go(const Rig& rig, FigureClass figure, PlannedAction& a) {
  std::string why;
  if (!a.goes || a.inches || !goes_against_facing(rig, figure, a.travel, &why)) return;
  a.turns_round = true;
  a.why += "; " + why;
}

bool leave_out_turns(MotionPlan& plan) {
  bool any = false;
  for (PlannedAction& a : plan.actions)
    if (a.turns_round) a.turns_round = false, a.why += "; its turn round left out (the pixel ranker saw a colour vanish edge on)", any = true;
  return any;
}

namespace {

// Whether `text` says a crawl's own word ("crawls", "creeps", "crept", "inches"): said of any
// figure, a creature's gait (a caterpillar is no class the lexicon knows: an object). Whole words
// only, a stem and its endings: by prefix, "a creepy doll moves" and "crawlspace" or "inchoate"
// sent a figure crawling.
bool says_crawl(const std::string& text) {
  std::istringstream in(text);
  for (std::string w; in >> w;) {
    std::string word;
    for (char ch : w)
      if (std::isalpha(static_cast<unsigned char>(ch))) word += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (word == "crept") return true;
    for (const std::string stem : {"crawl", "creep", "inch"})
      if (word.rfind(stem, 0) == 0)
        for (const char* ending : {"", "s", "es", "ed", "ing"})
          if (word == stem + ending) return true;
  }
  return false;
}

}  // namespace

void crawl_in_steps(MotionPlan& plan, size_t from, size_t slide, FigureClass figure) {
  PlannedAction& s = plan.actions[slide];
  if (s.verb != "move" || s.travel == 0 || !(is_creature(figure) || says_crawl(s.words))) return;
  for (size_t i = from; i < plan.actions.size(); ++i)
    if (PlannedAction& a = plan.actions[i]; a.primitive == Primitive::Stretch && a.parts.empty() && a.verb == s.verb) {
      a.inches = s.inches = true;
      a.amp = s.amp, a.cycles = s.cycles = 1, a.direction = a.travel = s.travel;
      a.why += "; a crawl's steps: longer ahead of its planted rear, then gathered up behind its planted front";
    }
}

}  // namespace svgm
