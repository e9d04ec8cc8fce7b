// Text from bytes (see svgmotion/utf8_text.h).
#include "svgmotion/utf8_text.h"

#include <cstdint>

namespace svgm {

namespace {

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF), or 0 when there is none.
size_t sequence_length(std::string_view s, size_t i) {
  const auto at = [&](size_t k) { return static_cast<uint8_t>(s[k]); };
  const uint8_t b = at(i);
  if (b < 0x80) return 1;
  size_t n = 0;
  uint8_t lo = 0x80, hi = 0xbf;  // the allowed range of the second byte
  if (b >= 0xc2 && b <= 0xdf) n = 2;
  else if (b == 0xe0) n = 3, lo = 0xa0;
  else if (b >= 0xe1 && b <= 0xec) n = 3;
  else if (b == 0xed) n = 3, hi = 0x9f;  // U+D800..U+DFFF are surrogates
  else if (b >= 0xee && b <= 0xef) n = 3;
  else if (b == 0xf0) n = 4, lo = 0x90;
  else if (b >= 0xf1 && b <= 0xf3) n = 4;
  else if (b == 0xf4) n = 4, hi = 0x8f;  // above U+10FFFF
  else return 0;
  if (i + n > s.size()) return 0;
  if (at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  return n;
}

constexpr const char* kHex = "0123456789abcdef";

void pack(nlohmann::json& v, const std::string& pointer, nlohmann::json& raw) {
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    if (is_valid_utf8(s)) return;
    std::string hex;
    for (unsigned char c : s) hex += {kHex[c >> 4], kHex[c & 15]};
    raw[pointer] = hex;
    v = shown_utf8(s);
  } else if (v.is_object()) {
    for (auto& [k, x] : v.items()) {
      if (!is_valid_utf8(k)) continue;  // keys are names (config keys, ids): shown, not packed
      std::string escaped;  // RFC 6901: "~" -> "~0", "/" -> "~1"
      for (char c : k) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
      pack(x, pointer + "/" + escaped, raw);
    }
  } else if (v.is_array()) {
    for (size_t i = 0; i < v.size(); ++i) pack(v[i], pointer + "/" + std::to_string(i), raw);
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

bool is_valid_utf8(std::string_view bytes) {
  for (size_t i = 0; i < bytes.size();) {
    const size_t n = sequence_length(bytes, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string shown_utf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (size_t i = 0; i < bytes.size();) {
    const size_t n = sequence_length(bytes, i);
    if (n == 0) {
      out += "\xef\xbf\xbd";  // U+FFFD
      ++i;
    } else {
      out.append(bytes.substr(i, n));
      i += n;
    }
  }
  return out;
}

std::string shown_path(const std::filesystem::path& path) { return shown_utf8(path.native()); }

std::string json_text(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

void pack_raw_strings(nlohmann::json& j) {
  nlohmann::json raw = nlohmann::json::object();
  pack(j, "", raw);
  if (!raw.empty()) j[kRawStringsKey] = std::move(raw);
}

void unpack_raw_strings(nlohmann::json& j) {
  if (!j.is_object() || !j.contains(kRawStringsKey)) return;
  const nlohmann::json raw = j[kRawStringsKey];
  j.erase(kRawStringsKey);
  if (!raw.is_object()) return;
  for (const auto& [pointer, hex] : raw.items()) {
    if (!hex.is_string()) continue;
    const std::string& h = hex.get_ref<const std::string&>();
    std::string bytes;
    for (size_t i = 0; i + 1 < h.size(); i += 2) {
      const int a = hex_digit(h[i]), b = hex_digit(h[i + 1]);
      if (a < 0 || b < 0) break;
      bytes += static_cast<char>(a * 16 + b);
    }
    try {
      const nlohmann::json::json_pointer p(pointer);
      if (j.contains(p) && j.at(p).is_string()) j.at(p) = bytes;
    } catch (const nlohmann::json::exception&) {
      // A malformed pointer names nothing of ours: the shown form stays.
    }
  }
}

}  // namespace svgm
