// Config loading (pipeline/config.h): the value bound that stops YAML alias bombs, wherever in
// the config they sit (a free-form options section, a list, an override), while ordinary
// aliases keep working. Config files are written by the test into a temporary folder.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/config.h"
#include "svgmotion/error.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& text) {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("svgm_config_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".yaml");
    std::ofstream(path) << text;
  }
  ~TempFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
};

// Nine levels of ten aliases to the level below: 10^9 strings when expanded, under 1 KB written.
// `indent` spaces before each line; the anchors are flow lists so each level is one line.
std::string bomb(const std::string& indent) {
  std::string s = indent + "l0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 8; ++i) {
    const std::string prev = "*a" + std::to_string(i - 1);
    s += indent + "l" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int j = 0; j < 10; ++j) s += (j ? ", " : "") + prev;
    s += "]\n";
  }
  return s;
}

std::string error_of(const std::optional<fs::path>& file, const std::vector<std::string>& overrides = {}) {
  try {
    load_config(file, overrides);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_SUITE("pipeline") {

TEST_CASE("config: a repeated key is an error naming its line") {
  const TempFile f("stages:\n  fitter:\n    iterations: 5\n    iterations: 7\n");
  CHECK(error_of(f.path) == f.path.string() + ":4: duplicate key 'stages.fitter.iterations'");
  const TempFile top("seed: 1\nseed: 2\n");
  CHECK(error_of(top.path) == top.path.string() + ":2: duplicate key 'seed'");
}

TEST_CASE("an alias bomb in a free-form options section is refused in one line naming the file") {
  const TempFile f("stages:\n  video:\n    options:\n" + bomb("      "));
  CHECK(error_of(f.path) == f.path.string() +
                                ":3: 'stages.video.options' expands to more than 100000 values "
                                "(YAML aliases of aliases?)");
}

TEST_CASE("an alias bomb in a list-valued key or in an override is refused the same way") {
  // The same nine levels as one flow list; each level is an element of plugin_paths.
  std::string flow = "[&a0 [x, x, x, x, x, x, x, x, x, x]";
  for (int i = 1; i <= 8; ++i) {
    flow += ", &a" + std::to_string(i) + " [";
    for (int j = 0; j < 10; ++j) flow += (j ? ", *a" : "*a") + std::to_string(i - 1);
    flow += "]";
  }
  flow += "]";
  const TempFile f("device: cpu\nplugin_paths: " + flow + "\n");
  CHECK(error_of(f.path) == f.path.string() +
                                ":2: 'plugin_paths' expands to more than 100000 values "
                                "(YAML aliases of aliases?)");
  const std::string o = "stages.fitter.options={big: " + flow + "}";
  CHECK(error_of(std::nullopt, {o}) ==
        "command line '" + o + "': 'stages.fitter.options' expands to more than 100000 values "
        "(YAML aliases of aliases?)");
}

TEST_CASE("config: each user setting's origin is known, so a value error can name the file and line") {
  const TempFile f("stages:\n  fitter:\n    iterations: 0\n    size: 64\n  video:\n    options:\n      frames: 3\n");
  ConfigOrigins origins;
  load_config(f.path, {"stages.fitter.size=128"}, &origins);
  CHECK(origins["stages.fitter.iterations"] == f.path.string() + ":3");
  CHECK(origins["stages.fitter.size"] == "command line 'stages.fitter.size=128'");  // the override wins
  CHECK(origins["stages.video.options"] == f.path.string() + ":6");
  CHECK(origins.count("stages.fitter.keyframes") == 0);  // a default
  CHECK(origin_of_message(origins, "stages.fitter.iterations: must be a whole number from 1 to 1000000, not 0") ==
        f.path.string() + ":3");
  CHECK(origin_of_message(origins, "stages.video.options.motion: must be a string") == f.path.string() + ":6");
  CHECK(origin_of_message(origins, "stages.fitter.keyframes: must be a whole number") == "");
  CHECK(origin_of_message(origins, "/tmp/x.svg: cannot open: No such file or directory") == "");
}

TEST_CASE("ordinary aliases in options still expand") {
  const TempFile f(
      "stages:\n  video:\n    options:\n      base: &b {fps: 12, size: 96}\n      a: *b\n      c: [*b, *b]\n");
  const nlohmann::json cfg = load_config(f.path, {});
  const nlohmann::json& o = cfg["stages"]["video"]["options"];
  CHECK(o["a"]["fps"] == 12);
  CHECK(o["c"].size() == 2);
  CHECK(o["c"][1]["size"] == 96);
}

TEST_CASE("config: a list or map as a key is an error naming its line, not an internal error") {
  const TempFile f("seed: 1\n? [a, b]\n: 1\n");
  CHECK(error_of(f.path) == f.path.string() + ":2: a key must be a name, not a list or a map");
  const TempFile nested("stages:\n  video:\n    options:\n      ? {k: v}\n      : 1\n");
  CHECK(error_of(nested.path) ==
        nested.path.string() + ":3: 'stages.video.options': a key must be a name, not a list or a map");
}

TEST_CASE("config: control characters in a key stay escaped, so the error is one line") {
  const TempFile f("stages:\n  fitter:\n    \"iter\\nations\\t\\x01\": 5\n");
  CHECK(error_of(f.path) == f.path.string() + ":3: unknown key 'stages.fitter.iter\\nations\\t\\x01'");
  CHECK(error_of(std::nullopt, {"stages.fitter.iterations=[1,\n"}).find('\n') == std::string::npos);
  // yaml-cpp's own message quotes the offending character raw (found by the config fuzz target).
  const TempFile esc("seed: \"a\\\rb\"\n");
  CHECK(error_of(esc.path) == esc.path.string() + ":1: unknown escape character: \\x0d");
  CHECK(error_of(std::nullopt, {"seed=\"a\\\rb\""}) ==
        "override 'seed=\"a\\\\x0db\"': unknown escape character: \\x0d");
}

TEST_CASE("config: text that is not UTF-8 is refused where it is read (plugins get JSON)") {
  const TempFile value("stages:\n  video:\n    options:\n      label: \"caf\xe9\"\n");
  CHECK(error_of(value.path) == value.path.string() + ":3: 'stages.video.options' is not valid UTF-8 text");
  const TempFile key("stages:\n  video:\n    options:\n      \xff: 1\n");
  CHECK(error_of(key.path) == key.path.string() + ":3: 'stages.video.options': a key is not valid UTF-8 text");
  const TempFile prompt("prompt: \"waves \xff\"\n");
  CHECK(error_of(prompt.path) == prompt.path.string() + ":1: 'prompt' is not valid UTF-8 text");
}

TEST_CASE("config: nesting beyond yaml-cpp's limit is named as such (yaml-cpp says 'bad file')") {
  const std::string deep = std::string(600, '[') + std::string(600, ']');
  const TempFile f("stages:\n  video:\n    options:\n      deep: " + deep + "\n");
  CHECK(error_of(f.path) == f.path.string() + ":4: nested too deeply (more than 500 levels)");
  const std::string o = "stages.video.options={d: " + deep + "}";
  CHECK(error_of(std::nullopt, {o}) == "override '" + o + "': nested too deeply (more than 500 levels)");
}

TEST_CASE("config: an alias inside its own anchor is refused in one line, not a stack overflow") {
  // yaml-cpp links "*a" to the list being built, so the node graph is a cycle (fuzz finding:
  // tests/fuzz/corpus/config/alias_cycle.yaml).
  const TempFile f("stages:\n  video:\n    options:\n      a: &a [x, *a]\n");
  CHECK(error_of(f.path) ==
        f.path.string() + ":3: 'stages.video.options' contains itself (a YAML alias inside its own anchor)");
  const std::string o = "stages.video.options={a: &a [*a, *a]}";
  CHECK(error_of(std::nullopt, {o}) ==
        "command line '" + o + "': 'stages.video.options' contains itself (a YAML alias inside its own anchor)");
  const TempFile list("stages:\n  video:\n    options: &o {b: *o}\n");
  CHECK(error_of(list.path) ==
        list.path.string() + ":3: 'stages.video.options' contains itself (a YAML alias inside its own anchor)");
}

TEST_CASE("config: numbers in free-form options are read as before (strtoll/strtod, not stoll/stod)") {
  const auto cfg = load_config(std::nullopt, {"stages.video.options={a: +5, b: 1e999, c: 1.5, d: 12abc, e: -7}"});
  const auto& o = cfg["stages"]["video"]["options"];
  CHECK(o["a"] == 5);
  CHECK(o["a"].is_number_integer());
  CHECK(o["b"] == "1e999");  // out of range: kept as text
  CHECK(o["c"] == 1.5);
  CHECK(o["d"] == "12abc");
  CHECK(o["e"] == -7);
}

}  // TEST_SUITE
