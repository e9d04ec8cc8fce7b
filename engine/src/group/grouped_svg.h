// Writing a scene as a flat grouped SVG: one <g> per part (see structural_grouper.h).
//
// The new document's root has width and height equal to the scene's canvas size and
// viewBox="0 0 W H", so user space is canvas space: every path's `d` is written from the
// scene's canvas-space cubics ("M x y C ... Z", every transform of the source baked in) and no
// element carries a transform. The source root's top-level <defs> and <style> elements are
// copied (deep) before the groups. The body is a flat sequence of <g> elements (never
// nested), each holding <path> elements with the path's id and its paint in a `style`
// attribute (fill colour, fill-opacity, fill-rule, stroke colour, stroke-opacity,
// stroke-width, stroke-linejoin, stroke-linecap, stroke-miterlimit, opacity), so that rules of
// a copied <style> sheet cannot override them. Paths appear in the scene's paint order.
//
// Group k (1-based, in the order of `groups`) is written as <g id="group-k"
// data-group="group-k">. When groups interleave in paint order (A below B below A'), a group
// is split into its runs of consecutive paths: the first run has id "group-k", the next ones
// "group-k-b", "group-k-c", ... ("group-k-27" and so on past "z"), and every run carries
// data-group="group-k", so a reader joins the runs of one part by that attribute.
//
// `names` (optional, one per group; empty ones are skipped) are what the parts are, from a
// grouper that knows ("left wing"): written as data-name on every run of the group, read back
// as Group::name, so that later stages (the procedural video's rig) use them.
//
// `groups` must hold every path index exactly once (svgm::Error otherwise). The file is written
// under a temporary name and renamed. Reading it back with read_svg_file gives the same paths
// (ids, order, geometry within 1e-5 canvas units, paint).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

void write_grouped_svg(const std::filesystem::path& source, const Scene& scene,
                       const std::vector<std::vector<int>>& groups,
                       const std::filesystem::path& out, const std::vector<std::string>& names = {});

}  // namespace svgm
