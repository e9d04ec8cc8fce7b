// The rig the procedural motion moves: the scene's parts (groups) with names, roles, pivots
// and a hierarchy, found from names where the drawing has them and from geometry otherwise.
//
// Names. A part is named from the user's document (ids, classes, <title> and inkscape:label
// of its paths and their ancestors: the deepest element holding all of the part's paths that
// has a meaningful name, "arm_right"), from the grouper's names when it gave some (grouper
// llm), else from its role ("wing_left" is never invented: geometric names are role names such
// as "limb_upper_left", "head", "root").
//
// Roles from geometry (canvas space, y down):
//  - background: a backdrop (scene/backdrop.h: a large box at two canvas edges, painted
//    early, its outline running along the canvas's edges: cut by the frame), the scenery
//    around a scene's subject (scenery.h), or a part named background/sky/ground/floor. It
//    stays still unless a prompt asks for it.
//  - root: the largest central part of the figure (area times centrality).
//  - every other part hangs from a larger part (the root for parts larger than the root): the
//    one its box overlaps most, or the nearest. Its pivot is the centroid of its control
//    points inside the parent's box (where it attaches), else its point nearest the parent; a
//    limb drawn as one open stroke turns about its end nearest the root's top (an arm) or
//    bottom (a leg).
//    Parts hanging from a non-root part form limb chains and move with their parent.
//  - relative to the root, the parts hanging from it are the head (central, above; a tall thin
//    part there is a raised wing or arm), upper limbs (arms, wings: beside the root, not below
//    its middle), lower limbs (legs: below its
//    middle) and the tail (the attached part farthest from the root, not the head).
//  - side: the figure's own side. A figure faces the viewer, so its right is drawn on the
//    viewer's left; a part named "right"/"left" keeps its name's side.
//  - round parts (a near-square box whose outline fills about pi/4 of it) are wheels.
//  - hands drawn at the face (a boxer's gloves in guard) that a grouper put with the head hang
//    from the arm they lie on (hands_at_head.h).
//  - repeated elements: at least three small paths or subpath pieces of similar size (drops,
//    stars, leaves), each with any smaller ones drawn inside its box (a highlight), moved one by
//    one (repeated_elements.h).
//  - arms drawn in a part's largest filled outline (a ghost's body path going out round each
//    arm and back): its arm lobes (outline_lobes.h), which a prompt's arms bend when the part
//    is the region that stands in for arms.
//  - a line drawing (every path an open stroke, stroke_rig.h): each stroke is a part, sized by
//    its length and placed by its curve's box; the strokes alongside the root are the body with
//    it, the head is above the body's top tenth, and a limb stroke hangs from a longer stroke of
//    its limb that one of its ends touches, else from the root, turning about its end nearer
//    the body.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"
#include "procedural/outline_lobes.h"

namespace svgm {

struct RigBox {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(Vec2 p);
  void add(const RigBox& b);
  bool empty() const { return x1 < x0; }
  double w() const { return std::max(0.0, x1 - x0); }
  double h() const { return std::max(0.0, y1 - y0); }
  double area() const { return w() * h(); }
  Vec2 centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
  // Whether this box lies within `outer` grown by `grow` on every side.
  bool within(const RigBox& outer, double grow = 0) const {
    return x0 >= outer.x0 - grow && x1 <= outer.x1 + grow && y0 >= outer.y0 - grow && y1 <= outer.y1 + grow;
  }
};

enum class Role { Root, Head, UpperLimb, LowerLimb, Tail, Detail, Background };
const char* role_name(Role r);

struct RigPart {
  int group = -1;             // index into Scene::groups
  std::string name;           // from the document, the grouper, or the role
  std::vector<std::string> words;  // lower-case name words (for prompt nouns and plan patterns)
  bool named = false;         // the name came from the document or the grouper
  Role role = Role::Detail;
  int side = 0;               // the figure's own side: +1 right, -1 left, 0 centre
  int parent = -1;            // index into Rig::parts, -1 for the root and the background
  int chain_top = -1;         // the ancestor hanging from the root (itself when it does)
  Vec2 pivot;                 // where it attaches to its parent (the root: its base centre)
  RigBox box;
  double base_x0 = 0, base_x1 = 0;  // the x-extent of its control points in the lowest quarter
                                    // of its box (a ghost's hem, a bat's feet): its core's width
  double area = 0;            // fill area of its outlines (shoelace over control polygons)
  bool round = false;         // a wheel-like part
  Affine wheel_plane;         // a round part's turn R is wheel_plane R wheel_plane^-1 (a wheel
                              // seen at a slant: stroke_rig.h's loop_plane); identity if upright
  bool carried = false;       // turns with the wheel it hangs from (its spokes and hub drawn in
                              // one group with its stand: part_rig.cpp's split_wheel_loads)
  std::vector<ArmLobe> arm_lobes;  // arms drawn in its largest outline (outline_lobes.h)
  std::string why;            // one phrase: how its role was found
};

// One piece of a repeated element: a whole path (subpath -1), or one subpath of a path that
// draws several elements (rain drops as the closed contours of one path; repeated_elements.h).
struct ElementPiece {
  int path = -1;
  int subpath = -1;
};

// A drawn element of the figure (part_locator.h finds parts the prompt names among them): a
// path, or one of its subpaths when they lie apart (a crab's claws drawn in its body's path).
struct RigElement {
  int path = -1;
  int subpath = -1;            // -1: every subpath of the path
  RigBox box;
  std::vector<Vec2> points;    // its control points
  double area = 0;             // its outlines' fill area (an open stroke's: length times width)
  bool thin = false;           // an open stroke drawn without fill
  double lightness = -1;       // its plain fill's luma (0 black .. 1 white), -1 without one
};

struct Rig {
  std::vector<RigPart> parts;  // one per scene group, same order
  int root = -1;
  RigBox canvas;               // 0,0 .. width,height
  RigBox figure;               // every non-background part
  // Repeated small elements (repeated_elements.h): each element is a list of paths or subpaths.
  std::vector<std::vector<ElementPiece>> repeated;
  std::string repeated_why;
  std::vector<int> part_of_path;  // path index -> part index (-1 for paths without a group)
  // The limbs of the figure's silhouette (every part but the background: fills and outlines
  // together, so a tail drawn as an outline over a body's fill is one limb), skeleton_lobes.h.
  std::vector<ArmLobe> limbs;
  std::vector<RigElement> elements;  // the figure's drawn elements (part_locator.h)
  // The head's side from a drawn eye (eye_cue.h): -1 left, +1 right, 0 none seen; the eye's middle.
  int eye_side = 0;
  Vec2 eye;
  std::string eye_why;
};

// Names for the paths of a scene from its source document: path id -> the named elements from
// the path up through its ancestors, innermost first, each as {locator, name as written}
// ({"/svg/g[2]", "arm_right"}). Only meaningful names are kept ("path12", "SVGID_3_" are not).
struct NamedElement {
  std::string locator;
  std::string name;
};
using SourceNames = std::map<std::string, std::vector<NamedElement>>;

// Reads `original` (the user's SVG) for the names of each path (ids as read_svg_file gives
// them). Missing or unreadable files give an empty map (names are a help, not a need).
SourceNames read_source_names(const std::string& original);

// `group_names` (optional, per scene group) are names a grouper gave.
Rig build_rig(const Scene& scene, const SourceNames& names, const std::vector<std::string>& group_names = {});

// The pivot of a limb drawn as one open, unfilled stroke: of its two ends (its endpoints, or for
// a stroke folding back on itself, their middle and the fold's tip) the one nearest `joint`
// (the body's shoulders or hips). Nothing for filled or closed paths and several subpaths.
std::optional<Vec2> stroke_limb_pivot(const Path& p, Vec2 joint);

// Lower-case words of a name: "upperArm_Right-2" -> {"upper", "arm", "right"}.
std::vector<std::string> name_words(const std::string& name);

}  // namespace svgm
