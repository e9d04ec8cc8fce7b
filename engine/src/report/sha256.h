// SHA-256 (FIPS 180-4) of a byte string, for the hash of report.html's own script in its
// Content-Security-Policy ('sha256-<base64 of the digest>'): the policy then lets that one
// script run and nothing else, and the page stays the same bytes for the same run.
#pragma once

#include <string>
#include <string_view>

namespace svgm {

// The 32-byte digest, as raw bytes.
std::string sha256(std::string_view bytes);

}  // namespace svgm
