// Repeated small elements of a drawing (rain drops, snowflakes, stars, bubbles, petals): the
// things a prompt's "rain falls" or "stars twinkle" moves one by one, each in its own phase.
//
// An element is drawn as one path, as several paths (a drop and the highlight inside it, a
// snowflake's three crossing lines, a drop's fill and its outline drawn twice), or as some of
// the subpaths of one path: a designer often draws all the drops in one path, one closed contour
// per drop. A path's subpaths fall into pieces by where they lie: a contour whose middle lies
// inside a larger one's box is part of it (a hole, a highlight); a path with two or more such
// pieces offers each piece as an element, so the drops of one path fall apart from each other
// (the motion moves control points, and the fitter fits each path's control points: a
// translation per subpath is an offset of those points).
//
// Elements are then gathered from the items (paths or subpath pieces, each box padded by half
// its stroke width so a line has an area): an item whose middle lies in a larger element's box
// joins it when it is much smaller (a highlight) or lies mostly on it (a cross's other arm, an
// outline over its fill). Elements of similar size that do not overlap much form a set; the
// largest set of at least kRepeatedMin is the drawing's repeated elements.
#pragma once

#include <string>
#include <vector>

#include "procedural/part_rig.h"
#include "svgmotion/scene.h"

namespace svgm {

struct RepeatedElements {
  std::vector<std::vector<ElementPiece>> elements;
  std::string why;  // "6 small paths of similar size" (or "... small shapes ..." with subpaths)
};

// The repeated elements of `scene`, leaving out the paths marked in `skip` (the background).
RepeatedElements find_repeated_elements(const Scene& scene, const std::vector<char>& skip);

// The pieces of one path: its subpaths gathered by containment (a subpath whose box's middle
// lies in a larger subpath's box belongs to it), as lists of subpath indices, largest first.
std::vector<std::vector<int>> subpath_pieces(const Path& p);

// Repeated elements: items whose (padded) box is at most this share of the canvas area, similar
// when their widths and heights agree within this factor, at least kRepeatedMin of them.
constexpr double kRepeatedArea = 0.02;
constexpr double kRepeatedSimilar = 1.6;
constexpr size_t kRepeatedMin = 3;

}  // namespace svgm
