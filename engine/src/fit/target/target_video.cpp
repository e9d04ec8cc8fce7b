// Reading the fitter's target: a video (FFmpeg, media/video_decoder.h) or a folder of numbered PNG
// frames, sampled to K keyframes, resized to the render size, and reduced to a cleaned image, a
// foreground mask and a distance field per keyframe.
//
// Everything OpenCV stays in this file; the public header only speaks std:: types.
#include "svgmotion/target_video.h"

#include "fit/target/heap_trim.h"
#include "fit/target/colour_correction.h"
#include "fit/target/deflated_bytes.h"
#include "fit/target/distance_field.h"
#include "fit/target/stabilise.h"
#include "fit/target/temporal_denoise.h"
#include "image/png_frame.h"
#include "media/video_decoder.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <system_error>

#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxSide = 16384;

[[noreturn]] void fail(const fs::path& where, const std::string& problem) {
  throw Error(where.string() + ": " + problem);
}

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// The largest target frame side, in pixels: --size is at most 4096 and every frame is shrunk
// to the fitting size, while an 8000x8000 clip took 2.7 GB and 142 s to load. A larger one is
// refused before its frames are decoded, in one line saying so.
constexpr int kMaxTargetSide = 4096;

void check_frame_size(const fs::path& source, int w, int h) {
  if (w > kMaxTargetSide || h > kMaxTargetSide)
    fail(source, "frames of " + size_text(w, h) + " are too large (limit " + std::to_string(kMaxTargetSide) + " px a side; "
                 "scale the video down first, e.g. ffmpeg -i IN -vf scale=1024:-2 OUT.mp4)");
}

std::string frames_text(int n) { return std::to_string(n) + (n == 1 ? " frame" : " frames"); }

// Missing sources get the errno wording users know from other tools ("cannot open: No such
// file or directory") rather than OpenCV's silence. Returns whether `source` is a folder.
bool classify_source(const fs::path& source) {
  std::error_code ec;
  const fs::file_status st = fs::status(source, ec);
  if (st.type() == fs::file_type::not_found)
    fail(source, "cannot open: " + std::generic_category().message(ENOENT));
  if (ec) fail(source, "cannot open: " + ec.message());
  if (fs::is_directory(st)) return true;
  // OpenCV reports an unreadable file the same way as an undecodable one; check access first
  // so that "Permission denied" is not reported as "not a readable video".
  std::FILE* f = std::fopen(source.c_str(), "rb");
  if (!f) fail(source, std::string("cannot open: ") + std::strerror(errno));
  std::fclose(f);
  return false;
}

// ---- numbered PNG folders ----------------------------------------------------------------

struct FolderFrame {
  fs::path path;
  std::string name;
  std::string number;  // the last run of digits in the stem, leading zeros stripped
};

// Numbers are compared as digit strings (shorter = smaller), so any length works.
bool number_less(const std::string& a, const std::string& b) {
  return a.size() != b.size() ? a.size() < b.size() : a < b;
}

std::vector<FolderFrame> list_png_frames(const fs::path& folder) {
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  if (ec) fail(folder, "cannot open: " + ec.message());
  std::vector<FolderFrame> frames;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) fail(folder, "cannot list: " + ec.message());
    const fs::path& p = it->path();
    std::string name = p.filename().string();
    // Hidden files (editor backups, macOS "._0001.png" resource forks) are never frames.
    if (name.empty() || name[0] == '.') continue;
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".png") continue;
    std::error_code fec;
    if (fs::is_directory(it->status(fec))) continue;
    const std::string stem = p.stem().string();
    size_t end = stem.size();
    while (end > 0 && !std::isdigit(static_cast<unsigned char>(stem[end - 1]))) --end;
    size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    if (begin == end) fail(folder, "cannot order " + name + ": no number in its name");
    std::string number = stem.substr(begin, end - begin);
    number.erase(0, std::min(number.find_first_not_of('0'), number.size() - 1));
    frames.push_back({p, std::move(name), std::move(number)});
  }
  if (frames.empty()) fail(folder, "no PNG frames");
  std::sort(frames.begin(), frames.end(), [](const FolderFrame& a, const FolderFrame& b) {
    if (a.number != b.number) return number_less(a.number, b.number);
    return a.name < b.name;
  });
  // Two frames with one number (1.png and 01.png) have no defined order: refuse rather than
  // silently pick one, since a swapped pair would show up as a jitter in the fitted motion.
  for (size_t i = 1; i < frames.size(); ++i)
    if (frames[i].number == frames[i - 1].number)
      fail(folder, "frames " + frames[i - 1].name + " and " + frames[i].name +
                       " have the same number");
  return frames;
}

// The size from a PNG's IHDR chunk: checks every frame (signature, size agreement) without
// decoding the ones that are not sampled.
std::pair<int, int> png_header_size(const fs::path& file) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f) fail(file, std::string("cannot open: ") + std::strerror(errno));
  unsigned char h[24];
  const size_t got = std::fread(h, 1, sizeof h, f);
  std::fclose(f);
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got != sizeof h || std::memcmp(h, sig, 8) != 0 || std::memcmp(h + 12, "IHDR", 4) != 0)
    fail(file, "not a readable PNG");
  auto be32 = [](const unsigned char* p) {
    return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
  };
  const uint32_t w = be32(h + 16), hh = be32(h + 20);
  if (w == 0 || hh == 0 || w > (1u << 30) || hh > (1u << 30)) fail(file, "not a readable PNG");
  return {static_cast<int>(w), static_cast<int>(hh)};
}

struct FolderSource {
  std::vector<FolderFrame> frames;
  int width = 0, height = 0;
};

FolderSource scan_folder(const fs::path& folder) {
  FolderSource src;
  src.frames = list_png_frames(folder);
  for (size_t i = 0; i < src.frames.size(); ++i) {
    const auto [w, h] = png_header_size(src.frames[i].path);
    if (i == 0) {
      check_frame_size(src.frames[i].path, w, h);
      src.width = w;
      src.height = h;
    } else if (w != src.width || h != src.height) {
      fail(folder, src.frames[i].name + " is " + size_text(w, h) + ", but " +
                       src.frames[0].name + " is " + size_text(src.width, src.height));
    }
  }
  return src;
}

// ---- videos ---------------------------------------------------------------------------------

// Counts by reading: the container's frame count can be 0 or wrong. grab() decodes without the
// colour conversion, so counting costs less than reading.
TargetInfo probe_video(const fs::path& file) {
  VideoDecoder cap(file);
  // The container's size, before decoding a frame of an oversized clip (0 when it has none).
  check_frame_size(file, cap.width(), cap.height());
  TargetInfo info;
  const double fps = cap.fps();
  info.fps = std::isfinite(fps) && fps > 0 ? fps : 24.0;
  cv::Mat first;
  if (!cap.read(first) || first.empty()) fail(file, "not a readable video");
  info.width = first.cols;
  info.height = first.rows;
  check_frame_size(file, info.width, info.height);
  info.frames = 1;
  while (cap.grab()) ++info.frames;
  return info;
}

// ---- per-frame processing -------------------------------------------------------------------

// Any decoded image (grey, grey+alpha, BGR, BGRA; 8/16-bit or float) as straight RGB float in
// [0,1], alpha composited over white: transparent backgrounds must not read as black ink.
cv::Mat to_rgb_float(const cv::Mat& img) {
  double scale = 1.0;
  switch (img.depth()) {
    case CV_8U: scale = 1.0 / 255.0; break;
    case CV_16U: scale = 1.0 / 65535.0; break;
    case CV_32F: break;
    default: throw Error("internal: unsupported image depth");
  }
  cv::Mat f;
  img.convertTo(f, CV_MAKETYPE(CV_32F, img.channels()), scale);
  cv::Mat rgb, alpha;
  switch (f.channels()) {
    case 1: cv::cvtColor(f, rgb, cv::COLOR_GRAY2RGB); break;
    case 2: {
      cv::Mat ch[2];
      cv::split(f, ch);
      cv::cvtColor(ch[0], rgb, cv::COLOR_GRAY2RGB);
      alpha = ch[1];
      break;
    }
    case 3: cv::cvtColor(f, rgb, cv::COLOR_BGR2RGB); break;
    case 4: {
      cv::cvtColor(f, rgb, cv::COLOR_BGRA2RGB);
      cv::extractChannel(f, alpha, 3);
      break;
    }
    default: throw Error("internal: unsupported channel count");
  }
  if (!alpha.empty()) {
    cv::Mat a3;
    cv::cvtColor(alpha, a3, cv::COLOR_GRAY2RGB);
    // rgb * a + (1 - a)
    cv::multiply(rgb, a3, rgb);
    cv::subtract(cv::Scalar::all(1.0), a3, a3);
    cv::add(rgb, a3, rgb);
  }
  return rgb;
}

cv::Mat resize_to(const cv::Mat& rgb, int width, int height) {
  if (rgb.cols == width && rgb.rows == height) return rgb;
  // INTER_AREA averages when shrinking (no aliasing of thin strokes); it degenerates to
  // something blocky when enlarging, where bilinear is the better choice.
  const bool shrink = width <= rgb.cols && height <= rgb.rows;
  cv::Mat out;
  cv::resize(rgb, out, cv::Size(width, height), 0, 0, shrink ? cv::INTER_AREA : cv::INTER_LINEAR);
  // Bilinear and area weights are convex, but keep [0,1] exact against rounding anyway.
  cv::min(cv::max(out, 0.0), 1.0, out);
  return out;
}

// Stores an RGB float frame (any size) as keyframe k of `raw` (RGBA float, A = 1).
void store_rgb(const cv::Mat& rgb_any_size, int k, int width, int height, std::vector<float>& raw) {
  const cv::Mat rgb = resize_to(rgb_any_size, width, height);
  float* dst = raw.data() + static_cast<size_t>(k) * width * height * 4;
  for (int y = 0; y < height; ++y) {
    const float* s = rgb.ptr<float>(y);
    for (int x = 0; x < width; ++x, dst += 4, s += 3) {
      dst[0] = s[0];
      dst[1] = s[1];
      dst[2] = s[2];
      dst[3] = 1.0f;
    }
  }
}

// Stores a decoded frame as keyframe k of `raw`.
void store_raw(const cv::Mat& decoded, int k, int width, int height, std::vector<float>& raw) {
  store_rgb(to_rgb_float(decoded), k, width, height, raw);
}

}  // namespace

std::array<float, 3> border_median_rgb(const float* f, int W, int H) {
  std::array<std::vector<float>, 3> v;
  auto add = [&](int x, int y) {
    for (int c = 0; c < 3; ++c) v[c].push_back(f[(static_cast<size_t>(y) * W + x) * 4 + c]);
  };
  for (int x = 0; x < W; ++x) add(x, 0), add(x, H - 1);
  for (int y = 1; y + 1 < H; ++y) add(0, y), add(W - 1, y);
  std::array<float, 3> m{1, 1, 1};
  for (int c = 0; c < 3; ++c) {
    if (v[c].empty()) continue;
    std::nth_element(v[c].begin(), v[c].begin() + static_cast<ptrdiff_t>(v[c].size() / 2), v[c].end());
    m[c] = v[c][v[c].size() / 2];
  }
  return m;
}

namespace {

// Held frames: a 64-pixel-wide grey thumbnail of each frame, and "the same frame" as no
// thumbnail pixel differing by more than a codec's re-encoding of a repeat does. The largest
// difference, not the mean: a small part moving on a still figure (a waving hand) changes few
// pixels, which a mean over the frame would not see.
constexpr double kHeldFrameMaxDiff = 6;  // 8-bit levels, after the thumbnail's averaging

// Width at which camera shake is measured: sub-pixel phase correlation is good to about a
// tenth of a pixel here, and the clip's every frame is measured.
constexpr int kShakeMeasureWidth = 512;

cv::Mat held_frame_thumbnail(const cv::Mat& frame) {
  cv::Mat grey, small;
  if (frame.channels() >= 3) cv::cvtColor(frame, grey, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  else grey = frame;
  const int w = 64, h = std::max(1, static_cast<int>(std::lround(64.0 * frame.rows / std::max(1, frame.cols))));
  cv::resize(grey, small, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  cv::Mat f;
  small.convertTo(f, CV_32F, grey.depth() == CV_16U ? 1.0 / 257 : 1.0);
  return f;
}

bool same_frame(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size()) return false;
  double lo = 0, hi = 0;
  cv::minMaxLoc(cv::abs(a - b), &lo, &hi);
  return hi <= kHeldFrameMaxDiff;
}

// Ink: 1 where a channel of `rgba` differs from the background colour by more than tol.
void mark_ink(const float* rgba, int w, int h, const std::array<float, 3>& bg, float tol, cv::Mat& ink) {
  ink.create(h, w, CV_8U);
  for (int y = 0; y < h; ++y) {
    uint8_t* row = ink.ptr<uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      const float* p = rgba + (static_cast<size_t>(y) * w + x) * 4;
      row[x] = std::max({std::fabs(p[0] - bg[0]), std::fabs(p[1] - bg[1]), std::fabs(p[2] - bg[2])}) > tol ? 1 : 0;
    }
  }
}

// Mask, cleaned target and distance field of keyframe k from its raw frame (the cleaned frame
// in slot `rgba_slot` of t.rgba).
void clean_keyframe(TargetFrames& t, int k, int rgba_slot, const TargetOptions& opt, const float* raw) {
  const int w = t.width, h = t.height;
  const size_t px = static_cast<size_t>(w) * h;

  // Ink: a pixel whose colour differs from the frame's background by more than
  // 1 - white_threshold in some channel. The background is white, or the light colour most of
  // the border shows (a generated video's off-white, drifting background); on white this is
  // exactly "darkest channel < white_threshold".
  cv::Mat ink;
  const float tol = 1.0f - static_cast<float>(opt.white_threshold);
  // Only a light background that most of the border agrees on stands in for white: a figure
  // covering half the border, or a drawing's own dark backdrop (a scene's sky), is figure.
  std::array<float, 3> bg = border_median_rgb(raw, w, h);
  {
    size_t agree = 0, border = 0;
    auto near = [&](int x, int y) {
      const float* p = raw + (static_cast<size_t>(y) * w + x) * 4;
      ++border;
      agree += std::max({std::fabs(p[0] - bg[0]), std::fabs(p[1] - bg[1]), std::fabs(p[2] - bg[2])}) <= tol;
    };
    for (int x = 0; x < w; ++x) near(x, 0), near(x, h - 1);
    for (int y = 1; y + 1 < h; ++y) near(0, y), near(w - 1, y);
    if (std::min({bg[0], bg[1], bg[2]}) < 0.85f || agree * 10 < border * 6) bg = {1, 1, 1};
  }
  mark_ink(raw, w, h, bg, tol, ink);

  // The component filter removes compression specks and stray marks far from the figure; the
  // floor of 4 px applies even when the figure itself is tiny. A part as large as the
  // drawing's own smallest (keep_part_share) is never taken for one.
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(ink, labels, stats, centroids, 8, CV_32S);
  int largest = 0;
  for (int i = 1; i < n; ++i) largest = std::max(largest, stats.at<int>(i, cv::CC_STAT_AREA));
  double min_area = opt.min_component_fraction * largest;
  if (opt.keep_part_share > 0) min_area = std::min(min_area, opt.keep_part_share * static_cast<double>(px));
  min_area = std::max(4.0, min_area);
  std::vector<uint8_t> keep(static_cast<size_t>(std::max(n, 1)), 0);
  bool any = false;
  for (int i = 1; i < n; ++i) {
    if (stats.at<int>(i, cv::CC_STAT_AREA) < min_area) continue;
    keep[static_cast<size_t>(i)] = 1;
    any = true;
  }
  // A small component that the kept figure encloses is the drawing's own detail, not a stray
  // mark: light grains on near-white rice, whose codec noise leaves the rice around them under
  // the ink threshold, came out as islands under the size floor, were whitened, and the fit
  // folded the grains flat. Stray specks lie outside the figure: everything reachable from the
  // frame's border without crossing a kept component.
  if (any) {
    cv::Mat open(h, w, CV_8U);  // 1: not part of a kept component
    for (int y = 0; y < h; ++y) {
      const int* l = labels.ptr<int>(y);
      uint8_t* o = open.ptr<uint8_t>(y);
      for (int x = 0; x < w; ++x) o[x] = keep[static_cast<size_t>(l[x])] ? 0 : 1;
    }
    cv::Mat open_labels;
    // 4-connected: a diagonal gap in a kept outline closes it.
    const int open_count = cv::connectedComponents(open, open_labels, 4, CV_32S);
    std::vector<uint8_t> outside(static_cast<size_t>(open_count), 0);  // by open_labels' label
    auto seed = [&](int x, int y) {
      if (open.at<uint8_t>(y, x)) outside[static_cast<size_t>(open_labels.at<int>(y, x))] = 1;
    };
    for (int x = 0; x < w; ++x) seed(x, 0), seed(x, h - 1);
    for (int y = 0; y < h; ++y) seed(0, y), seed(w - 1, y);
    std::vector<uint8_t> enclosed(static_cast<size_t>(n), 1);  // per ink component
    for (int y = 0; y < h; ++y) {
      const int* l = labels.ptr<int>(y);
      const int* ol = open_labels.ptr<int>(y);
      for (int x = 0; x < w; ++x)
        if (l[x] > 0 && outside[static_cast<size_t>(ol[x])]) enclosed[static_cast<size_t>(l[x])] = 0;
    }
    for (int i = 1; i < n; ++i) keep[static_cast<size_t>(i)] |= enclosed[static_cast<size_t>(i)];
  }

  // Background = 255 (non-zero) so that distanceTransform measures the distance to the
  // nearest kept foreground pixel; the precise mask makes it the exact Euclidean distance
  // between pixel centres, which also gives an exact disc dilation by thresholding it.
  cv::Mat background(h, w, CV_8U);
  for (int y = 0; y < h; ++y) {
    const int* l = labels.ptr<int>(y);
    uint8_t* b = background.ptr<uint8_t>(y);
    for (int x = 0; x < w; ++x) b[x] = keep[static_cast<size_t>(l[x])] ? 0 : 255;
  }
  uint8_t* mask = t.mask.data() + k * px;
  float* sdf = t.sdf.data() + k * px;
  float* out = t.rgba.data() + static_cast<size_t>(rgba_slot) * px * 4;
  if (any && opt.dilate_px > 0) {
    cv::Mat dist;
    cv::distanceTransform(background, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    // A small tolerance so that integer distances (r itself) are inside whatever the rounding.
    const float r = static_cast<float>(opt.dilate_px) + 1e-3f;
    for (int y = 0; y < h; ++y) {
      const float* d = dist.ptr<float>(y);
      uint8_t* b = background.ptr<uint8_t>(y);
      for (int x = 0; x < w; ++x) b[x] = d[x] <= r ? 0 : 255;
    }
  }
  // The mask (the kept figure, dilated), the figure's pixels on white, and the distance field
  // from the mask (distance_field.h: the distance to the nearest mask pixel).
  for (int y = 0; y < h; ++y) {
    const uint8_t* b = background.ptr<uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const bool fg = any && b[x] == 0;
      mask[i] = fg ? 1 : 0;
      for (int c = 0; c < 3; ++c) out[i * 4 + c] = fg ? raw[i * 4 + c] : 1.0f;
      out[i * 4 + 3] = 1.0f;
    }
  }
  distance_field_from_mask(mask, w, h, sdf);
}

void check_options(const fs::path& source, int width, int height, const TargetOptions& o) {
  if (o.keyframes < 1 && o.frames.empty())
    fail(source, "keyframes must be at least 1 (got " + std::to_string(o.keyframes) + ")");
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
    fail(source, "target size " + size_text(width, height) + " is out of range (each side 1.." +
                     std::to_string(kMaxSide) + ")");
  if (!(o.white_threshold > 0.0 && o.white_threshold <= 1.0))
    fail(source, "white threshold must be in (0, 1] (got " + std::to_string(o.white_threshold) +
                     ")");
  if (!(o.keep_part_share >= 0.0 && o.keep_part_share <= 1.0))
    fail(source, "kept part share must be in [0, 1] (got " + std::to_string(o.keep_part_share) + ")");
  if (!(o.min_component_fraction >= 0.0 && o.min_component_fraction <= 1.0))
    fail(source, "minimum component fraction must be in [0, 1] (got " +
                     std::to_string(o.min_component_fraction) + ")");
  if (o.dilate_px < 0 || o.dilate_px > kMaxSide)
    fail(source, "dilation must be 0.." + std::to_string(kMaxSide) + " pixels (got " +
                     std::to_string(o.dilate_px) + ")");
}

}  // namespace

// ---- load_target's steps, in the order it takes them.

namespace {

// The source's frame count and size (and a video's frame rate); a folder's frames are listed
// into `folder`.
TargetInfo source_info(const fs::path& source, bool is_folder, FolderSource& folder) {
  TargetInfo info;
  if (is_folder) {
    folder = scan_folder(source);
    info.frames = static_cast<int>(folder.frames.size());
    info.width = folder.width;
    info.height = folder.height;
  } else {
    info = probe_video(source);
  }
  return info;
}

// The frames asked for exist, in increasing order, and there are enough for K keyframes.
void check_frame_choice(const fs::path& source, const TargetOptions& options, int K, int N) {
  for (size_t j = 0; j < options.frames.size(); ++j)
    if (options.frames[j] < 0 || options.frames[j] >= N || (j > 0 && options.frames[j] <= options.frames[j - 1]))
      fail(source, "frame " + std::to_string(options.frames[j]) + " asked for is not in 0.." + std::to_string(N - 1) +
                       " or not after the one before");
  if (N < K)
    fail(source, "has " + frames_text(N) + ", fewer than the " + std::to_string(K) +
                     " keyframes asked for");
}

// The keyframes' sizes, their source frames and their (white, empty) images, before decoding.
TargetFrames empty_target(int width, int height, int K, const TargetInfo& info, const TargetOptions& options) {
  const int N = info.frames;
  TargetFrames t;
  t.width = width;
  t.height = height;
  t.keyframes = K;
  t.source_frames = N;
  t.fps = info.fps;
  t.source_width = info.width;
  t.source_height = info.height;
  // round(k (N-1) / (K-1)) in integers (halves round up): no floating-point ties, and strictly
  // increasing because the step (N-1)/(K-1) is at least 1.
  t.source_index.resize(static_cast<size_t>(K));
  for (int k = 0; k < K && !options.frames.empty(); ++k) t.source_index[static_cast<size_t>(k)] = options.frames[static_cast<size_t>(k)];
  for (int k = 0; k < K && options.frames.empty(); ++k) {
    const int64_t num = 2 * int64_t{k} * (N - 1) + (K - 1);
    t.source_index[static_cast<size_t>(k)] =
        K == 1 ? 0 : static_cast<int>(num / (2 * int64_t{K - 1}));
  }
  const size_t px = static_cast<size_t>(width) * height;
  // With a raw_sink each keyframe's frame passes through one slot.
  t.raw.assign((options.raw_sink ? 1 : K) * px * 4, 1.0f);
  // Reserved, filled keyframe by keyframe as each is stored (grow_cleaned): a load does not touch
  // 21 bytes per pixel and keyframe up front (115 MB: 21 at 512 px) beside what it reads from.
  t.rgba.reserve((options.rgba_sink ? 1 : K) * px * 4);
  t.mask.reserve(K * px);
  t.sdf.reserve(K * px);
  return t;
}

// Keyframes 0 .. k - 1's cleaned frames made: white, mask and sdf 0 until clean_keyframe writes
// (with an rgba_sink, one slot of rgba for them all).
void grow_cleaned(TargetFrames& t, int k, bool one_slot) {
  const size_t px = static_cast<size_t>(t.width) * t.height, n = static_cast<size_t>(k) * px;
  if (t.mask.size() >= n) return;
  t.rgba.resize((one_slot ? px : n) * 4, 1.0f);
  t.mask.resize(n, 0);
  t.sdf.resize(n, 0.0f);
}

// load_target's hand-off of one decoded frame (k: the next keyframe, i: the frame's index).
using DeliverFrame = std::function<void(int k, int i, bool sampled, const cv::Mat& frame)>;

// A folder's frames, read in order and handed to `deliver`.
void decode_folder(const FolderSource& folder, int N, int K, const std::vector<int>& source_index, bool measure_shake,
                   const std::function<bool(int)>& near_sample, ShakeEstimator& shake, const DeliverFrame& deliver) {
  // The sampled frames; every frame once when stabilising (each shows the camera's path).
  for (int i = 0, k = 0; i < N && (k < K || near_sample(i)); ++i) {
    const bool sampled = k < K && i == source_index[static_cast<size_t>(k)];
    if (!sampled && !measure_shake && !near_sample(i)) continue;  // not read
    const fs::path& file = folder.frames[static_cast<size_t>(i)].path;
    const cv::Mat img = read_png_frame(file);
    if (img.empty()) fail(file, "not a readable PNG");
    if (img.cols != folder.width || img.rows != folder.height)
      fail(file, "decodes to " + size_text(img.cols, img.rows) + ", but its header says " +
                     size_text(folder.width, folder.height));
    if (measure_shake) shake.add(img);
    deliver(k, i, sampled, img);
    if (sampled) ++k;
  }
}

// A video's frames, decoded in order and handed to `deliver`; held frames counted and the
// keyframes retimed to the first frame of their run when asked.
void decode_video(const fs::path& source, const TargetOptions& options, int N, int K, TargetFrames& t,
                  bool measure_shake, const std::function<bool(int)>& near_sample, ShakeEstimator& shake,
                  const DeliverFrame& deliver) {
  // Second pass: sequential reads (seeking is unreliable across codecs). Every frame is
  // decoded (a thumbnail of each finds held frames); only the sampled ones are kept at the
  // target size, and, when denoising, their neighbours go to the denoiser.
  VideoDecoder cap(source);
  int k = 0, run_start = 0;
  cv::Mat prev_thumb;
  try {
    for (int i = 0; i < N && (k < K || near_sample(i)); ++i) {
      if (!cap.grab()) fail(source, "frame " + std::to_string(i) + " cannot be read");
      const bool sampled = k < K && i == t.source_index[static_cast<size_t>(k)];
      if (!sampled && !options.retime_held_frames && !measure_shake && !near_sample(i)) continue;
      cv::Mat frame;
      if (!cap.retrieve(frame) || frame.empty())
        fail(source, "frame " + std::to_string(i) + " cannot be decoded");
      if (measure_shake) shake.add(frame);
      if (options.retime_held_frames) {
        cv::Mat thumb = held_frame_thumbnail(frame);
        if (!prev_thumb.empty() && same_frame(thumb, prev_thumb)) ++t.held_frames;
        else run_start = i;
        prev_thumb = thumb;
      }
      deliver(k, i, sampled, frame);
      if (!sampled) continue;
      // A repeat shows the pose of the run's first frame: time the keyframe there (never at
      // or before the previous keyframe, so times stay increasing).
      if (k > 0 && run_start > t.source_index[static_cast<size_t>(k - 1)]) t.source_index[static_cast<size_t>(k)] = run_start;
      ++k;
    }
  } catch (const cv::Exception&) {
    fail(source, "not a readable video");
  }
}

// Stabilising: the camera's path (measured on every frame, or the first load's), taken out of
// the kept keyframes as they go to `raw`.
// `finish(k)` cleans keyframe k once it is stored in slot `slot(k)` of `raw`.
void remove_camera_shake(TargetFrames& t, const TargetOptions& options, const ShakeEstimator& shake,
                         std::vector<cv::Mat>& kept, const std::vector<int>& kept_index, bool denoise, cv::Size work,
                         int width, int height, const std::function<int(int)>& slot,
                         const std::function<void(int)>& finish) {
  const int K = t.keyframes;
  if (options.shake_from) {
    t.frame_shake = options.shake_from->frame_shake;
    t.shake_model = options.shake_from->shake_model;
    t.still_share = options.shake_from->still_share;
    t.shake_loop = options.shake_from->shake_loop;
  } else {
    ShakeEstimate est = shake.estimate(options.stabilise_sigma_s * t.fps);
    t.frame_shake = std::move(est.shake);
    t.shake_model = est.model;
    t.still_share = est.still_share;
    t.shake_loop = est.loop;
  }
  for (int k = 0; k < K; ++k) {
    const auto& d = t.frame_shake.at(static_cast<size_t>(kept_index[static_cast<size_t>(k)]));
    const double fit_px = std::hypot(d[0], d[1]) * width / std::max(1, t.source_width);
    t.max_shake_px = std::max(t.max_shake_px, fit_px);
    const double s = denoise ? double(work.width) / t.source_width : 1.0;  // denoised frames: working size
    const cv::Mat steady = remove_shake(kept[static_cast<size_t>(k)], {d[0] * s, d[1] * s});
    kept[static_cast<size_t>(k)].release();
    if (denoise) store_rgb(steady, slot(k), width, height, t.raw);
    else store_raw(steady, slot(k), width, height, t.raw);
    finish(k);
  }
}

}  // namespace

double smallest_part_share(const std::vector<uint8_t>& rgba8, int width, int height, double white_threshold) {
  const size_t px = static_cast<size_t>(std::max(width, 0)) * std::max(height, 0);
  if (px == 0 || rgba8.size() < px * 4) return 0;
  std::vector<float> rgba(px * 4);
  for (size_t i = 0; i < px * 4; ++i) rgba[i] = rgba8[i] / 255.0f;
  cv::Mat ink, labels, stats, centroids;
  mark_ink(rgba.data(), width, height, {1, 1, 1}, 1.0f - static_cast<float>(white_threshold), ink);
  const int n = cv::connectedComponentsWithStats(ink, labels, stats, centroids, 8, CV_32S);
  int smallest = 0;
  for (int i = 1; i < n; ++i) {
    const int a = stats.at<int>(i, cv::CC_STAT_AREA);
    if (a >= 4 && (smallest == 0 || a < smallest)) smallest = a;
  }
  return static_cast<double>(smallest) / (static_cast<double>(width) * height);
}

TargetInfo probe_target(const fs::path& source) {
  if (!classify_source(source)) return probe_video(source);
  const FolderSource folder = scan_folder(source);
  TargetInfo info;
  info.width = folder.width;
  info.height = folder.height;
  info.frames = static_cast<int>(folder.frames.size());
  info.fps = 24;
  return info;
}

TargetFrames load_target(const fs::path& source, int width, int height,
                         const TargetOptions& options) {
  check_options(source, width, height, options);
  const bool is_folder = classify_source(source);
  FolderSource folder;
  const TargetInfo info = source_info(source, is_folder, folder);
  const int K = options.frames.empty() ? options.keyframes : static_cast<int>(options.frames.size()), N = info.frames;
  check_frame_choice(source, options, K, N);
  TargetFrames t = empty_target(width, height, K, info, options);
  const size_t px = static_cast<size_t>(width) * height;

  // Sampled frames go straight to `raw`, or, when stabilising, wait for the whole clip's
  // camera path (kept at their own size, K frames at most).
  ShakeEstimator shake(kShakeMeasureWidth);
  const bool measure_shake = options.stabilise && !options.shake_from;  // every frame decoded
  std::vector<cv::Mat> kept(static_cast<size_t>(K));
  std::vector<int> kept_index(static_cast<size_t>(K), 0);
  // Denoised frames are RGB float at the working size (at most twice the target's width);
  // without denoising, kept frames are as decoded.
  const bool denoise = options.denoise_radius > 0;
  const int work_w = std::min(info.width, 2 * width);
  const cv::Size work(work_w, std::max(1, static_cast<int>(std::lround(double(info.height) * work_w / info.width))));
  // Keyframe k stored in its slot of `raw`: colour-corrected and cleaned at once (each keyframe
  // on its own, as when every keyframe was stored first), then handed to the raw_sink if any.
  auto slot = [&](int k) { return options.raw_sink ? 0 : k; };
  auto finish = [&](int k) {
    grow_cleaned(t, k + 1, bool(options.rgba_sink));
    float* raw = t.raw.data() + static_cast<size_t>(slot(k)) * px * 4;
    if (!options.palette.empty()) t.colour_corrected += correct_colours(raw, width, height, options.palette).applied;
    const int cleaned_slot = options.rgba_sink ? 0 : k;
    clean_keyframe(t, k, cleaned_slot, options, raw);
    if (options.raw_sink) options.raw_sink(k, raw);
    if (options.rgba_sink) options.rgba_sink(k, t.rgba.data());
  };
  auto keep = [&](int k, int frame_index, cv::Mat frame) {
    if (denoise && options.keep_denoised) {
      CV_Assert(frame.isContinuous() && frame.type() == CV_32FC3);  // made by resize / average_aligned
      t.denoised.push_back(deflate_floats(frame.ptr<float>(0), frame.total() * 3));
      t.denoised_frame.push_back(frame_index);
    }
    if (!options.stabilise) {
      if (denoise) store_rgb(frame, slot(k), width, height, t.raw);
      else store_raw(frame, slot(k), width, height, t.raw);
      return finish(k);
    }
    kept[static_cast<size_t>(k)] = std::move(frame);
    kept_index[static_cast<size_t>(k)] = frame_index;
  };
  // Denoising, the sampled frames wait in the denoiser until their later neighbours are decoded
  // and come back in order, the j-th one keyframe j.
  TemporalDenoiser denoiser(options.denoise_radius, t.source_index);
  int denoised_k = 0;
  auto near_sample = [&](int i) { return denoise && denoiser.needs(i); };
  // A decoded frame: kept when sampled; when denoising, the denoiser takes it if a sampled frame
  // needs it (and hands back the sampled frames it completes).
  auto deliver = [&](int k, int i, bool sampled, const cv::Mat& frame) {
    if (!denoise) {
      if (sampled) keep(k, i, options.stabilise ? frame.clone() : frame);
      return;
    }
    if (!denoiser.needs(i)) return;
    for (auto& [index, avg] : denoiser.push(i, resize_to(to_rgb_float(frame), work.width, work.height)))
      keep(denoised_k++, index, std::move(avg));
  };
  // The refinement's second load reuses the first load's denoised keyframes when they were
  // made at the same working size: no decoding, no aligning (the camera path comes from
  // shake_from, as the keyframes' retimed indices come from the first load).
  TargetFrames* from = options.denoised_from;
  const size_t work_floats = static_cast<size_t>(work.width) * work.height * 3;
  auto whole = [&](const std::vector<uint8_t>& d) { return !d.empty(); };  // none taken yet
  const bool reuse = denoise && from && static_cast<int>(from->denoised.size()) == K &&
                     std::all_of(from->denoised.begin(), from->denoised.end(), whole) && from->denoised_width == work.width &&
                     from->denoised_height == work.height && from->keyframes == K && from->source_frames == N &&
                     (options.frames.empty() || options.frames == from->denoised_frame) &&
                     !measure_shake;
  if (denoise && options.keep_denoised) {
    t.denoised_width = work.width;
    t.denoised_height = work.height;
  }
  if (reuse) {
    t.source_index = from->source_index;
    t.held_frames = from->held_frames;
    for (int k = 0; k < K; ++k) {
      std::vector<uint8_t>& d = from->denoised[static_cast<size_t>(k)];
      cv::Mat frame(work.height, work.width, CV_32FC3);
      inflate_floats(d, frame.ptr<float>(0), work_floats);  // the same bits (throws if not this size)
      keep(denoised_k++, from->denoised_frame[static_cast<size_t>(k)], std::move(frame));
      std::vector<uint8_t>().swap(d);  // taken, from the heap, returned now
      trim_heap();
    }
    from->denoised.clear();
    from->denoised_frame.clear();
  } else if (is_folder) {
    decode_folder(folder, N, K, t.source_index, measure_shake, near_sample, shake, deliver);
  } else {
    decode_video(source, options, N, K, t, measure_shake, near_sample, shake, deliver);
  }
  if (denoise && !reuse) {
    for (auto& [index, avg] : denoiser.finish()) keep(denoised_k++, index, std::move(avg));
    t.denoise_seconds = denoiser.seconds();
    if (denoised_k != K) throw Error("internal: " + std::to_string(denoised_k) + " of " + std::to_string(K) + " keyframes denoised");
  }
  if (options.stabilise) remove_camera_shake(t, options, shake, kept, kept_index, denoise, work, width, height, slot, finish);
  if (options.raw_sink) std::vector<float>().swap(t.raw);
  grow_cleaned(t, K, bool(options.rgba_sink));
  if (options.rgba_sink) std::vector<float>().swap(t.rgba);
  return t;
}

void for_each_target_frame(const fs::path& source, int width, int height,
                           const std::function<void(int index, const float* rgba)>& visit) {
  TargetOptions options;
  options.denoise_radius = 0;
  options.retime_held_frames = false;  // every frame at its own index
  check_options(source, width, height, options);
  const bool is_folder = classify_source(source);
  FolderSource folder;
  const TargetInfo info = source_info(source, is_folder, folder);
  const int N = info.frames;
  // Every frame is "sampled": decode_* hand each one over in order, and `raw` holds one frame.
  TargetFrames t;
  t.source_index.resize(static_cast<size_t>(N));
  for (int i = 0; i < N; ++i) t.source_index[static_cast<size_t>(i)] = i;
  std::vector<float> raw(static_cast<size_t>(width) * height * 4);
  auto deliver = [&](int, int i, bool sampled, const cv::Mat& frame) {
    if (!sampled) return;
    store_raw(frame, 0, width, height, raw);
    visit(i, raw.data());
  };
  ShakeEstimator shake(kShakeMeasureWidth);  // not fed: nothing is stabilised
  auto near_sample = [](int) { return false; };
  if (is_folder) decode_folder(folder, N, N, t.source_index, false, near_sample, shake, deliver);
  else decode_video(source, options, N, N, t, false, near_sample, shake, deliver);
}

}  // namespace svgm
