// What each point of a drawing's line art rides on: an outline drawn over a fill moves exactly
// as the fill does, and a fill moves with the outline the plan moves when the outline traces it.
//
// Many drawings keep their colours and their line art apart: openmoji draws every shape's fill in
// one group and every black outline in another, twemoji and clipart often lay a shading or a
// contour over the fill it shades. The rig (part_rig.h) then puts a fill and the outline drawn on
// it in different parts, and a motion that moves one left the other: a turtle's green neck slid
// out of its black contour, a runner's torso outline swung away from its fill, a squid's outline
// strokes waved while the coloured strokes of its tentacles stayed, a butterfly's wing outlines
// flapped off their fills, a fencer's black body stood out beside its outline as his torso bent
// (openmoji 1F93A: the suite's share went from 0.61 to 0.94 once they moved as one).
//
// Here each control point of such a path takes the motion of a path it is drawn on (its "host"),
// so a point of the outline and the point of the fill under it go through the same rigid motion
// and the same bends (animate_plan applies every motion as the host's: its part, its bends, its
// place in a located part's paths). Two rules, in order:
//  1. A fill that the plan does not move, traced by a path it does move (most of the fill's
//     points lie within that path's stroke of its line: a wing's fill under the wing's outline,
//     a coloured tentacle stroke beside its black one), moves with that path, all of it.
//  2. A point of line art (a path stroked without fill, or any path of a detail part) lying on a
//     fill (inside it, or within the line's stroke width of its edge; on a coloured stroke: within
//     its half width plus the line's width of its line) of another part, painted before it, moves
//     as that fill moves now (after rule 1). Of several fills, the most specific (the smallest);
//     a point on a fill that already moves as the point's own path keeps its own motion. A path
//     the plan moves is not bound to a fill the plan leaves still (rule 1 carries the fill
//     instead), and its points on no fill take the motion of their nearest bound neighbour along
//     the line, so it is never cut in two motions. Handles go with the point they leave from or
//     arrive at, so a curve's tangent turns with its point.
// A stroke running from a limb onto the body has points of both: it stretches across the joint
// with them instead of following one. Paths of parts turning their own way (`fixed`: wheels and
// what turns with them) neither ride nor carry: a spoke turns with its wheel, not with the cabin
// at its end.
#pragma once

#include <vector>

#include "procedural/part_rig.h"
#include "svgmotion/scene.h"

namespace svgm {

// Per path, per control point (subpaths in order, points in order): the path whose motion the
// point takes, or -1 where it keeps its own. Empty inner vectors for paths no point of which is
// bound elsewhere. `moves` (per path, may be empty: nothing moved apart): the plan moves the path
// apart from the figure as a whole. `fixed` (per part, may be empty): parts that turn their own
// way. Background parts are never hosts.
std::vector<std::vector<int>> bind_to_hosts(const Scene& scene, const Rig& rig, const std::vector<char>& moves = {},
                                            const std::vector<char>& fixed = {});

}  // namespace svgm
