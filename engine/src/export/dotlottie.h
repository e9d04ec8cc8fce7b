// dotLottie (.lottie): the Lottie JSON in a zip with a manifest, the packaging LottieFiles'
// players (dotlottie-web, dotlottie-rs, the ThorVG-based players) open, and smaller than the JSON.
//
// The archive holds manifest.json ({"version":"1","generator":...,"animations":[{"id":ID,...}]})
// and animations/ID.json, deflated with zlib, written in one pass (a local header per file,
// the central directory, its end record) with a fixed time stamp so the same animation always
// gives the same bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace svgm {

// One file of a zip archive.
struct ZipEntry {
  std::string name;  // path inside the archive, '/'-separated
  std::string data;
};

// The bytes of a zip archive holding `entries` (deflated, or stored when that is smaller).
std::string zip_archive(const std::vector<ZipEntry>& entries);

// The .lottie archive of one animation: `json` under id `id`; `loop`: whether players loop it.
std::string dotlottie_archive(const std::string& json, const std::string& id, bool loop);

// Writes dotlottie_archive(...) to `out` (temporary name, then renamed).
void write_dotlottie(const std::filesystem::path& out, const std::string& json, bool loop);

}  // namespace svgm
