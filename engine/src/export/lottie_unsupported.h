// The one warning line of a Lottie export naming everything in the document that the Lottie
// file does not draw as the SVG does: what the reader left out of the scene (filters, pattern
// paints, markers, text, images, dashes: from its warnings) and what the writer drew only
// approximately (lottie_paint.h, lottie_compositing.h).
#pragma once

#include <string>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm::lottie {

// "cannot express in Lottie: filter on <g id=glow>, pattern paint on <rect id=bg>, ...", or
// empty when everything is expressed. `approximate`: the writer's own notes, in order.
std::string cannot_express_line(const Scene& scene, const std::vector<std::string>& approximate);

}  // namespace svgm::lottie
