// Inline SVG charts for report.html (see report_charts.h).
//
// Both charts share one frame: a plot area inside fixed margins (room for the axis numbers and
// labels), the y range from the data (a line chart's log axis spans whole decades' fractions
// as they fall), the minimum and maximum written at the ends of each axis. Coordinates are
// printed with one decimal: a tenth of a CSS pixel is below what a screen shows.
#include "report/report_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/html_text.h"

namespace svgm {

namespace {

// Margins of the plot area in CSS pixels: left holds the y numbers, bottom the x numbers and
// label, top the title.
constexpr double kLeft = 64, kRight = 12, kTop = 26, kBottom = 38;

std::string px(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

std::string frame(const ChartText& t, int w, int h, const std::string& y_lo, const std::string& y_hi,
                  const std::string& x_lo, const std::string& x_hi) {
  const double x0 = kLeft, x1 = w - kRight, y0 = kTop, y1 = h - kBottom;
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"svgm-chart\" width=\"" + std::to_string(w) +
                  "\" height=\"" + std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " +
                  std::to_string(h) + "\" role=\"img\" aria-label=\"" + html_escape(t.title) + "\">";
  s += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(w) + "\" height=\"" + std::to_string(h) + "\" fill=\"#fff\"/>";
  s += "<text x=\"" + px(x0) + "\" y=\"16\" font-size=\"13\" font-weight=\"bold\">" + html_escape(t.title) + "</text>";
  s += "<path d=\"M" + px(x0) + " " + px(y0) + "V" + px(y1) + "H" + px(x1) + "\" fill=\"none\" stroke=\"#444\"/>";
  auto label = [&](double x, double y, const std::string& text, const char* anchor) {
    s += "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\" font-size=\"11\" text-anchor=\"" + anchor + "\">" +
         html_escape(text) + "</text>";
  };
  label(x0 - 4, y0 + 4, y_hi, "end");
  label(x0 - 4, y1, y_lo, "end");
  label(x0, y1 + 14, x_lo, "start");
  label(x1, y1 + 14, x_hi, "end");
  label((x0 + x1) / 2, h - 6, t.x_label, "middle");
  s += "<text x=\"14\" y=\"" + px((y0 + y1) / 2) + "\" font-size=\"11\" text-anchor=\"middle\" transform=\"rotate(-90 14 " +
       px((y0 + y1) / 2) + ")\">" + html_escape(t.y_label) + "</text>";
  return s;
}

}  // namespace

std::string line_chart_svg(const std::vector<double>& x, const std::vector<double>& y, const ChartText& text,
                           bool log_y, int w, int h) {
  std::vector<std::pair<double, double>> pts;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i])) pts.emplace_back(x[i], y[i]);
  if (pts.empty()) return "";
  const bool log = log_y && std::all_of(pts.begin(), pts.end(), [](const auto& p) { return p.second > 0; });
  auto fy = [&](double v) { return log ? std::log10(v) : v; };
  double xlo = pts.front().first, xhi = xlo, ylo = fy(pts.front().second), yhi = ylo;
  for (const auto& [px_, py] : pts) {
    xlo = std::min(xlo, px_);
    xhi = std::max(xhi, px_);
    ylo = std::min(ylo, fy(py));
    yhi = std::max(yhi, fy(py));
  }
  if (!log) ylo = std::min(ylo, 0.0);  // a linear loss axis starts at zero
  if (xhi == xlo) xhi = xlo + 1;
  if (yhi == ylo) yhi = ylo + 1;
  const double x0 = kLeft, x1 = w - kRight, y0 = kTop, y1 = h - kBottom;
  auto shown = [&](double v) { return html_number(log ? std::pow(10.0, v) : v, 3); };
  std::string s = frame(text, w, h, shown(ylo), shown(yhi), html_number(xlo, 6), html_number(xhi, 6));
  if (log) s += "<text x=\"" + px(x1) + "\" y=\"" + px(y0 - 4) + "\" font-size=\"10\" text-anchor=\"end\">log scale</text>";
  std::string d;
  for (const auto& [vx, vy] : pts) {
    const double sx = x0 + (vx - xlo) / (xhi - xlo) * (x1 - x0);
    const double sy = y1 - (fy(vy) - ylo) / (yhi - ylo) * (y1 - y0);
    d += (d.empty() ? "M" : "L") + px(sx) + " " + px(sy);
  }
  s += "<path class=\"svgm-series\" d=\"" + d + "\" fill=\"none\" stroke=\"#1f6fb4\" stroke-width=\"1.5\"/>";
  return s + "</svg>";
}

std::string bar_chart_svg(const std::vector<double>& values, const ChartText& text, int w, int h) {
  if (values.empty()) return "";
  double hi = 0;
  for (double v : values)
    if (std::isfinite(v)) hi = std::max(hi, v);
  if (hi <= 0) hi = 1;
  const double x0 = kLeft, x1 = w - kRight, y0 = kTop, y1 = h - kBottom;
  const double slot = (x1 - x0) / static_cast<double>(values.size());
  std::string s = frame(text, w, h, "0", html_number(hi, 3), "", "");
  for (size_t i = 0; i < values.size(); ++i) {
    const double cx = x0 + (static_cast<double>(i) + 0.5) * slot;
    if (std::isfinite(values[i]) && values[i] > 0) {
      const double top = y1 - values[i] / hi * (y1 - y0);
      s += "<rect class=\"svgm-bar\" x=\"" + px(cx - 0.35 * slot) + "\" y=\"" + px(top) + "\" width=\"" + px(0.7 * slot) +
           "\" height=\"" + px(y1 - top) + "\" fill=\"#1f6fb4\"><title>" + std::to_string(i) + ": " +
           html_number(values[i]) + "</title></rect>";
    }
    s += "<text x=\"" + px(cx) + "\" y=\"" + px(y1 + 14) + "\" font-size=\"10\" text-anchor=\"middle\">" +
         std::to_string(i) + "</text>";
  }
  return s + "</svg>";
}

}  // namespace svgm
