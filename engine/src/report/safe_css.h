// CSS from the user's animation reduced to what can neither run nor fetch anything when the
// animation is inlined into report.html: the painting properties svgmotion's renderer reads
// (fill, stroke, opacity, clip-path, mask ...) with values whose only url() is a local
// "#id" and whose only functions are colours and transforms. At-rules (@import, @font-face,
// @media ...) and rules whose selector is not made of tags, .classes and #ids go. A style
// sheet's rules are scoped to the report's animation box, so they cannot restyle the page.
// An allow-list: what is not named here is dropped and counted in the tally.
#pragma once

#include <string>
#include <string_view>

#include "report/drop_tally.h"

namespace svgm {

// A property report.html keeps (lower case, as in a style sheet or a presentation attribute).
bool safe_css_property(std::string_view name);

// A value made only of words, numbers, colours, local url(#id) and transform functions: no
// escapes, comments, at-signs, braces, semicolons or angle brackets.
bool safe_css_value(std::string_view value);

// A "#id" reference into the same document (the only href or url() target kept).
bool local_reference(std::string_view ref);

// A style attribute's declarations, the unsafe ones left out ("fill:red;stroke:blue").
std::string safe_style_declarations(std::string_view style, DropTally& dropped);

// A <style> element's sheet, every selector prefixed with `scope` ("#svgm-stage ").
std::string safe_style_sheet(std::string_view css, std::string_view scope, DropTally& dropped);

}  // namespace svgm
