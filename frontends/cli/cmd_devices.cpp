// `svgmotion devices`: the OpenCL devices this machine offers, and which `auto` picks.
#include <cstdio>

#include "cli/cli_args.h"
#include "cli/commands.h"
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
  return 0;
}

}  // namespace svgm::cli
