// `svgmotion devices`: the OpenCL devices this machine offers, and which `auto` picks.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "opencl/cpu_share.h"
#include "svgmotion/device.h"

namespace svgm::cli {

int cmd_devices(const std::vector<std::string>& argv) {
  parse_args("devices", argv, {}, {});
  const auto devs = list_devices();
  const size_t pick = select_device(devs, "auto");
  for (size_t i = 0; i < devs.size(); ++i) {
    const auto& d = devs[i];
    std::printf("%s%zu  %-4s  %s  [%s]  %u compute units, %.1f GB, %s\n", i == pick ? "*" : " ",
                i, d.type.c_str(), d.name.c_str(), d.platform.c_str(), d.compute_units,
                d.global_mem_bytes / 1e9, d.version.c_str());
  }
  std::printf("(* = what --device auto picks)\n");
  // What PoCL's CPU device was told (opencl/cpu_share.h), for checking a cluster job's manners.
  const CpuShare share = apply_cpu_share();
  const char* threads = std::getenv("POCL_MAX_PTHREAD_COUNT");
  const bool pinned = std::getenv("POCL_AFFINITY") && std::string(std::getenv("POCL_AFFINITY")) == "1";
  const bool ours = threads && std::to_string(share.threads) == threads && pinned == share.pin;
  std::printf("PoCL CPU threads: %s, %s (%s)\n", threads ? threads : "?", pinned ? "pinned to cores" : "not pinned",
              ours ? share.why.c_str() : "set in the environment");
  return 0;
}

}  // namespace svgm::cli
