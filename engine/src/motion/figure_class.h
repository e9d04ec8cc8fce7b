// What kind of figure a drawing is (biped, quadruped, bird, fish or snake, plant, wheeled,
// object, scene), for choosing how a prompt's verbs move it.
//
// Three sources, strongest first: the words (a class a lexicon gave the prompt's nouns, with
// its confidence: it wins whenever it is given), the document's names (ids, labels, group
// names: a small keyword check, "wheel" -> wheeled), and the shape: the silhouette skeleton's
// limbs (limbs.h) and round parts (wheel_circles.h). The shape's rules, each scored, the best
// taken:
//  - scene: the mask fills the canvas, or it is four or more large separate parts;
//  - wheeled: two or more circles (round holes, round parts, arcs bulging out of the bottom
//    outline) in the lower half of the figure, standing on its ground line;
//  - fish or snake: one long branch, several times its width and of about one width all along,
//    carries most of the skeleton;
//  - biped: an upright body with one or two legs down and arms or a head;
//  - quadruped: a lying body with three or more legs down;
//  - bird: two long side branches of about the same length, mirrored, from one place (wings),
//    a body on one or two legs under a third of its thickness, or a lying body on two legs;
//  - plant: branches rising above one central stem on the ground, three or more branches
//    rising, or a narrow stem under a wide top;
//  - object: anything else.
// The verdict keeps the shape's own answer beside the final one, and a reason in words
// ("4 legs below a lying body: quadruped").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "motion/limbs.h"
#include "motion/skeleton.h"
#include "motion/wheel_circles.h"

namespace svgm::motion {

enum class FigureClass { Biped, Quadruped, Bird, FishOrSnake, Plant, Wheeled, Object, Scene };
const char* figure_class_name(FigureClass c);  // "biped", ..., "fish_or_snake", ...
std::optional<FigureClass> figure_class_from_name(const std::string& name);

struct ClassHint {
  FigureClass cls = FigureClass::Object;
  double confidence = 0;  // in (0, 1]; 0 is no hint
};

struct FigureVerdict {
  FigureClass cls = FigureClass::Object;
  double confidence = 0;
  std::string reason;
  FigureClass shape_cls = FigureClass::Object;  // the shape's answer alone
  double shape_confidence = 0;
  std::string shape_reason;
};

// The shape's answer from a mask already skeletonised (`mask` as given to skeletonise).
FigureVerdict classify_shape(const cv::Mat& mask, const Skeleton& s, const Figure& f);

// The class from the document's names alone (keyword check over their words), if any says one.
std::optional<ClassHint> class_from_names(const std::vector<std::string>& names);

// The whole rule: words, then names, then shape.
FigureVerdict classify_figure(const cv::Mat& mask, const Skeleton& s, const Figure& f,
                              const std::optional<ClassHint>& words = std::nullopt,
                              const std::vector<std::string>& names = {});

// Convenience: skeletonise, find limbs and classify one mask.
FigureVerdict classify_mask(const cv::Mat& mask, const std::optional<ClassHint>& words = std::nullopt,
                            const std::vector<std::string>& names = {});

}  // namespace svgm::motion
