// Offline generator of palette_table.inc (the distinct palettes for N = 1..256).
//
// Not part of the CMake build: the engine's recursive source glob picks this file up, so its
// body is compiled only when SVGM_PALETTE_TABLE_GENERATOR is defined, and it is built by hand:
//
//   g++ -std=c++20 -O2 -DSVGM_PALETTE_TABLE_GENERATOR -I engine/src
//       engine/src/color/tools/gen_palette_table.cpp engine/src/color/palette_optimiser.cpp
//       engine/src/color/palette.cpp -o /tmp/gen_palette_table      (one command line)
//
// Modes (results accumulate in a plain-text cache, one line per run and N, so runs can be
// resumed, repeated with other seeds, and improved; the best line per N wins):
//
//   gen_palette_table search CACHE FROM TO WORK [SEED]
//       pack_points for every N in FROM..TO (seed SEED*1000003 + N, WORK pair evaluations),
//       quantise, append "N d_continuous d_quantised hex... | x y z ..." to CACHE.
//   gen_palette_table remove CACHE FROM TO WORK
//       from TO-1 down to FROM: start from the best N+1 packing with one point removed (each
//       of its 8 most crowded points in turn), polish with WORK (basin hopping from there),
//       append if it beats the best line for N. Makes d(N) >= d(N+1) for the packings.
//   gen_palette_table emit CACHE > engine/src/color/palette_table.inc
//   gen_palette_table report CACHE          N, d_continuous, d_quantised per N
//   gen_palette_table free N WORK SEED      unpinned packing of N points (checks the optimiser
//                                           against published cube packings)
#ifdef SVGM_PALETTE_TABLE_GENERATOR

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "color/palette.h"
#include "color/palette_optimiser.h"

using svgm::Rgb8;
using svgm::color::Point3;

namespace {

struct Entry {
  double cont = 0, quant = -1;
  std::string hex;
  std::vector<Point3> points;
};

std::map<int, Entry> read_cache(const std::string& path) {
  std::map<int, Entry> best;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    int n;
    Entry e;
    std::string bar;
    if (!(s >> n >> e.cont >> e.quant >> e.hex >> bar) || bar != "|") continue;
    for (int i = 0; i < n; ++i) {
      Point3 p;
      s >> p[0] >> p[1] >> p[2];
      e.points.push_back(p);
    }
    if (!s || static_cast<int>(e.hex.size()) != 6 * n) continue;
    auto it = best.find(n);
    if (it == best.end() || e.quant > it->second.quant ||
        (e.quant == it->second.quant && e.cont > it->second.cont))
      best[n] = e;
  }
  return best;
}

std::string to_hex(std::vector<Rgb8> pal) {
  std::sort(pal.begin(), pal.end(), [](const Rgb8& a, const Rgb8& b) {
    return std::tie(a.r, a.g, a.b) < std::tie(b.r, b.g, b.b);
  });
  std::string s;
  char buf[8];
  for (const auto& c : pal) {
    std::snprintf(buf, sizeof buf, "%02x%02x%02x", c.r, c.g, c.b);
    s += buf;
  }
  return s;
}

void append(const std::string& path, int n, const svgm::color::Packing& p) {
  const auto pal = svgm::color::quantise_packing(p.points);
  const double dq = svgm::min_distance(pal, true);
  std::ofstream out(path, std::ios::app);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%d %.10f %.10f ", n, p.min_distance, dq);
  out << buf << to_hex(pal) << " |";
  for (const auto& q : p.points)
    for (double v : q) {
      std::snprintf(buf, sizeof buf, " %.12f", v);
      out << buf;
    }
  out << "\n";
  std::fprintf(stderr, "N=%d d=%.6f quantised=%.6f\n", n, p.min_distance, dq);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> a(argv + 1, argv + argc);
  if (a.size() >= 5 && a[0] == "search") {
    const int from = std::atoi(a[2].c_str()), to = std::atoi(a[3].c_str());
    const double work = std::atof(a[4].c_str());
    const uint64_t seed = a.size() > 5 ? std::strtoull(a[5].c_str(), nullptr, 10) : 1;
    for (int n = from; n <= to; ++n) {
      svgm::color::PackOptions o;
      o.seed = seed * 1000003ull + static_cast<uint64_t>(n);
      o.work = work;
      append(a[1], n, svgm::color::pack_points(n, o));
    }
    return 0;
  }
  if (a.size() == 5 && a[0] == "remove") {
    const int from = std::atoi(a[2].c_str()), to = std::atoi(a[3].c_str());
    const double work = std::atof(a[4].c_str());
    for (int n = to - 1; n >= from; --n) {
      const auto cache = read_cache(a[1]);
      auto up = cache.find(n + 1);
      if (up == cache.end()) continue;
      const auto cur = cache.find(n);
      const double have = cur == cache.end() ? -1 : cur->second.cont;
      // Candidate removals: the points with the most close neighbours (the crowded ones).
      const auto& pts = up->second.points;
      std::vector<std::pair<int, int>> crowd;
      for (int i = 0; i <= n; ++i) {
        int k = 0;
        for (int j = 0; j <= n; ++j) {
          if (j == i) continue;
          double d2 = 0;
          for (int c = 0; c < 3; ++c) d2 += (pts[i][c] - pts[j][c]) * (pts[i][c] - pts[j][c]);
          if (std::sqrt(d2) < up->second.cont * 1.02) ++k;
        }
        crowd.push_back({-k, i});
      }
      std::sort(crowd.begin(), crowd.end());
      svgm::color::Packing best;
      best.min_distance = -1;
      for (size_t c = 0; c < std::min<size_t>(8, crowd.size()); ++c) {
        std::vector<Point3> start;
        for (int i = 0; i <= n; ++i)
          if (i != crowd[c].second) start.push_back(pts[i]);
        svgm::color::PackOptions o;
        o.seed = 7000003ull + static_cast<uint64_t>(n) * 31 + c;
        o.work = work;
        o.start = &start;
        auto p = svgm::color::pack_points(n, o);
        if (p.min_distance > best.min_distance) best = p;
      }
      if (best.min_distance > have * (1 + 1e-9)) append(a[1], n, best);
      else std::fprintf(stderr, "N=%d no gain (%.6f vs %.6f)\n", n, best.min_distance, have);
    }
    return 0;
  }
  if (a.size() == 2 && a[0] == "emit") {
    const auto cache = read_cache(a[1]);
    std::printf(
        "// Generated by engine/src/color/tools/gen_palette_table.cpp (emit); do not edit.\n"
        "// kPaletteTable[N] holds the N most distinct 8-bit colours (white reserved) as 6 hex\n"
        "// digits each, sorted by #rrggbb; the order carries no meaning. d = the palette's\n"
        "// minimum distance in the unit cube, white included.\n"
        "static const char* const kPaletteTable[] = {\n    \"\",\n");
    int expect = 1;
    for (const auto& [n, e] : cache) {
      if (n != expect) {
        std::fprintf(stderr, "missing N=%d\n", expect);
        return 1;
      }
      ++expect;
      std::printf("    // N=%d d=%.5f\n", n, e.quant);
      for (size_t i = 0; i < e.hex.size(); i += 96)
        std::printf("    \"%s\"%s\n", e.hex.substr(i, 96).c_str(),
                    i + 96 >= e.hex.size() ? "," : "");
    }
    std::printf("};\nstatic constexpr int kPaletteTableMax = %d;\n", expect - 1);
    return 0;
  }
  if (a.size() == 2 && a[0] == "report") {
    for (const auto& [n, e] : read_cache(a[1]))
      std::printf("%d %.6f %.6f\n", n, e.cont, e.quant);
    return 0;
  }
  if (a.size() == 4 && a[0] == "free") {
    svgm::color::PackOptions o;
    o.pin_white = false;
    o.work = std::atof(a[2].c_str());
    o.seed = std::strtoull(a[3].c_str(), nullptr, 10);
    const auto p = svgm::color::pack_points(std::atoi(a[1].c_str()), o);
    std::printf("%s %.7f\n", a[1].c_str(), p.min_distance);
    return 0;
  }
  std::fprintf(stderr, "usage: see the comment at the top of gen_palette_table.cpp\n");
  return 2;
}

#endif  // SVGM_PALETTE_TABLE_GENERATOR
