#!/usr/bin/python3
"""How closely our renderer draws thin strokes the way Chromium does (issue 37, item 4).

usage: stroke_agreement.py OUT_DIR --ours BIN [--ours BIN2 ...] [--node-modules DIR] [--only SUBSTR]

Writes a small set of stroke-only SVGs to OUT_DIR (straight lines, gentle and tight curves,
circles, miter/round/bevel joins, butt/round/square caps, at widths 1, 2, 3 and 6 px; one user
unit per pixel), draws each with headless Chromium (tests/tools/svg_screenshots.js, needs
puppeteer-core under --node-modules, default /work/main/build/npm/node_modules) and with
`BIN render X.svg -o Y.png --size W` for each --ours (which may carry render options after the
binary, e.g. --ours "build/frontends/svgmotion --edges browser"), and prints one row per SVG:
the PSNR of each render against Chromium's, from /work/shared/tools/imgdiff.py.
Needs Debian's python3-numpy and python3-pil. Test-only: nothing in the build runs it.
"""
import math, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
IMGDIFF = "/work/shared/tools/imgdiff.py"
W, H = 200, 160


def svg(body, width):
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
            f'viewBox="0 0 {W} {H}"><g fill="none" stroke="#000" stroke-width="{width}">'
            f'{body}</g></svg>\n')


def arc_cubics(cx, cy, r, a0, a1, n):
    """A circular arc as n cubics (the standard 4/3 tan(quarter angle) handles)."""
    d = f"M{cx + r * math.cos(a0):.3f} {cy + r * math.sin(a0):.3f}"
    step = (a1 - a0) / n
    k = 4.0 / 3.0 * math.tan(step / 4.0)
    for i in range(n):
        t0, t1 = a0 + i * step, a0 + (i + 1) * step
        p0 = (cx + r * math.cos(t0), cy + r * math.sin(t0))
        p3 = (cx + r * math.cos(t1), cy + r * math.sin(t1))
        p1 = (p0[0] - k * r * math.sin(t0), p0[1] + k * r * math.cos(t0))
        p2 = (p3[0] + k * r * math.sin(t1), p3[1] - k * r * math.cos(t1))
        d += f" C{p1[0]:.3f} {p1[1]:.3f} {p2[0]:.3f} {p2[1]:.3f} {p3[0]:.3f} {p3[1]:.3f}"
    return d


def cases():
    out = {}
    for w in (1, 2, 3, 6):
        out[f"line-w{w}"] = svg(
            '<path d="M10.3 20.6 L190.2 30.1"/><path d="M15.5 140.2 L120.7 45.9"/>'
            '<path d="M140.25 60 L140.25 150"/><path d="M160.5 60.5 L185.5 150.5"/>', w)
        out[f"gentle-w{w}"] = svg(
            '<path d="M10 140 C 40 20, 160 20, 190 140"/>'
            '<path d="M10.4 150.3 C 70 110, 130 170, 190.6 120.8"/>', w)
        out[f"tight-w{w}"] = svg(
            f'<path d="{arc_cubics(40.3, 50.2, 6, 0.2, 5.9, 4)}"/>'
            f'<path d="{arc_cubics(100.6, 50.7, 12, -1.0, 3.5, 3)}"/>'
            '<path d="M20 120 C 20 90, 60 90, 40 130 S 80 150, 90 100 S 120 80, 130 120"/>'
            '<path d="M150 140 C 200 80, 140 80, 185 140"/>', w)
        out[f"circle-w{w}"] = svg(
            '<circle cx="50.3" cy="50.6" r="30"/><circle cx="140.2" cy="50.1" r="10"/>'
            '<circle cx="150.5" cy="120.5" r="20"/><ellipse cx="60" cy="120" rx="40" ry="15"/>', w)
    for w in (3, 6):
        for j in ("miter", "round", "bevel"):
            out[f"join-{j}-w{w}"] = svg(
                f'<path stroke-linejoin="{j}" d="M15 60 L45 20.5 L75 60 L95.3 25 L110 60 L118 20.2 '
                f'L125 60"/><path stroke-linejoin="{j}" d="M20 140 L100 100 L180 140 L140 90.5 Z"/>'
                f'<path stroke-linejoin="{j}" d="M150 20 L190 40 L150 60.5"/>', w)
        for c in ("butt", "round", "square"):
            out[f"cap-{c}-w{w}"] = svg(
                f'<g stroke-linecap="{c}"><path d="M20 30 L80 35.5"/><path d="M30.5 60 L50.5 140"/>'
                f'<path d="M110 120 C 120 60, 160 60, 170 130"/><path d="M120.3 25.7 L180.6 40.2"/>'
                f'<path d="M100 80 L101 80"/></g>', w)
    return out


def psnr(a, b):
    r = subprocess.run(["/usr/bin/python3", IMGDIFF, a, b], capture_output=True, text=True)
    for tok in r.stdout.split():
        if tok.startswith("psnr="):
            return float(tok[5:])
    raise SystemExit(f"stroke_agreement: imgdiff failed on {a} {b}: {r.stderr.strip()}")


def main(argv):
    if len(argv) < 2 or "--ours" not in argv:
        print(__doc__, file=sys.stderr)
        return 2
    out_dir = argv[1]
    ours = [argv[i + 1] for i, a in enumerate(argv) if a == "--ours"]
    modules = (argv[argv.index("--node-modules") + 1] if "--node-modules" in argv
               else "/work/main/build/npm/node_modules")
    only = argv[argv.index("--only") + 1] if "--only" in argv else ""
    os.makedirs(out_dir, exist_ok=True)
    names = []
    for name, text in cases().items():
        if only not in name:
            continue
        with open(os.path.join(out_dir, name + ".svg"), "w") as f:
            f.write(text)
        names.append(name)
    svgs = [os.path.join(out_dir, n + ".svg") for n in names]
    subprocess.run(["node", os.path.join(HERE, "svg_screenshots.js"), modules, ".chromium.png",
                    *svgs], check=True)
    print("case".ljust(20) + "".join(f"  ours{i}".rjust(9) for i in range(len(ours))))
    for n, s in zip(names, svgs):
        row = n.ljust(20)
        for i, b in enumerate(ours):
            png = os.path.join(out_dir, f"{n}.ours{i}.png")
            binary, *extra = b.split()
            subprocess.run([binary, "render", s, "-o", png, "--size", str(W), *extra], check=True,
                           capture_output=True)
            row += f"{psnr(os.path.join(out_dir, n + '.chromium.png'), png):9.2f}"
        print(row, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
