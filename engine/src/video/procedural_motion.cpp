// The procedural motion library (see procedural_motion.h).
#include "video/procedural_motion.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <random>

namespace svgm {

namespace {

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(Vec2 p) { x0 = std::min(x0, p.x); y0 = std::min(y0, p.y); x1 = std::max(x1, p.x); y1 = std::max(y1, p.y); }
  double area() const { return std::max(0.0, x1 - x0) * std::max(0.0, y1 - y0); }
  Vec2 centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
};

struct Part {
  Box box;
  int parent = -1;  // the group it hangs from
  Vec2 pivot;       // where it attaches
  double reach = 1; // largest distance of its points from the pivot
};

Vec2 rotate_about(Vec2 p, Vec2 c, double a) {
  const double cs = std::cos(a), sn = std::sin(a);
  const Vec2 d = p - c;
  return c + Vec2{cs * d.x - sn * d.y, sn * d.x + cs * d.y};
}

// Keywords of each motion, matched as word prefixes.
const std::vector<std::pair<std::string, std::vector<std::string>>>& library() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> lib = {
      {"wave", {"wav", "greet", "hello", "hi ", "salut"}},
      {"nod", {"nod", "bow", "agree", "yes"}},
      {"jump", {"jump", "hop", "leap", "skip"}},
      {"bounce", {"bounc", "boing", "spring"}},
      {"sway", {"sway", "rock", "lean", "blow", "breez", "float"}},
      {"spin", {"spin", "rotat", "twirl", "turn", "whirl"}},
      {"walk", {"walk", "march", "stroll", "step"}},
      {"run", {"run", "sprint", "jog", "rush"}},
      {"fly", {"fly", "flap", "flutter", "hover", "soar", "wing"}},
      {"swim", {"swim", "paddl", "dive", "undulat", "wriggl", "slither", "crawl", "arch"}},
      {"shake", {"shak", "shiver", "trembl", "vibrat", "jitter", "box", "punch", "fenc"}},
      {"pulse", {"puls", "breath", "beat", "throb", "inflat", "grow"}},
      {"wobble", {"wobbl", "jiggl", "jell", "squish"}},
      {"dance", {"danc", "groov", "boogie", "celebrat", "cheer", "exercis", "yoga", "surf", "ski"}},
      {"sit", {"sit", "crouch", "squat", "kneel", "melt"}},
      {"wag", {"wag", "tail", "swish"}},
  };
  return lib;
}

}  // namespace

std::string motion_for_prompt(const std::string& prompt, std::string* note) {
  std::string p = " ";
  for (char c : prompt) p += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  p += " ";
  size_t best_pos = std::string::npos;
  std::string best;
  for (const auto& [motion, words] : library())
    for (const auto& w : words)
      for (size_t at = p.find(w); at != std::string::npos; at = p.find(w, at + 1))
        if (!std::isalpha(static_cast<unsigned char>(p[at - 1])) && at < best_pos) {  // word start
          best_pos = at;
          best = motion;
        }
  if (best.empty()) {
    if (note) *note = "no motion word in the prompt; using a gentle idle motion";
    return "idle";
  }
  if (note) note->clear();
  return best;
}

namespace {

std::string to_lower(const std::string& s) {
  std::string r;
  for (char c : s) r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

bool has_word(const std::string& text, const std::string& word) {
  const std::string p = " " + to_lower(text) + " ";
  for (size_t at = p.find(word); at != std::string::npos; at = p.find(word, at + 1))
    if (!std::isalpha(static_cast<unsigned char>(p[at - 1])) &&
        !std::isalpha(static_cast<unsigned char>(p[at + word.size()])))
      return true;
  return false;
}

}  // namespace

int side_for_prompt(const std::string& prompt) {
  return static_cast<int>(has_word(prompt, "right")) - static_cast<int>(has_word(prompt, "left"));
}

std::vector<Vec2> animate_scene(const Scene& scene, const std::string& motion, int frames,
                                uint32_t seed, ProceduralMotion* info, int side) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const int G = static_cast<int>(scene.groups.size());
  std::vector<Part> parts(G);
  Box all;
  for (int g = 0; g < G; ++g)
    for (int p : scene.groups[g].paths)
      for (const auto& sp : scene.paths[p].subpaths)
        for (const Vec2& q : sp.points) {
          parts[g].box.add(q);
          all.add(q);
        }
  // The body: the largest part. Every other part hangs from the larger part it overlaps most
  // (or the nearest larger one), at the centre of their overlap.
  int body = 0;
  for (int g = 1; g < G; ++g)
    if (parts[g].box.area() > parts[body].box.area()) body = g;
  for (int g = 0; g < G; ++g) {
    if (g == body) continue;
    double best = -1;
    for (int h = 0; h < G; ++h) {
      if (h == g || parts[h].box.area() < parts[g].box.area()) continue;
      const Box& a = parts[g].box;
      const Box& b = parts[h].box;
      const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
      const double score = ox > 0 && oy > 0 ? ox * oy : -std::hypot(a.centre().x - b.centre().x, a.centre().y - b.centre().y) - 1;
      if (best < 0 ? score > best : score > best) {
        best = score;
        parts[g].parent = h;
        if (ox > 0 && oy > 0)
          parts[g].pivot = {0.5 * (std::max(a.x0, b.x0) + std::min(a.x1, b.x1)), 0.5 * (std::max(a.y0, b.y0) + std::min(a.y1, b.y1))};
        else  // the corner of the part nearest the other's centre
          parts[g].pivot = {std::clamp(b.centre().x, a.x0, a.x1), std::clamp(b.centre().y, a.y0, a.y1)};
      }
    }
    if (parts[g].parent < 0) { parts[g].parent = body; parts[g].pivot = parts[g].box.centre(); }
  }
  parts[body].pivot = {parts[body].box.centre().x, parts[body].box.y1};
  for (int g = 0; g < G; ++g)
    for (int p : scene.groups[g].paths)
      for (const auto& sp : scene.paths[p].subpaths)
        for (const Vec2& q : sp.points)
          parts[g].reach = std::max(parts[g].reach, std::hypot(q.x - parts[g].pivot.x, q.y - parts[g].pivot.y));

  // Candidate parts by position relative to the body.
  const Vec2 bc = parts[body].box.centre();
  std::vector<int> upper_left, upper_right, lower, top, small_far;
  const double body_w = parts[body].box.x1 - parts[body].box.x0;
  for (int g = 0; g < G; ++g) {
    if (g == body) continue;
    const Vec2 c = parts[g].box.centre();
    const bool central = std::fabs(c.x - bc.x) < 0.25 * body_w;
    if (central && c.y < parts[body].box.y0 + 0.2 * (parts[body].box.y1 - parts[body].box.y0)) {
      top.push_back(g);  // a head: above the body and centred on it
    } else if (c.y > bc.y) {
      lower.push_back(g);
    } else if (!central) {
      (c.x < bc.x ? upper_left : upper_right).push_back(g);  // arms, wings
    }
    if (parts[g].box.area() < 0.1 * parts[body].box.area()) small_far.push_back(g);
  }
  auto pick = [&](const std::vector<int>& v) { return v.empty() ? -1 : v[rng() % v.size()]; };
  const double amp = 0.7 + 0.6 * U(rng), phase = 2 * M_PI * U(rng);
  const double H = all.y1 - all.y0, W = all.x1 - all.x0;

  // Per part, per frame: rotation about its pivot (with a bend growing along the part), and a
  // whole-scene similarity.
  std::vector<int> movers;
  std::vector<double> mover_amp;
  auto move = [&](int g, double deg) { if (g >= 0) { movers.push_back(g); mover_amp.push_back(deg * amp); } };
  const std::string& m = motion;
  if (m == "wave") {  // one arm: the side asked for or chosen by the seed, else the other, else the top part
    const bool by_seed = U(rng) < 0.5;
    const bool right = side != 0 ? side > 0 : by_seed;
    int arm = -1;
    if (side != 0) {  // a group named for the side wins, raised or hanging beside the body
      const std::string word = side > 0 ? "right" : "left";
      for (int g = 0; g < G && arm < 0; ++g) {
        const Vec2 c = parts[g].box.centre();
        const bool beside = g != body && std::fabs(c.x - bc.x) >= 0.25 * body_w && c.y < parts[body].box.y1;
        if (beside && to_lower(scene.groups[g].id).find(word) != std::string::npos) arm = g;
      }
    }
    if (arm < 0) arm = pick(right ? upper_right : upper_left);
    if (arm < 0) arm = pick(right ? upper_left : upper_right);
    if (arm < 0) arm = pick(top);
    move(arm, 35);
  }
  else if (m == "nod") move(pick(top), 14);
  else if (m == "fly") { move(pick(upper_left), 30); move(pick(upper_right), -30); }
  else if (m == "walk" || m == "run") {
    const double a = m == "run" ? 30 : 18;
    for (size_t i = 0; i < lower.size(); ++i) move(lower[i], i % 2 ? a : -a);
    move(pick(upper_left), a * 0.7);
    move(pick(upper_right), -a * 0.7);
  } else if (m == "dance") { move(pick(upper_left), 30); move(pick(upper_right), -30); }
  else if (m == "wag") move(pick(small_far), 28);
  else if (m == "wobble" || m == "swim") for (int g = 0; g < G; ++g) if (g != body) move(g, 10);
  // A part motion that found no part where it expected one (a drawing grouped unlike a figure,
  // or parts the position rules do not place): the highest part other than the body moves,
  // else the whole drawing sways, so every candidate moves.
  bool sway_instead = false;
  if (movers.empty() && (m == "wave" || m == "nod" || m == "fly" || m == "wag")) {
    int best = -1;
    for (int g = 0; g < G; ++g)
      if (g != body && (best < 0 || parts[g].box.centre().y < parts[best].box.centre().y)) best = g;
    if (best >= 0) move(best, 25);
    else sway_instead = true;
  }
  if (info) {
    info->motion = m;
    info->parts = movers;
  }

  std::vector<Vec2> out;
  for (int f = 0; f < frames; ++f) {
    const double t = frames > 1 ? static_cast<double>(f) / (frames - 1) : 0;
    const double s1 = std::sin(2 * M_PI * t + phase) - std::sin(phase);  // 0 at t = 0 and 1
    const double s2 = std::sin(4 * M_PI * t + phase) - std::sin(phase);
    // Whole-scene motion: translation, rotation about the base, scale about the centre.
    double tx = 0, ty = 0, rot = 0, sx = 1, sy = 1, shear = 0;
    if (m == "jump") ty = -0.12 * H * amp * std::fabs(std::sin(2 * M_PI * t));
    else if (m == "bounce") { ty = -0.08 * H * amp * std::fabs(std::sin(2 * M_PI * t)); sy = 1 - 0.05 * amp * std::cos(4 * M_PI * t) + 0.05 * amp; }
    else if (m == "sway" || sway_instead) rot = 6 * amp * s1 * M_PI / 180;
    else if (m == "spin") rot = 2 * M_PI * t;
    else if (m == "walk" || m == "run") ty = -0.02 * H * amp * std::fabs(std::sin(4 * M_PI * t));
    else if (m == "fly") ty = -0.04 * H * amp * s1;
    else if (m == "swim") tx = 0.05 * W * amp * s1;
    else if (m == "shake") { tx = 0.015 * W * amp * std::sin(24 * M_PI * t); ty = 0.01 * H * amp * std::sin(18 * M_PI * t + 1); }
    else if (m == "pulse") sx = sy = 1 + 0.06 * amp * (1 - std::cos(4 * M_PI * t)) / 2;
    else if (m == "wobble") shear = 0.08 * amp * s2;
    else if (m == "dance") { rot = 7 * amp * s2 * M_PI / 180; ty = -0.03 * H * amp * std::fabs(std::sin(4 * M_PI * t)); }
    else if (m == "sit") { const double k = 0.5 - 0.5 * std::cos(2 * M_PI * t); ty = 0.08 * H * amp * k; sy = 1 - 0.1 * amp * k; }
    else if (m == "idle") { sx = sy = 1 + 0.02 * (1 - std::cos(2 * M_PI * t)) / 2; rot = 2 * s1 * M_PI / 180; }
    const Vec2 base{0.5 * (all.x0 + all.x1), all.y1}, centre = all.centre();
    // Points in scene order.
    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      const int g = scene.paths[pi].group;
      double part_deg = 0;
      for (size_t i = 0; i < movers.size(); ++i)
        if (movers[i] == g) part_deg = mover_amp[i] * (m == "wave" || m == "fly" || m == "wag" ? s2 : s1);
      for (const auto& sp : scene.paths[pi].subpaths)
        for (Vec2 q : sp.points) {
          if (g >= 0 && part_deg != 0) {
            // Rotation about the attachment, bending: farther points turn a little more.
            const Part& P = parts[g];
            const double d = std::hypot(q.x - P.pivot.x, q.y - P.pivot.y) / P.reach;
            q = rotate_about(q, P.pivot, part_deg * M_PI / 180 * (0.75 + 0.5 * d));
          }
          q = Vec2{centre.x + sx * (q.x - centre.x) + shear * (q.y - centre.y), centre.y + sy * (q.y - centre.y)};
          q = rotate_about(q, base, rot) + Vec2{tx, ty};
          out.push_back(q);
        }
    }
  }
  return out;
}

}  // namespace svgm
