// The OpenCL runtime: device selection, context/queue creation, program build and disk cache.
#include "opencl/runtime.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "opencl/compile_child.h"
#include "opencl/kernel_cache.h"
#include "opencl/kernel_sources.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

uint64_t fnv1a(std::string_view s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

// The build time of a program last measured here, per program (its first kernel file), in
// DIR/kernels/compile_seconds.txt ("flatten.cl 1.42" lines); used to say how long compiling
// will take. Most of it comes later: PoCL compiles each kernel again at its first launch, and
// that took about 14 times the build (`devices --warm` from empty caches: 42.9 s in all, of
// which 1.42 + 1.42 + 0.31 s in the three programs' builds).
constexpr double kFirstLaunchFactor = 14;

std::filesystem::path compile_seconds_file(const fs::path& dir) { return dir / "kernels" / "compile_seconds.txt"; }

std::map<std::string, double> read_compile_seconds(const fs::path& dir) {
  std::map<std::string, double> out;
  if (dir.empty()) return out;
  std::ifstream f(compile_seconds_file(dir));
  std::string name;
  double s = 0;
  while (f >> name >> s) out[name] = s;
  return out;
}

void record_compile_seconds(const fs::path& dir, const std::vector<std::string>& files, double seconds) {
  if (files.empty()) return;
  auto all = read_compile_seconds(dir);
  all[files.front()] = seconds;
  std::string text;
  for (const auto& [name, s] : all) text += name + " " + std::to_string(s) + "\n";
  // Through a temporary name and a rename, as every cache file: processes share the directory.
  const fs::path file = compile_seconds_file(dir), tmp = file.string() + ".tmp." + std::to_string(::getpid());
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  {
    std::ofstream f(tmp);
    if (!(f << text)) return;
  }
  fs::rename(tmp, file, ec);
  if (ec) fs::remove(tmp, ec);
}

// Once per runtime, on the first program not found in the cache: a first run spends most of a
// minute here and would otherwise look hung.
void say_compiling(const std::vector<std::string>& files, const fs::path& dir, bool& said) {
  if (said) return;
  said = true;
  const auto known = read_compile_seconds(dir);
  // Unmeasured here: what a 2-core PoCL machine took for the raster program, or the fitter's.
  double s = files.empty() || files.front() != "flatten.cl" ? 5 : 20;
  if (auto it = files.empty() ? known.end() : known.find(files.front()); it != known.end())
    s = kFirstLaunchFactor * it->second;
  log::info("  compiling the OpenCL kernels (once, about %.0f s)", std::max(1.0, s));
}

}  // namespace

ClRuntime::ClRuntime(const std::string& device_spec, bool profiling) : device_spec_(device_spec), profiling_(profiling) {
  const auto devices = list_devices();
  const size_t pick = select_device(devices, device_spec);
  info_ = devices[pick];
  // list_devices() enumerates in the same platform/device order; walk it again for the handle.
  std::vector<cl::Platform> platforms;
  cl::Platform::get(&platforms);
  size_t n = 0;
  for (const auto& p : platforms) {
    std::vector<cl::Device> devs;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devs);
    } catch (const cl::Error&) {
      continue;
    }
    for (const auto& d : devs)
      if (n++ == pick) device_ = d;
  }
  try {
    context_ = cl::Context(device_);
    queue_ = cl::CommandQueue(context_, device_,
                              profiling ? cl::QueueProperties::Profiling : cl::QueueProperties::None);
  } catch (const cl::Error& e) {
    throw Error("cannot use OpenCL device " + info_.name + ": " + e.what() + " " +
                cl_status_name(e.err()));
  }
}

cl::Program& ClRuntime::program(const std::vector<std::string>& files, const std::string& options,
                                const std::string& child_spec) {
  std::string source(kernel_source("prelude.cl"));
  std::string key_files;
  for (const auto& f : files) {
    source += "\n#line 1\n";
    source += kernel_source(f);
    key_files += (key_files.empty() ? "" : ", ") + f;
  }
  const std::string mem_key = key_files + "|" + options;
  if (auto it = programs_.find(mem_key); it != programs_.end()) return it->second;

  const auto t0 = std::chrono::steady_clock::now();
  const std::string disk_key = info_.platform + "|" + info_.name + "|" + info_.driver + "|" +
                               options + "|" + source;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(disk_key)));
  const fs::path dir = kernel_cache_dir();
  const fs::path cached = dir.empty() ? fs::path() : dir / "kernels" / (std::string(hex) + ".bin");

  // PoCL makes its cache directory when the platform loads, and fails every build once it is
  // gone (a cache cleared while a process runs; a test's temporary cache): make it again.
  if (const char* pocl = std::getenv("POCL_CACHE_DIR"); pocl && *pocl) {
    std::error_code ec;
    fs::create_directories(pocl, ec);
  }
  cl::Program prog;
  bool built = false;
  // A truncated or corrupt file reads as missing (kernel_cache.h); one the driver refuses
  // (another driver version) is rebuilt too; either way the rebuild rewrites the entry.
  std::optional<std::string> bin = cached.empty() ? std::nullopt : read_cached_binary(cached);
  // Missing: a child compiles it, and launches its kernels (compile_child.h), when it can.
  bool from_child = false;
  if (!bin && !cached.empty() && !child_spec.empty() && compile_child_enabled()) {
    say_compiling(files, dir, said_compiling_);
    from_child = compile_in_child(child_spec, device_spec_);
    if (from_child) bin = read_cached_binary(cached);
  }
  if (bin) {
    try {
      cl::Program::Binaries bins{std::vector<unsigned char>(bin->begin(), bin->end())};
      prog = cl::Program(context_, {device_}, bins);
      prog.build({device_}, options.c_str());
      built = true;
      ++loaded_from_cache_;
      compiled_in_child_ += from_child;
      if (from_child) log::debug("opencl: %s compiled in a child process, loaded from the cache", key_files.c_str());
    } catch (const cl::Error&) {
      built = false;  // stale or foreign binary: fall back to source
    }
  }
  if (!built) {
    say_compiling(files, dir, said_compiling_);
    prog = cl::Program(context_, source);
    try {
      prog.build({device_}, options.c_str());
    } catch (const cl::Error&) {
      const std::string log = prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
      throw Error("OpenCL build of " + key_files + " failed on " + info_.name + ":\n" + log);
    }
    ++built_from_source_;
    if (!dir.empty())
      record_compile_seconds(dir, files, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (!cached.empty()) {
      try {
        const auto bins = prog.getInfo<CL_PROGRAM_BINARIES>();
        if (!bins.empty() && !bins[0].empty())
          write_cached_binary(cached, std::string(bins[0].begin(), bins[0].end()));
      } catch (const cl::Error&) {
        // A device that cannot return binaries just compiles every time.
      }
    }
  }
  compile_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return programs_.emplace(mem_key, std::move(prog)).first->second;
}

}  // namespace svgm
