// The procedural video provider's motion library: a prompt in words becomes a motion of the
// SVG's parts (wave, nod, jump, bounce, sway, spin, walk, run, fly, swim, shake, pulse, wobble,
// dance, sit, wag; several words each; anything else a gentle idle), applied around pivots
// found from the geometry (where a part attaches to the part it overlaps most), with a smooth
// bend that grows along each moving part. Deterministic per seed: the seed varies amplitude,
// phase and, where there is a choice, which part moves.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

struct ProceduralMotion {
  std::string motion;       // the library entry used ("wave", ..., "idle")
  std::string note;         // e.g. "no motion word in the prompt; a gentle idle motion"
  std::vector<int> parts;   // groups that move on their own (besides whole-body motion)
};

// The motion chosen for a prompt (keyword match, case-insensitive).
std::string motion_for_prompt(const std::string& prompt, std::string* note);

// The side a prompt names for one-sided motions: +1 for the word "right", -1 for "left", 0 for
// neither (or both).
int side_for_prompt(const std::string& prompt);

// Control points of every frame: frames * (sum of the scene's path points) canvas-space points,
// in scene order (paths, subpaths, points), for t = f / (frames - 1) over one loop. `side`
// (side_for_prompt) picks the arm of a wave: first a side part whose group id says "right" or
// "left", else the part drawn on that side as the viewer sees it (drawings name their groups
// that way as often as by the character's side, and the viewer's side is what a user checks);
// 0 lets the seed choose.
std::vector<Vec2> animate_scene(const Scene& scene, const std::string& motion, int frames,
                                uint32_t seed, ProceduralMotion* info, int side = 0);

}  // namespace svgm
