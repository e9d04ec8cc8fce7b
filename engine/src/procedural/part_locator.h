// Finding a part the prompt names that the rig has no part for: "the rabbit twitches its ears"
// on a rabbit whose ears are two paths the grouper put with its body, "the bell's clapper
// swings", "the clock's hands go round". The rig's roles (part_rig.h) know heads, limbs, tails
// and wheels; a noun of another kind used to find nothing (the figure swayed as a whole) or a
// role's stand-in (a clock's hands read as the arms of its body's sides).
//
// Each noun the locator knows names a kind of part with a spatial and shape prior, and the part
// is looked for among the figure's drawn elements (Rig::elements: its paths, or the subpaths of
// a path drawn apart, as a crab's claws in its body's path), the largest of which is the body:
//  - ears (ear, antenna): the elements sticking out above the body at the figure's top, at most
//    two (a pair seen from the side lies on one side), each turning about its end nearest the
//    body; when a drawn eye shows the head's end (eye_cue.h), none behind the middle away from
//    it (a dog's raised tail); one reaching the figure's lower quarter is a head drawn in one
//    outline with its ear (openmoji's elephant, its trunk hanging from it): only its stretch
//    above the figure's middle turns, about its point there nearest the body's middle;
//  - a jet (spout, plume, jet, spray, steam, smoke, fountain): what is drawn above the body's
//    top, turning about its lowest middle;
//  - flames (flame): the tips of what is drawn above the body's top, each element there with
//    nothing else drawn over it (a candle's flame, not the candle), each turning about its
//    lowest middle; a blaze drawn whole has none (the whole figure flickers);
//  - a clapper (clapper, pendulum, tongue of a bell): the lowest small element below the body's
//    middle and centred under it, with the others there that overlap it (its colour under its
//    outline), turning whole (rigid) about the middle of their top, or of the body's bottom
//    when they hang wholly below it;
//  - hands (of a clock or a dial: hand, needle, pointer): thin elements inside a larger one,
//    one end of each at a common centre they turn about;
//  - a side pair (claw, pincer, nipper, mandible): the mirrored pair of side protrusions (each
//    with the elements overlapping it) farthest forward (up) and largest, each turning about
//    its point nearest the body;
//  - a branch (trunk, proboscis, snout): the longest limb of the silhouette's skeleton
//    (Rig::limbs) that does not stand on the ground (legs do), about its base;
//  - petals: a rosette outline or a ring of repeated elements round a centre, with what is
//    drawn inside it, spreading from the centre (petal_rosette.h);
//  - strands (tentacle, tendril, strand): the elongated elements hanging below the body (their
//    middles below its bottom) with one end at the body (a jellyfish's tentacles under its
//    bell), at least two, each with the strokes drawn along it (a colour under its outline),
//    turning about that end, all the same way (mirrored, neighbours crossed).
//  - a rotor (propeller, rotor, blade, vane): blades about a hub (rotor_blades.h);
//  - a bloom (no noun: a whole plant's bend, motion_plan.cpp): a flower's head on one stem,
//    the largest element above the stem's top end and at it with those above the end that
//    overlap it in turn, turning about that end (its neck); the stem and the leaves along it
//    hold. A plant of several stems (a sheaf) has no one bloom.
// A part found becomes lobes (outline_lobes.h): the hull of its elements' points beyond a base
// line across the joint, so its points (and the details drawn on it) turn, growing from nothing
// at the base, and the body holds. Only the elements' own paths (and those drawn inside them)
// move. `why` says what was found where, for motion.json and the terminal.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "motion/lexicon.h"
#include "procedural/part_rig.h"

namespace svgm {

enum class PartShape { None, Ears, Jet, Flames, Clapper, Hands, SidePair, Branch, Petals, Strands, Bloom, Rotor };

// The kind of part a noun names ("ears" -> Ears, "clapper" -> Clapper), None for nouns the
// locator does not place. `figure`: the prompt's figure class (lexicon.h): a trunk is a branch
// only on a creature (not a tree's body), hands are a dial's only on an object (a person with
// no figure word, "he raises his hand", keeps the rig's arms).
PartShape part_shape_of(std::string_view noun, FigureClass figure);
const char* part_shape_name(PartShape s);

struct LocatedPart {
  PartShape shape = PartShape::None;
  std::vector<ArmLobe> lobes;  // each turns about its pivot; empty: not found
  std::vector<int> paths;      // scene paths whose points may move (sorted)
  std::vector<int> holds;      // scene paths that hold while it moves, though drawn on it (the
                               // thing burning drawn over a blaze: flame_core.h), sorted
  std::string why;             // what was chosen and why, one phrase
};

// An element's long axis: its two ends (its extreme points along its principal direction) and
// its length over its width.
struct ElementAxis {
  Vec2 a, b;
  Vec2 mid_a, mid_b;  // the ends on its middle line (through its centroid along the direction)
  double elongation = 0;
};
ElementAxis element_axis(const RigElement& e);

// One lobe over elements `els` turning about `pivot`: its tip their point farthest from it, its
// base behind every one of their points.
ArmLobe lobe_over_elements(const Rig& rig, const std::vector<int>& els, Vec2 pivot);
// The same over points `pts`.
ArmLobe lobe_over_point_set(const Rig& rig, const std::vector<Vec2>& pts, Vec2 pivot);

// The elements of the figure (every part but the background), for Rig::elements.
std::vector<RigElement> figure_elements(const Scene& scene, const Rig& rig);

// The part of kind `shape` on the rig's figure; lobes empty when none fits the prior.
LocatedPart locate_part(const Rig& rig, PartShape shape);

// A tail the skeleton's labels missed: the limbs of the silhouette (Rig::limbs) opposite the
// head (a drawn eye, eye_cue.h, else the rig's head parts, else the skeleton's head limb). Its tip is the farthest from the
// head of the limbs that are neither the head nor legs nor as long as half the figure (the body
// itself, a lying bar's end under its head), on the far side of the figure's middle;
// other such limbs leaving the body beside its base (the two lobes of a fish's fin) go with it.
// Empty when no head shows where the front is. A mermaid's fin was labelled arms (her body
// stands upright), and the far end of her box bent her raised hand with it.
std::vector<ArmLobe> tail_limbs(const Rig& rig);

// A box in shares of the figure's box, as the notes name it: "0.10,0.20-0.40,0.55".
std::string fmt_box(const Rig& rig, const RigBox& b);

// The boxes of lobes' outlines (fmt_box), each with its skeleton label: "tail 0.80,0.40-1.00,0.90".
std::string fmt_lobes(const Rig& rig, const std::vector<ArmLobe>& lobes);

}  // namespace svgm
