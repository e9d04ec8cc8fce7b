// mp4 (H.264) and WebM (VP9, with or without alpha) through libavcodec/libavformat (see
// video_encoder.h). The steps: open the container on a temporary name, open the encoder with
// its colour tags and quality, then per frame composite/pad into RGBA, convert with swscale's
// BT.709 coefficients, encode and interleave; flush, write the trailer (the mp4 muxer moves its
// index to the front here, "faststart"), rename.
#include "media/video_encoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/temporary_name.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

std::string av_text(int err) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(err, buf, sizeof buf);
  return buf;
}

// Everything FFmpeg allocates for one file, freed in reverse order; the temporary file goes
// unless the write got as far as renaming it.
struct Encoder {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  fs::path tmp;
  bool keep = false;
  ~Encoder() {
    av_packet_free(&packet);
    av_frame_free(&frame);
    sws_freeContext(sws);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    if (!keep && !tmp.empty()) {
      std::error_code ec;
      fs::remove(tmp, ec);
    }
  }
};

}  // namespace

void write_video(const fs::path& file, int frames, double fps, const std::function<RgbaImage(int)>& frame_at,
                 const VideoOptions& options) {
  auto fail = [&](const std::string& problem, int av_error = 0) {
    throw Error(file.string() + ": " + problem + (av_error ? ": " + av_text(av_error) : ""));
  };
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool webp = ext == ".webp";  // animated WebP: lossless RGBA, as cheap as a GIF to play
  const bool webm = ext == ".webm";
  const int max_crf = webm ? kMaxVp9Crf : kMaxH264Crf;
  const int crf = options.quality < 0 ? (webm ? kDefaultVp9Crf : kDefaultH264Crf) : options.quality;
  if (crf > max_crf)
    fail("quality " + std::to_string(crf) + " is out of range (" + (webm ? "VP9" : "H.264") + " CRF 0.." +
         std::to_string(max_crf) + ", lower is better)");
  if (options.transparent && !webm && !webp) fail("only a WebM or WebP clip keeps transparency (mp4's H.264 has no alpha)");
  if (webp && options.quality >= 0) fail("an animated WebP is lossless; quality is for mp4 and webm");
  if (frames < 1) fail("a video needs at least one frame");
  if (!(std::isfinite(fps) && fps > 0)) fail("frame rate must be positive");
  if (av_log_get_level() > AV_LOG_ERROR) av_log_set_level(AV_LOG_ERROR);  // x264 and libvpx chat on stderr

  const fs::path target = output_target(file);  // refuse a device or folder before rendering
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  Encoder e;
  e.tmp = temporary_path(dir / target.filename(), webp ? ".webp" : webm ? ".webm" : ".mp4");

  RgbaImage first = frame_at(0);
  const int w = first.width, h = first.height;
  if (w < 1 || h < 1 || first.rgba.size() != static_cast<size_t>(w) * h * 4) fail("the first frame is empty");
  const int cw = webp ? w : w + w % 2, ch = webp ? h : h + h % 2;  // 4:2:0 wants even sides

  const char* codec_name = webp ? "libwebp_anim" : webm ? "libvpx-vp9" : "libx264";
  const AVCodec* codec = avcodec_find_encoder_by_name(codec_name);
  if (!codec) fail(std::string("cannot write: FFmpeg has no ") + codec_name + " encoder");
  if (const int r = avformat_alloc_output_context2(&e.format, nullptr, webp ? "webp" : webm ? "webm" : "mp4", e.tmp.c_str()); r < 0)
    fail("cannot write", r);
  AVStream* stream = avformat_new_stream(e.format, nullptr);
  e.codec = avcodec_alloc_context3(codec);
  if (!stream || !e.codec) fail("cannot write: out of memory");

  const AVRational rate = av_d2q(fps, 100000);
  AVCodecContext* c = e.codec;
  c->width = cw;
  c->height = ch;
  c->pix_fmt = webp ? AV_PIX_FMT_BGRA : options.transparent ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P;
  c->time_base = av_inv_q(rate);
  c->framerate = rate;
  c->sample_aspect_ratio = {1, 1};
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  c->gop_size = std::max(1, static_cast<int>(std::lround(2 * fps)));  // a keyframe every 2 s: seeking stays quick
  if (e.format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* opts = nullptr;
  if (webp) {
    av_dict_set(&opts, "lossless", "1", 0);  // flat vector art: exact colours, small frames
  } else if (webm) {
    av_dict_set_int(&opts, "crf", crf, 0);
    av_dict_set(&opts, "b", "0", 0);  // constant quality: no bitrate cap beside the CRF
    av_dict_set(&opts, "row-mt", "1", 0);
    av_dict_set(&opts, "cpu-used", "4", 0);  // libvpx's speed/quality step for a few-second clip on 2 cores
  } else {
    av_dict_set_int(&opts, "crf", crf, 0);
    av_dict_set(&opts, "preset", "medium", 0);
  }
  const int opened = avcodec_open2(c, codec, &opts);
  av_dict_free(&opts);
  if (opened < 0) fail(std::string("cannot open the ") + codec_name + " encoder", opened);
  if (const int r = avcodec_parameters_from_context(stream->codecpar, c); r < 0) fail("cannot write", r);
  stream->time_base = c->time_base;
  stream->avg_frame_rate = rate;

  if (const int r = avio_open(&e.format->pb, e.tmp.c_str(), AVIO_FLAG_WRITE); r < 0) fail("cannot write", r);
  AVDictionary* mux = nullptr;
  if (!webm && !webp) av_dict_set(&mux, "movflags", "+faststart", 0);  // the index before the data
  if (webp) av_dict_set(&mux, "loop", options.loop ? "0" : "1", 0);  // 0: forever
  const int header = avformat_write_header(e.format, &mux);
  av_dict_free(&mux);
  if (header < 0) fail("cannot write", header);

  // RGBA -> Y'CbCr with BT.709's matrix, full-range RGB in, limited range out (white is Y'=235).
  e.sws = sws_getContext(cw, ch, AV_PIX_FMT_RGBA, cw, ch, c->pix_fmt,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
  if (!e.sws) fail("cannot convert colours");
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(e.sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  e.frame = av_frame_alloc();
  e.packet = av_packet_alloc();
  if (!e.frame || !e.packet) fail("cannot write: out of memory");
  e.frame->format = c->pix_fmt;
  e.frame->width = cw;
  e.frame->height = ch;
  if (const int r = av_frame_get_buffer(e.frame, 0); r < 0) fail("cannot write: out of memory", r);

  auto drain = [&]() {
    for (;;) {
      const int r = avcodec_receive_packet(c, e.packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      if (r < 0) fail("cannot encode", r);
      av_packet_rescale_ts(e.packet, c->time_base, stream->time_base);
      e.packet->stream_index = stream->index;
      if (const int wr = av_interleaved_write_frame(e.format, e.packet); wr < 0) fail("cannot write", wr);
    }
  };

  std::vector<uint8_t> rgba(static_cast<size_t>(cw) * ch * 4);
  for (int i = 0; i < frames; ++i) {
    const RgbaImage img = i == 0 ? std::move(first) : frame_at(i);
    if (img.width != w || img.height != h || img.rgba.size() != static_cast<size_t>(w) * h * 4)
      fail("frame " + std::to_string(i) + " does not match the first frame's size");
    // Padding: white, or transparent when alpha is kept.
    std::fill(rgba.begin(), rgba.end(), options.transparent ? 0 : 255);
    for (int y = 0; y < h; ++y) {
      const uint8_t* s = img.rgba.data() + static_cast<size_t>(y) * w * 4;
      uint8_t* d = rgba.data() + static_cast<size_t>(y) * cw * 4;
      for (int x = 0; x < w; ++x, s += 4, d += 4) {
        const int a = s[3];
        if (options.transparent) {
          std::copy(s, s + 4, d);
          continue;
        }
        // Rounded s*a/255 + (255 - a): over white, exact for a = 0 and a = 255.
        for (int k = 0; k < 3; ++k) d[k] = static_cast<uint8_t>((s[k] * a + 255 * (255 - a) + 127) / 255);
        d[3] = 255;
      }
    }
    if (const int r = av_frame_make_writable(e.frame); r < 0) fail("cannot write: out of memory", r);
    const uint8_t* src[1] = {rgba.data()};
    const int stride[1] = {cw * 4};
    sws_scale(e.sws, src, stride, 0, ch, e.frame->data, e.frame->linesize);
    e.frame->pts = i;
    e.frame->color_primaries = c->color_primaries;
    e.frame->color_trc = c->color_trc;
    e.frame->colorspace = c->colorspace;
    e.frame->color_range = c->color_range;
    if (const int r = avcodec_send_frame(c, e.frame); r < 0) fail("cannot encode", r);
    drain();
  }
  if (const int r = avcodec_send_frame(c, nullptr); r < 0) fail("cannot encode", r);
  drain();
  if (const int r = av_write_trailer(e.format); r < 0) fail("cannot write", r);
  if (const int r = avio_closep(&e.format->pb); r < 0) fail("cannot write", r);
  std::error_code ec;
  fs::rename(e.tmp, target, ec);
  if (ec) fail("cannot write: " + ec.message());
  e.keep = true;
}

}  // namespace svgm
