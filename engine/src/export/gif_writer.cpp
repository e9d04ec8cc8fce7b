// The GIF89a writer (see gif_writer.h). Format: the GIF89a specification (W3C/CompuServe,
// 1990); the LZW coder's code-size and dictionary-reset rules are the specification's, in the
// shape of Charlie Tangora's public-domain gif.h (third_party_notes.md).
#include "export/gif_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

constexpr int kPaletteSize = 256;         // GIF's largest colour table (8 bits per index)
constexpr int kMinCodeSize = 8;           // LZW root codes: one per palette index
constexpr int kMaxCode = 4095;            // 12-bit codes, the format's limit
constexpr size_t kHistogramPixels = 1 << 18;  // pixels sampled per frame for the palette
constexpr int kMaxSide = 65535;           // GIF sizes are 16-bit

// Straight RGBA over white, packed 0xRRGGBB.
uint32_t over_white(const uint8_t* p) {
  const int a = p[3];
  uint32_t c = 0;
  for (int k = 0; k < 3; ++k) c = c << 8 | static_cast<uint32_t>((p[k] * a + 255 * (255 - a) + 127) / 255);
  return c;
}

int channel(uint32_t c, int k) { return static_cast<int>(c >> (16 - 8 * k) & 0xff); }

struct Entry {
  uint32_t colour;
  uint64_t count;
};

// A palette for the histogram: its colours when they fit, else a weighted median cut.
std::vector<uint32_t> make_palette(const std::unordered_map<uint32_t, uint64_t>& histogram) {
  std::vector<Entry> e;
  e.reserve(histogram.size());
  for (const auto& [c, n] : histogram) e.push_back({c, n});
  // Deterministic whatever the hash map's order.
  std::sort(e.begin(), e.end(), [](const Entry& a, const Entry& b) { return a.colour < b.colour; });
  std::vector<uint32_t> palette;
  if (e.size() <= static_cast<size_t>(kPaletteSize)) {
    for (const Entry& x : e) palette.push_back(x.colour);
    return palette;
  }
  struct Box {
    size_t begin, end;
  };
  auto widest = [&](const Box& b, int* axis) {
    int best = -1;
    for (int k = 0; k < 3; ++k) {
      int lo = 255, hi = 0;
      for (size_t i = b.begin; i < b.end; ++i) {
        lo = std::min(lo, channel(e[i].colour, k));
        hi = std::max(hi, channel(e[i].colour, k));
      }
      if (hi - lo > best) {
        best = hi - lo;
        *axis = k;
      }
    }
    return best;
  };
  std::vector<Box> boxes{{0, e.size()}};
  while (boxes.size() < static_cast<size_t>(kPaletteSize)) {
    // Split the box with the most pixels among those holding more than one colour, along its
    // widest channel, at the weighted median.
    int pick = -1;
    uint64_t most = 0;
    for (size_t b = 0; b < boxes.size(); ++b) {
      if (boxes[b].end - boxes[b].begin < 2) continue;
      uint64_t w = 0;
      for (size_t i = boxes[b].begin; i < boxes[b].end; ++i) w += e[i].count;
      if (pick < 0 || w > most) {
        pick = static_cast<int>(b);
        most = w;
      }
    }
    if (pick < 0) break;
    Box box = boxes[static_cast<size_t>(pick)];
    int axis = 0;
    widest(box, &axis);
    std::sort(e.begin() + static_cast<std::ptrdiff_t>(box.begin), e.begin() + static_cast<std::ptrdiff_t>(box.end),
              [axis](const Entry& a, const Entry& b) {
                return channel(a.colour, axis) != channel(b.colour, axis) ? channel(a.colour, axis) < channel(b.colour, axis)
                                                                          : a.colour < b.colour;
              });
    uint64_t half = 0;
    size_t cut = box.begin + 1;
    for (size_t i = box.begin; i + 1 < box.end; ++i) {
      half += e[i].count;
      cut = i + 1;
      if (2 * half >= most) break;
    }
    boxes[static_cast<size_t>(pick)] = {box.begin, cut};
    boxes.push_back({cut, box.end});
  }
  for (const Box& b : boxes) {
    double sum[3] = {0, 0, 0}, w = 0;
    for (size_t i = b.begin; i < b.end; ++i) {
      for (int k = 0; k < 3; ++k) sum[k] += static_cast<double>(channel(e[i].colour, k)) * e[i].count;
      w += static_cast<double>(e[i].count);
    }
    uint32_t c = 0;
    for (int k = 0; k < 3; ++k) c = c << 8 | static_cast<uint32_t>(std::lround(sum[k] / w));
    palette.push_back(c);
  }
  return palette;
}

// Packs LZW codes least significant bit first into 255-byte sub-blocks.
class CodeWriter {
 public:
  explicit CodeWriter(std::string& out) : out_(out) {}
  void put(int code, int bits) {
    acc_ |= static_cast<uint32_t>(code) << nbits_;
    nbits_ += bits;
    while (nbits_ >= 8) {
      byte(static_cast<uint8_t>(acc_ & 0xff));
      acc_ >>= 8;
      nbits_ -= 8;
    }
  }
  void finish() {
    if (nbits_ > 0) byte(static_cast<uint8_t>(acc_ & 0xff));
    acc_ = 0;
    nbits_ = 0;
    flush_block();
    out_.push_back('\0');  // block terminator
  }

 private:
  void byte(uint8_t b) {
    block_.push_back(static_cast<char>(b));
    if (block_.size() == 255) flush_block();
  }
  void flush_block() {
    if (block_.empty()) return;
    out_.push_back(static_cast<char>(block_.size()));
    out_ += block_;
    block_.clear();
  }
  std::string& out_;
  std::string block_;
  uint32_t acc_ = 0;
  int nbits_ = 0;
};

// GIF's variable-width LZW of one frame's palette indices.
void lzw(const std::vector<uint8_t>& idx, std::string& out) {
  out.push_back(static_cast<char>(kMinCodeSize));
  const int clear = 1 << kMinCodeSize, eoi = clear + 1;
  // next[code * 256 + byte]: the code of string(code) + byte, 0 when not in the dictionary.
  std::vector<uint16_t> next(static_cast<size_t>(kMaxCode + 1) * kPaletteSize, 0);
  CodeWriter w(out);
  int size = kMinCodeSize + 1, max_code = eoi;
  w.put(clear, size);
  int cur = -1;
  for (uint8_t v : idx) {
    if (cur < 0) {
      cur = v;
      continue;
    }
    uint16_t& slot = next[static_cast<size_t>(cur) * kPaletteSize + v];
    if (slot) {
      cur = slot;
      continue;
    }
    w.put(cur, size);
    slot = static_cast<uint16_t>(++max_code);
    if (max_code >= (1 << size)) ++size;
    if (max_code == kMaxCode) {  // dictionary full: start again
      w.put(clear, size);
      std::fill(next.begin(), next.end(), 0);
      size = kMinCodeSize + 1;
      max_code = eoi;
    }
    cur = v;
  }
  if (cur >= 0) w.put(cur, size);
  w.put(eoi, size);
  w.finish();
}

void put16(std::string& s, int v) {
  s.push_back(static_cast<char>(v & 0xff));
  s.push_back(static_cast<char>(v >> 8 & 0xff));
}

}  // namespace

void write_gif(const std::filesystem::path& file, int frames, double fps,
               const std::function<RgbaImage(int)>& frame, bool loop) {
  if (frames < 1) throw Error(file.string() + ": a GIF needs at least one frame");
  if (!(fps > 0 && std::isfinite(fps))) throw Error(file.string() + ": frame rate must be positive");
  output_target(file);  // refuse a device or folder before rendering anything

  // Pass 1: the colours of every frame (sampled evenly in large frames).
  std::unordered_map<uint32_t, uint64_t> histogram;
  int width = 0, height = 0;
  for (int i = 0; i < frames; ++i) {
    const RgbaImage img = frame(i);
    if (i == 0) {
      width = img.width;
      height = img.height;
      if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        throw Error(file.string() + ": a GIF is 1..65535 pixels on each side, not " + std::to_string(width) + "x" +
                    std::to_string(height));
    }
    if (img.width != width || img.height != height || img.rgba.size() != static_cast<size_t>(width) * height * 4)
      throw Error(file.string() + ": frame " + std::to_string(i) + " does not match the first frame's size");
    const size_t n = static_cast<size_t>(width) * height;
    const size_t step = std::max<size_t>(1, n / kHistogramPixels);
    for (size_t p = 0; p < n; p += step) ++histogram[over_white(&img.rgba[4 * p])];
  }
  const std::vector<uint32_t> palette = make_palette(histogram);

  std::string gif = "GIF89a";
  put16(gif, width);
  put16(gif, height);
  gif.push_back(static_cast<char>(0xF7));  // global table of 256 entries, 8-bit colour resolution
  gif.push_back('\0');                     // background index
  gif.push_back('\0');                     // square pixels
  for (int i = 0; i < kPaletteSize; ++i) {
    const uint32_t c = i < static_cast<int>(palette.size()) ? palette[static_cast<size_t>(i)] : 0;
    for (int k = 0; k < 3; ++k) gif.push_back(static_cast<char>(channel(c, k)));
  }
  if (loop) {
    gif += "\x21\xFF\x0B" "NETSCAPE2.0" "\x03\x01";
    put16(gif, 0);  // repeat forever
    gif.push_back('\0');
  }

  // Pass 2: each frame as indices into the palette (nearest colour, remembered per colour).
  std::unordered_map<uint32_t, uint8_t> nearest;
  std::vector<uint8_t> idx(static_cast<size_t>(width) * height);
  for (int i = 0; i < frames; ++i) {
    const RgbaImage img = frame(i);
    if (img.width != width || img.height != height || img.rgba.size() != idx.size() * 4)
      throw Error(file.string() + ": frame " + std::to_string(i) + " does not match the first frame's size");
    for (size_t p = 0; p < idx.size(); ++p) {
      const uint32_t c = over_white(&img.rgba[4 * p]);
      auto it = nearest.find(c);
      if (it == nearest.end()) {
        int best = 0;
        long best_d = -1;
        for (size_t q = 0; q < palette.size(); ++q) {
          long d = 0;
          for (int k = 0; k < 3; ++k) {
            const long dk = channel(c, k) - channel(palette[q], k);
            d += dk * dk;
          }
          if (best_d < 0 || d < best_d) {
            best_d = d;
            best = static_cast<int>(q);
          }
        }
        it = nearest.emplace(c, static_cast<uint8_t>(best)).first;
      }
      idx[p] = it->second;
    }
    // Graphic control: keep the frame (disposal 1), its delay in hundredths of a second.
    const int delay = static_cast<int>(std::lround(100.0 * (i + 1) / fps) - std::lround(100.0 * i / fps));
    gif += "\x21\xF9\x04";
    gif.push_back('\x04');
    put16(gif, std::min(delay, 65535));
    gif.push_back('\0');
    gif.push_back('\0');
    gif.push_back('\x2C');  // image descriptor: the whole canvas, the global table
    put16(gif, 0);
    put16(gif, 0);
    put16(gif, width);
    put16(gif, height);
    gif.push_back('\0');
    lzw(idx, gif);
  }
  gif.push_back('\x3B');
  write_file_atomic(file, gif);
}

}  // namespace svgm
