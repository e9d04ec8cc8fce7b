// The silhouette skeleton (motion/skeleton.h) on masks drawn here: a plus sign is one junction
// with four ends at the arms' tips, a rectangle is its mid line with the corner spurs pruned,
// 1-px bumps on an outline leave no spur, a ring is one loop, and bad input is refused.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "motion/skeleton.h"

using namespace svgm;
using namespace svgm::motion;

namespace {

int count_nodes(const Skeleton& s, bool junction) {
  int n = 0;
  for (const auto& node : s.nodes) n += junction ? node.junction() : node.end();
  return n;
}

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Skeleton pixels with exactly one 8-neighbour.
int end_pixels(const cv::Mat& sk) {
  int n = 0;
  for (int y = 1; y < sk.rows - 1; ++y)
    for (int x = 1; x < sk.cols - 1; ++x) {
      if (!sk.at<uchar>(y, x)) continue;
      int k = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) k += (dx || dy) && sk.at<uchar>(y + dy, x + dx);
      n += k == 1;
    }
  return n;
}

}  // namespace

TEST_SUITE("motion") {
  TEST_CASE("a plus sign is one junction and four ends at the arms' tips") {
    cv::Mat m(128, 128, CV_8U, cv::Scalar(0));
    cv::line(m, {20, 64}, {108, 64}, 255, 7);
    cv::line(m, {64, 20}, {64, 108}, 255, 7);
    const Skeleton s = skeletonise(m);
    REQUIRE(count_nodes(s, true) == 1);
    CHECK(count_nodes(s, false) == 4);
    CHECK(s.edges.size() == 4);
    for (const auto& n : s.nodes)
      if (n.junction()) CHECK(distance(n.pos, {64, 64}) <= 2);
    for (const Vec2 tip : {Vec2{20, 64}, Vec2{108, 64}, Vec2{64, 20}, Vec2{64, 108}}) {
      double best = 1e9;
      for (const auto& n : s.nodes)
        if (n.end()) best = std::min(best, distance(n.pos, tip));
      CHECK(best <= 2);
    }
    for (const auto& e : s.edges) {
      CHECK(e.terminal);
      CHECK(e.length == doctest::Approx(40).epsilon(0.1));
      CHECK(e.mean_radius == doctest::Approx(3.5).epsilon(0.35));
    }
  }

  TEST_CASE("a rectangle's skeleton is its mid line without spurs") {
    cv::Mat m(128, 128, CV_8U, cv::Scalar(0));
    cv::rectangle(m, cv::Rect(20, 40, 88, 31), 255, cv::FILLED);  // rows 40..70, mid line y = 55
    const Skeleton s = skeletonise(m);
    CHECK(count_nodes(s, true) == 0);
    REQUIRE(count_nodes(s, false) == 2);
    REQUIRE(s.edges.size() == 1);
    const auto& e = s.edges[0];
    for (const auto& p : e.points) CHECK(std::abs(p.y - 55) <= 1);
    CHECK(e.length > 88 - 31 - 4);  // the axis between the end discs' centres, within 2 px each end
    CHECK(e.max_radius == doctest::Approx(15.5).epsilon(0.1));
  }

  TEST_CASE("random bumps of 1 to 3 px on an outline leave no spur") {
    for (int height = 1; height <= 3; ++height) {
      CAPTURE(height);
      cv::Mat m(160, 160, CV_8U, cv::Scalar(0));
      cv::ellipse(m, {80, 80}, {60, 22}, 0, 0, 360, 255, cv::FILLED);
      std::vector<cv::Point> outline;
      cv::ellipse2Poly({80, 80}, {60, 22}, 0, 0, 360, 2, outline);
      std::mt19937 rng(7);
      for (const auto& p : outline)
        if (rng() % 8 == 0) {
          const int w = 1 + static_cast<int>(rng() % 2);
          cv::rectangle(m, cv::Rect(p.x - w / 2, p.y < 80 ? p.y - height : p.y + 1, w, height), 255, cv::FILLED);
        }
      CHECK(end_pixels(thin(m)) > 4);  // the bumps do grow spurs before pruning
      const Skeleton s = skeletonise(m);
      CHECK(s.spurs_pruned > 0);
      CHECK(count_nodes(s, true) == 0);
      CHECK(count_nodes(s, false) == 2);
      REQUIRE(s.edges.size() == 1);
      for (const auto& p : s.edges[0].points) CHECK(std::abs(p.y - 80) <= 2);
    }
  }

  TEST_CASE("a ring is one loop; two blobs are two components") {
    cv::Mat m(100, 200, CV_8U, cv::Scalar(0));
    cv::circle(m, {50, 50}, 30, 255, 8);
    cv::circle(m, {150, 50}, 20, 255, cv::FILLED);
    const Skeleton s = skeletonise(m);
    REQUIRE(s.component_area.size() == 2);
    int loops = 0;
    for (const auto& e : s.edges) loops += e.a == e.b;
    CHECK(loops == 1);
    for (const auto& e : s.edges)
      if (e.a == e.b) CHECK(e.length == doctest::Approx(2 * M_PI * 30).epsilon(0.12));
  }

  TEST_CASE("the same mask gives the same graph; a non-8-bit mask is refused") {
    cv::Mat m(96, 96, CV_8U, cv::Scalar(0));
    cv::line(m, {10, 80}, {48, 20}, 255, 6);
    cv::line(m, {48, 20}, {86, 80}, 255, 6);
    cv::line(m, {30, 50}, {66, 50}, 255, 6);
    const Skeleton a = skeletonise(m), b = skeletonise(m);
    REQUIRE(a.edges.size() == b.edges.size());
    for (size_t i = 0; i < a.edges.size(); ++i) CHECK(a.edges[i].points == b.edges[i].points);
    CHECK_THROWS_AS(skeletonise(cv::Mat(8, 8, CV_32F, cv::Scalar(1))), std::invalid_argument);
  }
}
