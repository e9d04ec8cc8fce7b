// The svgmotion subcommands; each takes the arguments after its name and returns an exit code.
#pragma once

#include <string>
#include <vector>

namespace svgm::cli {

int cmd_render(const std::vector<std::string>& args);
int cmd_devices(const std::vector<std::string>& args);
int cmd_bench(const std::vector<std::string>& args);
int cmd_fit(const std::vector<std::string>& args);
int cmd_palette(const std::vector<std::string>& args);
int cmd_run(const std::vector<std::string>& args);
int cmd_plugins(const std::vector<std::string>& args);
int cmd_batch(const std::vector<std::string>& args);


}  // namespace svgm::cli
