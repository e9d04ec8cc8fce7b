// The animation placed into report.html as an <svg> element (not an <img>), so the page's
// controls reach its SMIL clock: pauseAnimations(), unpauseAnimations(), setCurrentTime(t).
//
// The document is the user's own and arrives inside a page that runs our script, so whatever
// could run code is dropped: <script> elements, on* event attributes, and links whose target is
// javascript:. The XML declaration and doctype go (an HTML page has its own); the root gets a
// viewBox when it has none (from its width and height) and width/height 100%, so it scales to
// its box. Everything else (ids, styles, <animate> elements) is kept as written.
#pragma once

#include <filesystem>
#include <string>

namespace svgm {

// The root <svg> element of `file`, serialised for inlining. Throws svgm::Error "<file>: ...".
std::string inline_svg(const std::filesystem::path& file);

}  // namespace svgm
