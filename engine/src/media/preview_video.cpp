// Writing preview videos through OpenCV's VideoWriter (FFmpeg back end): panels composited over
// white, concatenated side by side, padded to even sizes, written atomically.
#include "media/preview_video.h"

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <opencv2/videoio/registry.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "svgmotion/atomic_file.h"
#include "svgmotion/temporary_name.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& where, const std::string& problem) {
  throw Error(where.string() + ": " + problem);
}

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// Removes the temporary file unless the write got as far as renaming it.
struct TempFile {
  fs::path path;
  bool keep = false;
  ~TempFile() {
    if (keep) return;
    std::error_code ec;
    fs::remove(path, ec);
  }
};

// Bytes a write probe writes (64 KiB: more than a filesystem's last free block or two, so a
// nearly full disk fails it as it failed the encoder).
constexpr size_t kProbeBytes = size_t{64} << 10;

// Why a file cannot be written in `dir` ("No space left on device", "File too large"), or ""
// when a probe file of kProbeBytes is written, synced and removed there without error. OpenCV's
// VideoWriter reports no errno: a writer that cannot open, or output that is empty or not a
// readable video, may come from a full disk as well as from a missing encoder, and only a write
// of our own tells them apart.
std::string write_problem(const fs::path& dir) {
  const fs::path probe = dir / (".svgm-write-probe." + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return std::strerror(errno);
  const std::string block(kProbeBytes, '\0');
  int err = 0;
  size_t done = 0;
  while (done < block.size() && !err) {
    const ssize_t n = ::write(fd, block.data() + done, block.size() - done);
    if (n < 0 && errno != EINTR) err = errno;
    if (n > 0) done += static_cast<size_t>(n);
  }
  if (!err && ::fsync(fd) != 0 && errno != EINVAL) err = errno;  // NFS and the like report here
  if (::close(fd) != 0 && !err) err = errno;
  ::unlink(probe.c_str());
  return err ? std::strerror(err) : "";
}

// Whether `path` opens as a video with at least one frame (an mp4 cut short by a failed write
// has no index, "moov atom not found", and does not open).
bool readable_video(const fs::path& path, int api) {
  try {
    cv::VideoCapture cap(path.string(), api);
    return cap.isOpened() && cap.get(cv::CAP_PROP_FRAME_COUNT) >= 1;
  } catch (const cv::Exception&) {
    return false;
  }
}

// Composites an RGBA panel over white into the BGR frame at column x0.
void blit(const RgbaImage& img, cv::Mat& frame, int x0) {
  for (int y = 0; y < img.height; ++y) {
    const uint8_t* s = img.rgba.data() + static_cast<size_t>(y) * img.width * 4;
    cv::Vec3b* d = frame.ptr<cv::Vec3b>(y) + x0;
    for (int x = 0; x < img.width; ++x, s += 4) {
      const int a = s[3];
      for (int c = 0; c < 3; ++c) {
        // Rounded s*a/255 + (255 - a), exact for a = 0 and a = 255.
        const int v = (s[c] * a + 255 * (255 - a) + 127) / 255;
        d[x][2 - c] = static_cast<uint8_t>(v);  // RGB -> OpenCV's BGR
      }
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

  // Declared before the writer, so that on an exception the writer closes before the file goes.
  TempFile tmp;
  std::vector<std::pair<int, int>> sizes;  // panel sizes of frame 0, which every frame repeats
  cv::VideoWriter writer;
  cv::Mat canvas;
  // The rename must not replace a device or FIFO; a symlink is written through (atomic_file.h).
  const fs::path target = output_target(file);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // The extension picks FFmpeg's container, so the temporary name keeps ".mp4" (or ".webm").
  std::string ext = target.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool webm = ext == ".webm";
  tmp.path = temporary_path(dir / target.filename(), webm ? ".webm" : ".mp4");
  const auto api = cv::videoio_registry::hasBackend(cv::CAP_FFMPEG) ? cv::CAP_FFMPEG : cv::CAP_ANY;

  for (int k = 0; k < frames; ++k) {
    std::vector<RgbaImage> row;
    row.reserve(static_cast<size_t>(panels));
    for (int p = 0; p < panels; ++p) {
      row.push_back(panel_image(k, p));
      const RgbaImage& img = row.back();
      if (img.width < 1 || img.height < 1 ||
          img.rgba.size() != static_cast<size_t>(img.width) * img.height * 4)
        fail(file, "panel " + std::to_string(p) + " of frame " + std::to_string(k) +
                       " is empty or does not match its size");
      if (k == 0) {
        if (p > 0 && img.height != sizes[0].second)
          fail(file, "panel " + std::to_string(p) + " is " + std::to_string(img.height) +
                         " pixels high, but panel 0 is " + std::to_string(sizes[0].second));
        sizes.emplace_back(img.width, img.height);
      } else if (img.width != sizes[static_cast<size_t>(p)].first ||
                 img.height != sizes[static_cast<size_t>(p)].second) {
        fail(file, "panel " + std::to_string(p) + " of frame " + std::to_string(k) + " is " +
                       size_text(img.width, img.height) + ", but in frame 0 it is " +
                       size_text(sizes[static_cast<size_t>(p)].first,
                                 sizes[static_cast<size_t>(p)].second));
      }
    }

    if (k == 0) {
      int width = 0;
      for (const auto& s : sizes) width += s.first;
      const int height = sizes[0].second;
      // H.264 in 4:2:0 needs even sides; FFmpeg would silently crop the last column/row.
      const cv::Size size(width + width % 2, height + height % 2);
      // WebM holds VP9 or VP8; mp4 H.264, else MPEG-4 Part 2.
      const std::array<const char*, 2> codecs = webm ? std::array<const char*, 2>{"VP90", "VP80"}
                                                     : std::array<const char*, 2>{"avc1", "mp4v"};
      for (const char* cc : codecs) {
        try {
          writer.open(tmp.path.string(), api, cv::VideoWriter::fourcc(cc[0], cc[1], cc[2], cc[3]),
                      fps, size);
        } catch (const cv::Exception&) {
          writer.release();
        }
        if (writer.isOpened()) break;
      }
      if (!writer.isOpened()) {
        std::error_code ec;
        if (!fs::is_directory(dir, ec))
          fail(file, "cannot write: " + std::generic_category().message(ENOENT));
        if (const std::string why = write_problem(dir); !why.empty()) fail(file, "cannot write: " + why);
        fail(file, webm ? "cannot write: no VP9 or VP8 video encoder could be opened"
                        : "cannot write: no H.264 (avc1) or MPEG-4 (mp4v) video encoder could be opened");
      }
      canvas.create(size, CV_8UC3);
    }

    canvas.setTo(cv::Scalar::all(255));
    int x0 = 0;
    for (const RgbaImage& img : row) {
      blit(img, canvas, x0);
      x0 += img.width;
    }
    try {
      writer.write(canvas);
    } catch (const cv::Exception& e) {
      fail(file, std::string("cannot write: ") + e.what());
    }
  }
  writer.release();

  // VideoWriter::write and release report nothing: an empty file, or one that does not read
  // back as a video (a full disk cuts an mp4 short of its index), is the visible sign.
  std::error_code ec;
  const auto bytes = fs::file_size(tmp.path, ec);
  if (ec || bytes == 0 || !readable_video(tmp.path, api)) {
    if (const std::string why = write_problem(dir); !why.empty()) fail(file, "cannot write: " + why);
    fail(file, bytes == 0 ? "cannot write: the encoder produced no output"
                          : "cannot write: the encoder's output does not read back as a video");
  }
  fs::rename(tmp.path, target, ec);
  if (ec) fail(file, "cannot write: " + ec.message());
  tmp.keep = true;
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
