// chat_client.h: the OpenAI-compatible chat client shared by the llm plugins.
#include "common/chat_client.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "common/curl_http.h"
#include "net/secret_scrub.h"
#include "svgmotion/error.h"

namespace svgm::plugin::chat {

using json = nlohmann::json;

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
  for (char& c : s)  // newlines, tabs, and the escape sequences a hostile server could send a terminal
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  if (s.size() > max_chars) s = s.substr(0, max_chars) + "...";
  return s;
}

namespace {
// The endpoint as messages show it: without its query and fragment, where some services take
// their key (`?key=...`); messages reach log.txt, motion.json and report.html.
std::string shown_url(const std::string& url) {
  const size_t cut = url.find_first_of("?#");
  return cut == std::string::npos ? url : url.substr(0, cut) + "?...";
}
}  // namespace

std::string post(const Settings& s, const std::string& body, const svgm_host* host,
                 const std::string& who) {
  auto cancelled = [host] { return host && host->cancelled && host->cancelled(host) != 0; };
  // The key goes only to the configured endpoint's origin (curl_http.h).
  ScopedHeaders key;
  if (!s.api_key.empty()) key = {s.url, {"Authorization: Bearer " + s.api_key}};
  std::string agent = "svgmotion-" + who + "/1";  // "svgmotion-grouper-llm/1"
  std::replace(agent.begin(), agent.end(), ' ', '-');
  CurlTransport http(cancelled, agent, {"Accept: application/json"}, std::move(key));
  const HttpReply r = http.post_json(s.url, body, s.timeout_s);
  if (!r.connected && cancelled()) throw svgm::Error(who + ": cancelled");
  if (r.refused) throw Failure(r.error);
  if (r.timed_out) {
    std::ostringstream m;
    m << "timeout: no answer from " << shown_url(s.url) << " within " << s.timeout_s << " s";
    throw Failure(m.str());
  }
  if (!r.connected) throw Failure("request to " + shown_url(s.url) + " failed: " + one_line(r.error));
  // The key is scrubbed from the whole body before any of it is cut or shown, and the reply
  // handed on is scrubbed too: an answer parsed, quoted in a fallback reason or logged by the
  // plugins cannot show it.
  // A server echoing the request (its path, its query) shows no key either.
  const size_t query = s.url.find('?');
  const std::string body_shown = query == std::string::npos ? r.body : scrub_secret(r.body, s.url.substr(query + 1));
  if (r.status < 200 || r.status > 299)
    throw Failure("HTTP " + std::to_string(r.status) + " from " + shown_url(s.url) +
                  (body_shown.empty() ? "" : ": " + safe_excerpt(body_shown, s.api_key, 200)));
  return scrub_secret(body_shown, s.api_key);
}

// The text of choices[0].message.content (a string, or a list of text parts).
std::string answer_text(const std::string& reply) {
  json r;
  try {
    r = json::parse(reply);
  } catch (const json::exception& e) {
    throw Failure("malformed JSON in the reply: " + one_line(e.what(), 200));
  }
  if (!r.is_object() || !r.contains("choices") || !r["choices"].is_array() || r["choices"].empty() ||
      !r["choices"][0].is_object() || !r["choices"][0].contains("message") || !r["choices"][0]["message"].is_object())
    throw Failure("malformed reply: no choices[0].message");
  const json& content = r["choices"][0]["message"].value("content", json());
  if (content.is_string()) return content.get<std::string>();
  if (content.is_array()) {
    std::string s;
    for (const auto& part : content)
      // (value("type", "") throws on a type that is not a string: a malformed reply must be a
      // Failure the callers fall back on, not an exception that ends the stage.)
      if (part.is_object() && part.contains("type") && part["type"].is_string() && part["type"].get<std::string>() == "text" &&
          part.contains("text") && part["text"].is_string())
        s += part["text"].get<std::string>();
    return s;
  }
  throw Failure("malformed reply: choices[0].message.content is not text");
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
