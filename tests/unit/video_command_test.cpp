// The video `command` plugin's logic: argv templates (no shell anywhere), running a program with
// its output logged and a time limit, and whole runs of generate_candidates with small /bin/sh
// "generators" written at run time that copy a video made here with the preview writer.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "media/preview_video.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/target_video.h"
#include "generators/command_runner.h"
#include "generators/command_video.h"

#include "error_of.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

struct CommandTempDir : test::TempDir {
  CommandTempDir() : test::TempDir("svgm_cmd_test") {}
};

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

double elapsed_s(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

RgbaImage solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  RgbaImage im;
  im.width = w;
  im.height = h;
  im.rgba.resize(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < im.rgba.size(); i += 4) {
    im.rgba[i] = r;
    im.rgba[i + 1] = g;
    im.rgba[i + 2] = b;
    im.rgba[i + 3] = 255;
  }
  return im;
}

// A run directory as the recolorer leaves it, plus a small mp4 for generators to copy.
struct RunDir {
  CommandTempDir tmp;
  fs::path run, video;
  RunDir() {
    run = tmp.path / "run";
    fs::create_directories(run);
    write_png(run / "recolored.png", solid(16, 16, 200, 30, 30));
    write_text(run / "recolored.svg", "<svg xmlns='http://www.w3.org/2000/svg'/>");
    video = tmp.path / "premade.mp4";
    write_preview_video(
        video, 6, 1, [](int k, int) { return solid(32, 32, static_cast<uint8_t>(40 * k), 0, 0); },
        24);
  }
};

// A generator: prints each argument as [arg] (to its log), then copies $1 to the value after
// --out (or does what `body` says instead).
fs::path write_generator(const fs::path& dir, const std::string& body) {
  const fs::path script = dir / "gen.sh";
  write_text(script,
             "for a in \"$@\"; do printf '[%s]\\n' \"$a\"; done\n"
             "src=\"$1\"; shift\n"
             "while [ $# -gt 0 ]; do\n"
             "  case \"$1\" in --out) out=\"$2\"; shift;; --seed) seed=\"$2\"; shift;; esac\n"
             "  shift\n"
             "done\n" +
                 body + "\n");
  return script;
}

using test::error_of;

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("video command: argv expansion fills placeholders and never splits or re-expands") {
  const std::map<std::string, std::string> values = {
      {"image", "/r/recolored.png"}, {"prompt", "waves {out} ; rm -rf x"}, {"seed", "7"},
      {"out", "/r/candidates/00.mp4"}};
  const auto argv = expand_argv({"python3", "gen.py", "--image", "{image}", "--prompt", "{prompt}",
                                 "--seed={seed}", "{out}", "; rm -rf x", "$(echo hi) *",
                                 "{\"json\": {1}}", "{", "}{", "{}"},
                                values);
  const std::vector<std::string> expected = {
      "python3", "gen.py", "--image", "/r/recolored.png", "--prompt", "waves {out} ; rm -rf x",
      "--seed=7", "/r/candidates/00.mp4", "; rm -rf x", "$(echo hi) *", "{\"json\": {1}}", "{",
      "}{", "{}"};
  CHECK(argv == expected);
  CHECK(expand_argv({"{seed}{seed}-{out}"}, values) ==
        std::vector<std::string>{"77-/r/candidates/00.mp4"});
  const std::string err = error_of([&] { expand_argv({"gen", "--seed", "{sede}"}, values); });
  CHECK(err.find("unknown placeholder {sede} in argv[2]") != std::string::npos);
  CHECK(err.find("{seed}") != std::string::npos);
  CHECK(replace_placeholder("A. {prompt} B {prompt}", "prompt", "x {prompt}") ==
        "A. x {prompt} B x {prompt}");
}

TEST_CASE("video command: run_command passes arguments verbatim, logs output, reports status") {
  CommandTempDir tmp;
  const fs::path script = tmp.path / "args.sh";
  write_text(script, "echo \"count=$#\"\nfor a in \"$@\"; do printf '<%s>\\n' \"$a\"; done\n"
                     "echo to-stderr >&2\nexit 0\n");
  const fs::path log = tmp.path / "00.log";
  const CommandResult ok = run_command(
      {"/bin/sh", script.string(), "; rm -rf x", "a b", "$(touch pwned)", "*"}, log, 10);
  CHECK(ok.ok());
  CHECK(ok.status == 0);
  CHECK_FALSE(ok.timed_out);
  CHECK_FALSE(ok.signalled);
  const std::string text = read_text(log);
  CHECK(text.find("count=4\n") != std::string::npos);
  CHECK(text.find("<; rm -rf x>\n<a b>\n<$(touch pwned)>\n<*>\n") != std::string::npos);
  CHECK(text.find("to-stderr\n") != std::string::npos);
  CHECK(text.rfind("# svgmotion: /bin/sh", 0) == 0);
  CHECK(text.find("exited with status 0") != std::string::npos);
  CHECK_FALSE(fs::exists(fs::current_path() / "pwned"));
  CHECK_FALSE(fs::exists(tmp.path / "pwned"));

  write_text(script, "echo failing; exit 3\n");
  const CommandResult three = run_command({"/bin/sh", script.string()}, log, 10);
  CHECK_FALSE(three.ok());
  CHECK(three.status == 3);
  CHECK_FALSE(three.signalled);
  CHECK(describe(three, 10) == "exited with status 3");
  CHECK(read_text(log).find("failing\n") != std::string::npos);  // truncated and rewritten
  CHECK(read_text(log).find("count=") == std::string::npos);

  write_text(script, "kill -9 $$\n");
  const CommandResult killed = run_command({"/bin/sh", script.string()}, log, 10);
  CHECK(killed.signalled);
  CHECK(killed.signal == 9);
  CHECK(describe(killed, 10).rfind("was killed by signal 9", 0) == 0);

  const CommandResult missing =
      run_command({"svgm-no-such-program-here", "x"}, tmp.path / "missing.log", 10);
  CHECK_FALSE(missing.ok());
  CHECK_FALSE(missing.spawn_error.empty());
  CHECK(describe(missing, 10).rfind("could not be started: ", 0) == 0);

  CHECK_THROWS_AS(run_command({}, log, 1), Error);
  CHECK_THROWS_AS(run_command({"/bin/true"}, tmp.path / "no" / "such" / "dir.log", 1), Error);
}

TEST_CASE("video command: run_command stops a program group at the time limit") {
  CommandTempDir tmp;
  const fs::path script = tmp.path / "slow.sh";
  write_text(script, "echo started\nsleep 30\necho never\n");
  const fs::path log = tmp.path / "slow.log";
  auto t0 = std::chrono::steady_clock::now();
  const CommandResult r = run_command({"/bin/sh", script.string()}, log, 1);
  const double took = elapsed_s(t0);
  CHECK(r.timed_out);
  CHECK(r.signalled);
  CHECK(r.status == -1);
  CHECK_FALSE(r.ok());
  CHECK(took >= 0.9);
  CHECK(took < 3.0);
  CHECK(describe(r, 1) == "timed out after 1 s");
  const std::string text = read_text(log);
  CHECK(text.find("started\n") != std::string::npos);
  CHECK(text.find("never") == std::string::npos);
  CHECK(text.find("timed out after 1 s") != std::string::npos);

  // A program (and its child) ignoring SIGTERM gets SIGKILL 2 s later.
  write_text(script, "trap '' TERM\nsleep 30\n");
  t0 = std::chrono::steady_clock::now();
  const CommandResult stubborn = run_command({"/bin/sh", script.string()}, log, 0.3);
  const double took2 = elapsed_s(t0);
  CHECK(stubborn.timed_out);
  CHECK(stubborn.signalled);
  CHECK(stubborn.signal == 9);
  CHECK(took2 >= 2.2);
  CHECK(took2 < 4.0);

  // Cancelling stops it the same way.
  write_text(script, "sleep 30\n");
  t0 = std::chrono::steady_clock::now();
  const CommandResult cancelled =
      run_command({"/bin/sh", script.string()}, log, 60, [t0] { return elapsed_s(t0) > 0.2; });
  CHECK(cancelled.cancelled);
  CHECK_FALSE(cancelled.timed_out);
  CHECK(elapsed_s(t0) < 2.0);
}

namespace {
volatile sig_atomic_t g_test_sigint = 0;
extern "C" void test_sigint_handler(int) { g_test_sigint = 1; }
}  // namespace

TEST_CASE("video command: Ctrl-C stops the program group, then reaches the host's handler") {
  CommandTempDir tmp;
  const fs::path script = tmp.path / "slow.sh";
  write_text(script, "sleep 30\n");
  g_test_sigint = 0;
  struct sigaction sa {}, old {};
  sa.sa_handler = test_sigint_handler;
  sigemptyset(&sa.sa_mask);
  REQUIRE(::sigaction(SIGINT, &sa, &old) == 0);
  const auto t0 = std::chrono::steady_clock::now();
  std::thread ctrl_c([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::kill(::getpid(), SIGINT);
  });
  const CommandResult r = run_command({"/bin/sh", script.string()}, tmp.path / "int.log", 60);
  ctrl_c.join();
  ::sigaction(SIGINT, &old, nullptr);
  CHECK(r.cancelled);
  CHECK(r.signalled);
  CHECK(elapsed_s(t0) < 2.0);
  CHECK(g_test_sigint == 1);  // raised again once the host's handler was back
}

TEST_CASE("video command: options are checked before anything runs") {
  using nlohmann::json;
  const CommandVideoOptions d = parse_command_video_options(json{{"argv", {"gen", "{out}"}}});
  CHECK(d.candidates == 4);
  CHECK(d.frames == 49);
  CHECK(d.timeout_s == 600);
  CHECK(d.fps == 24);
  CHECK(d.prompt_template == kDefaultVideoPromptTemplate);
  const CommandVideoOptions o = parse_command_video_options(
      json{{"argv", {"gen", "--frames", 25, "{out}"}}, {"candidates", 2}, {"frames", 25.0},
           {"timeout_s", 1.5}, {"fps", 8}, {"prompt_template", "x {prompt}"}});
  CHECK(o.argv == std::vector<std::string>{"gen", "--frames", "25", "{out}"});
  CHECK(o.candidates == 2);
  CHECK(o.frames == 25);
  CHECK(o.timeout_s == 1.5);
  CHECK(o.fps == 8);
  CHECK(o.prompt_template == "x {prompt}");

  CHECK(error_of([] { parse_command_video_options(json::object()); }).find("options.argv is not set") !=
        std::string::npos);
  CHECK(error_of([] { parse_command_video_options(json{{"argv", {"gen", "x.mp4"}}}); })
            .find("never mentions {out}") != std::string::npos);
  CHECK(error_of([] { parse_command_video_options(json{{"argv", {"g", "{out}"}}, {"candidate", 2}}); }) ==
        "video command: unknown option 'candidate' (options: argv, candidates, frames, timeout_s, "
        "fps, prompt_template)");
  CHECK(error_of([] { parse_command_video_options(json{{"argv", {"g", "{out}"}}, {"candidates", 0}}); })
            .find("options.candidates must be a whole number in 1..99") != std::string::npos);
  CHECK(error_of([] { parse_command_video_options(json{{"argv", {"g", "{out}"}}, {"timeout_s", -1}}); })
            .find("options.timeout_s") != std::string::npos);
  CHECK(error_of([] { parse_command_video_options(json{{"argv", "gen {out}"}}); })
            .find("options.argv must be a list") != std::string::npos);
}

TEST_CASE("video command: generate_candidates runs the generator once per candidate") {
  RunDir rd;
  const std::string png_before = read_text(rd.run / "recolored.png");
  write_text(rd.run / "candidates", "");  // a stale file where the folder goes
  const fs::path gen = write_generator(rd.tmp.path, "cp \"$src\" \"$out\"");
  CommandVideoOptions o;
  o.argv = {"/bin/sh", gen.string(), rd.video.string(), "--image", "{image}", "--prompt",
            "{prompt}", "--seed", "{seed}", "--frames", "{frames}", "--fps", "{fps}", "--out", "{out}"};
  o.candidates = 2;
  o.frames = 6;
  o.fps = 12.5;
  o.timeout_s = 20;
  std::vector<double> progress;
  std::vector<std::string> lines;
  CommandVideoHooks hooks;
  hooks.progress = [&](double f, const std::string&) { progress.push_back(f); };
  hooks.log = [&](const std::string& l) { lines.push_back(l); };

  const auto files = generate_candidates(o, rd.run, "the man waves; rm -rf /", 40, hooks);
  REQUIRE(files.size() == 2);
  CHECK(files[0] == rd.run / "candidates" / "00.mp4");
  CHECK(files[1] == rd.run / "candidates" / "01.mp4");
  for (const auto& f : files) CHECK(probe_target(f).frames == 6);
  const std::string log0 = read_text(rd.run / "candidates" / "00.log");
  const std::string log1 = read_text(rd.run / "candidates" / "01.log");
  CHECK(log0.find("[--image]\n[" + (rd.run / "recolored.png").string() + "]\n") !=
        std::string::npos);
  CHECK(log0.find(std::string("[--prompt]\n[") +
                  replace_placeholder(kDefaultVideoPromptTemplate, "prompt",
                                      "the man waves; rm -rf /") +
                  "]\n") != std::string::npos);
  CHECK(log0.find("[--seed]\n[40]\n[--frames]\n[6]\n[--fps]\n[12.5]\n") != std::string::npos);
  CHECK(log1.find("[--seed]\n[41]\n") != std::string::npos);
  CHECK(log1.find("[--out]\n[" + (rd.run / "candidates" / "01.mp4").string() + "]\n") !=
        std::string::npos);
  CHECK(progress.size() == 3);
  CHECK(progress.back() == 1.0);
  CHECK(lines.size() == 4);
  // Earlier stages' files are untouched; nothing but candidates/ was added.
  CHECK(read_text(rd.run / "recolored.png") == png_before);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(rd.run)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"candidates", "recolored.png", "recolored.svg"});

  // A custom prompt template; the previous candidates are cleared.
  o.candidates = 1;
  o.prompt_template = "<<{prompt}>>";
  generate_candidates(o, rd.run, "jumps", 0);
  CHECK(read_text(rd.run / "candidates" / "00.log").find("[<<jumps>>]\n") != std::string::npos);
  CHECK_FALSE(fs::exists(rd.run / "candidates" / "01.mp4"));
}

TEST_CASE("video command: generate_candidates names the failing candidate in one line") {
  RunDir rd;
  CommandVideoOptions o;
  o.candidates = 3;
  o.timeout_s = 20;

  // Candidate 01 fails with status 3: candidate 00 stays, the error names the log.
  fs::path gen = write_generator(
      rd.tmp.path, "if [ \"$seed\" = 1 ]; then echo 'CUDA out of memory' >&2; exit 3; fi\n"
                   "cp \"$src\" \"$out\"");
  o.argv = {"/bin/sh", gen.string(), rd.video.string(), "--seed", "{seed}", "--out", "{out}"};
  CHECK(error_of([&] { generate_candidates(o, rd.run, "waves", 0); }) ==
        "video command: candidate 01: /bin/sh exited with status 3 (see candidates/01.log)");
  CHECK(fs::exists(rd.run / "candidates" / "00.mp4"));
  CHECK(read_text(rd.run / "candidates" / "01.log").find("CUDA out of memory") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(rd.run / "candidates" / "02.log"));

  // Exit 0 without an output, and with an unreadable one.
  gen = write_generator(rd.tmp.path, "true");
  CHECK(error_of([&] { generate_candidates(o, rd.run, "waves", 0); }) ==
        "video command: candidate 00: /bin/sh wrote no readable video at candidates/00.mp4: "
        "no such file");
  gen = write_generator(rd.tmp.path, "echo 'not a video' > \"$out\"");
  const std::string bad = error_of([&] { generate_candidates(o, rd.run, "waves", 0); });
  CHECK(bad.rfind("video command: candidate 00: /bin/sh wrote no readable video at "
                  "candidates/00.mp4: ",
                  0) == 0);
  CHECK(bad.find('\n') == std::string::npos);
  CHECK(bad.find(rd.run.string()) == std::string::npos);

  // Timed out.
  gen = write_generator(rd.tmp.path, "sleep 30");
  o.timeout_s = 0.5;
  auto t0 = std::chrono::steady_clock::now();
  CHECK(error_of([&] { generate_candidates(o, rd.run, "waves", 0); }) ==
        "video command: candidate 00: /bin/sh timed out after 0.5 s (see candidates/00.log)");
  CHECK(elapsed_s(t0) < 3.0);

  // A program that is not there; a placeholder typo fails before candidates/ is touched.
  o.argv = {"svgm-no-such-generator", "{out}"};
  CHECK(error_of([&] { generate_candidates(o, rd.run, "waves", 0); })
            .rfind("video command: candidate 00: svgm-no-such-generator could not be started: ", 0) == 0);
  write_text(rd.run / "candidates" / "keep.txt", "x");
  o.argv = {"gen", "{imgae}", "{out}"};
  CHECK(error_of([&] { generate_candidates(o, rd.run, "waves", 0); })
            .rfind("video command: options.argv: unknown placeholder {imgae} in argv[1]", 0) == 0);
  CHECK(fs::exists(rd.run / "candidates" / "keep.txt"));

  // No recoloured image: nothing runs.
  fs::remove(rd.run / "recolored.png");
  CHECK(error_of([&] { generate_candidates(o, rd.run, "waves", 0); }).find("no such file") !=
        std::string::npos);
}

}  // TEST_SUITE
