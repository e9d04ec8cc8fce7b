// motion.json (motion_report, body_maps_json, path_motion_json; motion_plan.h): the rig's
// parts, the plan's actions with their amplitudes, directions and reasons, and what each path's
// points do in the target video.
#include "procedural/motion_plan.h"

#include <algorithm>
#include <cmath>

#include "procedural/motion_direction.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/hang_support.h"
#include "procedural/seat_support.h"
#include "procedural/support_band.h"
#include "geometry/rigid_bodies.h"

namespace svgm {

using namespace motion_plan_internal;

nlohmann::json motion_report(const Scene& scene, const Rig& rig, const MotionPlan& plan) {
  using nlohmann::json;
  json parts = json::array();
  for (const auto& P : rig.parts) {
    json p = {{"name", P.name},
              {"group", P.group >= 0 && P.group < static_cast<int>(scene.groups.size()) ? scene.groups[P.group].id : ""},
              {"role", role_name(P.role)},
              {"named_in_document", P.named},
              {"side", P.side > 0 ? "right" : P.side < 0 ? "left" : "centre"},
              {"parent", P.parent >= 0 ? rig.parts[P.parent].name : ""},
              {"pivot", {std::round(P.pivot.x * 100) / 100, std::round(P.pivot.y * 100) / 100}},
              {"why", P.why}};
    p["box"] = {std::round(P.box.x0 * 10) / 10, std::round(P.box.y0 * 10) / 10, std::round(P.box.x1 * 10) / 10, std::round(P.box.y1 * 10) / 10};
    json ids = json::array();
    for (size_t pi = 0; pi < rig.part_of_path.size(); ++pi)
      if (&rig.parts[rig.part_of_path[pi] >= 0 ? rig.part_of_path[pi] : 0] == &P && rig.part_of_path[pi] >= 0) ids.push_back(scene.paths[pi].id);
    p["paths"] = ids;
    if (P.round) p["round"] = true;
    parts.push_back(p);
  }
  json actions = json::array();
  for (const auto& a : plan.actions) {
    json names = json::array(), pivots = json::array();
    for (int p : a.parts) {
      names.push_back(rig.parts[p].name);
      const Vec2 c = a.primitive == Primitive::Spin ? rig.parts[p].box.centre() : rig.parts[p].pivot;
      pivots.push_back({std::round(c.x * 100) / 100, std::round(c.y * 100) / 100});
    }
    if (a.rooted) pivots.push_back({std::round(a.root.x * 100) / 100, std::round(a.root.y * 100) / 100});  // where a plant is held
    const char* unit = unit_of(a.primitive);
    actions.push_back({{"verb", a.verb},
                       {"motion", primitive_name(a.primitive)},
                       {"target", target_name(a.target)},
                       {"parts", a.target == Target::Whole ? json("whole figure") : a.target == Target::Repeated ? json(std::to_string(rig.repeated.size()) + " repeated elements") : names},
                       {"pivots", pivots},
                       {"amplitude", std::round(plan.amplitude(a) * 1e4) / 1e4},
                       {"unit", unit},
                       {"cycles", a.cycles},
                       {"region", a.region == Region::None ? "" : a.region == Region::Sides ? "sides" : a.region == Region::Lower ? "lower part"
                                  : a.region == Region::Top ? "top" : a.region == Region::Located ? "located part" : "far end"},
                       {"one_sided", a.one_sided},
                       {"direction", direction_words(a)},
                       {"words", a.words},
                       {"fallback", a.words == "(fallback)"},  // plan_from_prompt's sway: no motion word understood
                       {"why", a.why}});
    // A located part (part_locator.h): the paths it found, by id.
    if (a.region == Region::Located) {
      json ids = json::array();
      for (int p : a.lobe_paths) ids.push_back(scene.paths[p].id);
      actions.back()["located_paths"] = ids;
    }
  }
  std::string root = rig.root >= 0 ? rig.parts[rig.root].name : "";
  json held = json::array();
  for (int h : plan.held) held.push_back(rig.parts[h].name);
  // The ground the prompt names and the paths drawn as it (they stay).
  json ground = nullptr;
  if (!plan.ground.empty()) {
    json ids = json::array();
    const std::vector<char> band = support_paths(scene, rig, plan.ground);
    for (size_t pi = 0; pi < band.size(); ++pi)
      if (band[pi]) ids.push_back(scene.paths[pi].id);
    ground = {{"words", plan.ground}, {"paths", ids},
              {"why", ids.empty() ? "no band drawn across the figure's bottom: nothing is held"
                                  : "the band drawn across the figure's bottom stays while the figure moves"}};
  }
  // What the prompt says the figure hangs from, the paths drawn as it and its grip.
  json hang = nullptr;
  if (!plan.hang.empty()) {
    const HangSupport h = hang_support(scene, rig);
    json ids = json::array();
    for (size_t pi = 0; pi < h.paths.size(); ++pi)
      if (h.paths[pi]) ids.push_back(scene.paths[pi].id);
    hang = {{"words", plan.hang}, {"paths", ids}, {"grip", h.found ? json::array({std::round(h.grip.x * 100) / 100, std::round(h.grip.y * 100) / 100}) : json(nullptr)}};
  }
  // What the prompt says the figure sits in or on, the paths drawn as it and the sitter's box.
  json seat = nullptr;
  if (!plan.seat.empty()) {
    const SeatSupport s = seat_support(scene, rig);
    json ids = json::array();
    for (size_t pi = 0; pi < s.seat.size(); ++pi)
      if (s.seat[pi]) ids.push_back(scene.paths[pi].id);
    const RigBox& b = s.sitter;
    seat = {{"words", plan.seat}, {"paths", ids}, {"sitter", s.found ? json::array({b.x0, b.y0, b.x1, b.y1}) : json(nullptr)}};
  }
  return {{"source", plan.source},
          {"held", held},
          {"ground", ground},
          {"hang", hang},
          {"seat", seat},
          {"root", root},
          {"parts", parts},
          {"facing", rig.eye_side == 0 ? json("") : json(std::string(rig.eye_side < 0 ? "left: " : "right: ") + rig.eye_why)},
          {"repeated_elements", rig.repeated.size()},
          {"plan", actions},
          {"amplitude_scale", std::round(plan.scale * 1e4) / 1e4},
          {"keyframes", plan.keyframes},
          {"not_understood", plan.not_understood},
          {"readings", plan.readings},
          {"warnings", plan.warnings},
          {"notes", plan.notes}};
}

std::vector<PathMotion> path_motion(const Scene& scene, const std::vector<Vec2>& pts, int frames,
                                    std::vector<std::vector<Affine>>* body_maps) {
  std::vector<PathMotion> out(scene.paths.size());
  const size_t per = frames > 0 ? pts.size() / frames : 0;
  size_t i = 0;
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    PathMotion& m = out[p];
    double sum = 0;
    for (const auto& sp : scene.paths[p].subpaths)
      for (const Vec2& rest : sp.points) {
        double far = 0;
        m.rest.add(rest);
        for (int f = 0; f < frames; ++f) {
          const Vec2 q = pts[f * per + i];
          far = std::max(far, std::hypot(q.x - rest.x, q.y - rest.y));
        }
        m.max_travel = std::max(m.max_travel, far);
        m.travel.push_back(static_cast<float>(far));
        sum += far;
        ++m.points;
        ++i;
      }
    m.mean_travel = m.points ? sum / m.points : 0;
  }
  // To a ten-thousandth of the canvas's diagonal: the rig's maps are exact in double, and a
  // bending region's points leave any one map by far more.
  RigidBodies rb = rigid_bodies(scene, pts, frames, 1e-4 * std::hypot(scene.width, scene.height));
  for (size_t p = 0; p < out.size(); ++p) out[p].body = rb.body[p];
  if (body_maps) *body_maps = std::move(rb.maps);
  // The box each path's curves sweep: every cubic at t = 0, 1/4, 1/2, 3/4, 1 in every frame
  // (the drawing, not its handles: a turning circle's handles sweep beyond the circle).
  for (int f = 0; f < frames; ++f) {
    size_t j = 0;
    for (size_t p = 0; p < scene.paths.size(); ++p)
      for (const auto& sp : scene.paths[p].subpaths) {
        const Vec2* c = &pts[f * per + j];
        for (size_t s = 0; s + 3 < sp.points.size(); s += 3)
          for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
            const double u = 1 - t;
            out[p].swept.add(u * u * u * c[s] + 3 * u * u * t * c[s + 1] + 3 * u * t * t * c[s + 2] + t * t * t * c[s + 3]);
          }
        if (sp.points.size() < 4)
          for (size_t s = 0; s < sp.points.size(); ++s) out[p].swept.add(c[s]);
        j += sp.points.size();
      }
  }
  return out;
}

nlohmann::json body_maps_json(const std::vector<std::vector<Affine>>& maps) {
  auto r = [](double v) { return std::round(v * 1e6) / 1e6; };
  nlohmann::json a = nlohmann::json::array();
  for (const auto& body : maps) {
    nlohmann::json frames = nlohmann::json::array();
    for (const Affine& m : body) frames.push_back({r(m.a), r(m.b), r(m.c), r(m.d), r(m.e), r(m.f)});
    a.push_back(frames);
  }
  return a;
}

nlohmann::json path_motion_json(const Scene& scene, const std::vector<PathMotion>& motion) {
  auto r = [](double v) { return std::round(v * 100) / 100; };
  nlohmann::json a = nlohmann::json::array();
  for (size_t p = 0; p < motion.size(); ++p) {
    const PathMotion& m = motion[p];
    nlohmann::json pt = nlohmann::json::array();
    size_t k = 0;
    // Rest positions rounded as the rest box is: rounded to 0.1, a point on the box's edge fell
    // outside it (9.9 left of a box from 9.92) and a reader's region ending at the drawing's edge
    // left out the wheels' outermost points (om_cyclist_pedal).
    for (const auto& sp : scene.paths[p].subpaths)
      for (const Vec2& q : sp.points) {
        pt.push_back(r(q.x));
        pt.push_back(r(q.y));
        // Travels to 0.01 as well: to 0.1, a wing raised to the visible floor (4.1 px on a
        // 47 px emoji, 0.05 px is 1.2 % of it) read as 7.99 % of the figure's size.
        pt.push_back(r(k < m.travel.size() ? m.travel[k] : 0));
        ++k;
      }
    a.push_back({{"id", scene.paths[p].id},
                 {"point_travel", pt},
                 {"points", m.points},
                 {"max_travel", r(m.max_travel)},
                 {"mean_travel", r(m.mean_travel)},
                 {"body", m.body},
                 {"rest", {r(m.rest.x0), r(m.rest.y0), r(m.rest.x1), r(m.rest.y1)}},
                 {"swept", {r(m.swept.x0), r(m.swept.y0), r(m.swept.x1), r(m.swept.y1)}}});
  }
  return a;
}

}  // namespace svgm

