// Percent-encoding of URL parts (RFC 3986): every byte but the unreserved letters, digits and
// "-_.~" as %XX. Used for the query values of ComfyUI's URLs and to find a key in its encoded
// form in a server's reply (secret_scrub.h).
#pragma once

#include <string>
#include <string_view>

namespace svgm {

// `upper`: %2F (RFC 3986's recommendation) or %2f (what some servers echo back).
std::string percent_encode(std::string_view s, bool upper = true);

}  // namespace svgm
