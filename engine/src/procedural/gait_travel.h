// Which way a figure goes on its gait when the prompt does not say (issue 35: "the dog walks",
// "the caterpillar crawls", "the fish swims"). A gait gets somewhere: legs in turn on the spot,
// a body's wave in place, read as a figure marking time, not walking. So a gait's clause with no
// direction of its own (no "to the left", no "up", no "towards the viewer", not "on the spot" or
// "in place") travels the way the figure faces (limb_qualifiers.h: its eye, its head, its legs),
// as "to the right" would send it (motion_plan.cpp's travel_where_told). A figure whose facing is
// not known goes to the right first (its travel is a loop both ways about where it stands),
// unless it is a person, who drawn so faces the viewer and walks on the spot, as before.
#pragma once

#include <string>

#include "motion/motion_verbs.h"
#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm {

// Whether `v` gets a figure somewhere when sent: legs in turn, hops, a body's wave.
bool gets_somewhere(const Verb& v);

// A verb by which a figure gets somewhere: a gait (legs in turn), hops, a swimming or crawling
// body's wave, wings in flight, a slide of its own (a drive, a glide).
bool locomotes(const Verb& v);

// Whether `v`, said of a figure of class `figure` with no direction, is a gait that carries it
// along: legs in turn (not a rider's pedalling: a vehicle's travel is its drive's), a crawl (the
// vocabulary's "move", whose own slide is the crawl's creep), a body's wave on a figure that may
// be a creature (a swimming fish, a slithering worm; not a flag's or the sea's ripple). Not a hop
// ("the ball bounces", "he jumps for joy" stay) nor a flight ("flies", "floats" hold their place).
bool is_gait(const Verb& v, FigureClass figure);

// The viewer's side (-1 left, +1 right) a gait's clause `c` of `prompt` sends the figure when its
// words say none; 0 when they say one, or the prompt says it stays (in any clause: "runs on the
// spot, legs striding"), or it names limbs that move (their stride, not the figure's travel; the
// plan leaves out the whole figure's accents then, a swim's own slide among them), or the figure is a person whose facing is not known. `why` gets "no
// direction said: the figure faces left (its eye) and goes that way".
int untold_travel(const ParsedPrompt& prompt, const Clause& c, const Rig& rig, std::string* why);

// `prompt` with each clause that says the figure goes across and not which way ("floats across
// the screen", "the truck rolls across": Modifiers::across) sent the way the figure faces, else to
// the right, as a reader reads: "across" is a travel told, whatever the verb (the cloud and the
// truck it was said of stayed where they were).
ParsedPrompt travel_across(const ParsedPrompt& prompt, const Rig& rig);

// Whether a figure sent `travel` (-1 left, +1 right) goes against the way it faces
// (limb_qualifiers.h's facing_side for the figure's class `figure`: its drawn eye or head parts,
// a vehicle's outline), so it must turn round to go (PlannedAction::turns_round): a zebra drawn
// facing left, told to trot to the right, went there tail first, a lorry boot first. Not when its
// facing is not known that plainly (a person facing the viewer, a saloon car level at both ends,
// a facing only the silhouette's skeleton suggests).
// `why` gets "it faces left (its eye): it turns round to go right and back to come home".
bool goes_against_facing(const Rig& rig, FigureClass figure, int travel, std::string* why);

// A slide `a` going somewhere steadily (PlannedAction::goes; not a crawl's steps) against the
// way the figure (of class `figure`) faces turns round to go (PlannedAction::turns_round), its
// why saying so.
void turn_round_to_go(const Rig& rig, FigureClass figure, PlannedAction& a);

// Leaves out every turn round of `plan` (PlannedAction::turns_round): the figure goes where it
// goes facing its own way. Whether there was one. For a candidate the pixel ranker flags when
// the turn puts it edge on (video_procedural.cpp's self check).
bool leave_out_turns(MotionPlan& plan);

// "on the spot", "in place", "in one spot": words that keep the figure where it is.
bool stays_put(const std::string& text);

// How far ahead (and behind) of where it stands a figure sent somewhere goes, of its width
// (travel_profile.h: forward steadily, then back); fit_plan scales it down only to keep the figure
// in its canvas. At 8 % about rest, scaled to 80 % to fit, a turtle slid 3 of its canvas's 72
// units each way and read as rocking.
inline constexpr double kTravelReach = 0.15;

// A crawl sent somewhere ("move" said of a creature, or in a crawl's own words: "crawls",
// "creeps", "inches", whatever the figure): the whole figure's stretch of the clause (actions
// from `from`) and its slide `slide` go by the crawl's steps (PlannedAction::inches,
// travel_profile.h): the stretch the size of a step, along the way the slide goes, once a loop.
// A thing that "moves" or "goes" slides as before.
void crawl_in_steps(MotionPlan& plan, size_t from, size_t slide, FigureClass figure);

}  // namespace svgm
