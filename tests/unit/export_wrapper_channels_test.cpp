// A wrapper transform's channels keyed separately (compact_motion.h, wrapper_keys): a part that
// turns while its position holds (or only jitters within the tolerance) writes one position key
// however many keys its angle needs, in SMIL's form and in Lottie's `tr`; and the channels as
// their own keys draw them, composed, stay within the tolerance of the exact maps at every value
// and at the times checked between values.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "export/compact_motion.h"
#include "export/lottie_motion.h"

using namespace svgm;

namespace {

constexpr size_t kValues = 49;  // 2 s at 24 fps
const Vec2 kPivot{50, 20};
// An 8 x 40 arm hanging from the pivot (canvas = parent space).
const std::vector<double> kRest{46, 20, 54, 20, 54, 60, 46, 60};

std::vector<double> uniform_times() {
  std::vector<double> t;
  for (size_t i = 0; i < kValues; ++i) t.push_back(static_cast<double>(i) / (kValues - 1));
  return t;
}

// Value k: a swing of 35 degrees about the pivot, then a shift of `shift` plus a jitter of
// `jitter` pixels that changes at every value.
std::vector<Affine> swing(Vec2 shift, double jitter) {
  std::vector<Affine> out;
  for (size_t k = 0; k < kValues; ++k) {
    const double angle = 35.0 * std::sin(2 * M_PI * static_cast<double>(k) / (kValues - 1));
    const double j = jitter * (static_cast<double>((k * 7) % 5) - 2) / 2;  // -1..1 of it, no pattern in time
    out.push_back(Affine::translate(shift.x + j, shift.y - j) * Affine::translate(kPivot.x, kPivot.y) *
                  Affine::rotate_deg(angle) * Affine::translate(-kPivot.x, -kPivot.y));
  }
  return out;
}

// The largest distance of the rest points under `a` from under `b`.
double miss(const Affine& a, const Affine& b) {
  double worst = 0;
  for (size_t i = 0; i + 1 < kRest.size(); i += 2) {
    const Vec2 p = a.apply({kRest[i], kRest[i + 1]}) - b.apply({kRest[i], kRest[i + 1]});
    worst = std::max(worst, std::hypot(p.x, p.y));
  }
  return worst;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("wrapper keys: a constant translation beside a turning rotation is one translation key (SMIL form)") {
  const std::vector<double> times = uniform_times();
  const std::vector<Affine> maps = swing({5, 3}, 0);
  const double tol = 0.1;
  const WrapperKeys w = wrapper_keys(maps, Affine{}, kRest, times, tol, -1, kPivot, WrapperForm::Smil);
  CHECK(w.channel[kTranslate].keys.size() == 1);
  CHECK(w.trajectory[0] == doctest::Approx(5));
  CHECK(w.trajectory[1] == doctest::Approx(3));
  CHECK(w.channel[kRotate].keys.size() > 4);
  CHECK(w.channel[kSkew].keys.size() == 1);
  CHECK(w.channel[kScale].keys.size() == 1);
  // Shared keys wrote the translation at every one of the rotation's keys.
  CHECK(w.key_count() == w.channel[kRotate].keys.size() + 3);
  // What a player draws at every value: within the tolerance and the rounding's share of it.
  for (size_t v = 0; v < kValues; ++v) CHECK(miss(w.drawn[v], maps[v]) <= 1.5 * tol);
}

TEST_CASE("wrapper keys: the channels composed stay within the tolerance between values, and a jitter below it is one key") {
  const std::vector<double> times = uniform_times();
  const double tol = 0.1;
  const std::vector<Affine> maps = swing({0, 0}, 0.3 * tol);
  const WrapperKeys w = wrapper_keys(maps, Affine{}, kRest, times, tol, 8, kPivot, WrapperForm::Lottie);
  CHECK(w.channel[kTranslate].keys.size() == 1);
  CHECK(w.channel[kRotate].keys.size() > 4);
  // Between values the full export blends the exact numbers; the keys' draw stays within the
  // tolerance there too (checked at the reducer's quarter steps and at eighths).
  const std::vector<double> exact = wrapper_trajectory(maps, Affine{}, kPivot, WrapperForm::Lottie);
  double worst = 0;
  for (size_t i = 0; i + 1 < kValues; ++i)
    for (int j = 0; j < 8; ++j) {
      const double u = j / 8.0, t = times[i] + u * (times[i + 1] - times[i]);
      double blend[6];
      for (size_t k = 0; k < 6; ++k) blend[k] = exact[6 * i + k] + u * (exact[6 * (i + 1) + k] - exact[6 * i + k]);
      const std::vector<double> drawn = wrapper_keyed_at(w, times, t);
      worst = std::max(worst, miss(wrapper_map(drawn.data(), kPivot, WrapperForm::Lottie),
                                   wrapper_map(blend, kPivot, WrapperForm::Lottie)));
    }
  // The rotation's rounding (an eighth of the tolerance) comes on top of the reduction's.
  CHECK(worst <= 1.2 * tol);
}

TEST_CASE("compact lottie: a part turning about its joint while its position jitters writes one position key") {
  const std::vector<double> times = uniform_times();
  const double tol = 0.1;
  const std::vector<Affine> maps = swing({0, 0}, 0.3 * tol);
  std::vector<std::vector<double>> points;
  for (const Affine& m : maps) {
    std::vector<double> v;
    for (size_t i = 0; i + 1 < kRest.size(); i += 2) {
      const Vec2 p = m.apply({kRest[i], kRest[i + 1]});
      v.insert(v.end(), {p.x, p.y});
    }
    points.push_back(v);
  }
  std::vector<const double*> values;
  for (const auto& v : points) values.push_back(v.data());
  const lottie::CompactPathMotion motion = lottie::compact_path_motion(kRest, values, times, 48, tol, -1);
  REQUIRE(motion.moves);
  CHECK(!motion.residual);
  const auto tr = nlohmann::json::parse(motion.transform);
  CHECK(tr["p"]["a"] == 0);  // one position, where shared keys wrote it at every angle's key
  REQUIRE(tr["r"]["a"] == 1);
  CHECK(tr["r"]["k"].size() > 4);
  CHECK(!tr.contains("s"));  // a scale of 100 % is the players' default
  CHECK(!tr.contains("sk"));
}

}  // TEST_SUITE
