// The rigid motion of one action of a plan at a time of its loop (motion_plan_internal.h's
// rigid): a swing about its pivot, a rock about its base, a bob, a slide, a pulse, a squash, a
// hop, a spin; moved out of motion_frames.cpp, which draws the frames with it.
#include <algorithm>
#include <cmath>

#include "procedural/depth_travel.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/travel_profile.h"

namespace svgm::motion_plan_internal {

// The rigid motion of one action at time t on a part (or the figure) with box `box` and
// attachment `pivot`; `H`, `W` the figure's size (units of the translations).
Affine rigid(const PlannedAction& a, double amp, double sign, double phase, double t, const RigBox& box, Vec2 pivot, double W, double H,
             const Affine& plane) {
  const double u = a.cycles * t + phase;
  const double s = oscillation(a, u), k = 0.5 - 0.5 * std::cos(kTau * u);
  const Vec2 base{box.centre().x, box.y1}, centre = box.centre();
  auto about = [](Vec2 c, const Affine& m) { return Affine::translate(c.x, c.y) * m * Affine::translate(-c.x, -c.y); };
  switch (a.primitive) {
    case Primitive::Swing: return about(pivot, Affine::rotate_deg(sign * amp * s));
    case Primitive::Spin: return about(centre, plane * Affine::rotate_deg(360.0 * amp * a.direction * t) * plane.inverse());
    // About the vertical axis through the middle: never wider than at rest, so it stays where the figure stands.
    case Primitive::Turn: return about(centre, Affine::scale(turn_width(amp * t, a.scale), 1));
    // Whole turns about the joint, from the phase's start (a crawl's arms half a turn apart).
    case Primitive::Windmill: return about(pivot, Affine::rotate_deg(sign * 360.0 * (amp * t + phase)));
    case Primitive::Rock:
      return about(a.parts.empty() ? base : pivot, Affine::rotate_deg(a.vertical == 2 ? a.direction * amp * k : sign * amp * s));
    case Primitive::Bob: {  // along a heading: a launch or a landing by amp of the figure's extent that way
      if (const double reach = amp * (std::fabs(a.heading.x) * W + std::fabs(a.heading.y) * H) * flight_at(a.vertical < 0, u); a.heading != Vec2{})
        return Affine::translate(a.heading.x * reach, a.heading.y * reach);
      const double ty = a.vertical == 1 ? -amp * H * k : a.vertical == -1 ? amp * H * k : -amp * H * s;
      return Affine::translate(0, ty);
    }
    // Going somewhere on its own: forward steadily most of the loop, or by a crawl's steps, and
    // back (travel_profile.h); otherwise to one side and the other about rest.
    case Primitive::Slide: {
      // Turned round to go: no amplitude, no turn (a plan measured without it, fit_plan, is still).
      if (a.turns_round) return amp == 0 ? Affine() : turned_going_map(2 * a.direction * amp * W, centre.x, u);
      const double x = a.inches ? crawl_at(u).rear : a.goes ? going_at(u) : s;
      return Affine::translate(a.direction * amp * W * x, 0);
    }
    case Primitive::Shake:  // on the ground (vertical != 0: a launch's rumble), only sideways
      return Affine::translate(amp * H * s, a.vertical != 0 ? 0 : 0.6 * amp * H * std::sin(kTau * (std::max(1, a.cycles - 1) * t + phase)));
    case Primitive::Pulse: {
      // Going away or coming nearer: about its vanishing point (depth_travel.h).
      if (a.goes) {
        const double f = depth_scale(a, amp, u);
        return about(a.vanish, Affine::scale(f, f));
      }
      // Shrinking up (vertical 1): about the top's middle, a launch going away into the sky.
      const double f = 1 + amp * k;
      return about(a.vertical == 1 && amp < 0 ? Vec2{centre.x, box.y0} : centre, Affine::scale(f, f));
    }
    case Primitive::Squash: {
      const double sy = 1 - 1.2 * amp * k;
      return about(base, Affine::scale(1 + 0.5 * amp * k, sy));
    }
    case Primitive::Stretch: {
      if (a.inches) {
        // A crawl's step: longer ahead of its planted rear, along the way it goes, by the step
        // its slide takes (travel_profile.h).
        const double step = 2.0 / kCrawlSteps, f = 1 + amp * step * crawl_at(u).stretch * W / std::max(box.w(), 1e-9);
        return about({a.direction > 0 ? box.x0 : box.x1, centre.y}, Affine::scale(f, 1 / std::sqrt(f)));
      }
      const double f = 1 + amp * k;
      if (box.w() >= box.h()) return about({box.x0, centre.y}, Affine::scale(f, 1 / std::sqrt(f)));
      return about(base, Affine::scale(1 / std::sqrt(f), f));
    }
    case Primitive::Hop: {
      // Per cycle: a fifth on the ground squashing, then the flight (stretched rising,
      // squashed a little falling), landing where it started.
      const double c = u - std::floor(u);
      double ty = 0, sy = 1;
      if (c < 0.2) sy = 1 - 0.6 * amp * std::sin(M_PI * c / 0.2);
      else {
        const double v = (c - 0.2) / 0.8;
        ty = -amp * H * std::sin(M_PI * v);
        sy = 1 + 0.4 * amp * std::sin(kTau * v);
      }
      return Affine::translate(0, ty) * about(base, Affine::scale(1 / std::sqrt(sy), sy));
    }
    default: return {};
  }
}

}  // namespace svgm::motion_plan_internal
