// animateTransform at a time (see smil_transform.h).
#include "svg/smil_transform.h"
#include "svg/smil_spline.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include "svg/svg_number.h"

namespace svgm::svg {

namespace {

std::string_view local(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

// ';'-separated items, empty ones dropped.
std::vector<std::string_view> items(std::string_view v) {
  std::vector<std::string_view> out;
  while (true) {
    const size_t semi = v.find(';');
    const std::string_view item = v.substr(0, semi);
    if (item.find_first_not_of(" \t\r\n") != std::string_view::npos) out.push_back(item);
    if (semi == std::string_view::npos) break;
    v.remove_prefix(semi + 1);
  }
  return out;
}

std::vector<double> numbers(std::string_view s) {
  Cursor c{s};
  std::vector<double> out;
  c.skip_ws();
  while (!c.done()) {
    const auto n = c.number();
    if (!n) break;
    out.push_back(*n);
    c.skip_comma_ws();
  }
  return out;
}

// The fraction of the simple duration at `seconds` (the same timing as an <animate> of `d` in
// svg_reader.cpp), or nothing when the animation has ended without fill="freeze".
std::optional<double> fraction(pugi::xml_node anim, double seconds) {
  const double dur = parse_clock_value(anim.attribute("dur").value()).value_or(0);
  if (!(dur > 0)) return std::nullopt;
  const std::string_view repeat = anim.attribute("repeatCount").value();
  double f = seconds / dur;
  if (repeat == "indefinite") f -= std::floor(f);
  else if (const auto rc = parse_number(repeat); rc && *rc > 0 && f < *rc) f -= std::floor(f);
  else if (f > 1) {
    if (std::string_view(anim.attribute("fill").value()) != "freeze") return std::nullopt;
    f = 1;
  }
  return f;
}

Affine of_type(std::string_view type, const std::vector<double>& v) {
  auto at = [&](size_t i, double d) { return i < v.size() ? v[i] : d; };
  if (type == "translate") return Affine::translate(at(0, 0), at(1, 0));
  if (type == "scale") return Affine::scale(at(0, 1), at(1, at(0, 1)));
  if (type == "rotate") {
    const double cx = at(1, 0), cy = at(2, 0);
    return Affine::translate(cx, cy) * Affine::rotate_deg(at(0, 0)) * Affine::translate(-cx, -cy);
  }
  if (type == "skewX") return Affine::skew_x_deg(at(0, 0));
  if (type == "skewY") return Affine::skew_y_deg(at(0, 0));
  return Affine{};
}

}  // namespace

Affine animated_transform(pugi::xml_node element, double seconds, const Affine& base, std::string_view attribute) {
  Affine m = base;
  for (pugi::xml_node a = element.first_child(); a; a = a.next_sibling()) {
    if (local(a.name()) != "animateTransform" || std::string_view(a.attribute("attributeName").value()) != attribute)
      continue;
    const std::vector<std::string_view> values = items(a.attribute("values").value());
    const std::optional<double> f = fraction(a, seconds);
    if (values.empty() || !f) continue;
    std::vector<double> times;
    for (std::string_view t : items(a.attribute("keyTimes").value()))
      if (const auto n = parse_number(t)) times.push_back(*n);
    if (times.size() != values.size()) {
      times.clear();
      for (size_t i = 0; i < values.size(); ++i)
        times.push_back(values.size() > 1 ? static_cast<double>(i) / (values.size() - 1) : 0.0);
    }
    size_t i = 0;
    while (i + 1 < times.size() && *f >= times[i + 1]) ++i;
    std::vector<double> v = numbers(values[i]);
    if (i + 1 < values.size() && std::string_view(a.attribute("calcMode").value()) != "discrete") {
      const std::vector<double> w = numbers(values[i + 1]);
      const double span = times[i + 1] - times[i];
      const double u = spline_fraction(a, i, span > 0 ? std::clamp((*f - times[i]) / span, 0.0, 1.0) : 0.0);
      for (size_t j = 0; j < std::min(v.size(), w.size()); ++j) v[j] = (1 - u) * v[j] + u * w[j];
    }
    const Affine t = of_type(a.attribute("type").value(), v);
    m = std::string_view(a.attribute("additive").value()) == "sum" ? m * t : t;
  }
  return m;
}

}  // namespace svgm::svg
