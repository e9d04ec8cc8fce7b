// http_transport.h: the default download (through get()) and the URL parts messages name.
#include "net/http_transport.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace svgm {

HttpReply HttpTransport::download(const std::string& url, const std::filesystem::path& file,
                                  uint64_t max_bytes, double timeout_s) {
  HttpReply r = get(url, timeout_s);
  if (!r.connected || r.status < 200 || r.status >= 300) return r;
  if (r.body.size() > max_bytes) {
    HttpReply refused;
    refused.refused = true;
    refused.error = too_large_message("download", url, max_bytes);
    return refused;
  }
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) {
    r.write_error = std::strerror(errno);
  } else {
    const bool wrote = std::fwrite(r.body.data(), 1, r.body.size(), f) == r.body.size();
    const int write_errno = errno;
    if (std::fclose(f) != 0 || !wrote) r.write_error = std::strerror(wrote ? errno : write_errno);
  }
  r.body.clear();
  return r;
}

std::string url_scheme(const std::string& url) {
  // RFC 3986: scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ), then ":".
  if (url.empty() || !std::isalpha(static_cast<unsigned char>(url[0]))) return "";
  for (size_t i = 0; i < url.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(url[i]);
    if (c == ':') {
      std::string s = url.substr(0, i);
      for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      return s;
    }
    if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return "";
  }
  return "";
}

std::string url_host(const std::string& url) {
  const size_t start = url.find("://");
  if (start == std::string::npos) return "";
  std::string authority = url.substr(start + 3, url.find_first_of("/?#", start + 3) - (start + 3));
  const size_t at = authority.rfind('@');
  return at == std::string::npos ? authority : authority.substr(at + 1);
}

std::string scheme_for_message(const std::string& url) {
  const std::string s = url_scheme(url);
  return s.empty() ? "a URL without a scheme" : "a " + s + ": URL";
}

std::string too_large_message(const std::string& what, const std::string& url, uint64_t max_bytes) {
  const uint64_t mib = max_bytes >> 20;
  const std::string size = mib << 20 == max_bytes ? std::to_string(mib) + " MiB" : std::to_string(max_bytes) + " bytes";
  return "the " + what + " from " + url_host(url) + " is larger than " + size;
}

}  // namespace svgm
