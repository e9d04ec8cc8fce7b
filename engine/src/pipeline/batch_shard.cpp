// Shards of a batch (see batch_shard.h).
#include "pipeline/batch_shard.h"

#include <charconv>
#include <string_view>

#include "svgmotion/error.h"

namespace svgm {

namespace {

// The most shards of one manifest (--shard's N and a job array's task count): far more than any
// cluster runs at once, and small enough for `int`.
constexpr long kMaxShards = 1000000;

// Slurm's task ids are below its MaxArraySize, which may be at most 4000001 (slurm.conf(5)).
constexpr long kMaxSlurmTaskId = 4000000;

std::optional<long> whole(std::string_view s) {
  long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  const auto i = slash == std::string::npos ? std::nullopt : whole(std::string_view(text).substr(0, slash));
  const auto n = slash == std::string::npos ? std::nullopt : whole(std::string_view(text).substr(slash + 1));
  if (!i || !n) throw Error("--shard " + text + ": expected I/N, e.g. 0/4 (shard I of N, counted from 0)");
  if (*n < 1 || *n > kMaxShards || *i < 0 || *i >= *n)
    throw Error("--shard " + text + ": I must be in 0.." + (*n >= 1 ? std::to_string(*n - 1) : "N-1") +
                " and N at least 1");
  return {static_cast<int>(*i), static_cast<int>(*n)};
}

std::optional<Shard> shard_from_slurm(const std::function<const char*(const char*)>& env) {
  const char* id_text = env("SLURM_ARRAY_TASK_ID");
  if (!id_text || !*id_text) return std::nullopt;
  // Each variable whole and in range before any arithmetic: a count that overflowed `int`
  // became 0 and the modulo of Shard::takes divided by it (SIGFPE), and other wrapped values
  // picked a wrong shard without a word.
  auto number = [&](const char* name, long lo, long hi) -> std::optional<long> {
    const char* v = env(name);
    if (!v || !*v) return std::nullopt;
    const auto n = whole(v);
    if (!n || *n < lo || *n > hi)
      throw Error(std::string(name) + "=" + v + ": must be a whole number from " + std::to_string(lo) + " to " +
                  std::to_string(hi));
    return n;
  };
  const long id = *number("SLURM_ARRAY_TASK_ID", 0, kMaxSlurmTaskId);
  const long min = number("SLURM_ARRAY_TASK_MIN", 0, kMaxSlurmTaskId).value_or(0);
  const std::optional<long> max = number("SLURM_ARRAY_TASK_MAX", 0, kMaxSlurmTaskId);
  const long step = number("SLURM_ARRAY_TASK_STEP", 1, kMaxSlurmTaskId).value_or(1);
  std::optional<long> count = number("SLURM_ARRAY_TASK_COUNT", 1, kMaxShards);
  if (id < min)
    throw Error("SLURM_ARRAY_TASK_ID=" + std::to_string(id) + ": below SLURM_ARRAY_TASK_MIN=" + std::to_string(min));
  if (max && id > *max)
    throw Error("SLURM_ARRAY_TASK_ID=" + std::to_string(id) + ": above SLURM_ARRAY_TASK_MAX=" + std::to_string(*max));
  if (!count && max) {
    if (*max < min)
      throw Error("SLURM_ARRAY_TASK_MAX=" + std::to_string(*max) + ": below SLURM_ARRAY_TASK_MIN=" +
                  std::to_string(min));
    count = (*max - min) / step + 1;
    if (*count > kMaxShards)
      throw Error("SLURM_ARRAY_TASK_MAX=" + std::to_string(*max) + ": more than " + std::to_string(kMaxShards) +
                  " tasks from SLURM_ARRAY_TASK_MIN=" + std::to_string(min));
  }
  if (!count)
    throw Error("SLURM_ARRAY_TASK_ID is set but neither SLURM_ARRAY_TASK_COUNT nor SLURM_ARRAY_TASK_MAX is "
                "(pass --shard I/N)");
  const long index = (id - min) / step;
  if (index < 0 || index >= *count || (id - min) % step != 0)
    throw Error("SLURM_ARRAY_TASK_ID=" + std::to_string(id) + " does not fit the array (min " + std::to_string(min) +
                ", step " + std::to_string(step) + ", " + std::to_string(*count) + " tasks); pass --shard I/N");
  return Shard{static_cast<int>(index), static_cast<int>(*count)};
}

}  // namespace svgm
