// What the `llm` plugins (grouper llm, ranker llm) share: reading an OpenAI-compatible
// chat-completions endpoint's settings, POSTing a request with libcurl (cancellable, one time
// limit), and reading the answer text out of the reply. Every failure that should make the
// plugin fall back to its non-LLM sibling is a chat::Failure with a one-line reason; a user's
// Ctrl-C is an svgm::Error ("<who>: cancelled").
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "net/base64.h"
#include "svgmotion/plugin.h"

namespace svgm::plugin::chat {

// A reason to fall back (one line).
struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Settings {
  std::string url, model, api_key;
  double timeout_s = 60;
};

// Reads url (required), model, api_key_env (the environment variable holding the key, sent as
// "Authorization: Bearer <key>" when set and not empty) and timeout_s from `options`; `stage`
// names the stage in the messages ("no url configured (stages.<stage>.options.url)").
Settings read_settings(const nlohmann::json& options, const std::string& stage);

// s with control characters (newlines, tabs, ESC) as spaces, cut to max_chars (then "...").
std::string one_line(std::string s, size_t max_chars = 300);

using svgm::base64;  // net/base64.h

// POSTs `body` (JSON) to s.url and returns the body of a 2xx reply, the key scrubbed out
// (net/secret_scrub.h); Failure for a timeout, a transport error, a reply over kMaxReplyBytes
// or another status (with a short, scrubbed excerpt of its body). `who` names the plugin in the user agent and messages.
std::string post(const Settings& s, const std::string& body, const svgm_host* host,
                 const std::string& who);

// The text of choices[0].message.content (a string, or a list of text parts); Failure otherwise.
std::string answer_text(const std::string& reply);

// The answer without ```json ... ``` (or ``` ... ```) fences around it.
std::string strip_fences(const std::string& text);

}  // namespace svgm::plugin::chat
