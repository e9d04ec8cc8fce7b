// The svgmotion subcommands; each takes the arguments after its name and returns an exit code.
#pragma once

#include <filesystem>
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
int cmd_report(const std::vector<std::string>& args);
int cmd_config(const std::vector<std::string>& args);
int cmd_export(const std::vector<std::string>& args);
// report.html for a run directory after `run` or `fit`; a failure is a warning (cmd_report.cpp).
// True when the page was written (a summary lists it only then).
bool write_run_report(const std::filesystem::path& run, const std::string& device, bool quiet);


}  // namespace svgm::cli
