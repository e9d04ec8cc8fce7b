// The procedural video's optional `llm` planner (stages.video.options.planner: llm): asks an
// OpenAI-compatible chat endpoint that takes images for the motion plan, in the syntax of
// stages.video.options.motion ("flap:wing_left+wing_right, bob:whole slow"), instead of reading
// the prompt's words offline.
//
// Request (plugins/common/chat_client.h, the llm grouper's and ranker's client and settings):
//   {"model", "temperature": 0, "seed": the run's seed, "messages": [
//     system: the plan syntax, the verbs of the motion library (motion_verbs.h) and the modifiers;
//     user: [text: the parts (number, name, role, box in canvas px) and the prompt;
//            image_url: the recoloured drawing as a PNG data URL, each part outlined in a colour
//            of its own with its number on it (image/numbered_parts.h)]]}
// Answer: choices[0].message.content, one line of plan (``` fences and surrounding backticks or
// quotes are taken off). It is checked as an explicit plan is (parse_explicit_plan, then
// plan_from_steps on the rig: unknown verbs, modifiers and parts, empty items), and anything
// else (no url, refused, timeout, an HTTP status, a malformed reply, an empty or multi-line
// answer) is a chat::Failure whose one-line reason the plugin reports before planning offline.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "svgmotion/plugin.h"
#include "svgmotion/scene.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm::plugin {

struct LlmPlan {
  std::string model;
  std::string answer;               // the model's text as it came (scrubbed of the key)
  std::string plan;                 // the plan line that was checked
  std::vector<ExplicitStep> steps;  // the plan, parsed and checked against the rig
};

// Asks the model (`options`: stages.video.options; `device`: the OpenCL device for the render).
// Throws chat::Failure with the reason to fall back; svgm::Error only for a user's Ctrl-C.
LlmPlan ask_llm_planner(const nlohmann::json& options, const Scene& scene, const Rig& rig, const std::string& prompt,
                        uint32_t seed, const std::string& device, const svgm_host* host);

// ask_llm_planner with its failure reported: on the terminal (one warning: the reason, then
// "using the offline planner") and in `record` (motion.json's "planner": source llm with the
// model, plan and answer, or source offline with the fallback reason).
struct PlannerOutcome {
  bool from_llm = false;
  std::vector<ExplicitStep> steps;  // the model's plan (from_llm), else none
  nlohmann::json record;
};
PlannerOutcome run_llm_planner(const nlohmann::json& options, const Scene& scene, const Rig& rig, const std::string& prompt,
                               uint32_t seed, const std::string& device, const svgm_host* host);

// The model's answer as a plan line, checked against the rig; chat::Failure naming what is wrong.
std::vector<ExplicitStep> check_llm_plan(const std::string& answer, const Rig& rig, std::string& plan_line);

}  // namespace svgm::plugin
