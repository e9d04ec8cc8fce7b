// The travel of a figure sent somewhere over one loop, steady, by crawling steps or turning round
// to go (see travel_profile.h).
#include "procedural/travel_profile.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

double ease(double x) { return 0.5 - 0.5 * std::cos(M_PI * x); }

// Where in the forward run (0 at its start, behind; 1 at its end, ahead) loop time u is, or -1
// during the glide back, with `back` its share done (0 to 1). The run is centred on u = 0.
double forward_share(double u, double* back) {
  const double c = u - std::floor(u), half = 0.5 * kForwardShare;
  if (c < half) return 0.5 + c / kForwardShare;
  if (c >= 1 - half) return (c - (1 - half)) / kForwardShare;
  *back = (c - half) / (1 - kForwardShare);
  return -1;
}

}  // namespace

double going_at(double u) {
  double back = 0;
  const double s = forward_share(u, &back);
  return s >= 0 ? 2 * s - 1 : 1 - 2 * ease(back);
}

double launch_at(double u) {
  const double c = u - std::floor(u);
  if (c < kIgnitionShare) return 0;
  if (c < kLaunchOut) {
    const double x = (c - kIgnitionShare) / (kLaunchOut - kIgnitionShare);
    return x * x * x * (4 - 3 * x);
  }
  return 1 - ease((c - kLaunchOut) / (1 - kLaunchOut));
}

double land_at(double u) {
  const double c = u - std::floor(u);
  if (c < kLandBack) return ease(c / kLandBack);
  if (c < kLandDown) {
    const double x = 1 - (c - kLandBack) / (kLandDown - kLandBack);
    return x * x;
  }
  return 0;
}

double flight_at(bool lands, double u) { return lands ? -land_at(u) : launch_at(u); }

CrawlPose crawl_at(double u) {
  double back = 0;
  const double s = forward_share(u, &back);
  if (s < 0) return {1 - 2 * ease(back), 0};
  // Step j of kCrawlSteps, w its share done: the first half stretches (the rear planted), the
  // second gathers (the front planted: the rear catches up by what the stretch gives back).
  const double step = 2.0 / kCrawlSteps, at = s * kCrawlSteps;
  const double j = std::min(std::floor(at), kCrawlSteps - 1.0), w = at - j;
  const double start = -1 + j * step;
  if (w < 0.5) return {start, ease(2 * w)};
  const double e = 1 - ease(2 * w - 1);
  return {start + (1 - e) * step, e};
}

TurnedPose turned_going_at(double u) {
  const double c = u - std::floor(u), leg = 0.5 - kTurnShare;
  // The turns at a steady rate (turned_width's steady loss of width): eased, the width fell
  // fastest at the edge-on moment.
  if (c < kTurnShare) return {0, 0.5 * c / kTurnShare};
  if (c < 0.5) return {(c - kTurnShare) / leg, 0.5};
  if (c < 0.5 + kTurnShare) return {1, 0.5 + 0.5 * (c - 0.5) / kTurnShare};
  return {1 - (c - 0.5 - kTurnShare) / leg, 1};
}

double turned_width(double turns) {
  // h: how far through its half turn (0 facing a side, 0.5 edge on); d: 1 facing, 0 edge on.
  const double h = 2 * (turns - 0.5 * std::floor(2 * turns)), d = std::fabs(1 - 2 * h);
  return (std::cos(2 * M_PI * turns) < 0 ? -1 : 1) * std::pow(kTurnRoundEdge, 1 - d);
}

Affine turned_going_map(double reach, double middle, double u) {
  const TurnedPose p = turned_going_at(u);
  return Affine::translate(reach * p.along + middle, 0) * Affine::scale(turned_width(p.turns), 1) * Affine::translate(-middle, 0);
}

}  // namespace svgm
