// Choosing the compact export's tolerance by rendering it against the full export (see
// tolerance_choice.h).
#include "fit/output/tolerance_choice.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "export/compact_motion.h"
#include "export/lottie_player.h"
#include "export/smil_clock.h"
#include "opencl/runtime.h"
#include "raster/render_image.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/temporary_name.h"

namespace svgm {

namespace fs = std::filesystem;

double render_psnr(const RgbaImage& a, const RgbaImage& b) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size())
    throw Error("internal: renders of different sizes compared");
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c, ++n) {
      const double d = static_cast<double>(a.rgba[i + c]) - b.rgba[i + c];
      sum += d * d;
    }
  if (sum == 0 || n == 0) return std::numeric_limits<double>::infinity();
  return 10 * std::log10(255.0 * 255.0 * static_cast<double>(n) / sum);
}

double lottie_tolerance(double svg_tolerance_1024) {
  // The steps below animation.svg's, tightest first; kLottieStepsBelow of them down.
  std::vector<double> below;
  for (double step : kToleranceLadder)
    if (step < svg_tolerance_1024) below.push_back(step);
  if (below.empty()) return kToleranceLadder.front();
  return below[below.size() - std::min(below.size(), kLottieStepsBelow)];
}

namespace {

// Removes a candidate file however the search ends.
struct Candidate {
  fs::path path;
  ~Candidate() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot read back the export being measured");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// animation.svg at the sampled times of its SMIL clock (opaque, over white).
class SvgDrawer : public ExportDrawer {
 public:
  explicit SvgDrawer(const fs::path& full) : rt_("auto") {
    load(full);
    const std::string& text = text_;
    const SmilClock clock = smil_clock(text, full.string());
    const double pass = clock.duration_s > 0 ? clock.duration_s : 1;
    for (int k = 0; k < kToleranceTimes; ++k) times_.push_back((k + 0.5) * pass / kToleranceTimes);
    const Scene first = read_svg_string(text, full.string());
    const double larger = std::max(first.width, first.height);
    width_ = std::max(1, static_cast<int>(std::lround(kToleranceRenderPx * (larger > 0 ? first.width / larger : 1))));
  }
  size_t count() const override { return times_.size(); }
  void load(const fs::path& file) override { text_ = read_text(file), name_ = file.string(); }
  RgbaImage draw(size_t k) override {
    SvgReadLimits at;
    at.animation_time = times_[k];
    return render_image(rt_, read_svg_string(text_, name_, at), width_, false);
  }

 private:
  ClRuntime rt_;
  std::vector<double> times_;
  int width_ = 1;
  std::string text_, name_;  // the file loaded
};

// animation.json at whole frames of the player's timeline (opaque, over white).
class LottieDrawer : public ExportDrawer {
 public:
  explicit LottieDrawer(const fs::path& full) {
    load(full);
    const auto& player = player_;
    for (int k = 0; k < kToleranceTimes; ++k)
      frames_.push_back(static_cast<size_t>((k + 0.5) / kToleranceTimes * static_cast<double>(player->total_frames())));
    const double w = static_cast<double>(player->width()), h = static_cast<double>(player->height());
    const double larger = std::max(w, h);
    width_ = std::max(1, static_cast<int>(std::lround(kToleranceRenderPx * w / larger)));
    height_ = std::max(1, static_cast<int>(std::lround(kToleranceRenderPx * h / larger)));
  }
  size_t count() const override { return frames_.size(); }
  void load(const fs::path& file) override { player_ = open(file); }
  RgbaImage draw(size_t k) override { return over_white(player_->draw(frames_[k], width_, height_)); }

 private:
  static std::unique_ptr<LottiePlayer> open(const fs::path& file) {
    std::string why;
    auto player = LottiePlayer::open(file, why);
    if (!player) throw Error(why);
    return player;
  }
  std::vector<size_t> frames_;
  int width_ = 1, height_ = 1;
  std::unique_ptr<LottiePlayer> player_;  // the file loaded
};

}  // namespace

DrawerMaker svg_drawer() {
  return [](const fs::path& full) -> std::unique_ptr<ExportDrawer> { return std::make_unique<SvgDrawer>(full); };
}

DrawerMaker lottie_drawer() {
  if (!LottiePlayer::available()) return nullptr;
  return [](const fs::path& full) -> std::unique_ptr<ExportDrawer> { return std::make_unique<LottieDrawer>(full); };
}

ToleranceChoice choose_compact_tolerance(const fs::path& beside, const std::function<void(const fs::path&)>& write_full,
                                         const std::function<void(const fs::path&, double)>& write_compact,
                                         const std::function<void(const fs::path&, double, double)>& write_residual,
                                         const DrawerMaker& draw) {
  const fs::path dir = beside.parent_path().empty() ? fs::path(".") : beside.parent_path();
  const std::string ext = beside.extension().string();
  Candidate full{temporary_path(dir / ("animation.full" + ext))};
  write_full(full.path);
  const std::unique_ptr<ExportDrawer> drawer = draw(full.path);
  std::vector<RgbaImage> reference;
  for (size_t k = 0; k < drawer->count(); ++k) reference.push_back(drawer->draw(k));  // it holds the full export

  ToleranceChoice choice;
  const double floor_db = kCompactTargetDb + kCompactMarginDb;
  // The worst PSNR of the compact export at ladder step i, stopped at the first time below floor.
  auto trial = [&](size_t i, double scale = 1) {
    Candidate c{temporary_path(dir / ("animation.compact" + ext))};
    if (scale == 1) write_compact(c.path, kToleranceLadder[i]);
    else write_residual(c.path, kToleranceLadder[i], scale);
    ToleranceTrial t{kToleranceLadder[i], std::numeric_limits<double>::infinity(), scale};
    drawer->load(c.path);
    for (size_t k = 0; k < drawer->count() && t.worst_db >= floor_db; ++k)
      t.worst_db = std::min(t.worst_db, render_psnr(reference[k], drawer->draw(k)));
    choice.trials.push_back(t);
    return t.worst_db;
  };
  // Binary search for the last step that holds the floor: `good` holds it (-1: none tried
  // yet does), `bad` does not (size: past the ladder). Step 0 is taken when none holds.
  std::ptrdiff_t good = -1, bad = static_cast<std::ptrdiff_t>(kToleranceLadder.size());
  double good_db = 0, first_db = 0;
  while (bad - good > 1) {
    const std::ptrdiff_t mid = (good + bad) / 2;
    const double db = trial(static_cast<size_t>(mid));
    if (mid == 0) first_db = db;
    if (db >= floor_db) good = mid, good_db = db;
    else bad = mid;
  }
  choice.tolerance_1024 = kToleranceLadder[static_cast<size_t>(std::max<std::ptrdiff_t>(good, 0))];
  choice.worst_db = good >= 0 ? good_db : first_db;
  // The residual's tolerance, loosened while the floor holds (the error grows with it too).
  if (good >= 0 && write_residual)
    for (size_t s = 1; s < kResidualScales.size(); ++s) {
      const double db = trial(static_cast<size_t>(good), kResidualScales[s]);
      if (db < floor_db) break;
      choice.residual_scale = kResidualScales[s];
      choice.worst_db = db;
    }
  return choice;
}

}  // namespace svgm
