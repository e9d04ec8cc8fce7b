// Fit groups along a procedural motion (see motion_groups.h).
#include "fit/plan/motion_groups.h"

#include <algorithm>
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

Scene merge_groups_by_body(const Scene& scene, const nlohmann::json& motion, std::vector<std::string>* notes) {
  if (!motion.contains("paths")) return scene;
  std::map<std::string, int> body_of;  // path id -> its moving body
  for (const auto& p : motion["paths"]) {
    const int b = p.value("body", -1);
    if (b >= 0 && p.value("max_travel", 0.0) > kMovingTravel) body_of[p.value("id", "")] = b;
  }
  // The one moving body that carries all of `paths`, or -1.
  auto body = [&](const std::vector<int>& paths) {
    int b = -1;
    for (int pi : paths) {
      const auto it = body_of.find(scene.paths[pi].id);
      if (it == body_of.end() || (b >= 0 && it->second != b)) return -1;
      b = it->second;
    }
    return b;
  };
  // The fit's groups in scene order: each scene group, and each path in none as a group of its own.
  struct Unit {
    Group group;
    bool own = false;  // a group-less path
  };
  std::vector<Unit> units;
  for (const Group& g : scene.groups) units.push_back({g, false});
  for (size_t pi = 0; pi < scene.paths.size(); ++pi)
    if (scene.paths[pi].group < 0) units.push_back({Group{scene.paths[pi].id, {static_cast<int>(pi)}, ""}, true});
  std::map<int, std::vector<size_t>> of_body;  // body -> its units
  for (size_t u = 0; u < units.size(); ++u)
    if (const int b = body(units[u].group.paths); b >= 0) of_body[b].push_back(u);

  std::vector<char> absorbed(units.size(), 0);
  bool changed = false;
  for (auto& [b, us] : of_body) {
    if (us.size() < 2) continue;
    // The first unit that is a scene group keeps its id (a group-less path's id names a path).
    size_t keeper = us.front();
    for (size_t u : us)
      if (!units[u].own) {
        keeper = u;
        break;
      }
    std::string names;
    for (size_t u : us) {
      if (u == keeper) continue;
      auto& into = units[keeper].group.paths;
      into.insert(into.end(), units[u].group.paths.begin(), units[u].group.paths.end());
      absorbed[u] = 1;
      names += (names.empty() ? "" : ", ") + units[u].group.id;
    }
    std::sort(units[keeper].group.paths.begin(), units[keeper].group.paths.end());
    units[keeper].own = false;
    changed = true;
    if (notes)
      notes->push_back(units[keeper].group.id + ": " + std::to_string(us.size()) +
                       " groups the target moves as one rigid body fit as one (with " + names + ")");
  }
  if (!changed) return scene;
  Scene out = scene;
  out.groups.clear();
  for (size_t u = 0; u < units.size(); ++u)
    if (!absorbed[u] && !units[u].own) out.groups.push_back(units[u].group);
  for (Path& p : out.paths) p.group = -1;
  for (size_t gi = 0; gi < out.groups.size(); ++gi)
    for (int pi : out.groups[gi].paths) out.paths[pi].group = static_cast<int>(gi);
  return out;
}

KnownMotion known_motion(const Scene& scene, const nlohmann::json& motion, const std::string& candidate) {
  KnownMotion k;
  if (!motion.contains("paths") || !motion["paths"].is_array()) return k;
  // The maps and each listed path's body: the report's own, or the chosen candidate's.
  const nlohmann::json* bodies = motion.contains("bodies") ? &motion["bodies"] : nullptr;
  std::vector<int> listed;  // body of each entry of "paths", in order
  for (const auto& p : motion["paths"]) listed.push_back(p.value("body", -1));
  if (!candidate.empty()) {
    bodies = nullptr;
    const auto it = motion.find("candidates");
    if (it != motion.end() && it->is_array())
      for (const auto& c : *it)
        if (c.is_object() && c.value("name", "") == candidate && c.contains("bodies") && c.contains("path_body") &&
            c["path_body"].is_array() && c["path_body"].size() == listed.size()) {
          bodies = &c["bodies"];
          for (size_t i = 0; i < listed.size(); ++i)
            listed[i] = c["path_body"][i].is_number_integer() ? c["path_body"][i].get<int>() : -1;
        }
  }
  if (!bodies || !bodies->is_array()) return k;
  for (const auto& body : *bodies) {
    std::vector<Affine> maps;
    for (const auto& m : body) {
      if (!m.is_array() || m.size() != 6) return {};
      for (const auto& v : m)
        if (!v.is_number()) return {};
      maps.push_back({m[0].get<double>(), m[1].get<double>(), m[2].get<double>(), m[3].get<double>(), m[4].get<double>(),
                      m[5].get<double>()});
    }
    k.maps.push_back(std::move(maps));
  }
  std::map<std::string, int> body_of;
  for (size_t i = 0; i < listed.size(); ++i) body_of[motion["paths"][i].value("id", "")] = listed[i];
  k.body.assign(scene.paths.size(), -1);
  for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
    const auto it = body_of.find(scene.paths[pi].id);
    if (it == body_of.end() || it->second >= static_cast<int>(k.maps.size())) return {};
    k.body[pi] = it->second;
  }
  return k;
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
