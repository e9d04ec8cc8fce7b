// secret_scrub.h: removing a key, in the forms a server could echo it, before text is shown.
#include "net/secret_scrub.h"

#include <cctype>
#include <vector>

#include "net/base64.h"
#include "net/percent_encode.h"

namespace svgm {

namespace {

// Encoded forms of a key shorter than this are not looked for: a fragment of two or three
// characters would match ordinary text. (Real keys are 20-60 characters.)
constexpr size_t kMinEncodedKey = 4;

std::string json_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\' || c == '/') out += '\\';
    out += c;
  }
  return out;
}

// The characters of base64(prefix + key + suffix) that depend on the key's bits alone, for a
// prefix of `shift` bytes (0, 1, 2): the same whatever surrounds the key in the encoded text.
// Character j encodes bits [6j, 6j + 6); the key holds bits [8 shift, 8 (shift + n)).
std::string base64_core(const std::string& key, size_t shift) {
  const std::string enc = base64(std::string(shift, '\0') + key);
  const size_t first = (8 * shift + 5) / 6, end = 8 * (shift + key.size()) / 6;
  return end > first ? enc.substr(first, end - first) : std::string();
}

void replace_all(std::string& s, const std::string& what, const std::string& with) {
  if (what.empty()) return;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size()))
    s.replace(at, what.size(), with);
}

}  // namespace

std::string scrub_secret(std::string text, const std::string& secret) {
  if (secret.empty()) return text;
  const std::string mark = "<key>";
  replace_all(text, secret, mark);
  if (secret.size() < kMinEncodedKey) return text;
  std::vector<std::string> forms = {percent_encode(secret, true),
                                    percent_encode(secret, false), json_escaped(secret)};
  for (size_t shift = 0; shift < 3; ++shift) {
    std::string b = base64_core(secret, shift);
    forms.push_back(b);
    for (char& c : b) c = c == '+' ? '-' : c == '/' ? '_' : c;  // RFC 4648 section 5
    forms.push_back(b);
  }
  for (const std::string& f : forms)
    if (f.size() >= kMinEncodedKey && f != secret) replace_all(text, f, mark);
  return text;
}

std::string safe_excerpt(const std::string& text, const std::string& secret, size_t max_chars) {
  std::string s = scrub_secret(text, secret);
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';  // newlines, ESC sequences
  while (!s.empty() && s.back() == ' ') s.pop_back();
  if (s.size() <= max_chars) return s;
  size_t cut = max_chars;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
  return s.substr(0, cut) + "...";
}

}  // namespace svgm
