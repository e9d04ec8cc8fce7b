// Fit groups along a procedural motion. The fitter moves each group by one homography (and a
// smooth field), warm-started per group from the target's tracks; a group whose paths the
// target moves apart cannot follow both motions: a ferris wheel's spokes grouped with the stand
// that holds it turned the stand's legs with the wheel in the warm start, and 60 iterations
// could not bring them back (the fit fell from 27 to 14 dB over the loop and the gate
// rejected it). When the video stage was the procedural one, its report (motion.json: the
// rig's parts and each path's travel) says what moves: a group whose paths it partly holds
// still and partly moves is split, its still paths keeping the group and its moving paths
// getting a group per rig part; a group whose moving paths belong to several rig parts is split
// the same way, the part with the most paths keeping it (a boxer's gloves, grouped with his head,
// swing with the arm while the head turns with the body); and the groups it holds wholly still
// are held still in the fit
// (flag1's pole, drawn past the canvas's edge, drifted 1.3 px farther out in the fit while the
// target held it; the ferris wheel's stand still bent with the spokes passing behind it).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

// A path moves when its largest travel in the report is above this (canvas px; the report
// rounds to 0.01 and a held part's travel is exactly 0).
constexpr double kMovingTravel = 0.05;

// `scene` with its groups split along `motion` (a motion.json report; paths matched by id).
// One line per split group in `notes` (may be null). The scene is returned unchanged when the
// report names no parts or paths.
Scene split_groups_by_motion(const Scene& scene, const nlohmann::json& motion, std::vector<std::string>* notes);

// `scene` with the groups (and group-less paths) that one moving rigid body of `motion` carries
// wholly merged into one group, the first of them in scene order (motion.json's "body": the
// paths one affine map moves in every frame, geometry/rigid_bodies.h). The fitter moves a group
// by one homography: a body cut into many small groups (the fingers of a fist, a trident's
// arrowheads) has each piece found again at every keyframe from its own few pixels, and a thin
// one that moved farther than its width between keyframes collapsed or tore (man_demon's
// raised hand shrank to a point; rejected by the result gate). One line per merged body in
// `notes` (may be null). Unchanged when the report has no bodies.
Scene merge_groups_by_body(const Scene& scene, const nlohmann::json& motion, std::vector<std::string>* notes);

// The target's own motion from `motion`'s "bodies" (per body, per frame, [a b c d e f] in canvas
// units) and each path's "body", matched to `scene`'s paths by id: FitOptions::known_body and
// known_maps. With `candidate` (the video the ranker chose, "01.mp4"), that candidate's own
// "bodies" and "path_body" (in the order of "paths") from motion.json's "candidates"; nothing
// when the report does not list it. Empty when the report has no bodies, or when a path it
// names is not in the scene.
struct KnownMotion {
  std::vector<int> body;
  std::vector<std::vector<Affine>> maps;
};
KnownMotion known_motion(const Scene& scene, const nlohmann::json& motion, const std::string& candidate = "");

// The fit groups of `scene` (as fit_plan.h names them: a group's id, a path's own id when it is
// in none) whose every path `motion` holds still: the fitter holds them at rest (FitOptions::
// held_groups), as the target does exactly. A path the report does not know is not still.
std::vector<std::string> still_groups(const Scene& scene, const nlohmann::json& motion);

}  // namespace svgm
