// Batch manifests, shards and the summary (pipeline/batch_manifest.h, batch_shard.h, batch.h):
// what a manifest yields (paths resolved, ids, overrides), the exact error for each malformed
// manifest, that N shards cover every item exactly once, the Slurm array arithmetic and its
// range checks, the run arguments of an item, and a summary rebuilt from records with missing
// items pending. The security issue's manifest findings each have a check here: alias bombs
// stop at the config loader's cap, overrides are settings and never options, odd ids, a BOM,
// a NUL byte, a folder, YAML keys and values of the wrong kind.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "pipeline/batch.h"
#include "pipeline/batch_manifest.h"
#include "pipeline/batch_shard.h"
#include "pipeline/config.h"
#include "svgmotion/error.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::string error_of(const fs::path& manifest) {
  try {
    read_batch_manifest(manifest);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

std::function<const char*(const char*)> env_of(const std::map<std::string, std::string>& vars) {
  return [vars](const char* name) -> const char* {
    const auto it = vars.find(name);
    return it == vars.end() ? nullptr : it->second.c_str();
  };
}

}  // namespace

TEST_SUITE("pipeline") {
  TEST_CASE("a CSV manifest: quoted fields, comments, defaults, paths relative to it") {
    test::TempDir dir("svgm_batch");
    const fs::path m = write(dir.path / "m.csv",
                             "input,prompt,id,target,overrides\n"
                             "# a comment line\n"
                             "art/cat.svg,\"the cat, waving\",,clips/cat.mp4,stages.fitter.iterations=50 seed=2\n"
                             "\n"
                             "/abs/dog house.svg,\"a \"\"quoted\"\" word\",dog-1,,\n");
    const auto items = read_batch_manifest(m);
    REQUIRE(items.size() == 2);
    CHECK(items[0].id == "cat");
    CHECK(items[0].input == dir.path / "art" / "cat.svg");
    CHECK(items[0].prompt == "the cat, waving");
    CHECK(items[0].target == dir.path / "clips" / "cat.mp4");
    CHECK(items[0].overrides == std::vector<std::string>{"stages.fitter.iterations=50", "seed=2"});
    CHECK(items[0].line == 3);
    CHECK(items[1].id == "dog-1");
    CHECK(items[1].input == fs::path("/abs/dog house.svg"));
    CHECK(items[1].prompt == "a \"quoted\" word");
    CHECK(items[1].target.empty());
    CHECK(items[1].overrides.empty());
    CHECK(items[1].line == 5);
  }

  TEST_CASE("a YAML manifest: a list under items, overrides as a nested map or key=value list") {
    test::TempDir dir("svgm_batch");
    const fs::path m = write(dir.path / "m.yaml",
                             "items:\n"
                             "  - input: a b.svg\n"
                             "    prompt: it jumps\n"
                             "    overrides: {stages: {fitter: {iterations: 40}}, seed: 3}\n"
                             "  - input: /x/b.svg\n"
                             "    id: second\n"
                             "    target: v.mp4\n"
                             "    overrides: [stages.fitter.size=64]\n");
    const auto items = read_batch_manifest(m);
    REQUIRE(items.size() == 2);
    CHECK(items[0].id == "a_b");  // a space is not an id character
    CHECK(items[0].prompt == "it jumps");
    CHECK(items[0].overrides == std::vector<std::string>{"stages.fitter.iterations=40", "seed=3"});
    CHECK(items[0].line == 2);
    CHECK(items[1].id == "second");
    CHECK(items[1].target == dir.path / "v.mp4");
    CHECK(items[1].overrides == std::vector<std::string>{"stages.fitter.size=64"});
  }

  TEST_CASE("a malformed manifest is one line naming the file, the line and the problem") {
    test::TempDir dir("svgm_batch");
    const std::string d = dir.path.string();
    CHECK(error_of(write(dir.path / "a.csv", "input,colour\nx.svg,red\n")) ==
          d + "/a.csv:1: unknown column 'colour' (columns: id, input, prompt, target, overrides)");
    CHECK(error_of(write(dir.path / "b.csv", "prompt\nhello\n")) == d + "/b.csv:1: no 'input' column");
    CHECK(error_of(write(dir.path / "c.csv", "input,prompt\nx.svg\n")) ==
          d + "/c.csv:2: 1 fields, the header has 2");
    CHECK(error_of(write(dir.path / "d.csv", "input,prompt\nx.svg,\"open\n")) ==
          d + "/d.csv:2: a quoted field is not closed");
    CHECK(error_of(write(dir.path / "e.csv", "input\nart/x.svg\nother/x.svg\n")) ==
          d + "/e.csv:3: id 'x' is already used on line 2 (give the item an id)");
    CHECK(error_of(write(dir.path / "f.csv", "input,id\nx.svg,../up\n")) ==
          d + "/f.csv:2: id '../up' may hold only letters, digits, '.', '_' and '-'");
    CHECK(error_of(write(dir.path / "g.csv", "input,prompt\n,hello\n")) == d + "/g.csv:2: the item has no input");
    CHECK(error_of(write(dir.path / "h.csv", "input,overrides\nx.svg,seed\n")) ==
          d + "/h.csv:2: override 'seed' is not key.path=value");
    CHECK(error_of(write(dir.path / "i.csv", "input\n")) == d + "/i.csv: no items");
    CHECK(error_of(write(dir.path / "j.yaml", "- input: x.svg\n  colour: red\n")) ==
          d + "/j.yaml:2: unknown key 'colour' (keys: id, input, prompt, target, overrides)");
    CHECK(error_of(write(dir.path / "k.yaml", "things: []\n")) ==
          d + "/k.yaml:1: unknown key 'things' (a manifest holds `items:`)");
    CHECK(error_of(write(dir.path / "l.txt", "input\nx.svg\n")) == d + "/l.txt: a manifest is .csv, .yaml or .yml");
    CHECK(error_of(dir.path / "missing.csv") == d + "/missing.csv: cannot open: No such file");
  }

  TEST_CASE("a YAML alias bomb in a manifest stops at the config loader's cap, in one line") {
    test::TempDir dir("svgm_batch");
    const std::string d = dir.path.string();
    // Nine levels of ten aliases each: 10^9 overrides (1.8 GB in 30 s before the cap).
    std::string bomb = "- input: x.svg\n  overrides:\n    stages:\n      video:\n        options:\n"
                       "          a0: &a0 {k: v}\n";
    for (int i = 1; i <= 9; ++i) {
      bomb += "          a" + std::to_string(i) + ": &a" + std::to_string(i) + " {";
      for (int j = 0; j < 10; ++j) bomb += (j ? ", k" : "k") + std::to_string(j) + ": *a" + std::to_string(i - 1);
      bomb += "}\n";
    }
    CHECK(error_of(write(dir.path / "bomb.yaml", bomb)) ==
          d + "/bomb.yaml:2: item 1: overrides expand to more than " + std::to_string(kMaxConfigValues) +
              " values (YAML aliases of aliases?)");
    CHECK(error_of(write(dir.path / "cycle.yaml", "- input: x.svg\n  overrides: &o {stages: *o}\n")) ==
          d + "/cycle.yaml:2: item 1: overrides contain themselves (a YAML alias inside its own anchor)");
    // Many items repeating one long text: each alias is cheap in the file, not in memory.
    std::string many = "- {input: x.svg, id: i0, prompt: &p " + std::string(1 << 20, 'w') + "}\n";
    for (int i = 1; i < 70; ++i) many += "- {input: x.svg, id: i" + std::to_string(i) + ", prompt: *p}\n";
    CHECK(error_of(write(dir.path / "many.yaml", many)) ==
          d + "/many.yaml:64: the manifest expands to more than 64 MB of text (YAML aliases?)");
    std::string deep = "- input: x.svg\n  overrides: ";
    for (int i = 0; i < 600; ++i) deep += "{a: ";
    deep += "1" + std::string(600, '}') + "\n";
    CHECK(error_of(write(dir.path / "deep.yaml", deep)).find(d + "/deep.yaml:2: nested too deeply") == 0);
  }

  TEST_CASE("overrides are config settings, never options, and not the batch's own input, prompt, output") {
    test::TempDir dir("svgm_batch");
    const std::string d = dir.path.string();
    // `svgmotion run` read these as its -o and --input: the item ran elsewhere, reported done.
    CHECK(error_of(write(dir.path / "a.csv", "input,overrides\nx.svg,-o=/elsewhere\n")) ==
          d + "/a.csv:2: override '-o=/elsewhere' is a command-line option, not a setting (overrides are key.path=value)");
    CHECK(error_of(write(dir.path / "b.csv", "input,overrides\nx.svg,seed=1 --input=y.svg\n")) ==
          d + "/b.csv:2: override '--input=y.svg' is a command-line option, not a setting (overrides are key.path=value)");
    CHECK(error_of(write(dir.path / "c.yaml", "- input: x.svg\n  overrides: [\"-o=/elsewhere\"]\n")) ==
          d + "/c.yaml:2: override '-o=/elsewhere' is a command-line option, not a setting (overrides are key.path=value)");
    CHECK(error_of(write(dir.path / "d.csv", "input,overrides\nx.svg,output=/elsewhere\n")) ==
          d + "/d.csv:2: override 'output=/elsewhere': an item's run directory is OUT_DIR/<id>, not an override");
    CHECK(error_of(write(dir.path / "e.yaml", "- input: x.svg\n  overrides: {input: y.svg}\n")) ==
          d + "/e.yaml:1: override 'input=y.svg': an item's input is its manifest field 'input', not an override");
    CHECK(error_of(write(dir.path / "f.csv", "input,overrides\nx.svg,stages.fitter.iterationz=3\n")) ==
          d + "/f.csv:2: override 'stages.fitter.iterationz=3': unknown key 'stages.fitter.iterationz' (did you mean "
              "'stages.fitter.iterations'?)");
    CHECK(error_of(write(dir.path / "g.csv", "input,overrides\nx.svg,stages.fitter.iterations=many\n")) ==
          d + "/g.csv:2: override 'stages.fitter.iterations=many': 'stages.fitter.iterations' must be a number");
    CHECK_NOTHROW(check_batch_override("stages.video.options.motion=flap:wing*"));
    CHECK_NOTHROW(check_batch_override("device=cpu"));
    CHECK_THROWS_WITH_AS(check_batch_override("prompt=it waves"),
                         "override 'prompt=it waves': an item's prompt is its manifest field 'prompt', not an override",
                         Error);
  }

  TEST_CASE("small manifest defects: BOM, NUL, a folder, the extension's case, ids from odd names") {
    test::TempDir dir("svgm_batch");
    const std::string d = dir.path.string();
    // A spreadsheet's byte order mark was part of the first column's name: unknown column 'ï»¿id'.
    auto items = read_batch_manifest(write(dir.path / "bom.csv", "\xEF\xBB\xBFid,input\nm,x.svg\n"));
    REQUIRE(items.size() == 1);
    CHECK(items[0].id == "m");
    CHECK(error_of(write(dir.path / "nul.csv", std::string("id,input\nm,x\0.svg\n", 18))) ==
          d + "/nul.csv:2: a NUL byte (a manifest is text)");
    CHECK(error_of(write(dir.path / "nul.yaml", std::string("- input: x.svg\n\n- input: y\0\n", 28))) ==
          d + "/nul.yaml:3: a NUL byte (a manifest is text)");
    fs::create_directories(dir.path / "folder.csv");
    CHECK(error_of(dir.path / "folder.csv") == d + "/folder.csv: is a directory, not a manifest");
    CHECK(read_batch_manifest(write(dir.path / "upper.YAML", "- input: x.svg\n")).size() == 1);
    CHECK(read_batch_manifest(write(dir.path / "upper.Csv", "input\nx.svg\n")).size() == 1);
    // Ids from file names: leading dots go (a hidden run directory), nothing left is an error.
    items = read_batch_manifest(write(dir.path / "ids.csv", "input\n.hidden.svg\n..x.y.svg\nweird name!.svg\n"));
    REQUIRE(items.size() == 3);
    CHECK(items[0].id == "hidden");
    CHECK(items[1].id == "x.y");
    CHECK(items[2].id == "weird_name_");
    CHECK(error_of(write(dir.path / "stem.csv", "input\nsub/\n")) ==
          d + "/stem.csv:2: no id can be made from the input's name 'sub/' (give the item an id)");
    CHECK(error_of(write(dir.path / "dots.csv", "input\n..\n")) ==
          d + "/dots.csv:2: no id can be made from the input's name '..' (give the item an id)");
  }

  TEST_CASE("ids never name the batch's own files or leave OUT_DIR; YAML keys and values of the wrong kind") {
    test::TempDir dir("svgm_batch");
    const std::string d = dir.path.string();
    CHECK(error_of(write(dir.path / "a.csv", "id,input\nok,x.svg\nsummary.csv,y.svg\n")) ==
          d + "/a.csv:3: id 'summary.csv' is taken by the batch's own summary.csv (give the item another id)");
    CHECK(error_of(write(dir.path / "b.csv", "id,input\nSummary.JSON,y.svg\n")) ==
          d + "/b.csv:2: id 'Summary.JSON' is taken by the batch's own summary.json (give the item another id)");
    CHECK(error_of(write(dir.path / "c.csv", "input\nsummary.csv.svg\n")) ==
          d + "/c.csv:2: id 'summary.csv' is taken by the batch's own summary.csv (give the item another id)");
    CHECK(error_of(write(dir.path / "d.csv", "id,input\na..b,y.svg\n")) == d + "/d.csv:2: id 'a..b' may not contain '..'");
    CHECK(error_of(write(dir.path / "e.csv", "id,input\na/b,y.svg\n")) ==
          d + "/e.csv:2: id 'a/b' may hold only letters, digits, '.', '_' and '-'");
    CHECK(error_of(write(dir.path / "f.csv", "id,input\n.lock,y.svg\n")) == d + "/f.csv:2: id '.lock' may not start with '.'");
    // yaml-cpp's own conversion said "internal error: yaml-cpp: ... bad conversion".
    CHECK(error_of(write(dir.path / "g.yaml", "- input: x.svg\n- input: [a.svg, b.svg]\n")) ==
          d + "/g.yaml:2: item 2: 'input' must be a single value, not a list");
    CHECK(error_of(write(dir.path / "h.yaml", "- input: x.svg\n  ? [a, b]\n  : x\n")) ==
          d + "/h.yaml:2: item 1: a key must be a name, not a list or a map");
    CHECK(error_of(write(dir.path / "i.yaml", "- input: x.svg\n  overrides: {stages: {? [a]: 1}}\n")) ==
          d + "/i.yaml:2: item 1: overrides 'stages': a key must be a name, not a list or a map");
    CHECK(error_of(write(dir.path / "j.yaml", "? {a: 1}\n: x\n")) == d + "/j.yaml:1: a key must be a name, not a list or a map");
    CHECK(error_of(write(dir.path / "k.yaml", "- input: x.svg\n  overrides: [{seed: 1}]\n")) ==
          d + "/k.yaml:2: item 1: each override is one key.path=value, not a map");
  }

  TEST_CASE("N shards take every item exactly once, sizes within one") {
    for (int n = 1; n <= 5; ++n) {
      std::vector<int> taken(13, 0);
      std::vector<int> sizes;
      for (int i = 0; i < n; ++i) {
        const Shard s = parse_shard(std::to_string(i) + "/" + std::to_string(n));
        int size = 0;
        for (size_t k = 0; k < taken.size(); ++k)
          if (s.takes(k)) ++taken[k], ++size;
        sizes.push_back(size);
      }
      for (int t : taken) CHECK(t == 1);
      CHECK(*std::max_element(sizes.begin(), sizes.end()) - *std::min_element(sizes.begin(), sizes.end()) <= 1);
    }
    CHECK(parse_shard("2/3").index == 2);
    CHECK_THROWS_WITH_AS(parse_shard("3/3"), "--shard 3/3: I must be in 0..2 and N at least 1", Error);
    CHECK_THROWS_WITH_AS(parse_shard("1-3"), "--shard 1-3: expected I/N, e.g. 0/4 (shard I of N, counted from 0)",
                         Error);
    CHECK_THROWS_WITH_AS(parse_shard("0/0"), "--shard 0/0: I must be in 0..N-1 and N at least 1", Error);
  }

  TEST_CASE("a Slurm job array picks the shard: --array=0-2, 1-3 and 0-10:5 are shards 0..2 of 3") {
    CHECK(!shard_from_slurm(env_of({{"SLURM_JOB_ID", "7"}})));
    auto s = shard_from_slurm(env_of({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "3"},
                                      {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_MAX", "2"}}));
    REQUIRE(s);
    CHECK((s->index == 2 && s->count == 3));
    s = shard_from_slurm(env_of({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"},
                                 {"SLURM_ARRAY_TASK_MAX", "3"}}));  // no COUNT: from MIN and MAX
    REQUIRE(s);
    CHECK((s->index == 0 && s->count == 3));
    s = shard_from_slurm(env_of({{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "0"},
                                 {"SLURM_ARRAY_TASK_MAX", "10"}, {"SLURM_ARRAY_TASK_STEP", "5"}}));
    REQUIRE(s);
    CHECK((s->index == 1 && s->count == 3));
    CHECK_THROWS_WITH_AS(shard_from_slurm(env_of({{"SLURM_ARRAY_TASK_ID", "4"}})),
                         "SLURM_ARRAY_TASK_ID is set but neither SLURM_ARRAY_TASK_COUNT nor SLURM_ARRAY_TASK_MAX "
                         "is (pass --shard I/N)",
                         Error);
    CHECK_THROWS_WITH_AS(shard_from_slurm(env_of({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "2"}})),
                         "SLURM_ARRAY_TASK_ID=x: must be a whole number from 0 to 4000000", Error);
  }

  TEST_CASE("Slurm array variables are whole numbers in range, the task id within [MIN, MAX]") {
    const auto error = [](const std::map<std::string, std::string>& vars) {
      try {
        shard_from_slurm(env_of(vars));
      } catch (const Error& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    };
    // 2^32 wrapped to a count of 0 and Shard::takes divided by it: SIGFPE.
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4294967296"}}) ==
          "SLURM_ARRAY_TASK_COUNT=4294967296: must be a whole number from 1 to 1000000");
    // 2^32 + 2 wrapped to 2 and ran shard 1/2 of a count nobody asked for.
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4294967298"}}) ==
          "SLURM_ARRAY_TASK_COUNT=4294967298: must be a whole number from 1 to 1000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "99999999999999999999"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}) ==
          "SLURM_ARRAY_TASK_ID=99999999999999999999: must be a whole number from 0 to 4000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "-1"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}) ==
          "SLURM_ARRAY_TASK_ID=-1: must be a whole number from 0 to 4000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", " 1"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}) ==
          "SLURM_ARRAY_TASK_ID= 1: must be a whole number from 0 to 4000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "2x"}}) ==
          "SLURM_ARRAY_TASK_COUNT=2x: must be a whole number from 1 to 1000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "0"}}) ==
          "SLURM_ARRAY_TASK_COUNT=0: must be a whole number from 1 to 1000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "2"}, {"SLURM_ARRAY_TASK_STEP", "0"}}) ==
          "SLURM_ARRAY_TASK_STEP=0: must be a whole number from 1 to 4000000");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_MIN", "3"}, {"SLURM_ARRAY_TASK_MAX", "5"}}) ==
          "SLURM_ARRAY_TASK_ID=2: below SLURM_ARRAY_TASK_MIN=3");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "6"}, {"SLURM_ARRAY_TASK_MIN", "3"}, {"SLURM_ARRAY_TASK_MAX", "5"},
                 {"SLURM_ARRAY_TASK_COUNT", "9"}}) == "SLURM_ARRAY_TASK_ID=6: above SLURM_ARRAY_TASK_MAX=5");
    CHECK(error({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_MAX", "4000000"}}) ==
          "SLURM_ARRAY_TASK_MAX=4000000: more than 1000000 tasks from SLURM_ARRAY_TASK_MIN=0");
  }

  TEST_CASE("an item's run arguments: config, item, device, target through the file provider, overrides last") {
    BatchItem item{"cat", "/d/cat.svg", "it waves", "/d/cat.mp4", {"seed=4"}, 2};
    BatchOptions o;
    o.out_dir = "/out";
    o.config = fs::path("/c/fast.yaml");
    o.device = "cpu";
    o.overrides = {"stages.fitter.iterations=20"};
    CHECK(batch_run_argv(item, o) ==
          std::vector<std::string>{"run", "/c/fast.yaml", "--input", "/d/cat.svg", "--prompt", "it waves", "-o",
                                   "/out/cat", "--quiet", "--device", "cpu", "stages.video.plugin=file",
                                   "stages.video.path=/d/cat.mp4", "stages.fitter.iterations=20", "seed=4"});
  }

  TEST_CASE("the summary lists every item of the manifest from their records, missing ones pending") {
    test::TempDir dir("svgm_batch");
    const std::vector<BatchItem> items = {{"a", "/a.svg", "", {}, {}, 2}, {"b", "/b.svg", "", {}, {}, 3}};
    fs::create_directories(dir.path / "a");
    write(dir.path / "a" / "batch.json",
          R"({"id":"a","status":"failed","reason":"a.svg:1: bad, very","seconds":1.25,"peak_rss_mb":20,)"
          R"("exit_status":1,"fidelity_psnr_db":null,"fidelity_iou":null})");
    const auto rows = write_batch_summary(items, dir.path);
    REQUIRE(rows.size() == 2);
    CHECK(rows[0].status == "failed");
    CHECK(rows[1].status == "pending");
    std::ifstream csv(dir.path / "summary.csv");
    std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
    CHECK(text ==
          "id,status,reason,seconds,fidelity_psnr_db,fidelity_iou,peak_rss_mb\n"
          "a,failed,\"a.svg:1: bad, very\",1.2,,,20\n"
          "b,pending,,,,,\n");
    std::ifstream js(dir.path / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(js);
    CHECK(j["total"] == 2);
    CHECK(j["counts"]["failed"] == 1);
    CHECK(j["counts"]["pending"] == 1);
  }

  TEST_CASE("a summary assembled before another one was written does not replace it") {
    test::TempDir dir("svgm_batch");
    const std::vector<BatchItem> items = {{"a", "/a.svg", "", {}, {}, 2}};
    // Tickets "NEXT WRITTEN": assemblies 1..3 started, number 5 already written (a shard that
    // began later finished first), so the one starting now (4) read older records.
    write(dir.path / ".summary.lock", "3 5\n");
    write_batch_summary(items, dir.path);
    CHECK(!fs::exists(dir.path / "summary.csv"));
    write(dir.path / ".summary.lock", "5 5\n");
    write_batch_summary(items, dir.path);
    CHECK(fs::exists(dir.path / "summary.csv"));
    std::ifstream lock(dir.path / ".summary.lock");
    std::string tickets;
    std::getline(lock, tickets);
    CHECK(tickets == "6 6");
  }
}
