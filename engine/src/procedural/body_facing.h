// Which way an animal seen from the side faces, from its silhouette, when no eye is read
// (issue 35). Many openmoji animals are line drawings with no eye at all (a bison, an ox, a
// rhino, a camel): their facing was not read, and told to go the other way they went tail first.
//
// The silhouette (every drawn element of the figure: fills as polygons, open strokes as lines)
// is read at kBodyMaskSize pixels on its long side. Its ground is its lowest kGroundShare rows
// (the hooves, the feet, a fish's belly); each end is read for two things:
//  - its overhang: the silhouette beyond the outermost ground column, as a share of the box. A
//    head and neck are held out ahead of the front legs; the hind legs stand under the rump, and
//    what a tail hangs beyond them is a thin line.
//  - its end's fill: the silhouette in the outer kBodyEndShare of the width, as a share of those
//    columns. A snout or a beak ends the head slim; a rump, a tail fin, a bushy tail end broad.
// The head's end is the one that overhangs more AND ends slimmer, each by kBodyStep at least;
// when the two disagree (a skunk's bushy tail held out, a bison's broad head) nothing is read.
//
// Measured (tests/tools/facing_probe) on 126 side views of animals of both emoji sets and 88
// drawings showing no facing (faces and bugs seen from the front or above), labelled by eye
// before the rule was made, and on their mirror images; a third (every third drawing) kept
// aside. The readings a turn trusts (eye, head parts, this), right / wrong / unread of the side
// views (x2, mirrors) and turns of the others: tuned part 76/3/99 and 10 before, 108/7/63 and 14
// after (the new wrong: an openmoji lizard's long tail held out, twemoji's rhino head cut by its
// frame); kept part 23/0/51 and 6 before, 39/0/35 and 8 after. Fish are not read: with no feet
// the ground is a belly or a fin (a pufferfish and a whale read wrong in the kept part). A
// big-headed beast (openmoji's bison: its head end the broader) reads nothing: the cues disagree.
// Read for creatures on feet (quadrupeds, birds), never a person (who must stay unturned) nor an
// insect (most are drawn from above).
#pragma once

#include <string>

#include "motion/lexicon.h"
#include "procedural/part_rig.h"

namespace svgm {

constexpr int kBodyMaskSize = 96;        // px on the silhouette's long side
constexpr double kGroundShare = 0.08;    // the ground: this share of the height at the bottom
constexpr double kBodyEndShare = 0.15;   // an end: this share of the width at each side
constexpr double kBodyStep = 0.03;       // each cue's difference between the ends, at least
constexpr double kLineWidth = 0.028;     // an unfilled line's width, of the long side (openmoji's 2 of 72)

// The two cues at each end of the figure's silhouette.
struct BodyEnds {
  double overhang_left = 0, overhang_right = 0;  // silhouette beyond the outermost ground column, of the box's area
  double fill_left = 0, fill_right = 0;          // silhouette in the end's columns, of their area
  bool empty = true;
};

BodyEnds body_ends(const Rig& rig);

// The viewer's side the figure of class `figure` faces by its silhouette (-1 left, +1 right, 0
// not read); `why` says how ("its shape: ...": gait_travel.h trusts it to turn the figure round).
// 0 for a class but a quadruped or a bird.
int body_facing(const Rig& rig, FigureClass figure, std::string* why);

}  // namespace svgm
