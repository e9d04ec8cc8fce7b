// Keeping a credential (an API key) out of every message, log line and excerpt of a server's
// reply. A hostile or careless server may echo the key it was sent, verbatim or encoded, and
// anywhere in a long body; so the key is removed from the whole text first and only then is the
// text cut to a short excerpt (cutting first can leave most of a key that straddles the cut).
// Every network client (hosted video sessions, the llm plugins' chat client) goes through here.
#pragma once

#include <cstddef>
#include <string>

namespace svgm {

// `text` with every occurrence of `secret` replaced by "<key>": verbatim, percent-encoded (as in
// a URL or form body, upper- or lower-case hex), JSON-escaped ("/" as "\/") and base64-encoded
// (standard or URL-safe alphabet, at any of the three byte alignments, so the key is found
// inside a longer encoded run such as a Basic credential). An empty secret changes nothing.
std::string scrub_secret(std::string text, const std::string& secret);

// What may be shown of a server's text: scrubbed of `secret` (first), on one line (every
// control character a space, trailing spaces dropped), then cut to at most `max_chars` bytes at
// a UTF-8 character boundary with "..." appended.
std::string safe_excerpt(const std::string& text, const std::string& secret, size_t max_chars = 200);

}  // namespace svgm
