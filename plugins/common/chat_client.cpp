// chat_client.h: the OpenAI-compatible chat client shared by the llm plugins.
#include "common/chat_client.h"

#include <curl/curl.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "svgmotion/error.h"

namespace svgm::plugin::chat {

using json = nlohmann::json;
using Fallback = Failure;

Settings read_settings(const json& options, const std::string& stage) {
  Settings s;
  const json opts = options.is_object() ? options : json::object();
  auto str = [&](const char* key) -> std::string {
    if (!opts.contains(key) || opts[key].is_null()) return "";
    if (!opts[key].is_string()) throw Failure(std::string("options.") + key + " must be a string");
    return opts[key].get<std::string>();
  };
  s.url = str("url");
  s.model = str("model");
  if (const std::string env = str("api_key_env"); !env.empty())
    if (const char* k = std::getenv(env.c_str()); k && *k) s.api_key = k;
  if (opts.contains("timeout_s")) {
    if (!opts["timeout_s"].is_number() || !(opts["timeout_s"].get<double>() > 0))
      throw Failure("options.timeout_s must be a positive number");
    s.timeout_s = opts["timeout_s"].get<double>();
  }
  if (s.url.empty()) throw Failure("no url configured (stages." + stage + ".options.url)");
  return s;
}

std::string one_line(std::string s, size_t max_chars) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (s.size() > max_chars) s = s.substr(0, max_chars) + "...";
  return s;
}

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) |
                       (static_cast<unsigned char>(in[i + 1]) << 8) | static_cast<unsigned char>(in[i + 2]);
    out += t[(v >> 18) & 63];
    out += t[(v >> 12) & 63];
    out += t[(v >> 6) & 63];
    out += t[v & 63];
  }
  if (i < in.size()) {
    unsigned v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    out += t[(v >> 18) & 63];
    out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

namespace {

struct Transfer {
  const svgm_host* host = nullptr;
  std::string body;
  bool cancelled = false;
};

size_t on_data(char* data, size_t size, size_t n, void* user) {
  try {
    static_cast<Transfer*>(user)->body.append(data, size * n);
    return size * n;
  } catch (...) {
    return 0;  // aborts the transfer
  }
}

int on_progress(void* user, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
  auto* t = static_cast<Transfer*>(user);
  if (t->host && t->host->cancelled && t->host->cancelled(t->host)) {
    t->cancelled = true;
    return 1;
  }
  return 0;
}

}  // namespace

std::string post(const Settings& s, const std::string& body, const svgm_host* host,
                 const std::string& who) {
  static const bool initialised = curl_global_init(CURL_GLOBAL_DEFAULT) == CURLE_OK;
  if (!initialised) throw Fallback("libcurl failed to initialise");
  CURL* c = curl_easy_init();
  if (!c) throw Fallback("libcurl failed to initialise");
  curl_slist* headers = curl_slist_append(nullptr, "Content-Type: application/json");
  headers = curl_slist_append(headers, "Accept: application/json");
  if (!s.api_key.empty()) headers = curl_slist_append(headers, ("Authorization: Bearer " + s.api_key).c_str());
  Transfer t;
  t.host = host;
  char err[CURL_ERROR_SIZE] = {0};
  const long timeout_ms = std::max(1L, std::lround(s.timeout_s * 1000));
  curl_easy_setopt(c, CURLOPT_URL, s.url.c_str());
  curl_easy_setopt(c, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(c, CURLOPT_POST, 1L);
  curl_easy_setopt(c, CURLOPT_POSTFIELDS, body.data());
  curl_easy_setopt(c, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(body.size()));
  curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, on_data);
  curl_easy_setopt(c, CURLOPT_WRITEDATA, &t);
  curl_easy_setopt(c, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(c, CURLOPT_XFERINFOFUNCTION, on_progress);
  curl_easy_setopt(c, CURLOPT_XFERINFODATA, &t);
  curl_easy_setopt(c, CURLOPT_TIMEOUT_MS, timeout_ms);
  curl_easy_setopt(c, CURLOPT_CONNECTTIMEOUT_MS, timeout_ms);
  curl_easy_setopt(c, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(c, CURLOPT_ERRORBUFFER, err);
  const std::string agent = "svgmotion-" + who + "/1";
  curl_easy_setopt(c, CURLOPT_USERAGENT, agent.c_str());
  const CURLcode rc = curl_easy_perform(c);
  long status = 0;
  curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &status);
  curl_slist_free_all(headers);
  curl_easy_cleanup(c);
  if (t.cancelled) throw svgm::Error(who + ": cancelled");
  if (rc == CURLE_OPERATION_TIMEDOUT) {
    std::ostringstream m;
    m << "timeout: no answer from " << s.url << " within " << s.timeout_s << " s";
    throw Fallback(m.str());
  }
  if (rc != CURLE_OK)
    throw Fallback("request to " + s.url + " failed: " + one_line(*err ? err : curl_easy_strerror(rc)));
  if (status < 200 || status > 299)
    throw Fallback("HTTP " + std::to_string(status) + " from " + s.url +
                   (t.body.empty() ? "" : ": " + one_line(t.body, 200)));
  return t.body;
}

// The text of choices[0].message.content (a string, or a list of text parts).
std::string answer_text(const std::string& reply) {
  json r;
  try {
    r = json::parse(reply);
  } catch (const json::exception& e) {
    throw Fallback("malformed JSON in the reply: " + one_line(e.what(), 200));
  }
  if (!r.is_object() || !r.contains("choices") || !r["choices"].is_array() || r["choices"].empty() ||
      !r["choices"][0].is_object() || !r["choices"][0].contains("message") || !r["choices"][0]["message"].is_object())
    throw Fallback("malformed reply: no choices[0].message");
  const json& content = r["choices"][0]["message"].value("content", json());
  if (content.is_string()) return content.get<std::string>();
  if (content.is_array()) {
    std::string s;
    for (const auto& part : content)
      if (part.is_object() && part.value("type", "") == "text" && part.contains("text") && part["text"].is_string())
        s += part["text"].get<std::string>();
    return s;
  }
  throw Fallback("malformed reply: choices[0].message.content is not text");
}

// Removes ```json ... ``` (or ``` ... ```) fences around the answer.
std::string strip_fences(const std::string& text) {
  const size_t open = text.find("```");
  if (open == std::string::npos) return text;
  const size_t line_end = text.find('\n', open);
  if (line_end == std::string::npos) return text;
  const size_t close = text.find("```", line_end + 1);
  return text.substr(line_end + 1, close == std::string::npos ? std::string::npos : close - line_end - 1);
}

}  // namespace svgm::plugin::chat
