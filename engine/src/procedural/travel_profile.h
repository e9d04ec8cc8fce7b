// How a figure sent somewhere moves along its way over one loop (issue 35: "the turtle plods
// along", "the snail crawls to the left"). A loop must end where it began, so the figure cannot
// only go forward; moved there and back about where it stands (a sine), it rocked: a viewer saw
// it sway, not go. Here it goes forward at a steady pace for kForwardShare of the loop, from
// behind where it stands to as far ahead, passing its rest place at the loop's start, and glides
// back (eased) in the rest of the loop: most of what is seen is the going.
//
// A crawl (a caterpillar, a snail, a worm: an inchworm's or a slug's gait) goes by steps: its
// body stretches forward with its rear planted, then gathers with its front planted, so each
// step carries it one stretch ahead. The forward run is kCrawlSteps such steps; the figure's
// slide is then a staircase (the rear moves only while the body gathers) and its stretch the
// extension, both from crawl_at, so the ends stay put in turn when the stretch's size equals
// the slide's (motion_plan.cpp sets them so).
#pragma once

namespace svgm {

inline constexpr double kForwardShare = 2.0 / 3;  // of the loop spent going forward
inline constexpr int kCrawlSteps = 2;             // stretch-and-gather steps in one forward run

// Where a figure travelling steadily is at loop time u (in cycles; any real): -1 (behind its
// rest place) to +1 (ahead), 0 at u = 0.
double going_at(double u);

struct CrawlPose {
  double rear = 0;     // the rear's place, -1 to +1 as going_at's
  double stretch = 0;  // the body's extension, 0 to 1 step (a step: 2 / kCrawlSteps of rear's unit)
};

// A crawl's pose at loop time u: the rear's place and the body's stretch, the front at rear +
// stretch * 2 / kCrawlSteps. Rest (0, 0) at u = 0.
CrawlPose crawl_at(double u);

}  // namespace svgm
