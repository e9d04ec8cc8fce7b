// Base64 (RFC 4648, standard alphabet, with padding): images inlined into JSON requests (the
// chat models' data URLs, the Gemini API's bytesBase64Encoded, a hosted API's image field).
#pragma once

#include <string>

namespace svgm {

std::string base64(const std::string& bytes);

}  // namespace svgm
