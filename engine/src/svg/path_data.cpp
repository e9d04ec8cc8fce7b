// Path data parsing and arc conversion (see path_data.h).
#include "svg/path_data.h"

#include <cctype>
#include <cmath>

#include "svg/svg_number.h"

namespace svgm::svg {

namespace {

void line_to(std::vector<Vec2>& pts, Vec2 a, Vec2 b) {
  pts.push_back(a + (1.0 / 3.0) * (b - a));
  pts.push_back(a + (2.0 / 3.0) * (b - a));
  pts.push_back(b);
}

int arg_count(char cmd) {
  switch (std::toupper(static_cast<unsigned char>(cmd))) {
    case 'M': case 'L': case 'T': return 2;
    case 'H': case 'V': return 1;
    case 'C': return 6;
    case 'S': case 'Q': return 4;
    case 'A': return 7;
    case 'Z': return 0;
  }
  return -1;
}

}  // namespace

void arc_to_cubics(Vec2 p0, double rx, double ry, double phi_deg, bool large_arc, bool sweep,
                   Vec2 p1, std::vector<Vec2>& out) {
  if (p0 == p1) return;  // F.6.2: identical endpoints draw nothing
  rx = std::fabs(rx);
  ry = std::fabs(ry);
  if (rx == 0 || ry == 0) {
    line_to(out, p0, p1);
    return;
  }
  const double phi = phi_deg * M_PI / 180.0, cp = std::cos(phi), sp = std::sin(phi);
  // F.6.5.1: the midpoint in the ellipse's frame. Halving each coordinate before subtracting
  // keeps p0 - p1 finite for any finite endpoints (1e308 - -1e308 overflows).
  const double dx = 0.5 * p0.x - 0.5 * p1.x, dy = 0.5 * p0.y - 0.5 * p1.y;
  const double x1 = cp * dx + sp * dy, y1 = -sp * dx + cp * dy;
  // The spec's formulas square the radii and coordinates, which overflows (radius 1e308) or
  // underflows (1e-300) long before the geometry does. They are rewritten here in the ratios
  // ux = x1/rx, uy = y1/ry and root = sqrt(lambda) = hypot(ux, uy), exact rearrangements:
  //   F.6.6    lambda = ux² + uy²; if lambda > 1, rx, ry *= root (so that root becomes 1)
  //   F.6.5.2  k = sqrt((rx²ry² - rx²y1² - ry²x1²) / (rx²y1² + ry²x1²)) = sqrt((1 - L) / L)
  //            cx' = k rx y1/ry = rx (uy/root) sqrt(1 - L),  cy' = -ry (ux/root) sqrt(1 - L)
  double ux = x1 / rx, uy = y1 / ry, root = std::hypot(ux, uy);
  if (!std::isfinite(root)) {
    // Radii smaller than the chord by more than the double range (x1/rx overflows): the
    // scaled-up radii of F.6.6 directly, rx root = hypot(x1, y1 rx/ry) and likewise ry.
    const double sx = std::hypot(x1, y1 * (rx / ry)), sy = std::hypot(x1 * (ry / rx), y1);
    rx = sx;
    ry = sy;
    ux = x1 / rx;
    uy = y1 / ry;
    root = 1;
  }
  // A chord a billionth of the radii (or smaller, down to underflow) bends the small arc by
  // under a billionth of its length: that arc is its chord. Computing it through a centre
  // 1e9 chords away would lose more than that to rounding.
  if (!(root > 2e-9) && large_arc == false) {
    line_to(out, p0, p1);
    return;
  }
  if (root > 1) {
    rx *= root;
    ry *= root;
    ux /= root;
    uy /= root;
    root = 1;
  }
  const double lift = std::sqrt(std::max(0.0, 1 - root * root));
  const double sign = large_arc == sweep ? -1 : 1;
  // The centre in the ellipse's frame, in radii (ncx = cx'/rx, ncy = cy'/ry: at most 1).
  const double ncx = sign * (root > 0 ? uy / root : 0) * lift;
  const double ncy = -sign * (root > 0 ? ux / root : 0) * lift;
  const double cxp = rx * ncx, cyp = ry * ncy;
  const double cx = cp * cxp - sp * cyp + (0.5 * p0.x + 0.5 * p1.x);
  const double cy = sp * cxp + cp * cyp + (0.5 * p0.y + 0.5 * p1.y);
  // F.6.5.5-6: start angle and sweep; (x1 - cx')/rx = ux - ncx and so on, which cannot overflow.
  auto angle = [](double ux, double uy, double vx, double vy) {
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  };
  const double th1 = angle(1, 0, ux - ncx, uy - ncy);
  double dth = angle(ux - ncx, uy - ncy, -ux - ncx, -uy - ncy);
  if (!sweep && dth > 0) dth -= 2 * M_PI;
  if (sweep && dth < 0) dth += 2 * M_PI;
  if (!std::isfinite(dth) || !std::isfinite(cx) || !std::isfinite(cy)) {
    // Only reachable for radii whose ellipse does not fit in a double (the large arc of a
    // 1e308 radius): left non-finite for the reader to refuse, never cast to an int.
    out.insert(out.end(), {Vec2{HUGE_VAL, HUGE_VAL}, Vec2{HUGE_VAL, HUGE_VAL}, p1});
    return;
  }
  // Pieces of at most 90 degrees, each the standard cubic of a circular arc mapped by the
  // ellipse's affine frame.
  const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(dth) / (M_PI / 2) - 1e-9)));
  const double step = dth / n, t = 4.0 / 3.0 * std::tan(step / 4);
  auto map = [&](double ux, double uy) {
    return Vec2{cx + rx * ux * cp - ry * uy * sp, cy + rx * ux * sp + ry * uy * cp};
  };
  double a = th1;
  for (int i = 0; i < n; ++i) {
    const double b = a + step;
    const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
    out.push_back(map(ca - t * sa, sa + t * ca));
    out.push_back(map(cb + t * sb, sb - t * cb));
    out.push_back(i + 1 == n ? p1 : map(cb, sb));  // land exactly on the endpoint
    a = b;
  }
}

PathDataResult parse_path_data(std::string_view d, std::vector<Subpath>& out) {
  PathDataResult res;
  Cursor c{d};
  Vec2 cur, start, last_ctrl;
  char prev = 0;  // previous command (upper case), for S/T reflection
  char cmd = 0;
  Subpath* sp = nullptr;
  auto fail = [&](size_t at) {
    if (sp && sp->points.size() == 1 && !sp->closed) out.pop_back();
    res.ok = false;
    res.error_offset = at;
    res.out_of_range = c.out_of_range;
    return res;
  };
  c.skip_ws();
  while (true) {
    c.skip_ws();
    if (c.done()) break;
    const size_t seg_start = c.pos;
    const char ch = c.peek();
    if (std::isalpha(static_cast<unsigned char>(ch))) {
      if (arg_count(ch) < 0) return fail(c.pos);
      cmd = ch;
      ++c.pos;
    } else if (!cmd || std::toupper(static_cast<unsigned char>(cmd)) == 'Z') {
      return fail(c.pos);  // numbers with no command, or after Z
    }
    // (else: an implicit repetition of the previous command; after M it is L.)
    if (!sp && std::toupper(static_cast<unsigned char>(cmd)) != 'M') return fail(seg_start);
    const bool rel = std::islower(static_cast<unsigned char>(cmd));
    const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd)));
    double a[7];
    const int n = arg_count(cmd);
    for (int i = 0; i < n; ++i) {
      c.skip_comma_ws();
      if (up == 'A' && (i == 3 || i == 4)) {
        const auto f = c.flag();
        if (!f) return fail(seg_start);
        a[i] = *f;
      } else {
        const auto v = c.number();
        if (!v) return fail(seg_start);
        a[i] = *v;
      }
    }
    c.skip_comma_ws();
    const Vec2 base = rel ? cur : Vec2{};
    switch (up) {
      case 'M': {
        cur = base + Vec2{a[0], a[1]};
        start = cur;
        // A lone moveto draws nothing (not even a cap dot): reuse its subpath.
        if (!(sp && sp->points.size() == 1 && !sp->closed)) out.push_back({});
        sp = &out.back();
        sp->points.clear();
        sp->points.push_back(cur);
        cmd = rel ? 'l' : 'L';  // implicit repetitions are line-tos
        break;
      }
      case 'Z': {
        // A repeated Z (the subpath the previous Z opened is still empty) changes nothing.
        if (sp && !(prev == 'Z' && sp->points.size() == 1 && !sp->closed)) {
          if (!(cur == start)) line_to(sp->points, cur, start);
          sp->closed = true;
          cur = start;
          // A command after Z without M starts a new subpath at the same point.
          out.push_back({});
          sp = &out.back();
          sp->points.push_back(cur);
        }
        break;
      }
      case 'L': case 'H': case 'V': {
        Vec2 to = up == 'L' ? base + Vec2{a[0], a[1]}
                  : up == 'H' ? Vec2{(rel ? cur.x : 0) + a[0], cur.y}
                              : Vec2{cur.x, (rel ? cur.y : 0) + a[0]};
        line_to(sp->points, cur, to);
        cur = to;
        break;
      }
      case 'C': case 'S': {
        Vec2 c1, c2, to;
        if (up == 'C') {
          c1 = base + Vec2{a[0], a[1]};
          c2 = base + Vec2{a[2], a[3]};
          to = base + Vec2{a[4], a[5]};
        } else {
          c1 = (prev == 'C' || prev == 'S') ? cur + (cur - last_ctrl) : cur;
          c2 = base + Vec2{a[0], a[1]};
          to = base + Vec2{a[2], a[3]};
        }
        sp->points.insert(sp->points.end(), {c1, c2, to});
        last_ctrl = c2;
        cur = to;
        break;
      }
      case 'Q': case 'T': {
        Vec2 q, to;
        if (up == 'Q') {
          q = base + Vec2{a[0], a[1]};
          to = base + Vec2{a[2], a[3]};
        } else {
          q = (prev == 'Q' || prev == 'T') ? cur + (cur - last_ctrl) : cur;
          to = base + Vec2{a[0], a[1]};
        }
        // Degree elevation is exact: c1 = p0 + 2/3 (q - p0), c2 = p1 + 2/3 (q - p1).
        sp->points.insert(sp->points.end(),
                          {cur + (2.0 / 3.0) * (q - cur), to + (2.0 / 3.0) * (q - to), to});
        last_ctrl = q;
        cur = to;
        break;
      }
      case 'A': {
        const Vec2 to = base + Vec2{a[5], a[6]};
        arc_to_cubics(cur, a[0], a[1], a[2], a[3] != 0, a[4] != 0, to, sp->points);
        cur = to;
        break;
      }
    }
    prev = up;
  }
  // A trailing lone moveto (or the subpath a final Z opened) draws nothing.
  if (sp && sp->points.size() == 1 && !sp->closed) out.pop_back();
  res.out_of_range = c.out_of_range;
  return res;
}

}  // namespace svgm::svg
