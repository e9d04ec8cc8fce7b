#!/usr/bin/env python3
"""Scores one procedural motion against its labels (tests/bench/motion_prompts.sh).

Reads a run directory's motion.json: for every control point of the drawing, its rest position
and how far it travels in the target video (its largest distance from rest, canvas units), and
for every path the box it sweeps. With --fitted, the same from the FITTED animation instead:
animation.json (the Lottie export of animation.svg, keyframed path data in canvas pixels, one
layer per path id): each control point's rest is its position at the first keyframe and its
travel its largest distance from there over the keyframes; the swept box is that of the curves
(each cubic at quarters), not of their handles. Labels name regions of the drawing independently of the
engine's rig:
  all                  every point
  -                    no point
  large                the points of backgrounds: paths whose rest box covers at least 45 % of
                       the canvas, reaches two of its edges (within 4 % of the canvas size) and
                       that are painted in the first 35 % of the paths (the issue's "large
                       shapes behind everything at the canvas edges"; the same numbers as
                       engine/src/scene/backdrop.h). Area alone took a figure filling its canvas
                       for a background: an octopus's body (46 % of the canvas, far from every
                       edge) and a ferris wheel's rim (59 %) were left out of every region, so
                       their motion counted against the share and no label could name them.
  x0,y0,x1,y1          points resting in this box, in fractions of the drawing's box (the union
                       of the rest boxes of all paths that are not large), not of large paths
  several joined by '|'
With --no-backdrop the drawing has no background (a reader's word for it): no path is large, the
drawing's box is that of every path. An emoji's figure often fills its canvas (a dog's body, a
mermaid's tail, a waving hand: 45 % of the canvas, touching its edges, painted first), and the
large rule took it for a background and left it out of every box.
Prints one tab-separated line: share of the motion (summed travel) on the expected points, the
ratio of the mean travel of the still points to that of the expected points, the largest travel
of a still point (in % of the canvas diagonal), how many paths left the canvas, and pass/FAIL.
Pass: share >= 0.7, still ratio <= 0.25, nothing out of the canvas.
The travel column (with --verdict) is the issue's floor for motion a viewer can see: the largest
travel of a point that must move, in % of the drawing's box diagonal (the figure's size); the
engine raises a clause's motion to 8 % of it (motion_plan_internal.h, kVisibleTravel). It is one
of the bars: "<8" follows it when it is below the floor, and the case fails (FAIL(travel)) unless
  - every verb of the plan is one whose motion is small by meaning (EXEMPT_VERBS: a pulse, a
    breath or a heartbeat swells by a few % and reads as inflating at 8 % of the size; a tremble
    is a shiver, a jitter of a pixel or two; a twinkle is a blink of light): "<8 exempt", or
  - motion.json warns that the canvas held the motion under the floor (the figure fills its
    picture: amplitudes are scaled down only to stay inside the frame): "<8 canvas".
With --verdict (tests/bench/motion_emoji.sh), the line also says what the ranker thought of the
candidates and what the prompt's parser did not understand: share, still ratio, paths out of
the canvas, travel (below), flagged candidates (ranking.json: those with defects or an error, "k/N" and the
first reason), the plan, motion.json's not_understood words ("(fallback sway)" when none of the
prompt's words was a motion the engine knows), then pass, or FAIL naming the bars
missed (share, still, out, flagged: every candidate must pass the ranker).
"""
import json
import math
import sys

SHARE_MIN = 0.7     # the bar
STILL_RATIO_MAX = 0.25  # still paths move at most a quarter as much as the expected ones
LARGE = 0.45        # share of the canvas: a background (as a reader of the drawing would say)
EDGE = 0.04         # share of the canvas size: a box this close to an edge touches it
TRAVEL_MIN = 8      # % of the figure's diagonal: motion a viewer can see (the item 4)
EXEMPT_VERBS = {"pulse", "tremble", "twinkle"}  # small by meaning (the docstring says why)
EARLY = 0.35        # share of the paths: a background is painted among the first ones


def shape_keyframes(sh):
    """Keyframes of one Lottie path shape: a list of control-point lists (v, v+o, next v+i ...)."""
    k = sh["ks"]["k"]
    frames = [kf["s"][0] for kf in k] if sh["ks"]["a"] else [k]
    out = []
    for f in frames:
        v, i, o = f["v"], f["i"], f["o"]
        pts = []
        n = len(v)
        for j in range(n):
            pts.append(v[j])
            if j + 1 < n or f.get("c"):
                nxt = (j + 1) % n
                pts.append([v[j][0] + o[j][0], v[j][1] + o[j][1]])
                pts.append([v[nxt][0] + i[nxt][0], v[nxt][1] + i[nxt][1]])
        out.append(pts)
    return out


def curve_samples(pts):
    """Points of one shape's cubics (shape_keyframes' order) at t = 0, 1/4, 1/2, 3/4, 1."""
    out = []
    n = len(pts)
    for k in range(0, n - 1, 3):
        c = [pts[k], pts[k + 1], pts[(k + 2) % n], pts[(k + 3) % n]]
        for t in (0, 0.25, 0.5, 0.75, 1):
            u = 1 - t
            w = (u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t)
            out.append([sum(w[i] * c[i][0] for i in range(4)), sum(w[i] * c[i][1] for i in range(4))])
    return out or pts


def fitted_paths(run_dir, canvas):
    """motion.json's per-path fields (rest, swept, point_travel) measured on animation.json."""
    a = json.load(open(run_dir + "/animation.json"))
    sx, sy = canvas[0] / a["w"], canvas[1] / a["h"]
    paths = []

    def shapes(items):
        for it in items:
            if it.get("ty") == "sh":
                yield it
            elif it.get("ty") == "gr":
                yield from shapes(it.get("it", []))

    for layer in a["layers"]:
        if layer.get("ty") != 4:
            continue
        rest_box = [1e300, 1e300, -1e300, -1e300]
        swept = [1e300, 1e300, -1e300, -1e300]
        travel = []
        for sh in shapes(layer.get("shapes", [])):
            kfs = shape_keyframes(sh)
            for f in kfs:  # the box the curves sweep (not their handles, as motion.json)
                for x, y in curve_samples(f):
                    x, y = x * sx, y * sy
                    swept = [min(swept[0], x), min(swept[1], y), max(swept[2], x), max(swept[3], y)]
            for j, q in enumerate(kfs[0]):
                far = 0.0
                for f in kfs:
                    x, y = f[j][0] * sx, f[j][1] * sy
                    far = max(far, math.hypot(x - q[0] * sx, y - q[1] * sy))
                rx, ry = q[0] * sx, q[1] * sy
                rest_box = [min(rest_box[0], rx), min(rest_box[1], ry), max(rest_box[2], rx), max(rest_box[3], ry)]
                travel += [rx, ry, far]
        if travel:
            paths.append({"id": layer.get("nm"), "rest": rest_box, "swept": swept, "point_travel": travel})
    return paths


def ranker_verdict(run_dir):
    """(flagged candidates, candidates, the first flagged one's first reason) from ranking.json."""
    try:
        r = json.load(open(run_dir + "/ranking.json"))
    except (OSError, ValueError):
        return None
    cands = r.get("candidates", [])
    flagged = [c for c in cands if c.get("defects") or c.get("error")]
    first = ""
    if flagged:
        c = flagged[0]
        first = c["error"] if c.get("error") else c["defects"][0]
    return len(flagged), len(cands), first


def main():
    args = [a for a in sys.argv[1:] if a not in ("--fitted", "--verdict", "--no-backdrop")]
    no_backdrop = "--no-backdrop" in sys.argv[1:]
    fitted = "--fitted" in sys.argv[1:]
    verdict = "--verdict" in sys.argv[1:]
    run_dir, move_spec, still_spec = args[0], args[1], args[2]
    m = json.load(open(run_dir + "/motion.json"))
    cw, ch = m["canvas"]
    paths = fitted_paths(run_dir, m["canvas"]) if fitted else m["paths"]

    order = {p["id"]: i for i, p in enumerate(m["paths"])}  # paint order (animation.json keeps the ids)

    def is_large(p):
        if no_backdrop:
            return False
        x0, y0, x1, y1 = p["rest"]
        edges = (x0 <= EDGE * cw) + (y0 <= EDGE * ch) + (x1 >= cw - EDGE * cw) + (y1 >= ch - EDGE * ch)
        early = order.get(p["id"], 0) < EARLY * len(m["paths"])
        return (x1 - x0) * (y1 - y0) >= LARGE * cw * ch and edges >= 2 and early

    fig = [p for p in paths if not is_large(p)] or paths
    dx0 = min(p["rest"][0] for p in fig)
    dy0 = min(p["rest"][1] for p in fig)
    dx1 = max(p["rest"][2] for p in fig)
    dy1 = max(p["rest"][3] for p in fig)

    pts = []  # (x, y, travel, path is large)
    for p in paths:
        t = p["point_travel"]
        big = is_large(p)
        for k in range(0, len(t), 3):
            pts.append((t[k], t[k + 1], t[k + 2], big))

    def members(spec):
        out = set()
        if spec == "-":
            return out
        for part in spec.split("|"):
            if part != "all" and part != "large":
                a, b, c, d = (float(v) for v in part.split(","))
            for i, (x, y, _, big) in enumerate(pts):
                if part == "all":
                    out.add(i)
                elif part == "large":
                    if big:
                        out.add(i)
                else:
                    cx = (x - dx0) / max(dx1 - dx0, 1e-9)
                    cy = (y - dy0) / max(dy1 - dy0, 1e-9)
                    if a <= cx <= c and b <= cy <= d and not big:
                        out.add(i)
        return out

    move, still = members(move_spec), members(still_spec) - members(move_spec)
    total = sum(p[2] for p in pts)
    share = sum(pts[i][2] for i in move) / total if total > 0 else 0.0

    def mean(ids):
        return sum(pts[i][2] for i in ids) / len(ids) if ids else 0.0

    ratio = mean(still) / mean(move) if still and mean(move) > 0 else 0.0
    # The visible-motion floor: the farthest a point that must move goes, against the
    # figure's size (the drawing's box, as the labels' fractions).
    travel = max((pts[i][2] for i in move), default=0.0) / max(math.hypot(dx1 - dx0, dy1 - dy0), 1e-9) * 100
    diag = math.hypot(cw, ch)
    still_max = max((pts[i][2] for i in still), default=0.0) / diag * 100
    # Out of the canvas: a swept box beyond the canvas where the rest box was inside it.
    out = 0
    for p in paths:
        r, s = p["rest"], p["swept"]
        if (s[0] < min(0, r[0]) - 0.5 or s[1] < min(0, r[1]) - 0.5 or s[2] > max(cw, r[2]) + 0.5
                or s[3] > max(ch, r[3]) + 0.5):
            out += 1
    ok = share >= SHARE_MIN and ratio <= STILL_RATIO_MAX and out == 0
    plan = "; ".join(a["verb"] + ":" + (a["parts"] if isinstance(a["parts"], str) else "+".join(a["parts"]))
                     + ("(" + a["region"] + ")" if a.get("region") else "") for a in m["plan"])
    if verdict:
        v = ranker_verdict(run_dir)
        flags = "no ranking.json" if v is None else f"{v[0]}/{v[1]}" + (f" {v[2]}" if v[0] else "")
        words = ",".join(m.get("not_understood", [])) or "-"
        # No motion word understood: the plan is the gentle sway every such prompt gets, which a
        # label of 'all' (or of a figure's top) scores as if it were the motion asked for.
        if any("no motion understood" in w for w in m.get("warnings", [])):
            words += " (fallback sway)"
        seen, small = f"{travel:.1f}", travel < TRAVEL_MIN
        if small:
            seen += "<8"
            verbs = {a["verb"] for a in m["plan"]}
            if verbs and verbs <= EXEMPT_VERBS:
                seen, small = seen + " exempt", False
            elif any("by the canvas, under the" in w for w in m.get("warnings", [])):
                seen, small = seen + " canvas", False
        why = [w for w, bad in (("share", share < SHARE_MIN), ("still", ratio > STILL_RATIO_MAX), ("out", out > 0),
                                ("travel", small), ("flagged", v is None or v[0] > 0)) if bad]
        print(f"{share:.2f}\t{ratio:.2f}\t{out}\t{seen}\t{flags}\t{plan}\t{words}\t{'FAIL(' + ','.join(why) + ')' if why else 'pass'}")
        return
    print(f"{share:.2f}\t{ratio:.2f}\t{still_max:.2f}\t{out}\t{'pass' if ok else 'FAIL'}\t{len(move)}/{len(still)}/{len(pts)}\t{plan}")


if __name__ == "__main__":
    main()
