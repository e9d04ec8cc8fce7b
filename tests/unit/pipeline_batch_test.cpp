// Batch manifests, shards and the summary (pipeline/batch_manifest.h, batch_shard.h, batch.h):
// what a manifest yields (paths resolved, ids, overrides), the exact error for each malformed
// manifest, that N shards cover every item exactly once, the Slurm array arithmetic, the run
// arguments of an item, and a summary rebuilt from records with missing items pending.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "pipeline/batch.h"
#include "pipeline/batch_manifest.h"
#include "pipeline/batch_shard.h"
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
                         "SLURM_ARRAY_TASK_ID=x: not a whole number", Error);
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
}
