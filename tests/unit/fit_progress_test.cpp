// The fit's progress estimate (fit/fit_progress.h): it never goes back, it stays
// below 1, it is 0 until the pace is known, and the ETA the host draws from it is
// within 2x of the time left at every step after the first tenth (issue 37).
//
// The clock is the test's own: a fit's timeline as the bundled man's default fit
// measured it on 2 idle cores (log.txt of a run): 7.3 s of setup, 21 keyframes
// activated about every 31 iterations at 1.6 ms + 0.6 ms per active keyframe + 1,
// the coarse fit ending 100 iterations after its last activation, 4.1 s judging
// 28 frames between keyframes, the refinement at 512 px (4x the pixels) after 1.6
// s of setup, 150 iterations at 43 ms, 5.0 s writing the outputs (their tolerance searches for
// animation.svg and animation.json; 1.3 s before animation.json had a search of its own). The variants
// move what the estimate cannot know in advance: which plateau test ends each
// stage, keyframes added by the choice, a slower refinement, a loaded machine. Not covered, and not
// within 2x near their end: a refinement ending at its earliest test (100) or
// running its whole budget (1 and 2 of 15 in this session's runs; fit_progress.h).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "fit/fit_progress.h"

using namespace svgm;

namespace {

struct Timeline {
  double setup = 7.3;                      // s before the first iteration
  double fixed_ms = 1.6, keyframe_ms = 0.6;  // an iteration: fixed + per (active + 1)
  double choice = 4.1, refine_setup = 1.6;   // s
  double refine_ms = 43;                   // per iteration
  double end = 5.0;                        // s writing
  int coarse_tail = 100;                   // iterations after the last activation
  int added = 0;                           // keyframes the choice adds (0: none)
  int keyed_iters = 100;                   // the joint fit after it
  int refine_iters = 150;                  // of its budget of 250
};

struct Sample {
  double now, fraction;
};

// Runs the timeline through a FitProgress; every step's time and fraction, and
// the end time.
std::vector<Sample> replay(const Timeline& tl, double& end) {
  constexpr int K = 21, kEvery = 31;
  FitProgress::Plan plan;
  plan.keyframes = K;
  plan.coarse_budget = 2000;
  plan.refine_budget = 250;
  plan.fine_pixels = 4;
  plan.plateau_window = 50;
  plan.choice_frames = 28;
  FitProgress bar(plan);
  std::vector<Sample> out;
  double t = tl.setup;
  auto iteration_ms = [&](int active) { return tl.fixed_ms + tl.keyframe_ms * (active + 1); };
  const int all_active = (K - 1) * kEvery;
  for (int it = 1; it <= all_active + tl.coarse_tail; ++it) {
    const int active = std::min(K, 1 + it / kEvery);
    t += iteration_ms(active) / 1000 + (it == 1 ? 0.5 : 0);  // first launches
    bar.coarse_step(it, active, t);
    out.push_back({t, bar.fraction(t)});
  }
  bar.coarse_done(t);
  out.push_back({t, bar.fraction(t)});  // the choice's activity note
  t += tl.choice;
  int k = K;
  if (tl.added > 0) {
    k += tl.added;
    t += 0.1 * tl.added;  // reading them
    bar.keyed_start(k, 500, t);
    for (int it = 1; it <= tl.keyed_iters; ++it) {
      t += iteration_ms(k) / 1000;
      bar.keyed_step(it, t);
      out.push_back({t, bar.fraction(t)});
    }
    t += 0.18 * k;  // the refinement's frames again
  }
  bar.choice_done(t);
  t += tl.refine_setup;
  for (int it = 1; it <= tl.refine_iters; ++it) {
    t += tl.refine_ms * k / K / 1000;
    bar.refine_step(it, t);
    out.push_back({t, bar.fraction(t)});
  }
  bar.refine_done(t);
  out.push_back({t, bar.fraction(t)});  // "writing the animation"
  // Only the end is left: kEndRefined refinement iterations at their pace.
  CHECK(bar.seconds_left() == doctest::Approx(FitProgress::kEndRefined * tl.refine_ms * k / K / 1000));
  end = t + tl.end;
  return out;
}

// The host's ETA (frontends/cli ProgressView::eta): the seconds since the stage
// started (here the job's start) over the bar's share, times the share left; none
// before 2 s and 1 %.
double host_eta(const Sample& s, bool& shown) {
  shown = s.now >= 2 && s.fraction >= 0.01;
  return shown ? s.now / s.fraction * (1 - s.fraction) : 0;
}

void check_timeline(const Timeline& tl) {
  double end = 0;
  const std::vector<Sample> s = replay(tl, end);
  for (size_t i = 1; i < s.size(); ++i) REQUIRE(s[i].fraction >= s[i - 1].fraction);
  CHECK(s.back().fraction < 1);
  // The last step before the end: what is left is the end's few seconds (5 of the man's 40).
  CHECK(s.back().fraction > 0.75);
  double worst = 1;
  std::string where;
  int judged = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    bool shown = false;
    const double eta = host_eta(s[i], shown);
    if (!shown || s[i].fraction < 0.1) continue;
    ++judged;
    const double real = end - s[i].now;
    const double r = std::max(eta / real, real / eta);
    if (r > worst) {
      worst = r;
      std::ostringstream w;
      w << "step " << i << " at " << s[i].now << " s, bar " << s[i].fraction << ": ETA " << eta << " s, left " << real << " s";
      where = w.str();
    }
  }
  INFO("worst: " << where);
  CHECK(judged > 100);
  CHECK(worst < 2);
}

}  // namespace

TEST_SUITE("fit") {
  TEST_CASE("fit progress: the host's ETA within 2x of the time left after the first tenth") {
    SUBCASE("the man as measured") { check_timeline({}); }
    SUBCASE("each stage ends one plateau test later than most") {
      Timeline tl;
      tl.coarse_tail = 150;
      tl.refine_iters = 200;
      check_timeline(tl);
    }
    SUBCASE("the choice adds keyframes and fits them jointly") {
      Timeline tl;
      tl.added = 6;
      check_timeline(tl);
    }
    SUBCASE("the refinement is 1.6x slower than its prior") {
      Timeline tl;
      tl.refine_ms = 70;
      tl.end = 8.0;  // the exports run at the refinement's pace
      check_timeline(tl);
    }
    SUBCASE("a loaded machine (load average 20 on 2 cores): the cost is the keyframes'") {
      Timeline tl;  // the man's run under load, captured by tests/bench/progress_eta.sh
      tl.setup = 31;
      tl.fixed_ms = 0;
      tl.keyframe_ms = 5.3;
      tl.choice = 17.7;
      tl.refine_setup = 7;
      tl.refine_ms = 285;
      tl.end = 26;  // 6.7 s before animation.json's own search: 5.2x the idle 1.3 s, so 5.2 x 5.0 (scaled, not measured)
      check_timeline(tl);
    }
  }

  TEST_CASE("fit progress: 0 until the pace is known, then the setup counts as time spent") {
    FitProgress::Plan plan;
    plan.keyframes = 4;
    plan.coarse_budget = 100;
    FitProgress bar(plan);
    double t = 10;  // setup
    // Not with fewer than half the keyframes active, however many iterations.
    for (int it = 1; it <= 2 * FitProgress::kPaceWindow; ++it) {
      bar.coarse_step(it, 1, t);
      CHECK(bar.fraction(t) == 0);
    }
    FitProgress fresh(plan);
    bar = fresh;
    for (int it = 1; it <= FitProgress::kPaceWindow / 5; ++it) {
      bar.coarse_step(it, 4, t += 0.01);
      CHECK(bar.fraction(t) == 0);
    }
    bar.coarse_step(21, 4, t += 0.01);
    // Without a plateau test every iteration of the budget runs: 79 left at 0.01
    // s, and the end, kEnd iterations of 0.01 s (the 4 keyframes active + kBase: the
    // step's units are the pace's).
    CHECK(bar.seconds_left() == doctest::Approx((79 + FitProgress::kEnd) * 0.01));
    CHECK(bar.fraction(t) == doctest::Approx(t / (t + bar.seconds_left())));
    CHECK(bar.fraction(t) > 0.6);  // 10.21 s of setup and iterations spent, 6.29 left
  }

  TEST_CASE("fit progress: a stage that outlives its expected end is expected to the next plateau test") {
    FitProgress::Plan plan;
    plan.keyframes = 1;
    plan.coarse_budget = 1000;
    plan.plateau_window = 50;
    FitProgress bar(plan);
    double t = 0;
    for (int it = 1; it <= 99; ++it) bar.coarse_step(it, 1, t += 0.01);
    // Every keyframe active from the start: plateau tests at 50, 100, 150 ...; the
    // earliest end at 100, and 2/5 of a window more: 120 expected, then the end
    // (kEnd iterations with every keyframe active).
    const double end_share = FitProgress::kEnd * 0.01;
    CHECK(bar.seconds_left() == doctest::Approx(21 * 0.01 + end_share));
    const double f = bar.fraction(t);
    // The test at 100 did not end it: 170 expected.
    bar.coarse_step(100, 1, t += 0.01);
    CHECK(bar.seconds_left() == doctest::Approx(70 * 0.01 + end_share));
    CHECK(bar.fraction(t) >= f);
  }
}  // TEST_SUITE
