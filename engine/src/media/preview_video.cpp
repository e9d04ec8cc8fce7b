// Preview videos: each frame's panels checked against frame 0's sizes, composited over white
// side by side, and handed to media/video_encoder.h one frame at a time (see preview_video.h).
#include "media/preview_video.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "media/video_encoder.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& where, const std::string& problem) {
  throw Error(where.string() + ": " + problem);
}

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// Composites an RGBA panel over white into the RGBA frame (row width `frame_w`) at column x0.
void blit(const RgbaImage& img, RgbaImage& frame, int x0) {
  for (int y = 0; y < img.height; ++y) {
    const uint8_t* s = img.rgba.data() + static_cast<size_t>(y) * img.width * 4;
    uint8_t* d = frame.rgba.data() + (static_cast<size_t>(y) * frame.width + x0) * 4;
    for (int x = 0; x < img.width; ++x, s += 4, d += 4) {
      const int a = s[3];
      // Rounded s*a/255 + (255 - a), exact for a = 0 and a = 255.
      for (int c = 0; c < 3; ++c) d[c] = static_cast<uint8_t>((s[c] * a + 255 * (255 - a) + 127) / 255);
      d[3] = 255;
    }
  }
}

}  // namespace

RgbaImage rgba8_image(const float* rgba, int width, int height) {
  RgbaImage img;
  img.width = width;
  img.height = height;
  const size_t n = static_cast<size_t>(width) * height * 4;
  img.rgba.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float v = std::isfinite(rgba[i]) ? std::clamp(rgba[i], 0.0f, 1.0f) : 0.0f;
    img.rgba[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
  }
  return img;
}

void write_preview_video(const fs::path& file, int frames, int panels,
                         const PreviewPanelFn& panel_image, double fps) {
  if (frames < 1) fail(file, "a preview needs at least one frame");
  if (panels < 1) fail(file, "a preview needs at least one panel");
  if (!(std::isfinite(fps) && fps > 0)) fail(file, "frame rate must be positive");

  std::vector<std::pair<int, int>> sizes;  // panel sizes of frame 0, which every frame repeats
  auto frame_at = [&](int k) {
    std::vector<RgbaImage> row;
    row.reserve(static_cast<size_t>(panels));
    for (int p = 0; p < panels; ++p) {
      row.push_back(panel_image(k, p));
      const RgbaImage& img = row.back();
      if (img.width < 1 || img.height < 1 || img.rgba.size() != static_cast<size_t>(img.width) * img.height * 4)
        fail(file, "panel " + std::to_string(p) + " of frame " + std::to_string(k) +
                       " is empty or does not match its size");
      if (k == 0) {
        if (p > 0 && img.height != sizes[0].second)
          fail(file, "panel " + std::to_string(p) + " is " + std::to_string(img.height) +
                         " pixels high, but panel 0 is " + std::to_string(sizes[0].second));
        sizes.emplace_back(img.width, img.height);
      } else if (img.width != sizes[static_cast<size_t>(p)].first || img.height != sizes[static_cast<size_t>(p)].second) {
        fail(file, "panel " + std::to_string(p) + " of frame " + std::to_string(k) + " is " +
                       size_text(img.width, img.height) + ", but in frame 0 it is " +
                       size_text(sizes[static_cast<size_t>(p)].first, sizes[static_cast<size_t>(p)].second));
      }
    }
    int width = 0;
    for (const auto& s : sizes) width += s.first;
    RgbaImage frame{width, sizes[0].second, std::vector<uint8_t>(static_cast<size_t>(width) * sizes[0].second * 4)};
    int x0 = 0;
    for (const RgbaImage& img : row) {
      blit(img, frame, x0);
      x0 += img.width;
    }
    return frame;
  };
  write_video(file, frames, fps, frame_at, VideoOptions{});
}

void write_preview_video(const fs::path& file, const std::vector<std::vector<RgbaImage>>& panels,
                         double fps) {
  if (panels.empty()) fail(file, "a preview needs at least one panel");
  const size_t frames = panels[0].size();
  for (size_t p = 1; p < panels.size(); ++p)
    if (panels[p].size() != frames)
      fail(file, "panel " + std::to_string(p) + " has " + std::to_string(panels[p].size()) +
                     " frames, but panel 0 has " + std::to_string(frames));
  write_preview_video(
      file, static_cast<int>(frames), static_cast<int>(panels.size()),
      [&](int k, int p) { return panels[static_cast<size_t>(p)][static_cast<size_t>(k)]; }, fps);
}

}  // namespace svgm
