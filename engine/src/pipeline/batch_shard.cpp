// Shards of a batch (see batch_shard.h).
#include "pipeline/batch_shard.h"

#include <charconv>
#include <string_view>

#include "svgmotion/error.h"

namespace svgm {

namespace {

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
  if (*n < 1 || *n > 1000000 || *i < 0 || *i >= *n)
    throw Error("--shard " + text + ": I must be in 0.." + (*n >= 1 ? std::to_string(*n - 1) : "N-1") +
                " and N at least 1");
  return {static_cast<int>(*i), static_cast<int>(*n)};
}

std::optional<Shard> shard_from_slurm(const std::function<const char*(const char*)>& env) {
  const char* id_text = env("SLURM_ARRAY_TASK_ID");
  if (!id_text || !*id_text) return std::nullopt;
  auto number = [&](const char* name) -> std::optional<long> {
    const char* v = env(name);
    if (!v || !*v) return std::nullopt;
    const auto n = whole(v);
    if (!n) throw Error(std::string(name) + "=" + v + ": not a whole number");
    return n;
  };
  const long id = *number("SLURM_ARRAY_TASK_ID");
  const long min = number("SLURM_ARRAY_TASK_MIN").value_or(0);
  const long step = number("SLURM_ARRAY_TASK_STEP").value_or(1);
  if (step < 1) throw Error("SLURM_ARRAY_TASK_STEP=" + std::to_string(step) + ": must be at least 1");
  std::optional<long> count = number("SLURM_ARRAY_TASK_COUNT");
  if (!count)
    if (const auto max = number("SLURM_ARRAY_TASK_MAX")) count = (*max - min) / step + 1;
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
