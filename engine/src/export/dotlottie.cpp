// The .lottie writer (see dotlottie.h); zip layout from PKWARE's APPNOTE (local file header,
// central directory file header, end of central directory record), all fields little-endian.
#include "export/dotlottie.h"

#include <zlib.h>

#include <cstdint>
#include <nlohmann/json.hpp>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace {

// MS-DOS date of 1980-01-01 00:00 (the format's epoch): reproducible archives.
constexpr uint16_t kDosTime = 0, kDosDate = (0 << 9) | (1 << 5) | 1;
constexpr uint16_t kVersionNeeded = 20;  // 2.0: deflate
constexpr uint16_t kStored = 0, kDeflated = 8;

void put16(std::string& s, uint16_t v) {
  s += static_cast<char>(v & 0xff);
  s += static_cast<char>(v >> 8);
}
void put32(std::string& s, uint32_t v) {
  put16(s, static_cast<uint16_t>(v & 0xffff));
  put16(s, static_cast<uint16_t>(v >> 16));
}

// Raw deflate (no zlib header: zip's method 8) of `data`.
std::string deflate_raw(const std::string& data) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw Error("internal: zlib deflateInit2 failed");
  std::string out(deflateBound(&z, static_cast<uLong>(data.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw Error("internal: zlib deflate failed");
  return out;
}

}  // namespace

std::string zip_archive(const std::vector<ZipEntry>& entries) {
  std::string out, central;
  for (const ZipEntry& e : entries) {
    // Zip without its 64-bit extension: each size and offset must fit 32 bits.
    if (e.data.size() >= 0xffffffffu || out.size() >= 0xffffffffu || e.name.size() > 0xffff)
      throw Error("internal: zip entry " + e.name + " too large");
    const uint32_t crc = static_cast<uint32_t>(
        crc32(crc32(0, nullptr, 0), reinterpret_cast<const Bytef*>(e.data.data()), static_cast<uInt>(e.data.size())));
    std::string packed = deflate_raw(e.data);
    const bool stored = packed.size() >= e.data.size();
    if (stored) packed = e.data;
    auto header = [&](std::string& s, bool local) {
      put32(s, local ? 0x04034b50 : 0x02014b50);
      if (!local) put16(s, kVersionNeeded);  // version made by
      put16(s, kVersionNeeded);
      put16(s, 0);  // flags
      put16(s, stored ? kStored : kDeflated);
      put16(s, kDosTime);
      put16(s, kDosDate);
      put32(s, crc);
      put32(s, static_cast<uint32_t>(packed.size()));
      put32(s, static_cast<uint32_t>(e.data.size()));
      put16(s, static_cast<uint16_t>(e.name.size()));
      put16(s, 0);  // extra field length
      if (!local) {
        put16(s, 0);  // comment length
        put16(s, 0);  // disk number
        put16(s, 0);  // internal attributes
        put32(s, 0);  // external attributes
        put32(s, static_cast<uint32_t>(out.size()));  // this entry's local header
      }
      s += e.name;
    };
    header(central, false);
    header(out, true);
    out += packed;
  }
  const uint32_t central_at = static_cast<uint32_t>(out.size());
  out += central;
  put32(out, 0x06054b50);
  put16(out, 0);  // this disk
  put16(out, 0);  // the central directory's disk
  put16(out, static_cast<uint16_t>(entries.size()));
  put16(out, static_cast<uint16_t>(entries.size()));
  put32(out, static_cast<uint32_t>(central.size()));
  put32(out, central_at);
  put16(out, 0);  // comment length
  return out;
}

std::string dotlottie_archive(const std::string& json, const std::string& id, bool loop) {
  const nlohmann::json manifest = {
      {"version", "1"},
      {"generator", std::string("svgmotion ") + SVGM_VERSION},
      {"animations", {{{"id", id}, {"speed", 1}, {"loop", loop}, {"autoplay", true}}}}};
  return zip_archive({{"manifest.json", json_text(manifest)}, {"animations/" + id + ".json", json}});
}

void write_dotlottie(const std::filesystem::path& out, const std::string& json, bool loop) {
  write_file_atomic(out, dotlottie_archive(json, "animation", loop));
}

}  // namespace svgm
