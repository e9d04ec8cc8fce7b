// Room to move: a drawing that fills its canvas (an emoji, an icon) cannot move without leaving
// it, so the offline motion library scaled every such motion down to nothing (issue 35: 17 of 86
// suite cases, a waving hand, a hopping rabbit, a shaking alarm clock, were still). The pipeline
// gives such a drawing room before anything reads it: input.svg's viewBox grows by a share of
// its size on every side, and its width and height by the same factor, so the figure keeps its
// size in pixels and its place in the middle, and the canvas around it grows. Every later stage
// (grouper, recolorer, video, fitter, exporters) reads that input.svg, so the animation the user
// gets has the larger canvas, said on the terminal and in the report.
//
// When: stages.video.room (auto | 0 | a share in (0, 0.5]). auto gives kAutoRoom when the video
// is made by the procedural plugin from this canvas and the figure spans at least kFillsCanvas of
// the canvas's width or height (a backdrop, a shape covering the whole canvas, is not the
// figure); a video the user brings is drawn on the canvas as it is, so auto leaves it alone.
// A figure the prompt sends across the canvas (a gait, a crawl, hops: gait_travel.h's
// sends_figure_across) gets the room already at kTravelFills of the canvas's width: it goes
// kTravelReach of its width ahead and behind where it stands, and with less room the plan cut
// the travel to fit (a trotting zebra across 88 % of its canvas went 5 % of its width, at 38 %
// of its reach, and read as marking time). So does a figure the prompt carries about in the air
// (a hover, a buzz, a float, an insect's flight: travel_words.h's carries_figure_about) from
// kTravelFills of the canvas's width or height. A figure told a way (travel_words.h's
// sends_figure_one_way) gets kTurnRoom: drawn facing the other way it turns round and its whole
// trip, 2 kTravelReach of its width, lies on the told side; at kAutoRoom the camel sent right
// kept 45 % of it (a tenth of its width, read as marking time). At kTurnRoom a figure as wide
// as its canvas has a fifth of its width on each side: its trip is at least 20 % of its width.
// A figure the prompt launches (travel_words.h's launches_figure) gets kTurnRoom too, from
// kTravelFills of the canvas's width or height: it goes off along its nose, one way.
#pragma once

#include <string>
#include <string_view>

#include "svgmotion/scene.h"

namespace svgm {

constexpr double kAutoRoom = 0.15;     // of the canvas's size, added on each side
constexpr double kFillsCanvas = 0.92;  // the figure's share of the canvas's width or height
constexpr double kTravelFills = 0.75;  // of the canvas's width, for a figure sent across it
constexpr double kTurnRoom = 0.2;      // of the canvas's size on each side, for a figure told a way

// The figure's extent as shares of the canvas's width and height: the box of every painted
// path's control points (a stroke's half width added), backdrops left out.
struct FigureSpan {
  double x = 0, y = 0;
  bool empty = true;
};
FigureSpan figure_span(const Scene& scene);

// The share of room stages.video.room=auto gives `scene` (its figure's span) for `prompt`:
// kTurnRoom when the figure spans kTravelFills of the canvas's width and the prompt tells it a
// way, or of its width or height and the prompt launches it, else kAutoRoom when the figure fills kFillsCanvas of the canvas, or kTravelFills of its
// width and the prompt sends it across; else 0. `why` (of `size` chars, may be null) says which.
double auto_room(const Scene& scene, const std::string& prompt, char* why, size_t size);

// `text`: an SVG document; `share` > 0. The same document with the root's viewBox grown by
// `share` of its width and height on each side (a viewBox is added from the canvas size when
// there is none), width and height (when given in an absolute unit) by 1 + 2 share and the
// share said in the root's data-svgmotion-room (svg_reader.h reads it as Scene::room); the rest
// is kept (comments, doctype and the formatting inside the root; pugixml drops whitespace
// between the nodes outside it). Throws svgm::Error "<name>: ..." when the
// document has no <svg> root or an unreadable viewBox.
std::string give_canvas_room(std::string_view text, std::string_view name, const Scene& scene, double share);

}  // namespace svgm
