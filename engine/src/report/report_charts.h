// The charts of report.html, drawn as inline SVG elements (no script, no library): a line
// chart of a series over x (the fit's loss over iterations) and a bar chart of one value per
// item (the loss of each keyframe).
#pragma once

#include <string>
#include <vector>

namespace svgm {

struct ChartText {
  std::string title, x_label, y_label;  // plain text; escaped when drawn
};

// Points (x[i], y[i]); non-finite y are skipped. A log10 y axis when `log_y` and every drawn y
// is > 0. Returns "" when there is nothing to draw. `width` x `height` in CSS pixels.
std::string line_chart_svg(const std::vector<double>& x, const std::vector<double>& y, const ChartText& text,
                           bool log_y, int width = 560, int height = 220);

// One bar per value, labelled 0, 1, ... below; non-finite values are drawn as no bar.
// Returns "" when `values` is empty.
std::string bar_chart_svg(const std::vector<double>& values, const ChartText& text, int width = 560,
                          int height = 220);

}  // namespace svgm
