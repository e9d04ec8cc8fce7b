// Reading a video through libavformat/libavcodec/libswscale (see video_decoder.h). The steps:
// refuse images FFmpeg would read as one-frame clips, open the container and its best video
// stream, read the container's rotation; per frame: feed packets until the decoder gives a frame
// (skipping damaged packets, flushing at the end), then convert it to 8-bit BGR with the
// stream's own matrix and range and rotate it upright.
#include "media/video_decoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/display.h>
#include <libavutil/log.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <opencv2/core.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// What `file` holds when it is an image rather than a video ("" otherwise): FFmpeg reads an SVG,
// PNG or JPEG as a one-frame clip, so such a file named .mp4 would be fitted as a still.
std::string image_content(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[512] = {0};
  in.read(head, sizeof head);
  const size_t n = static_cast<size_t>(in.gcount());
  const std::string_view h(head, n);
  if (h.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) return "a PNG image";
  if (h.substr(0, 3) == "\xff\xd8\xff") return "a JPEG image";
  // Markup: an optional UTF-8 byte-order mark and white space, then "<" (XML, SVG, HTML).
  size_t i = h.substr(0, 3) == "\xef\xbb\xbf" ? 3 : 0;
  while (i < n && std::strchr(" \t\r\n", h[i]) && h[i] != '\0') ++i;
  if (i < n && h[i] == '<') return h.find("<svg") != std::string_view::npos ? "an SVG document" : "an XML or HTML document";
  return "";
}

// The JPEG-range ("yuvj") formats are deprecated spellings of their plain twins at full range.
AVPixelFormat plain_format(AVPixelFormat f, bool& full_range) {
  switch (f) {
    case AV_PIX_FMT_YUVJ420P: full_range = true; return AV_PIX_FMT_YUV420P;
    case AV_PIX_FMT_YUVJ422P: full_range = true; return AV_PIX_FMT_YUV422P;
    case AV_PIX_FMT_YUVJ444P: full_range = true; return AV_PIX_FMT_YUV444P;
    case AV_PIX_FMT_YUVJ440P: full_range = true; return AV_PIX_FMT_YUV440P;
    case AV_PIX_FMT_YUVJ411P: full_range = true; return AV_PIX_FMT_YUV411P;
    default: return f;
  }
}

// A damaged stream that never yields another frame must end the read, not spin: this many
// consecutive failures in a row end it (a few bad packets between good ones are skipped).
constexpr int kMaxConsecutiveErrors = 64;

}  // namespace

struct VideoDecoder::Impl {
  fs::path file;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVPacket* packet = nullptr;
  AVFrame* frame = nullptr;
  SwsContext* sws = nullptr;
  int stream = -1;
  int quarter_turns = 0;  // clockwise quarter turns that make a frame upright (0..3)
  bool flushed = false;   // the end of the file was sent to the decoder
  bool have_frame = false;
  // The conversion the context was set up for (set again when a frame differs).
  int sws_format = -1, sws_w = 0, sws_h = 0, sws_space = -1, sws_full = -1;

  ~Impl() {
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }

  [[noreturn]] void unreadable() const { throw Error(file.string() + ": not a readable video"); }
};

VideoDecoder::VideoDecoder(const fs::path& file) : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.file = file;
  if (const std::string what = image_content(file); !what.empty())
    throw Error(file.string() + ": not a readable video (it holds " + what + ")");
  if (av_log_get_level() > AV_LOG_FATAL) av_log_set_level(AV_LOG_FATAL);  // our own line says what failed
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) d.unreadable();
  if (avformat_open_input(&d.format, file.c_str(), nullptr, nullptr) < 0) d.unreadable();
  if (avformat_find_stream_info(d.format, nullptr) < 0) d.unreadable();
  const AVCodec* decoder = nullptr;
  d.stream = av_find_best_stream(d.format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (d.stream < 0 || !decoder) d.unreadable();
  AVStream* st = d.format->streams[d.stream];
  d.codec = avcodec_alloc_context3(decoder);
  d.packet = av_packet_alloc();
  d.frame = av_frame_alloc();
  if (!d.codec || !d.packet || !d.frame) throw Error(file.string() + ": out of memory");
  if (avcodec_parameters_to_context(d.codec, st->codecpar) < 0) d.unreadable();
  d.codec->thread_count = 0;  // as many as the machine has; H.264/VP9 decode the same bits either way
  if (avcodec_open2(d.codec, decoder, nullptr) < 0) d.unreadable();
  // The display matrix gives the counter-clockwise angle a player turns the picture by.
  if (const uint8_t* m = av_stream_get_side_data(st, AV_PKT_DATA_DISPLAYMATRIX, nullptr)) {
    const double ccw = av_display_rotation_get(reinterpret_cast<const int32_t*>(m));
    if (std::isfinite(ccw)) d.quarter_turns = ((static_cast<int>(std::lround(-ccw / 90.0)) % 4) + 4) % 4;
  }
}

VideoDecoder::~VideoDecoder() = default;

int VideoDecoder::width() const {
  const AVCodecParameters* p = impl_->format->streams[impl_->stream]->codecpar;
  return impl_->quarter_turns % 2 ? p->height : p->width;
}

int VideoDecoder::height() const {
  const AVCodecParameters* p = impl_->format->streams[impl_->stream]->codecpar;
  return impl_->quarter_turns % 2 ? p->width : p->height;
}

double VideoDecoder::fps() const {
  const AVStream* st = impl_->format->streams[impl_->stream];
  for (const AVRational r : {st->avg_frame_rate, st->r_frame_rate})
    if (r.num > 0 && r.den > 0) return av_q2d(r);
  return 0.0;
}

bool VideoDecoder::grab() {
  Impl& d = *impl_;
  d.have_frame = false;
  for (int errors = 0; errors < kMaxConsecutiveErrors;) {
    const int got = avcodec_receive_frame(d.codec, d.frame);
    if (got == 0) {
      d.have_frame = true;
      return true;
    }
    if (got == AVERROR_EOF) return false;
    if (got != AVERROR(EAGAIN)) {  // a frame that did not decode: skip it
      ++errors;
      continue;
    }
    if (d.flushed) return false;
    const int read = av_read_frame(d.format, d.packet);
    if (read < 0) {  // the end (or a read error): let the decoder give what it holds
      d.flushed = true;
      if (avcodec_send_packet(d.codec, nullptr) < 0) return false;
      continue;
    }
    const bool ours = d.packet->stream_index == d.stream;
    const int sent = ours ? avcodec_send_packet(d.codec, d.packet) : 0;
    av_packet_unref(d.packet);
    if (sent < 0 && sent != AVERROR(EAGAIN)) ++errors;  // a damaged packet
  }
  return false;
}

bool VideoDecoder::retrieve(cv::Mat& bgr) {
  Impl& d = *impl_;
  if (!d.have_frame) return false;
  const AVFrame* f = d.frame;
  bool full = f->color_range == AVCOL_RANGE_JPEG;
  const AVPixelFormat format = plain_format(static_cast<AVPixelFormat>(f->format), full);
  const int space = f->colorspace;
  if (!d.sws || format != d.sws_format || f->width != d.sws_w || f->height != d.sws_h || space != d.sws_space ||
      static_cast<int>(full) != d.sws_full) {
    // Chroma interpolated to every pixel and rounded exactly: the inverse of how
    // media/video_encoder.cpp subsamples it.
    d.sws = sws_getCachedContext(d.sws, f->width, f->height, format, f->width, f->height, AV_PIX_FMT_BGR24,
                                 SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
    if (!d.sws) return false;
    const AVPixFmtDescriptor* desc = av_pix_fmt_desc_get(format);
    if (desc && !(desc->flags & AV_PIX_FMT_FLAG_RGB) && desc->nb_components >= 3) {
      // sws_getCoefficients takes the stream's AVColorSpace code (its SWS_CS_* values are the
      // same numbers) and falls back to BT.601 for "unspecified" and anything it does not know.
      sws_setColorspaceDetails(d.sws, sws_getCoefficients(space), full ? 1 : 0, sws_getCoefficients(SWS_CS_DEFAULT), 1,
                               0, 1 << 16, 1 << 16);
    }
    d.sws_format = format;
    d.sws_w = f->width;
    d.sws_h = f->height;
    d.sws_space = space;
    d.sws_full = full ? 1 : 0;
  }
  cv::Mat upright(f->height, f->width, CV_8UC3);
  uint8_t* dst[1] = {upright.data};
  const int stride[1] = {static_cast<int>(upright.step)};
  if (sws_scale(d.sws, f->data, f->linesize, 0, f->height, dst, stride) != f->height) return false;
  switch (d.quarter_turns) {
    case 1: cv::rotate(upright, bgr, cv::ROTATE_90_CLOCKWISE); break;
    case 2: cv::rotate(upright, bgr, cv::ROTATE_180); break;
    case 3: cv::rotate(upright, bgr, cv::ROTATE_90_COUNTERCLOCKWISE); break;
    default: bgr = upright;
  }
  return true;
}

}  // namespace svgm
