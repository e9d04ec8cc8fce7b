// PoCL's share of the machine (see cpu_share.h).
#include "opencl/cpu_share.h"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace svgm {

namespace {

// A positive whole number, or nothing (unset, empty, "2(x3)"-style lists are read up to the
// first non-digit, which is the per-node count Slurm means).
std::optional<int> positive(const char* s) {
  if (!s || !*s) return std::nullopt;
  const std::string_view v(s);
  int n = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || end == v.data() || n <= 0) return std::nullopt;
  return n;
}

}  // namespace

CpuShare decide_cpu_share(const std::function<const char*(const char*)>& env, int allowed_cpus, int online_cpus) {
  CpuShare s;
  allowed_cpus = std::max(1, allowed_cpus);
  online_cpus = std::max(allowed_cpus, online_cpus);
  s.threads = allowed_cpus;
  const bool slurm = env("SLURM_JOB_ID") != nullptr;
  if (const auto per_task = positive(env("SLURM_CPUS_PER_TASK")); slurm && per_task)
    s.threads = std::min(s.threads, *per_task);
  bool owns = s.threads >= online_cpus;
  if (!owns) {
    s.why = (slurm ? "the job may use " : "this process may use ") + std::to_string(s.threads) + " of " +
            std::to_string(online_cpus) + " CPUs";
  } else if (slurm) {
    // Without cgroups the mask is the whole node even when other jobs share it.
    const auto on_node = positive(env("SLURM_CPUS_ON_NODE"));
    owns = on_node && *on_node >= online_cpus;
    s.why = owns ? "the Slurm job owns the node"
                 : "Slurm allocated " + (on_node ? std::to_string(*on_node) : std::string("an unknown number")) +
                       " of the node's " + std::to_string(online_cpus) + " CPUs";
  } else {
    s.why = "owns the machine";
  }
  s.pin = owns;
  if (const char* p = env("SVGMOTION_PIN"); p && *p) {
    s.pin = std::string_view(p) == "1";
    s.why = std::string("SVGMOTION_PIN=") + p;
  }
  return s;
}

CpuShare apply_cpu_share() {
  int allowed = 0;
  cpu_set_t set;
  if (::sched_getaffinity(0, sizeof set, &set) == 0) allowed = CPU_COUNT(&set);
  const long online = ::sysconf(_SC_NPROCESSORS_ONLN);
  const CpuShare s = decide_cpu_share([](const char* name) { return std::getenv(name); }, allowed,
                                      static_cast<int>(std::max(1L, online)));
  // overwrite = 0: the user's own settings win.
  setenv("POCL_AFFINITY", s.pin ? "1" : "0", 0);
  const std::string n = std::to_string(s.threads);
  setenv("POCL_MAX_PTHREAD_COUNT", n.c_str(), 0);
  setenv("POCL_CPU_MAX_CU_COUNT", n.c_str(), 0);
  return s;
}

}  // namespace svgm
