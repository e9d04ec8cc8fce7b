// The animation placed into report.html as an <svg> element (not an <img>), so the page's
// controls reach its SMIL clock: pauseAnimations(), unpauseAnimations(), setCurrentTime(t).
//
// The document is the user's own and arrives inside a page that runs our script, so it is
// rebuilt from an allow-list instead of filtered by a deny-list: the parsed document (pugixml)
// keeps only the SVG elements and attributes a drawing and its SMIL animation need (shapes,
// groups, defs, use, gradients, clip paths, masks, text, title/desc as text, style reduced to
// safe painting properties, animate/animateTransform/animateMotion/set of safe attributes) and
// only hrefs and url()s to a "#id" of the same document. Everything else (script,
// foreignObject, iframe, image, filters, on* attributes, links, outside files, comments
// holding markup, CDATA, processing instructions, DOCTYPE declarations) is dropped and counted.
//
// The result is written for an HTML parser, which reads an inline <svg> as "foreign content"
// with rules of its own (comments end at "<!-->", CDATA and tag names are read otherwise, some
// HTML tag names break out of the <svg>): no comments, no CDATA, every name as the SVG spec
// spells it (names HTML lower-cases are lower case or on HTML's camelCase table), every text
// and attribute value escaped, every element closed explicitly. HTML and XML read the markup as
// the same tree. The root gets a viewBox when it has none (from its width and height) and
// width/height 100%, so it scales to its box. Style sheets are scoped to #svgm-stage, the box
// report.html puts the animation in.
#pragma once

#include <filesystem>
#include <string>

namespace svgm {

struct InlinedSvg {
  std::string markup;   // the root <svg> element, ready to inline
  std::string dropped;  // what was left out, by kind: "2 <script>, 3 on* attributes"; "" if nothing
};

// The root <svg> element of `file`, made safe to inline. Throws svgm::Error "<file>: ...".
InlinedSvg inline_svg(const std::filesystem::path& file);

}  // namespace svgm
