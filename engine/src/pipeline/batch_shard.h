// Which items of a batch manifest one process takes: shard I of N takes the items whose
// position in the manifest is I modulo N (0-based), so N shards cover every item exactly once
// and their sizes differ by at most one. Positions, not ids: a shard's items depend only on
// the manifest, not on what other shards have done, so a re-run of one shard redoes the same
// items. (Reordering the manifest between shards of one submission would move items between
// shards; the run directory lock then stops two shards from working on one item at once.)
//
// `--shard I/N` names the shard; without it, under a Slurm job array, the array variables do:
// I = (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN) / SLURM_ARRAY_TASK_STEP and
// N = SLURM_ARRAY_TASK_COUNT (or (MAX - MIN) / STEP + 1), so `--array=0-2`, `1-3` and `0-10:5`
// all give shards 0, 1, 2 of 3.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace svgm {

struct Shard {
  int index = 0, count = 1;
  bool takes(size_t item_position) const {
    return static_cast<int>(item_position % static_cast<size_t>(count)) == index;
  }
  std::string name() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "I/N" with 0 <= I < N; throws svgm::Error "--shard 3/3: ..." otherwise.
Shard parse_shard(const std::string& text);

// The shard a Slurm job array task is, from an environment lookup (`env(name)` is nullptr when
// unset); nothing when SLURM_ARRAY_TASK_ID is unset. Each variable must be a whole number in
// range (task ids 0..4000000, COUNT 1..1000000, STEP at least 1) and the task id within
// [MIN, MAX]; otherwise throws svgm::Error "NAME=VALUE: problem" (the CLI exits 2).
std::optional<Shard> shard_from_slurm(const std::function<const char*(const char*)>& env);

}  // namespace svgm
