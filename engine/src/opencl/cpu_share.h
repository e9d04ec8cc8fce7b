// How PoCL's CPU device shares the machine with other jobs: how many worker threads it starts
// and whether it pins them to cores. Decided once, before the OpenCL platform loads (PoCL reads
// its environment then), from the CPUs this process may use and the Slurm job's allocation.
//
// Pinning made a lone process steady (see device.cpp), but PoCL pins worker i to core i: two
// processes on one machine, or a Slurm job that was given some of a node's cores, would stack
// their workers on the same cores. So workers are pinned only when this process owns the whole
// machine (all online CPUs are in its affinity mask and, under Slurm, all of them are allocated
// to the job), or when asked (SVGMOTION_PIN=1; SVGMOTION_PIN=0 never pins). The thread count is
// the CPUs in the affinity mask, capped by SLURM_CPUS_PER_TASK. A user's own POCL_AFFINITY,
// POCL_MAX_PTHREAD_COUNT or POCL_CPU_MAX_CU_COUNT always wins.
#pragma once

#include <functional>
#include <string>

namespace svgm {

struct CpuShare {
  int threads = 1;   // PoCL worker threads (compute units)
  bool pin = false;  // pin worker i to core i (POCL_AFFINITY)
  std::string why;   // one phrase, for logs: "owns the machine", "Slurm allocated 1 of 2 CPUs", ...
};

// The decision, from an environment lookup (`env(name)` is nullptr when unset), the number of
// CPUs in this process's affinity mask and the number of online CPUs.
CpuShare decide_cpu_share(const std::function<const char*(const char*)>& env, int allowed_cpus, int online_cpus);

// decide_cpu_share() over the real environment and sched_getaffinity(), applied by setting
// POCL_AFFINITY, POCL_MAX_PTHREAD_COUNT (PoCL 3) and POCL_CPU_MAX_CU_COUNT (PoCL 4 and later)
// unless already set. Idempotent; returns what was decided.
CpuShare apply_cpu_share();

}  // namespace svgm
