// The ground a figure moves on, when the prompt names one ("the sailboat bobs on the waves",
// "rides along the road", "pulls the oar through the water"): a band drawn across the bottom
// of the figure that the figure's own motions leave where it is. Without it the sea bobbed
// with the boat and the water a rower pulls through rowed with him.
//
// Found from the drawing, not from the word: the prompt only says that there is a ground (a
// noun after on, onto, along, across, over, through or off that names no part of the figure;
// or a thing that leaves, or goes a way told: the sea stays as the ship sails to the left);
// the band is the widest path at the figure's bottom that spans most of its width in one piece
// (two wheels drawn as one path are no ground) and lies in its lower part, or that the rest of
// the figure stands on (a tall sea under a flat boat), with every path drawn within it (the
// crest line of the waves). No such band, no support: "the rose droops on its stem" holds
// nothing.
#pragma once

#include <string>
#include <vector>

#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"
#include "svgmotion/scene.h"

namespace svgm {

// Whether the preposition opens a phrase that names where the figure moves (a ground).
bool names_ground(const std::string& preposition);

// The prompt's words for the ground the figure moves on: "on the waves" for the first noun after
// a preposition of place (names_ground) that names no part of the figure and is not its own ("on
// his skis": gear that goes with it, seat_support.h); a launch, and a figure
// that leaves with no way told ("sails away": travel_words.h's says_leaving), leaves a ground,
// named after "from" or not ("off the ground"); a thing (not a creature: its board or skis go
// with it) sent a way told goes along one ("along the ground"). Empty when none.
std::string ground_words(const ParsedPrompt& prompt, const Rig& rig);

// ground_words for a thing sent a way told, no ground named: its band must be one the rest of
// the figure stands on (more of its paths above it than within it, none hanging lower). A ship's
// hull reaching below its sea (drawn past the canvas) was taken for the ground, and the sea went.
inline const std::string kAlongGround = "along the ground";

// Per path of the scene: 1 when it belongs to the band the figure moves on (see above), for the
// prompt's ground words `words` (ground_words).
std::vector<char> support_paths(const Scene& scene, const Rig& rig, const std::string& words = "");
// The same from the rig alone (each path's box from its drawn elements, Rig::elements: the
// figure's paths have the same boxes), for the plan, which has no scene (flight_axis.h leaves the
// band out of a launched figure's shape).
std::vector<char> support_paths(const Rig& rig);

// The same band when it is as wide as the whole figure (kGroundWide of its width), named in the
// prompt or not: the water a polo player stands in up to the chest, the sea under a surfer. It
// is ground, never the figure's limb: the rig reads the figure's limbs from the silhouette
// without it (part_rig_assemble.cpp). In the silhouette with it, the skeleton's thick core was
// the water and its two ends the arms, and a throw swung the water's left end. A lying cat's
// body is no such band: its head and tail reach past it.
constexpr double kGroundWide = 0.9;
std::vector<char> ground_band_paths(const Scene& scene, const Rig& rig);

}  // namespace svgm
