// Small file helpers shared by svgmotion's built-in plugins.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "svgmotion/png_io.h"
#include "svgmotion/scene.h"

namespace svgm::plugin {

// Copies a file or a folder to `to` (replacing it), through a temporary name. A file follows
// write_file_atomic's rules for `to` (svgmotion/atomic_file.h): a device or FIFO is refused,
// a symbolic link is written through.
void copy_atomic(const std::filesystem::path& from, const std::filesystem::path& to);
// Writes JSON (indented) through a temporary name.
void write_json(const std::filesystem::path& file, const nlohmann::json& j);
// Renders `scene` at `width` px over white into a PNG (OpenCL device `device`).
// The scene at rest on white, `width` px wide (height by its aspect), on `device`.
RgbaImage render_image(const Scene& scene, int width, const std::string& device);

void render_png(const Scene& scene, int width, const std::string& device,
                const std::filesystem::path& file);
// "#rrggbb" of a colour.
std::string hex_color(const Rgba& c);

// The ranker's last step: the chosen candidate becomes the run's target.mp4 (an mp4 copied
// atomically; a frames folder, webm, ... re-encoded as mp4 at its own size and rate).
void write_target(const std::filesystem::path& chosen, const std::filesystem::path& target);

// The colours the candidate videos are drawn in, for rankers: the palette's (palette.json)
// when the videos were generated from the recoloured image, the SVG's own (every fill and
// stroke of grouped.svg) for a video the user brings (`video: file`), following the fitter's
// stages.fitter.colors (auto | palette | original). `who` names the ranker in errors.
std::vector<Rgba> candidate_colours(const nlohmann::json& request, const std::string& who);

// The fitter's keyframes for this run: stages.fitter.keyframes, raised to the count the chosen
// procedural candidate asks for (motion.json's candidates[].keyframes, ranking.json's choice,
// else the first candidate; motion_plan.h fit_plan), at most twice as many gaps. The tracker
// samples its flows at the same keyframes. `why` (may be null) gets a line when it was raised.
int fitter_keyframes(const nlohmann::json& request, std::string* why = nullptr);

// The keyframes each procedural candidate's motion asks of the fitter, by candidate name
// ("00.mp4"), from the run directory's motion.json; empty for any other video plugin.
std::map<std::string, int> candidate_keyframes(const nlohmann::json& request);

}  // namespace svgm::plugin
