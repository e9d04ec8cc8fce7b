// The on-disk cache of compiled OpenCL programs, safe when many processes share it: several
// Slurm tasks on one node, or nodes over a shared file system (SVGMOTION_CACHE_DIR).
//
// A cache file is a small header (magic, payload length, FNV-1a hash of the payload) and the
// program binary. Writers write a temporary name unique to the host, process and call, then
// rename it over the entry, so a reader sees an old whole file or a new whole file; concurrent
// writers of one entry write the same bytes, and the last rename wins. A reader checks the
// length and the hash and treats a truncated, corrupt or foreign file as missing: the caller
// compiles from source and writes the entry again. No locks, which NFS may not honour.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace svgm {

// $SVGMOTION_CACHE_DIR, else $XDG_CACHE_HOME/svgmotion, else ~/.cache/svgmotion; empty when
// none can be named (no cache then).
std::filesystem::path kernel_cache_dir();

// The payload of a cache file, or nothing when it is missing, truncated or corrupt.
std::optional<std::string> read_cached_binary(const std::filesystem::path& file);

// Writes a cache file through a unique temporary name and a rename. Best effort: a cache that
// cannot be written only costs compile time, so failures are silent and leave nothing behind.
void write_cached_binary(const std::filesystem::path& file, const std::string& payload);

}  // namespace svgm
