// Hands drawn at the face: a boxer's gloves raised in guard before his face, a hand held to the
// mouth. A grouper that groups by colour and nearness puts them with the head (man_boxing2's
// gloves were 4 of its head group's 12 paths), so an arm's punch swung the arm while the gloves
// turned only with the body. The rig takes them from the head (part_rig.cpp's
// split_head_holds) and hangs them from the arm they lie on: a path of the head lying beside
// the face (its middle outside the face's box) that overlaps an arm's box more than the face's
// is the arm's; so is a smaller path beside the face with its middle inside such a path's box
// (a glove's lacing).
#pragma once

#include <vector>

#include "procedural/part_rig.h"

namespace svgm {

// For the paths of a head part (`boxes`, `areas`: each path's box and fill area) and the boxes
// of the figure's arms (`arms`): per path, the index of the arm that holds it, or -1 (the face,
// the largest path, and whatever lies on it stays the head's).
std::vector<int> held_at_head(const std::vector<RigBox>& boxes, const std::vector<double>& areas,
                              const std::vector<RigBox>& arms);

}  // namespace svgm
