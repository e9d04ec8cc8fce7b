// Fit groups along a procedural motion (see motion_groups.h).
#include "fit/motion_groups.h"

#include <map>

namespace svgm {

Scene split_groups_by_motion(const Scene& scene, const nlohmann::json& motion, std::vector<std::string>* notes) {
  if (!motion.contains("parts") || !motion.contains("paths")) return scene;
  std::map<std::string, std::string> part_of;  // path id -> part name
  for (const auto& part : motion["parts"])
    for (const auto& id : part.value("paths", nlohmann::json::array())) part_of[id.get<std::string>()] = part.value("name", "");
  std::map<std::string, bool> moving;
  for (const auto& p : motion["paths"]) moving[p.value("id", "")] = p.value("max_travel", 0.0) > kMovingTravel;

  Scene out = scene;
  out.groups.clear();
  for (const Group& g : scene.groups) {
    std::vector<int> still;
    std::map<std::string, std::vector<int>> moved;  // part name -> its moving paths of the group
    bool known = true;
    for (int pi : g.paths) {
      const std::string& id = scene.paths[pi].id;
      const auto m = moving.find(id);
      const auto part = part_of.find(id);
      known = known && m != moving.end() && part != part_of.end();
      if (!known) break;
      if (m->second) moved[part->second].push_back(pi);
      else still.push_back(pi);
    }
    // Split when it holds some paths still and moves others, or moves paths of two parts (hands
    // the rig took from the head's group: the arm swings them while the head turns with the body).
    if (!known || moved.empty() || (still.empty() && moved.size() < 2)) {
      out.groups.push_back(g);
      continue;
    }
    std::string keeper;  // with no still paths, the part with the most moving paths keeps the group
    if (still.empty())
      for (const auto& [name, paths] : moved)
        if (keeper.empty() || paths.size() > moved[keeper].size()) keeper = name;
    Group kept = g;
    kept.paths = still.empty() ? moved[keeper] : still;
    out.groups.push_back(kept);
    std::string names;
    for (auto& [name, paths] : moved) {
      if (name == keeper) continue;
      Group piece = g;
      piece.id = g.id + "-" + name;
      piece.paths = paths;
      out.groups.push_back(piece);
      names += (names.empty() ? "" : ", ") + name;
    }
    if (notes && still.empty())
      notes->push_back(g.id + ": its paths move as " + std::to_string(moved.size()) + " parts; " + keeper +
                       " keeps the group, the others fit as groups of their own (" + names + ")");
    else if (notes)
      notes->push_back(g.id + ": " + std::to_string(still.size()) + " still paths keep the group; the moving ones fit as " +
                       std::to_string(moved.size()) + " groups (" + names + ")");
  }
  // Paths point at their new groups.
  for (Path& p : out.paths) p.group = -1;
  for (size_t gi = 0; gi < out.groups.size(); ++gi)
    for (int pi : out.groups[gi].paths) out.paths[pi].group = static_cast<int>(gi);
  return out;
}

std::vector<std::string> still_groups(const Scene& scene, const nlohmann::json& motion) {
  std::vector<std::string> out;
  if (!motion.contains("paths")) return out;
  std::map<std::string, bool> still;
  for (const auto& p : motion["paths"]) still[p.value("id", "")] = !(p.value("max_travel", 1e300) > kMovingTravel);
  auto is_still = [&](int pi) {
    const auto it = still.find(scene.paths[pi].id);
    return it != still.end() && it->second;
  };
  for (const Group& g : scene.groups) {
    bool all = !g.paths.empty();
    for (int pi : g.paths) all = all && is_still(pi);
    if (all) out.push_back(g.id);
  }
  for (size_t pi = 0; pi < scene.paths.size(); ++pi)
    if (scene.paths[pi].group < 0 && is_still(static_cast<int>(pi))) out.push_back(scene.paths[pi].id);
  return out;
}

}  // namespace svgm
