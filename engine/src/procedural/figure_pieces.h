// The separate pieces of a figure drawn apart: two fallen leaves side by side, a few
// snowflakes, petals blown off a flower. "The leaves tumble in the wind" moves each piece its
// own way (PlannedAction::apart): moved as one, two leaves fell in step like one stiff
// drawing.
//
// Pieces are the rig's parts (not the background) joined where their boxes overlap or come
// within kPieceGap of the figure's diagonal of each other. The figure is in pieces when there
// are at least two and each covers at least kPieceMin of the figure's box (a dot beside a
// leaf is a detail, not a piece that tumbles by itself).
#pragma once

#include <vector>

#include "procedural/part_rig.h"

namespace svgm {

inline constexpr double kPieceGap = 0.01;
inline constexpr double kPieceMin = 0.05;

// Per part of the rig: its piece (0, 1, ...), -1 for a background or empty part; every figure
// part 0 when the figure is not in pieces (see above).
std::vector<int> figure_pieces(const Rig& rig);

// The number of pieces figure_pieces found (1 when the figure is not in pieces; 0 when no part
// is the figure's).
int piece_count(const std::vector<int>& pieces);

}  // namespace svgm
