// Clips from rendered frames (see clip_writer.h).
#include "export/clip_writer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "export/gif_writer.h"
#include "media/video_encoder.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxFieldWidth = 9;  // %09d: a billion frames, far beyond any clip

struct Field {
  size_t at = 0, length = 0;  // where the % field stands in the pattern
  int width = 0;
  bool zero = false;
};

// The frame-number fields of a name: -1 when a % starts anything but %%, %d, %Nd or %0Nd.
int fields(const std::string& s, Field* f) {
  int n = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') continue;
    if (i + 1 < s.size() && s[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t j = i + 1;
    Field x{i, 0, 0, false};
    if (j < s.size() && s[j] == '0') {
      x.zero = true;
      ++j;
    }
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])) && x.width <= kMaxFieldWidth)
      x.width = x.width * 10 + (s[j++] - '0');
    if (j >= s.size() || s[j] != 'd' || x.width > kMaxFieldWidth) return -1;
    x.length = j + 1 - i;
    if (n++ == 0) *f = x;
    i = j;
  }
  return n;
}

std::string unescape(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
  }
  return out;
}

}  // namespace

ClipFormat clip_format(const std::string& out) {
  std::string ext = fs::path(out).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  Field f;
  const int n = fields(out, &f);
  if (ext == ".png") {
    if (n == 0) return ClipFormat::Still;
    if (n == 1) return ClipFormat::Sequence;
    throw Error(out + ": a frame sequence names one frame-number field (%d or %04d), " +
                (n < 0 ? std::string("and % may only start %d, %0Nd or %%") : std::to_string(n) + " found"));
  }
  if (ext == ".mp4" || ext == ".webm" || ext == ".gif" || ext == ".webp") {
    if (n != 0) throw Error(out + ": a % field is for frame sequences (frames/%04d.png), not " + ext + " files");
    return ext == ".mp4" ? ClipFormat::Mp4 : ext == ".webm" ? ClipFormat::Webm : ext == ".webp" ? ClipFormat::Webp : ClipFormat::Gif;
  }
  throw Error(out + ": render writes .png images, .mp4, .webm, .gif or .webp clips, or frame sequences like frames/%04d.png" +
              (ext.empty() ? std::string() : " (not " + ext + ")"));
}

std::string sequence_name(const std::string& pattern, int i) {
  Field f;
  if (fields(pattern, &f) != 1) throw Error(pattern + ": not a frame sequence pattern");
  std::string num = std::to_string(i);
  if (static_cast<int>(num.size()) < f.width) num.insert(0, static_cast<size_t>(f.width) - num.size(), f.zero ? '0' : ' ');
  return unescape(pattern.substr(0, f.at)) + num + unescape(pattern.substr(f.at + f.length));
}

void write_clip(const std::string& out, ClipFormat format, int frames, double fps, bool loop,
                const std::function<RgbaImage(int)>& frame, const ClipOptions& options) {
  switch (format) {
    case ClipFormat::Still:
      write_png(out, frame(0));
      return;
    case ClipFormat::Sequence: {
      const fs::path dir = fs::path(sequence_name(out, 0)).parent_path();
      std::error_code ec;
      if (!dir.empty() && !fs::is_directory(dir, ec)) {
        fs::create_directories(dir, ec);
        if (ec) throw Error(dir.string() + ": cannot create: " + ec.message());
      }
      for (int i = 0; i < frames; ++i) write_png(sequence_name(out, i), frame(i));
      return;
    }
    case ClipFormat::Mp4:
    case ClipFormat::Webm:
    case ClipFormat::Webp:
      write_video(out, frames, fps, frame, {options.quality, options.transparent, loop});
      return;
    case ClipFormat::Gif:
      write_gif(out, frames, fps, frame, loop, options.transparent);
      return;
  }
}

}  // namespace svgm
