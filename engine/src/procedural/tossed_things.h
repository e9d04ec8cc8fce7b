// Juggling (issue 35): the small round things a figure keeps in the air (a juggler's balls) and
// the arcs they fly along from hand to hand.
//
// The tossed things are the figure's drawn elements (part_rig.h) that are small (at most
// kTossMaxSize of the figure's larger side), compact and round (their fill within kTossRound of
// the ellipse their box holds), of about one size (within kTossSizeRatio of the middle one), not
// in the figure's lower part (a ball at the feet is kicked, not tossed), not drawn inside
// another element's outline (an eye on a face, a button on a shirt) and holding no more than one
// other element (a face holds its eyes and mouth). Elements drawn over one (an outline over its
// fill, a highlight) go with it. At least two make a juggle.
//
// They fly a cascade: each thing's path is one closed curve of two throws, from near the middle
// on one side up over to the far side of the other (a parabola: kTossAir of each half cycle in
// the air), then carried back in by that hand along a small scoop, and thrown across again. The
// curve spans the things' spread (at least kTossMinSpan of the figure's width), rises from the
// hands (the lowest thing) to the highest thing (at least kTossMinRise of the span). N things
// are N equal phases apart (three balls: the hands throw in turn), each given the phase on the
// curve nearest where the drawing has it (the order and the offset with the least squared
// distance), and each moves by the curve's difference from that phase, so the loop starts at
// the drawing; its offset from the curve fades out by half a cycle and back (toss_shift). The idea of the cascade's timing (odd counts alternate hands) is Shannon's
// juggling theorem (third_party_notes.md).
#pragma once

#include <string>
#include <vector>

#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm {

inline constexpr double kTossMaxSize = 0.22;   // of the figure's larger side
inline constexpr double kTossMinSize = 0.025;  // of the figure's larger side: not a speck
inline constexpr double kTossAspect = 1.4;     // longer side over shorter
inline constexpr double kTossRound = 0.16;     // |fill / inscribed ellipse - 1|
inline constexpr double kTossSizeRatio = 1.6;  // of the middle thing's size
inline constexpr double kTossLowest = 0.7;     // of the figure's height from its top: lower, at the feet
inline constexpr double kTossAir = 0.7;        // of each throw's half cycle in the air
inline constexpr double kTossMinSpan = 0.5;    // of the figure's width, the hands' spread
inline constexpr double kTossMinRise = 0.5;    // of the spread: how high a throw rises at least
inline constexpr double kTossInner = 0.4;      // where a throw starts, as a share of the half spread
inline constexpr double kTossScoop = 0.12;     // how far a hand dips carrying a thing in, of the half spread

struct TossedThing {
  std::vector<ElementPiece> pieces;  // its paths (or subpaths)
  RigBox box;
  double phase = 0;                  // where on the cascade the drawing has it, in cycles
};

// The cascade's curve: the middle between the hands, the half spreads where a throw leaves
// (inner) and lands (outer), the hands' height and how high a throw rises above them.
struct TossArc {
  double centre = 0, inner = 0, outer = 0, hand = 0, rise = 0;
};

// The tossed things of the figure (none when fewer than two are drawn).
std::vector<TossedThing> find_tossed_things(const Rig& rig);

// The cascade the things fly, and each thing's phase on it.
TossArc cascade_arc(const Rig& rig, std::vector<TossedThing>& things);

// The point of the cascade at phase v (cycles; one cycle is two throws, left hand then right).
Vec2 cascade_point(const TossArc& arc, double v);

// How far thing `th` is from its place in the drawing after u cycles, at amplitude `amp`
// (1: the whole curve; less shrinks the motion toward where the drawing has it). Its offset from
// the curve where the drawing has it fades out and back over each cycle (by 1/2 + cos(2 pi u)/2):
// half a cycle on, every thing is on the one curve, as a cascade is.
Vec2 toss_shift(const TossArc& arc, const TossedThing& th, double amp, double u);

// Each path's and subpath's shift in one frame (on[p][s]: it belongs to a tossed thing).
struct TossFrame {
  std::vector<std::vector<char>> on;
  std::vector<std::vector<Vec2>> shift;
};
TossFrame still_toss_frame(const Scene& scene);
// Adds the shifts of `things` on `arc` after u cycles at amplitude `amp` to `frame`.
void add_toss(const std::vector<TossedThing>& things, const TossArc& arc, double amp, double u, TossFrame& frame);

// Whether clause `c` reads as juggling on this figure: it tosses or throws several things
// ("tosses the balls") or keeps them in the air, and the drawing holds tossed things.
bool reads_as_juggling(const Clause& c, const Rig& rig);

}  // namespace svgm
