// PoCL's share of the machine (opencl/cpu_share.h): threads from the affinity mask and
// SLURM_CPUS_PER_TASK, pinning only when the process owns the machine or is told to.
#include <doctest/doctest.h>

#include <map>
#include <string>

#include "opencl/cpu_share.h"

using namespace svgm;

namespace {

CpuShare decide(const std::map<std::string, std::string>& vars, int allowed, int online) {
  return decide_cpu_share(
      [&vars](const char* name) -> const char* {
        const auto it = vars.find(name);
        return it == vars.end() ? nullptr : it->second.c_str();
      },
      allowed, online);
}

}  // namespace

TEST_SUITE("opencl") {
  TEST_CASE("a lone process owning the machine pins; one confined to some CPUs does not") {
    CpuShare s = decide({}, 8, 8);
    CHECK((s.threads == 8 && s.pin));
    CHECK(s.why == "owns the machine");
    s = decide({}, 2, 8);  // taskset, a cpuset
    CHECK((s.threads == 2 && !s.pin));
    CHECK(s.why == "this process may use 2 of 8 CPUs");
  }

  TEST_CASE("under Slurm: threads from SLURM_CPUS_PER_TASK, pinned only when the job owns the node") {
    CpuShare s = decide({{"SLURM_JOB_ID", "5"}, {"SLURM_CPUS_PER_TASK", "1"}, {"SLURM_CPUS_ON_NODE", "1"}}, 2, 2);
    CHECK((s.threads == 1 && !s.pin));
    CHECK(s.why == "the job may use 1 of 2 CPUs");
    // No cgroups: the mask is the whole node, but the job was given part of it.
    s = decide({{"SLURM_JOB_ID", "5"}, {"SLURM_CPUS_ON_NODE", "4"}}, 16, 16);
    CHECK((s.threads == 16 && !s.pin));
    CHECK(s.why == "Slurm allocated 4 of the node's 16 CPUs");
    s = decide({{"SLURM_JOB_ID", "5"}, {"SLURM_CPUS_PER_TASK", "16"}, {"SLURM_CPUS_ON_NODE", "16"}}, 16, 16);
    CHECK((s.threads == 16 && s.pin));
    // More CPUs per task than the mask allows: the mask wins.
    s = decide({{"SLURM_JOB_ID", "5"}, {"SLURM_CPUS_PER_TASK", "8"}}, 4, 16);
    CHECK((s.threads == 4 && !s.pin));
    // A malformed value is ignored rather than trusted.
    s = decide({{"SLURM_JOB_ID", "5"}, {"SLURM_CPUS_PER_TASK", "x"}, {"SLURM_CPUS_ON_NODE", "2"}}, 2, 2);
    CHECK((s.threads == 2 && s.pin));
  }

  TEST_CASE("SVGMOTION_PIN overrides the decision either way") {
    CHECK(!decide({{"SVGMOTION_PIN", "0"}}, 8, 8).pin);
    CHECK(decide({{"SVGMOTION_PIN", "1"}}, 2, 8).pin);
    CHECK(decide({{"SVGMOTION_PIN", "1"}}, 2, 8).why == "SVGMOTION_PIN=1");
  }
}
