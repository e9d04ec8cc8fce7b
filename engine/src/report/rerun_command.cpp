// The recorded run command and the re-run with another candidate (see rerun_command.h).
#include "report/rerun_command.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "pipeline/candidate_choice.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

fs::path command_file(const fs::path& run) { return run / ".svgmotion" / "command.json"; }

}  // namespace

void record_run_command(const fs::path& run, const std::vector<std::string>& args, const std::string& prompt) {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) exe = "svgmotion";
  const fs::path cwd = fs::current_path(ec);
  fs::create_directories(run / ".svgmotion", ec);
  const nlohmann::json j = {{"cwd", cwd.string()}, {"exe", exe.string()}, {"command", "run"}, {"args", args},
                         {"prompt", prompt}};
  write_file_atomic(command_file(run), json_text(j, 2) + "\n");
}

std::string shell_quote(const std::string& w) {
  if (!w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=./:,@%") ==
                        std::string::npos)
    return w;
  std::string out = "'";
  for (const char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::optional<std::string> choose_command(const fs::path& run, const std::string& name) {
  std::ifstream in(command_file(run));
  if (!in) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("args") || !j["args"].is_array() || !j.value("cwd", std::string()).size() ||
      j.value("command", std::string()) != "run")
    return std::nullopt;
  const std::string choice = std::string(kChooseKey) + "=";
  std::vector<std::string> args;
  const nlohmann::json& a = j["args"];
  for (size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_string()) return std::nullopt;
    const std::string s = a[i].get<std::string>();
    if (s == "--from") {  // and its value
      ++i;
      continue;
    }
    if (s.rfind("--from=", 0) == 0 || s.rfind(choice, 0) == 0) continue;
    args.push_back(s);
  }
  args.push_back(choice + name);
  std::string cmd = "cd " + shell_quote(j["cwd"].get<std::string>()) + " && " +
                    shell_quote(j.value("exe", std::string("svgmotion"))) + " run";
  for (const std::string& s : args) cmd += " " + shell_quote(s);
  return cmd;
}

}  // namespace svgm
