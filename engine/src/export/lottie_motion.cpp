// The compact Lottie motion of one path (see lottie_motion.h).
#include "export/lottie_motion.h"

#include <algorithm>
#include <cmath>

#include "export/lottie_json.h"
#include "export/smil_writer.h"

namespace svgm::lottie {

CompactPathMotion compact_path_motion(const std::vector<double>& rest, const std::vector<const double*>& values,
                                      const std::vector<double>& times, double frames, double tolerance, int decimals,
                                      double residual_scale) {
  CompactPathMotion out;
  const size_t count = rest.size() / 2;
  const double rtol = tolerance * residual_scale;
  PartMotion motion = analyse_part_motion(rest, values, tolerance, rtol);
  if (!motion.moves) return out;
  out.moves = true;
  // The pivot (the anchor) rounded within a quarter of the tolerance: any point serves exactly
  // at the written values, and a short number is written in every position key.
  Vec2 centre = motion_pivot(motion.affine, rest, Affine{});
  const double grid = std::pow(10.0, std::ceil(std::log10(4 / tolerance)));
  centre = {std::round(centre.x * grid) / grid, std::round(centre.y * grid) / grid};
  const WrapperKeys w =
      wrapper_keys(motion.affine, Affine{}, rest, times, tolerance, decimals, centre, WrapperForm::Lottie);
  out.drawn = w.drawn;
  out.transform_keys = w.key_count();
  // The skew Lottie's transform leaves out: how far it would move a point.
  const std::vector<double> exact = wrapper_trajectory(motion.affine, Affine{}, centre, WrapperForm::Lottie);
  double skew_miss = 0;
  for (size_t v = 0; v < values.size(); ++v) {
    const Affine m = wrapper_map(&exact[6 * v], centre, WrapperForm::Lottie);
    for (size_t i = 0; i < count; ++i) {
      const Vec2 a = m.apply({rest[2 * i], rest[2 * i + 1]}), b = motion.affine[v].apply({rest[2 * i], rest[2 * i + 1]});
      skew_miss = std::max(skew_miss, std::hypot(a.x - b.x, a.y - b.y));
    }
  }
  out.residual = motion.residual || skew_miss > rtol;

  // The group's transform: T(centre + t) R(r) S(s) T(-centre), each property keyed at its own
  // channel's keys, static when they agree.
  std::vector<double> key_frames;
  for (const double t : times) key_frames.push_back(t * frames);
  const std::vector<double>& tr = w.trajectory;
  auto varies = [&](size_t c) {
    const ReducedKeys& r = w.channel[c];
    for (size_t k : r.keys)
      for (size_t j = 0; j < kChannelSize[c]; ++j)
        if (tr[6 * k + kChannelAt[c] + j] != tr[6 * r.keys[0] + kChannelAt[c] + j]) return true;
    return false;
  };
  JsonText j(std::max(1, w.translate_decimals));
  const double scale_places = std::pow(10.0, std::max(0, w.scale_decimals - 2));
  const double rotate_places = std::pow(10.0, w.rotate_decimals);
  const bool moves_p = varies(kTranslate), moves_r = varies(kRotate), moves_s = varies(kScale);
  const size_t first_p = w.channel[kTranslate].keys[0], first_r = w.channel[kRotate].keys[0],
               first_s = w.channel[kScale].keys[0];
  j.raw("{\"ty\":\"tr\",\"p\":");
  write_property(j, key_frames, times.size(), [&](size_t i) {
    j.pair(centre.x + tr[6 * (moves_p ? i : first_p)], centre.y + tr[6 * (moves_p ? i : first_p) + 1]);
  }, moves_p, false, &w.channel[kTranslate]);
  j.raw(",\"a\":{\"a\":0,\"k\":").pair(centre.x, centre.y).raw("}");
  // Skew and a scale of 100 % are the players' defaults (lottie_json.h): not written.
  const bool unit_scale = !moves_s && std::round(100 * tr[6 * first_s + 4] * scale_places) == 100 * scale_places &&
                          std::round(100 * tr[6 * first_s + 5] * scale_places) == 100 * scale_places;
  if (!unit_scale) {
    j.raw(",\"s\":");
    write_property(j, key_frames, times.size(), [&](size_t i) {
      const size_t k = moves_s ? i : first_s;
      j.raw("[").num(100 * tr[6 * k + 4], scale_places).raw(",").num(100 * tr[6 * k + 5], scale_places).raw("]");
    }, moves_s, false, &w.channel[kScale]);
  }
  j.raw(",\"r\":");
  write_property(j, key_frames, times.size(), [&](size_t i) { j.num(tr[6 * (moves_r ? i : first_r) + 2], rotate_places); },
                 moves_r, true, &w.channel[kRotate]);
  j.raw(",\"o\":{\"a\":0,\"k\":100}}");  // lottie-web draws no group without its opacity
  out.transform = std::move(j.text());
  if (!out.residual) return out;

  // The residual: each value's shape in the group's moving frame, as players draw the group.
  for (size_t v = 0; v < values.size(); ++v) {
    out.px_per_unit = std::max(out.px_per_unit, w.drawn[v].mean_scale());
    const Affine back = w.drawn[v].inverse();
    for (size_t i = 0; i < count; ++i) {
      const Vec2 q = back.apply({values[v][2 * i], values[v][2 * i + 1]});
      out.local.insert(out.local.end(), {q.x, q.y});
    }
  }
  const SampleError error = point_error(out.local, 2 * count, out.px_per_unit);
  out.shape_keys = reduce_keyframes(times, out.local, 2 * count, rtol, error);
  // Lottie writes tangents relative to their vertex, each rounded: a control point moves by up to
  // twice the measured rounding, half the tolerance at most (as the static shapes' decimals).
  out.shape_decimals = decimals >= 0 ? decimals
                                     : measured_decimals(out.local, 2 * count, out.shape_keys.keys, error, rtol / 4, 0,
                                                         2 * count, kMaxDecimals);
  return out;
}

}  // namespace svgm::lottie
