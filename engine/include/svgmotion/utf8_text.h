// Text from bytes: file names (and ids, prompts, anything read from argv or a file) are bytes,
// not necessarily UTF-8, while JSON, YAML, HTML and our messages must be valid UTF-8.
//
// shown_utf8() is the one conversion for showing such bytes: every byte that is not part of a
// well-formed UTF-8 sequence becomes U+FFFD (the replacement character), the rest is kept, so
// "caf\xe9.svg" (Latin-1) shows as "caf\uFFFD.svg" and a UTF-8 name is unchanged. json_text()
// dumps JSON the same way (nlohmann's replace handler), so a written file is always valid JSON.
//
// Where the bytes themselves must survive a trip through JSON (the plugin request names the
// run directory and the input, and the plugin opens them), pack_raw_strings() keeps every
// string that is not UTF-8 under "raw_strings" (JSON pointer -> the bytes in hex) beside its
// shown form, and unpack_raw_strings() puts the bytes back.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace svgm {

bool is_valid_utf8(std::string_view bytes);
// `bytes` with every byte outside a well-formed UTF-8 sequence replaced by U+FFFD.
std::string shown_utf8(std::string_view bytes);
// A path for a message, a JSON or YAML value or a page: shown_utf8 of its bytes.
std::string shown_path(const std::filesystem::path& path);
// j.dump(indent) with invalid UTF-8 in any string replaced by U+FFFD (never throws for it).
std::string json_text(const nlohmann::json& j, int indent = -1);

// The key pack_raw_strings() adds to an object (absent when every string is UTF-8).
inline constexpr const char* kRawStringsKey = "raw_strings";
// Replaces every string value of `j` that is not valid UTF-8 by shown_utf8() of it and records
// its bytes (hex) under j[kRawStringsKey][JSON pointer]. `j` must be an object.
void pack_raw_strings(nlohmann::json& j);
// Undoes pack_raw_strings(): the recorded strings get their bytes back, the key goes.
void unpack_raw_strings(nlohmann::json& j);

}  // namespace svgm
