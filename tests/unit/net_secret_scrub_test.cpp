// net/secret_scrub: the key removed in every form a server could echo it (verbatim,
// percent-encoded, JSON-escaped, base64 at any alignment) before text is cut, so no piece of
// it survives an excerpt; excerpts on one line, control characters gone, cut between
// characters. Also the URL parts the transport's messages name (net/http_transport.h).
#include <doctest/doctest.h>

#include <string>

#include "net/base64.h"
#include "net/http_transport.h"
#include "net/secret_scrub.h"

using namespace svgm;

namespace {

// 46 characters with /, +, =, : and . so that every encoded form differs from the key.
const std::string kKey = "sk-live/Ab+Cd=Ef:Gh.Ij_Kl-Mn0123456789opqrstuv";

// Whether any 8-character piece of `key` appears in `text`.
bool has_piece(const std::string& text, const std::string& key) {
  for (size_t i = 0; i + 8 <= key.size(); ++i)
    if (text.find(key.substr(i, 8)) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("scrub_secret removes the key verbatim, percent-encoded, JSON-escaped and base64-encoded") {
  CHECK(scrub_secret("key=" + kKey + ", again " + kKey + ".", kKey) == "key=<key>, again <key>.");
  // By hand: / + = : are %2F %2B %3D %3A; the unreserved - . _ stay.
  const std::string pct = "sk-live%2FAb%2BCd%3DEf%3AGh.Ij_Kl-Mn0123456789opqrstuv";
  CHECK(scrub_secret("GET /x?k=" + pct + "&y=1", kKey) == "GET /x?k=<key>&y=1");
  CHECK(scrub_secret("k=sk-live%2fAb%2bCd%3dEf%3aGh.Ij_Kl-Mn0123456789opqrstuv", kKey) == "k=<key>");
  CHECK(scrub_secret(R"({"k": "sk-live\/Ab+Cd=Ef:Gh.Ij_Kl-Mn0123456789opqrstuv"})", kKey) == R"({"k": "<key>"})");
  // Inside a longer base64 run (a Basic credential "user:KEY"), at each of the three alignments:
  // nothing of the key's encoding may remain.
  for (const std::string user : {"", "u:", "us:", "use:"}) {
    const std::string basic = base64(user + kKey);
    const std::string scrubbed = scrub_secret("Authorization: Basic " + basic, kKey);
    CHECK(scrubbed.find("<key>") != std::string::npos);
    CHECK(scrubbed.size() < basic.size());
    // What is left of the encoded run is at most the user's part and a boundary character or
    // two on each side.
    CHECK(scrubbed.size() - std::string("Authorization: Basic <key>").size() <= base64(user).size() + 4);
  }
  CHECK(scrub_secret("nothing here", "") == "nothing here");
  CHECK(scrub_secret("abc", "abc") == "<key>");
  // A short key is removed verbatim only: its encoded fragments would match ordinary text.
  CHECK(scrub_secret("a/b a%2Fb", "a/b") == "<key> a%2Fb");
}

TEST_CASE("safe_excerpt scrubs before it cuts: a key across the cut leaves no piece of itself") {
  for (size_t at : {150, 190, 195, 199, 200, 201}) {
    const std::string text = std::string(at, 'x') + kKey + " was refused";
    const std::string e = safe_excerpt(text, kKey, 200);
    CHECK_FALSE(has_piece(e, kKey));
    CHECK(e.size() <= 203);  // 200 and "..."
  }
  CHECK(safe_excerpt(std::string(190, 'x') + kKey + " is not a key we know", kKey) ==
        std::string(190, 'x') + "<key> is n...");
  // The cut-first order this replaces kept 10 characters of the key here.
  CHECK(has_piece((std::string(190, 'x') + kKey).substr(0, 200), kKey));
}

TEST_CASE("safe_excerpt is one line without control characters, cut between UTF-8 characters") {
  CHECK(safe_excerpt("a\nb\r\tc\x1b[31md\x7f  ", "") == "a b  c [31md");
  // "é" is two bytes: a cut at byte 4 would split the second one.
  CHECK(safe_excerpt("aéé", "", 4) == "aé...");
  CHECK(safe_excerpt("short", "", 200) == "short");
}

TEST_CASE("URL parts for messages: the scheme, the host, a size limit") {
  CHECK(url_scheme("HTTPS://h/x") == "https");
  CHECK(url_scheme("file:///etc/passwd") == "file");
  CHECK(url_scheme("dict://127.0.0.1:1/info") == "dict");
  CHECK(url_scheme("/video.mp4") == "");
  CHECK(url_scheme("video.mp4") == "");
  CHECK(scheme_for_message("file:///etc/passwd") == "a file: URL");
  CHECK(scheme_for_message("video.mp4") == "a URL without a scheme");
  CHECK(url_host("https://user:pw@api.test:8443/v1?k=1") == "api.test:8443");
  CHECK(too_large_message("reply", "http://127.0.0.1:9/x", kMaxReplyBytes) ==
        "the reply from 127.0.0.1:9 is larger than 16 MiB");
  CHECK(too_large_message("download", "http://h/x", 1000) == "the download from h is larger than 1000 bytes");
}

}  // TEST_SUITE
