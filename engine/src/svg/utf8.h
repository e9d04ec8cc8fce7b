// UTF-8 well-formedness: text that reaches JSON (ids, prompts) must be valid UTF-8, or the JSON
// writer fails deep inside a stage; readers check it where the text enters.
#pragma once

#include <string_view>

namespace svgm {

// True when `s` is well-formed UTF-8 (shortest forms only, no surrogates, at most U+10FFFF).
bool valid_utf8(std::string_view s);

}  // namespace svgm
