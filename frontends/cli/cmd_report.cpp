// `svgmotion report RUN_DIR`: (re)writes RUN_DIR/report.html, the run's self-contained preview
// page (engine/src/report/report_page.h). `run` writes it at the end of every run and `fit`
// after fitting into a run directory, through write_run_report below.
#include <cstdio>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "report/report_page.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm::cli {

bool write_run_report(const std::filesystem::path& run, const std::string& device, bool quiet) {
  try {
    ReportOptions o;
    o.device = device;
    const ReportResult r = write_report(run, o);
    for (const std::string& n : r.notes) log::warning("report.html: %s", n.c_str());
    if (!quiet) log::info("svgmotion: wrote %s (%zu kB)", r.file.c_str(), r.bytes >> 10);
    return true;
  } catch (const Error& e) {
    // The page shows a run; it never turns a finished run into a failed one.
    log::warning("report.html not written: %s", e.what());
    return false;
  }
}

int cmd_report(const std::vector<std::string>& argv) {
  const Args a = parse_args("report", argv, {"--device"}, {});
  if (a.positional.size() != 1) throw UsageError("report: expected one run directory (svgmotion report RUN_DIR)");
  ReportOptions o;
  o.device = a.get("--device").value_or("auto");
  const ReportResult r = write_report(a.positional[0], o);
  for (const std::string& n : r.notes) log::warning("report.html: %s", n.c_str());  // as `run` says them
  std::printf("wrote %s (%zu kB)\n", r.file.c_str(), r.bytes >> 10);
  return 0;
}

}  // namespace svgm::cli
