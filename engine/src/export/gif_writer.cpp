// The GIF89a writer (see gif_writer.h). Format: the GIF89a specification (W3C/CompuServe,
// 1990); the LZW coder's code-size and dictionary-reset rules are the specification's, in the
// shape of Charlie Tangora's public-domain gif.h (third_party_notes.md).
#include "export/gif_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "export/palette_quantiser.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

constexpr int kPaletteSize = 256;         // GIF's largest colour table (8 bits per index)
constexpr int kMinCodeSize = 8;           // LZW root codes: one per palette index
constexpr int kMaxCode = 4095;            // 12-bit codes, the format's limit
constexpr int kMaxSide = 65535;           // GIF sizes are 16-bit
constexpr int kMaxDelay = 65535;          // hundredths of a second, 16-bit

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

struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1); empty when x1 <= x0
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  void add(int x, int y) {
    if (empty()) *this = {x, y, x + 1, y + 1};
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x + 1), y1 = std::max(y1, y + 1);
  }
  void add(const Rect& r) {
    if (r.empty()) return;
    add(r.x0, r.y0);
    add(r.x1 - 1, r.y1 - 1);
  }
};

// A frame decided but not yet written: its disposal depends on the frame after it.
struct Pending {
  std::vector<uint8_t> target;  // the whole canvas this frame shows
  std::vector<uint8_t> before;  // the canvas before it is drawn
  Rect rect;                    // what it draws
  int delay = 0;                // hundredths of a second
  bool clear = false;           // disposal 2: its rectangle returns to transparent afterwards
};

// Frame differencing in index space. A frame draws only the rectangle holding every pixel that
// differs from the canvas it is drawn on, and inside it writes the transparent index for
// pixels that already show the right colour (long runs of one code: LZW's best case). A pixel
// that must turn transparent cannot be drawn (transparent means "leave as is"), so the frame
// before it is given disposal 2 over a rectangle grown to cover those pixels: the decoder
// clears it, and the new frame redraws whatever inside it stays opaque. A frame identical to
// the canvas is not written; its time is added to the frame before.
class GifFrames {
 public:
  GifFrames(std::string& gif, int width, int height, int transparent)
      : gif_(gif), w_(width), h_(height), t_(static_cast<uint8_t>(transparent)),
        canvas_(static_cast<size_t>(width) * height, t_) {}

  void add(const std::vector<uint8_t>& target, int delay) {
    if (pending_) {
      // Pixels the pending frame leaves opaque that this one wants transparent.
      Rect clear;
      for (int y = 0; y < h_; ++y)
        for (int x = 0; x < w_; ++x) {
          const size_t p = static_cast<size_t>(y) * w_ + x;
          if (target[p] == t_ && pending_->target[p] != t_) clear.add(x, y);
        }
      canvas_ = pending_->target;
      if (!clear.empty()) {
        pending_->rect.add(clear);
        pending_->clear = true;
        const Rect& r = pending_->rect;
        for (int y = r.y0; y < r.y1; ++y) std::fill_n(canvas_.begin() + static_cast<ptrdiff_t>(y) * w_ + r.x0, r.x1 - r.x0, t_);
      }
    }
    Rect changed;
    for (int y = 0; y < h_; ++y)
      for (int x = 0; x < w_; ++x)
        if (target[static_cast<size_t>(y) * w_ + x] != canvas_[static_cast<size_t>(y) * w_ + x]) changed.add(x, y);
    if (changed.empty() && pending_ && !pending_->clear) {
      pending_->delay += delay;  // the same picture: shown longer
      return;
    }
    if (changed.empty()) changed = {0, 0, 1, 1};  // a frame must draw something to hold its time
    flush();
    pending_ = Pending{target, canvas_, changed, delay, false};
  }

  void finish() { flush(); }

 private:
  void flush() {
    if (!pending_) return;
    const Pending& f = *pending_;
    // Graphic control: disposal (1 keep, 2 clear), transparent index, delay.
    gif_ += "\x21\xF9\x04";
    gif_.push_back(static_cast<char>((f.clear ? 2 : 1) << 2 | 1));
    put16(gif_, std::min(f.delay, kMaxDelay));
    gif_.push_back(static_cast<char>(t_));
    gif_.push_back('\0');
    gif_.push_back('\x2C');  // image descriptor: the rectangle, the global table
    const Rect& r = f.rect;
    put16(gif_, r.x0);
    put16(gif_, r.y0);
    put16(gif_, r.x1 - r.x0);
    put16(gif_, r.y1 - r.y0);
    gif_.push_back('\0');
    // Unchanged pixels as the transparent index usually make the longer runs, but a short run
    // of them inside changed pixels breaks strings LZW has already seen: runs shorter than
    // `min_run` are written as their colours. A few settings are coded and the shortest kept;
    // either way every pixel shows what it should (a transparent canvas pixel is the transparent
    // index in both spellings).
    const int rw = r.x1 - r.x0;
    std::string best;
    for (const int min_run : {1, 3, 8, rw + 1}) {
      std::vector<uint8_t> idx;
      idx.reserve(static_cast<size_t>(rw) * (r.y1 - r.y0));
      for (int y = r.y0; y < r.y1; ++y) {
        const size_t row = static_cast<size_t>(y) * w_;
        for (int x = r.x0; x < r.x1;) {
          int run = 0;
          while (x + run < r.x1 && f.target[row + x + run] == f.before[row + x + run]) ++run;
          const bool mark = run >= min_run;
          for (int k = 0; k < run; ++k) idx.push_back(mark ? t_ : f.target[row + x + k]);
          x += run;
          if (x < r.x1) idx.push_back(f.target[row + x++]);
        }
      }
      std::string coded;
      lzw(idx, coded);
      if (best.empty() || coded.size() < best.size()) best.swap(coded);
    }
    gif_ += best;
    pending_.reset();
  }

  std::string& gif_;
  int w_, h_;
  uint8_t t_;
  std::vector<uint8_t> canvas_;  // what the decoder shows before the next frame is drawn
  std::optional<Pending> pending_;
};

}  // namespace

void write_gif(const std::filesystem::path& file, int frames, double fps,
               const std::function<RgbaImage(int)>& frame, bool loop, bool transparent) {
  if (frames < 1) throw Error(file.string() + ": a GIF needs at least one frame");
  if (!(fps > 0 && std::isfinite(fps))) throw Error(file.string() + ": frame rate must be positive");
  output_target(file);  // refuse a device or folder before rendering anything

  // Pass 1: the palette from every frame's colours.
  std::unique_ptr<PaletteQuantiser> quantiser;
  int width = 0, height = 0;
  for (int i = 0; i < frames; ++i) {
    const RgbaImage img = frame(i);
    if (i == 0) {
      width = img.width;
      height = img.height;
      if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        throw Error(file.string() + ": a GIF is 1..65535 pixels on each side, not " + std::to_string(width) + "x" +
                    std::to_string(height));
      quantiser = std::make_unique<PaletteQuantiser>(width, height, transparent, file.string());
    }
    if (img.width != width || img.height != height || img.rgba.size() != static_cast<size_t>(width) * height * 4)
      throw Error(file.string() + ": frame " + std::to_string(i) + " does not match the first frame's size");
    quantiser->gather(img);
  }
  const std::array<uint32_t, 256>& palette = quantiser->palette();
  const int t = quantiser->transparent_index();

  std::string gif = "GIF89a";
  put16(gif, width);
  put16(gif, height);
  gif.push_back(static_cast<char>(0xF7));  // global table of 256 entries, 8-bit colour resolution
  gif.push_back(static_cast<char>(t));     // background: transparent, what disposal 2 restores
  gif.push_back('\0');                     // square pixels
  for (int i = 0; i < kPaletteSize; ++i)
    for (int k = 0; k < 3; ++k) gif.push_back(static_cast<char>(palette[static_cast<size_t>(i)] >> (16 - 8 * k) & 0xff));
  if (loop) {
    gif += "\x21\xFF\x0B" "NETSCAPE2.0" "\x03\x01";
    put16(gif, 0);  // repeat forever
    gif.push_back('\0');
  }

  // Pass 2: each frame's indices, differenced against the canvas. Frame i is shown from
  // round(100 i / fps) to round(100 (i+1) / fps) hundredths.
  GifFrames out(gif, width, height, t);
  int mapped = 0;
  auto take = [&](const std::vector<uint8_t>& idx) {
    const int delay = static_cast<int>(std::lround(100.0 * (mapped + 1) / fps) - std::lround(100.0 * mapped / fps));
    ++mapped;
    out.add(idx, delay);
  };
  for (int i = 0; i < frames; ++i) {
    const RgbaImage img = frame(i);
    if (img.width != width || img.height != height || img.rgba.size() != static_cast<size_t>(width) * height * 4)
      throw Error(file.string() + ": frame " + std::to_string(i) + " does not match the first frame's size");
    quantiser->map(img, take);
  }
  quantiser->finish(take);
  if (mapped != frames)
    throw Error(file.string() + ": cannot quantise colours: paletteuse returned " + std::to_string(mapped) + " of " +
                std::to_string(frames) + " frames");
  out.finish();
  gif.push_back('\x3B');
  write_file_atomic(file, gif);
}

}  // namespace svgm
