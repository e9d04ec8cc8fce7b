// The figure's class (motion/figure_class.h) from drawn masks: a quadruped, a snake, a car, a
// stick figure, a bird with spread wings, a plant and a full canvas each get their class from
// the shape alone; the words' class wins over the shape and the names, and names win over the
// shape.
#include <doctest/doctest.h>

#include <string>

#include "motion/figure_class.h"
#include "motion_masks.h"

using namespace svgm::motion;

namespace {

FigureClass shape_of(const cv::Mat& m) { return classify_mask(m).cls; }

}  // namespace

TEST_SUITE("motion") {
  TEST_CASE("the shape alone: quadruped, fish or snake, wheeled, biped") {
    const FigureVerdict q = classify_mask(motion_masks::quadruped());
    CHECK(figure_class_name(q.cls) == std::string("quadruped"));
    CHECK(q.reason.find("4 legs") != std::string::npos);
    CHECK(shape_of(motion_masks::snake()) == FigureClass::FishOrSnake);
    const FigureVerdict car = classify_mask(motion_masks::car());
    CHECK(car.cls == FigureClass::Wheeled);
    CHECK(car.reason.find("2 round wheels") != std::string::npos);
    CHECK(shape_of(motion_masks::stick_figure()) == FigureClass::Biped);
  }

  TEST_CASE("wheels drawn as rings under a box are wheels; one ring alone is not a vehicle") {
    cv::Mat m(160, 220, CV_8U, cv::Scalar(0));
    cv::rectangle(m, cv::Rect(40, 30, 140, 40), 255, cv::FILLED);
    cv::circle(m, {70, 110}, 25, 255, 6);
    cv::circle(m, {150, 110}, 25, 255, 6);
    cv::line(m, {70, 70}, {70, 85}, 255, 6);
    cv::line(m, {150, 70}, {150, 85}, 255, 6);
    CHECK(shape_of(m) == FigureClass::Wheeled);
    cv::Mat ring(160, 160, CV_8U, cv::Scalar(0));
    cv::circle(ring, {80, 80}, 50, 255, 8);
    CHECK(shape_of(ring) != FigureClass::Wheeled);
  }

  TEST_CASE("a bird with spread wings, a plant, a full canvas") {
    cv::Mat bird(160, 240, CV_8U, cv::Scalar(0));
    cv::ellipse(bird, {120, 85}, {14, 30}, 0, 0, 360, 255, cv::FILLED);
    cv::ellipse(bird, {70, 70}, {45, 9}, -15, 0, 360, 255, cv::FILLED);
    cv::ellipse(bird, {170, 70}, {45, 9}, 15, 0, 360, 255, cv::FILLED);
    cv::circle(bird, {120, 48}, 11, 255, cv::FILLED);
    CHECK(shape_of(bird) == FigureClass::Bird);

    cv::Mat plant(200, 160, CV_8U, cv::Scalar(0));
    cv::line(plant, {80, 190}, {80, 100}, 255, 6);
    cv::line(plant, {80, 100}, {40, 30}, 255, 6);
    cv::line(plant, {80, 100}, {80, 20}, 255, 6);
    cv::line(plant, {80, 100}, {120, 30}, 255, 6);
    cv::ellipse(plant, {40, 30}, {10, 16}, -30, 0, 360, 255, cv::FILLED);
    cv::ellipse(plant, {120, 30}, {10, 16}, 30, 0, 360, 255, cv::FILLED);
    CHECK(shape_of(plant) == FigureClass::Plant);

    cv::Mat full(100, 100, CV_8U, cv::Scalar(255));
    cv::circle(full, {50, 50}, 10, 0, cv::FILLED);
    CHECK(shape_of(full) == FigureClass::Scene);
  }

  TEST_CASE("the words win over the names and the shape; names win over the shape") {
    const cv::Mat q = motion_masks::quadruped();
    const FigureVerdict words = classify_mask(q, ClassHint{FigureClass::Bird, 0.7}, {"front_wheel"});
    CHECK(words.cls == FigureClass::Bird);
    CHECK(words.shape_cls == FigureClass::Quadruped);
    CHECK(words.confidence == doctest::Approx(0.7));
    CHECK(words.reason.find("the words say bird") == 0);
    const FigureVerdict agree = classify_mask(q, ClassHint{FigureClass::Quadruped, 0.7});
    CHECK(agree.confidence == doctest::Approx(0.85));
    const FigureVerdict named = classify_mask(motion_masks::stick_figure(), std::nullopt, {"frontWheel", "frame"});
    CHECK(named.cls == FigureClass::Wheeled);
    CHECK(named.shape_cls == FigureClass::Biped);
    CHECK(classify_mask(q, std::nullopt, {"path12", "g3"}).cls == FigureClass::Quadruped);  // no keyword: the shape
    CHECK(class_from_names({"leftWing", "tail"})->cls == FigureClass::Bird);
    CHECK(figure_class_from_name("fish_or_snake") == FigureClass::FishOrSnake);
    CHECK_FALSE(figure_class_from_name("fish").has_value());
  }
}
