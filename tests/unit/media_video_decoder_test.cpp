// Reading videos and PNG frames without OpenCV's videoio/imgcodecs (media/video_decoder.h,
// image/png_frame.h).
//
// Clips are written by our own encoder (media/video_encoder.h: BT.709-tagged H.264), so the
// colour facts are the round trip's: a decoder that converted with BT.601's matrix, as OpenCV's
// does whatever the stream says, brings saturated colours back up to 18 levels off (measured on
// this clip: red 220,40,30 came back 204,22,31 through OpenCV's VideoCapture, 220,41,29 here). PNG frames are written with OpenCV's imgcodecs, which the
// test binary still links, and must read back bit for bit, 16-bit ones included.
#include <doctest/doctest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/png_frame.h"
#include "media/video_decoder.h"
#include "media/video_encoder.h"
#include "svgmotion/error.h"

#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

struct Rgb {
  int r, g, b;
};

// 64x48 white with three saturated 16x24 squares (red, green, blue) at x = 4, 24, 44.
RgbaImage squares() {
  RgbaImage img{64, 48, std::vector<uint8_t>(64 * 48 * 4, 255)};
  const Rgb colours[3] = {{220, 40, 30}, {30, 200, 60}, {40, 50, 210}};
  for (int s = 0; s < 3; ++s)
    for (int y = 12; y < 36; ++y)
      for (int x = 4 + 20 * s; x < 20 + 20 * s; ++x) {
        uint8_t* p = &img.rgba[(static_cast<size_t>(y) * 64 + x) * 4];
        p[0] = static_cast<uint8_t>(colours[s].r);
        p[1] = static_cast<uint8_t>(colours[s].g);
        p[2] = static_cast<uint8_t>(colours[s].b);
      }
  return img;
}

}  // namespace

TEST_SUITE("image") {

TEST_CASE("video decoder: our BT.709 clip reads back in its own colours, size, rate and length") {
  test::TempDir dir("svgm_decoder_test");
  const fs::path clip = dir.path / "c.mp4";
  const RgbaImage img = squares();
  write_video(clip, 7, 12.0, [&](int) { return img; }, VideoOptions{});
  VideoDecoder d(clip);
  CHECK(d.width() == 64);
  CHECK(d.height() == 48);
  CHECK(d.fps() == doctest::Approx(12.0));
  int frames = 0;
  cv::Mat bgr;
  while (d.read(bgr)) {
    REQUIRE(bgr.type() == CV_8UC3);
    REQUIRE(bgr.cols == 64);
    REQUIRE(bgr.rows == 48);
    // Inside each square (away from the 4:2:0 chroma edge): within 3 levels per channel.
    const Rgb want[3] = {{220, 40, 30}, {30, 200, 60}, {40, 50, 210}};
    for (int s = 0; s < 3; ++s) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(24, 12 + 20 * s);
      CHECK(std::abs(p[2] - want[s].r) <= 3);
      CHECK(std::abs(p[1] - want[s].g) <= 3);
      CHECK(std::abs(p[0] - want[s].b) <= 3);
    }
    // White paper: x264 keeps its Y' at 234-235 of the limited range's 235, so 253-255 (a
    // decoder that ignored the range would give 234).
    for (int c = 0; c < 3; ++c) CHECK(bgr.at<cv::Vec3b>(2, 2)[c] >= 253);
    ++frames;
  }
  CHECK(frames == 7);
  CHECK_FALSE(d.grab());  // stays at the end
}

TEST_CASE("video decoder: what is not a video is refused with one line naming the file") {
  test::TempDir dir("svgm_decoder_test");
  const fs::path text = dir.path / "a.mp4";
  std::ofstream(text) << "not a video at all\n";
  CHECK_THROWS_WITH_AS(VideoDecoder{text}, (text.string() + ": not a readable video").c_str(), Error);
  const fs::path svg = dir.path / "b.mp4";
  std::ofstream(svg) << "<svg xmlns='http://www.w3.org/2000/svg'/>";
  CHECK_THROWS_WITH_AS(VideoDecoder{svg}, (svg.string() + ": not a readable video (it holds an SVG document)").c_str(),
                       Error);
  const fs::path missing = dir.path / "none.mp4";
  CHECK_THROWS_WITH_AS(VideoDecoder{missing}, (missing.string() + ": not a readable video").c_str(), Error);
  CHECK_THROWS_WITH_AS(VideoDecoder{dir.path}, (dir.path.string() + ": not a readable video").c_str(), Error);
}

TEST_CASE("video decoder: a clip the container says to turn a quarter is read upright") {
  // FFmpeg's command line writes the display matrix; without it (it is a test-only tool that
  // .ci/setup.sh installs) there is nothing to read.
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) {
    MESSAGE("ffmpeg not installed: rotation not checked");
    return;
  }
  test::TempDir dir("svgm_decoder_test");
  const fs::path flat = dir.path / "flat.mp4", turned = dir.path / "turned.mp4";
  // 64x48 with a red square at the left, so a turn either way or none shows.
  RgbaImage img{64, 48, std::vector<uint8_t>(64 * 48 * 4, 255)};
  for (int y = 16; y < 32; ++y)
    for (int x = 4; x < 20; ++x) {
      uint8_t* p = &img.rgba[(static_cast<size_t>(y) * 64 + x) * 4];
      p[1] = p[2] = 0;
    }
  write_video(flat, 2, 12.0, [&](int) { return img; }, VideoOptions{});
  // mp4's "rotate" tag is the clockwise angle a player turns the picture by.
  const std::string cmd = "ffmpeg -v error -y -i '" + flat.string() + "' -c copy -metadata:s:v:0 rotate=90 '" +
                          turned.string() + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  // What a player shows: FFmpeg's own decoder turns the picture as the container says.
  const fs::path shown = dir.path / "shown.png";
  REQUIRE(std::system(("ffmpeg -v error -y -i '" + turned.string() + "' -frames:v 1 '" + shown.string() + "'").c_str()) == 0);
  const cv::Mat player = read_png_frame(shown);
  REQUIRE(player.cols == 48);
  REQUIRE(player.rows == 64);
  VideoDecoder d(turned);
  CHECK(d.width() == 48);
  CHECK(d.height() == 64);
  cv::Mat bgr;
  REQUIRE(d.read(bgr));
  REQUIRE(bgr.cols == 48);
  REQUIRE(bgr.rows == 64);
  // The red square lands where the player puts it (red: green below half), pixel for pixel.
  int red = 0, disagree = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 48; ++x) {
      const bool ours = bgr.at<cv::Vec3b>(y, x)[1] < 128;
      red += ours;
      disagree += ours != (player.at<cv::Vec3b>(y, x)[1] < 128);
    }
  CHECK(red == 16 * 16);
  CHECK(disagree == 0);
}

TEST_CASE("PNG frames read bit for bit: 8-bit BGR/BGRA/grey and 16-bit grey and colour") {
  test::TempDir dir("svgm_decoder_test");
  cv::RNG rng(7);
  const int types[] = {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4};
  for (int type : types) {
    cv::Mat m(9, 13, type);
    rng.fill(m, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
    const fs::path f = dir.path / ("t" + std::to_string(type) + ".png");
    REQUIRE(cv::imwrite(f.string(), m));
    const cv::Mat back = read_png_frame(f);
    CAPTURE(type);
    REQUIRE(back.type() == type);
    REQUIRE(back.size() == m.size());
    CHECK(cv::norm(back, m, cv::NORM_INF) == 0.0);
  }
  const fs::path junk = dir.path / "junk.png";
  std::ofstream(junk) << "\x89PNG\r\n\x1a\n but then nothing";
  CHECK(read_png_frame(junk).empty());
  CHECK(read_png_frame(dir.path / "absent.png").empty());
}

}  // TEST_SUITE
