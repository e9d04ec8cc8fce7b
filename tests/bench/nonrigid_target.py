#!/usr/bin/python3
"""Non-rigid known-motion targets for judging fits at display size (needs librsvg through gi).

  nonrigid_target.py X.svg OUTDIR [--frames 49] [--size 256] [--hires 1024] [--seed 0]
                     [--degrade NAME] [--hold K] [--pingpong P]

Renders X.svg with librsvg (not our renderer) at twice the hires width, deforms it with a
moving-least-squares *rigid* warp (Schaefer, McPhail and Warren, "Image deformation using
moving least squares", SIGGRAPH 2006): handles are spread over the figure by k-means of its
pixels, one handle near the figure's centre stays put and every other handle swings about it
on its own smooth loop (rotation plus a little stretch), so limbs bend as-rigidly-as-possible
instead of following one global formula. Each frame is area-downsampled to SIZE for the target
video (OUTDIR/target.mp4, H.264) and the clean frames (OUTDIR/clean/%03d.png), and to the hires
width for OUTDIR/clean_hires/%03d.png, the same layout as ../shared/tools/fitcheck.py, whose
`eval ... --hires --between` judges the fit.

--degrade adds one defect that real video models show to the *video only* (the clean frames
stay clean, so the fit is judged against what should have been generated):
  offwhite  background 0.93-0.97 grey with noise (sigma 2/255)   shading  x0.85..1 ramp on parts
  blur      Gaussian blur sigma 1.5 px                            drift    colour drift up to 8%
  jpeg      JPEG quality 20 per frame                             fps8     8 fps (frames held)
  jitter    1-2 px camera shake
  inband    the same shake's part in the loop's lowest two harmonics alone: what is left of it
            when everything the figure's motion (one swing per handle) does not also have is
            taken out. With --hold 1 no stabiliser can leave less; fitting this video is their
            bound (the clean fit is the bound when a part holds still)

--pingpong P samples the motion at P poses (from rest to the middle of the loop, its far
extreme) and plays them back and forth, one pose a frame (0, 1, .., P-1, .., 1, 0, 1, ..): an
abrupt target whose every frame differs a lot from the next (issue 38's acceptance: 6 poses over
24 frames). The clean frames are those poses too.

--hold K keeps the anchor and the K - 1 handles nearest it still (default 1: the anchor alone):
a body that holds while its limbs move, the usual shape of a character animation ("the man
waves his right arm"). With K = 1 every part of the figure swings, and nothing in the frame
says where a camera shake ends and the motion begins.
"""
import math
import os
import sys

import cv2
import numpy as np
import gi
gi.require_version("Rsvg", "2.0")
from gi.repository import Rsvg
import cairo


def render(path, width):
    handle = Rsvg.Handle.new_from_file(path)
    ok, w, h = handle.get_intrinsic_size_in_pixels()
    if not ok or w <= 0:
        r = handle.get_intrinsic_dimensions()
        w, h = r.out_viewbox.width, r.out_viewbox.height
    H = max(1, round(width * h / w))
    surf = cairo.ImageSurface(cairo.FORMAT_ARGB32, width, H)
    ctx = cairo.Context(surf)
    ctx.set_source_rgb(1, 1, 1)
    ctx.paint()
    vp = Rsvg.Rectangle()
    vp.x, vp.y, vp.width, vp.height = 0, 0, width, H
    handle.render_document(ctx, vp)
    surf.flush()
    buf = np.frombuffer(surf.get_data(), np.uint8).reshape(H, surf.get_stride() // 4, 4)[:, :width, :3]
    return buf.copy()


def handles(img, count, seed):
    """Handle points (in units of the image width) spread over the figure by k-means."""
    fg = np.argwhere(img.min(axis=2) < 240)[:, ::-1].astype(np.float32)  # x, y
    rng = np.random.default_rng(seed)
    if len(fg) > 20000:
        fg = fg[rng.choice(len(fg), 20000, replace=False)]
    crit = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 50, 0.5)
    cv2.setRNGSeed(seed)
    _, _, centres = cv2.kmeans(fg, count, None, crit, 3, cv2.KMEANS_PP_CENTERS)
    w = img.shape[1]
    centres = centres / w
    mid = fg.mean(axis=0) / w
    anchor = int(np.argmin(((centres - mid) ** 2).sum(axis=1)))
    return centres, anchor


def held_handles(centres, anchor, hold):
    """The anchor and the hold - 1 handles nearest it (indices)."""
    return np.argsort(((centres - centres[anchor]) ** 2).sum(axis=1))[:max(1, hold)]


def motion(centres, anchor, t, seed, hold=1):
    """Handle positions at time t in [0, 1] (one loop): each swings about the anchor, but for
    the `hold` handles nearest the anchor (the anchor among them), which stay put."""
    rng = np.random.default_rng(seed + 1)
    n = len(centres)
    amp = rng.uniform(6, 14, n) * np.where(rng.random(n) < 0.5, -1, 1)  # degrees
    phase = rng.uniform(0, 2 * math.pi, n)
    stretch = rng.uniform(-0.04, 0.04, n)
    a0 = centres[anchor]
    held = set(held_handles(centres, anchor, hold).tolist())
    out = centres.copy()
    for i in range(n):
        if i in held:
            continue
        s = math.sin(2 * math.pi * t + phase[i]) - math.sin(phase[i])  # 0 at t = 0
        ang = math.radians(amp[i] * s)
        d = (centres[i] - a0) * (1 + stretch[i] * s)
        c, sn = math.cos(ang), math.sin(ang)
        out[i] = a0 + np.array([c * d[0] - sn * d[1], sn * d[0] + c * d[1]])
    return out


def warp(img, p_unit, q_unit, grid=8, held=()):
    """Warp img by the MLS map, evaluated on a coarse grid and interpolated (smooth anyway).
    `held`: handles whose neighbourhood holds exactly still. An MLS map with 1/d^2 weights
    reaches everywhere (a still handle's surroundings still drift with the others), so the
    displacement is faded out near held handles: zero within r of one, whole from 2r on, r half
    the distance from the held handles to the nearest moving one (smoothstep between)."""
    h, w = img.shape[:2]
    gw, gh = w // grid + 2, h // grid + 2
    # Evaluate at grid nodes spaced `grid` pixels, then resize the map to full size.
    # Node j sits where cv2.resize's bilinear sampling puts it: output pixel i reads source
    # coordinate (i + 0.5) / grid - 0.5, so node j is pixel (j + 0.5) * grid - 0.5.
    yy, xx = (np.mgrid[0:gh, 0:gw].astype(np.float64) + 0.5) * grid - 0.5
    gx, gy = mls_rigid_inverse(xx, yy, p_unit * w, q_unit * w)
    if len(held) > 1:  # (one held handle, the anchor, is the plain MLS warp)
        hp = p_unit[list(held)] * w
        moving = np.delete(p_unit, list(held), axis=0) * w
        if len(moving):
            r = 0.5 * np.sqrt(((moving[:, None] - hp[None]) ** 2).sum(-1)).min()
            dist = np.sqrt((xx[..., None] - hp[:, 0]) ** 2 + (yy[..., None] - hp[:, 1]) ** 2).min(-1)
            u = np.clip((dist - r) / r, 0, 1)
            fade = u * u * (3 - 2 * u)
            gx, gy = xx + fade * (gx - xx), yy + fade * (gy - yy)
    mx = cv2.resize(gx.astype(np.float32), (gw * grid, gh * grid), interpolation=cv2.INTER_LINEAR)[:h, :w]
    my = cv2.resize(gy.astype(np.float32), (gw * grid, gh * grid), interpolation=cv2.INTER_LINEAR)[:h, :w]
    return cv2.remap(img, mx, my, cv2.INTER_LINEAR, borderValue=(255, 255, 255))


def mls_rigid_inverse(xx, yy, p, q):
    """At output points (xx, yy), the source point: the MLS rigid deformation that takes the
    deformed handles q back to the rest handles p (the inverse map that remap needs).
    Schaefer et al., eq. 8: f(v) = |v - q*| frot/|frot| + p*, frot the best rotation."""
    v = np.stack([xx, yy], axis=-1)
    d2 = ((v[:, :, None, :] - q[None, None, :, :]) ** 2).sum(-1)
    wt = 1.0 / np.maximum(d2, 1e-6)
    ws = wt.sum(-1, keepdims=True)
    qs = (wt[..., None] * q).sum(2) / ws
    ps = (wt[..., None] * p).sum(2) / ws
    qh = q[None, None] - qs[:, :, None]
    ph = p[None, None] - ps[:, :, None]
    vq = v - qs
    a = (wt * (qh[..., 0] * ph[..., 0] + qh[..., 1] * ph[..., 1])).sum(-1)
    b = (wt * (qh[..., 0] * ph[..., 1] - qh[..., 1] * ph[..., 0])).sum(-1)
    norm = np.sqrt(a * a + b * b) + 1e-12
    c, s = a / norm, b / norm
    fx = c * vq[..., 0] - s * vq[..., 1]
    fy = s * vq[..., 0] + c * vq[..., 1]
    return fx + ps[..., 0], fy + ps[..., 1]


def degrade(frame, name, i, frames, rng, state):
    f = frame.astype(np.float32)
    if name == "offwhite":
        bg = state.setdefault("bg", rng.uniform(0.93, 0.97) * 255)
        paper = f.min(axis=2, keepdims=True) > 250
        f = np.where(paper, bg + rng.normal(0, 2, f.shape), f)
    elif name == "shading":
        h, w = f.shape[:2]
        ramp = 0.85 + 0.15 * np.linspace(0, 1, w)[None, :, None]
        ink = f.min(axis=2, keepdims=True) < 250
        f = np.where(ink, f * ramp, f)
    elif name == "blur":
        f = cv2.GaussianBlur(f, (0, 0), 1.5)
    elif name == "drift":
        g = 0.08 * i / max(1, frames - 1)
        ink = f.min(axis=2, keepdims=True) < 250
        tint = np.array([1 + g, 1 - g * 0.5, 1 - g], np.float32)
        f = np.where(ink, f * tint, f)
    elif name == "jpeg":
        ok, enc = cv2.imencode(".jpg", np.clip(f, 0, 255).astype(np.uint8), [cv2.IMWRITE_JPEG_QUALITY, 20])
        f = cv2.imdecode(enc, cv2.IMREAD_COLOR).astype(np.float32)
    elif name == "fps8":
        if i % 3:
            return state["held"]
    elif name in ("jitter", "inband"):
        dx, dy = rng.uniform(-2, 2, 2) if name == "jitter" else state["inband"][i]
        m = np.float32([[1, 0, dx], [0, 1, dy]])
        f = cv2.warpAffine(f, m, (f.shape[1], f.shape[0]), borderValue=(255, 255, 255))
    out = np.clip(f + 0.5, 0, 255).astype(np.uint8)
    state["held"] = out
    return out


def inband_shake(rng, frames, harmonics=2):
    """The jitter `jitter` draws (same generator, same order), low-passed round the loop (period
    frames - 1; the last frame is the first again) to its mean and first `harmonics` harmonics:
    the frequencies each handle's swing (one harmonic, plus the second its stretch and rotation
    make) occupies, where no low-pass can tell shake from motion."""
    shake = np.array([rng.uniform(-2, 2, 2) for _ in range(frames)])
    spec = np.fft.rfft(shake[:-1], axis=0)
    spec[harmonics + 1:] = 0
    low = np.fft.irfft(spec, n=frames - 1, axis=0)
    return np.vstack([low, low[:1]])


def main(argv):
    svg, outdir = argv[1], argv[2]
    opts = dict(zip(argv[3::2], argv[4::2]))
    frames, size = int(opts.get("--frames", 49)), int(opts.get("--size", 256))
    hires, seed = int(opts.get("--hires", 1024)), int(opts.get("--seed", 0))
    defect, hold = opts.get("--degrade", ""), int(opts.get("--hold", 1))
    pingpong = int(opts.get("--pingpong", 0))
    big = render(svg, 2 * hires)
    h, w = big.shape[:2]
    centres, anchor = handles(cv2.resize(big, (w // 8, h // 8), interpolation=cv2.INTER_AREA), 7, seed)
    for sub in ("clean", "clean_hires"):
        os.makedirs(os.path.join(outdir, sub), exist_ok=True)
    sh = round(size * h / w)
    vw = cv2.VideoWriter(os.path.join(outdir, "target.mp4"), cv2.VideoWriter_fourcc(*"avc1"), 24, (size, sh))
    rng, state = np.random.default_rng(seed + 7), {}
    if defect == "inband":
        state["inband"] = inband_shake(np.random.default_rng(seed + 7), frames)
    for i in range(frames):
        t = i / (frames - 1)
        if pingpong > 1:  # pose j of P, back and forth
            m = i % (2 * (pingpong - 1))
            t = 0.5 * (m if m < pingpong else 2 * (pingpong - 1) - m) / (pingpong - 1)
        q = motion(centres, anchor, t, seed, hold)
        f = warp(big, centres, q, held=held_handles(centres, anchor, hold) if hold > 1 else ())
        hi = cv2.resize(f, (hires, round(hires * h / w)), interpolation=cv2.INTER_AREA)
        lo = cv2.resize(f, (size, sh), interpolation=cv2.INTER_AREA)
        cv2.imwrite(os.path.join(outdir, "clean_hires", f"{i:03d}.png"), hi)
        cv2.imwrite(os.path.join(outdir, "clean", f"{i:03d}.png"), lo)
        vw.write(degrade(lo, defect, i, frames, rng, state) if defect else lo)
    vw.release()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
