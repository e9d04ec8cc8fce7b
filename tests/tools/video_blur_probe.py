#!/usr/bin/python3
"""How blurred a bench target's video really is, luma and chroma apart (issue 38, blur).

  video_blur_probe.py DIR [SIGMA ...]

DIR is a tests/bench/nonrigid_target.py folder (target.mp4 and the clean frames at the video's
size: clean_video/ once fit_nonrigid.sh has run, clean/ before). For each SIGMA (default 0 to
2 in steps of 0.1) the clean first frame is blurred by OpenCV's Gaussian of SIGMA, an affine
colour map (3x4, least squares) takes it to the decoded first frame (the codec's levels: white
decodes to about 250/252/251), and the residual's PSNR is printed in RGB, luma and chroma
(BT.601 Y, B-Y, R-Y). The SIGMA of the best luma PSNR is the blur the video applied as the
codec left it; blur matching (engine/src/fit/target/blur_match.h) should then find
sqrt(1 + SIGMA^2) at the video's size, since its render blur is the loss's sigma-1 Gaussian
composed with the video's.

Measured (twemoji 1f987, 512-px H.264, --degrade blur = sigma 1.5): luma best at 1.50-1.55
(48.4 dB; 1.3: 45.7, 1.8: 44.9), chroma still rising at 1.8 (4:2:0); the clean video's luma
best at 0.3 (46.4 dB, 0: 46.3). The codec does not bias the luma blur: 1.80 is the right
render sigma at 512 px, not 1.6.
"""
import os
import sys

import cv2
import numpy as np


def first_frames(d):
    cap = cv2.VideoCapture(os.path.join(d, "target.mp4"))
    ok, decoded = cap.read()
    if not ok:
        sys.exit(f"{d}/target.mp4: cannot read its first frame")
    sub = "clean_video" if os.path.isdir(os.path.join(d, "clean_video")) else "clean"
    clean = cv2.imread(os.path.join(d, sub, "000.png"))
    if clean is None or clean.shape != decoded.shape:
        sys.exit(f"{d}/{sub}/000.png: missing or not the video's size")
    return clean.astype(np.float32), decoded.reshape(-1, 3).astype(np.float64)


def yuv(bgr):
    b, g, r = bgr[:, 0], bgr[:, 1], bgr[:, 2]
    y = 0.299 * r + 0.587 * g + 0.114 * b
    return y, b - y, r - y


def psnr(e):
    return 10 * np.log10(255.0 ** 2 / max(e, 1e-12))


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    clean, decoded = first_frames(argv[1])
    sigmas = [float(s) for s in argv[2:]] or [0.1 * i for i in range(21)]
    for s in sigmas:
        g = cv2.GaussianBlur(clean, (0, 0), s) if s > 0 else clean
        x = np.hstack([g.reshape(-1, 3), np.ones((decoded.shape[0], 1))]).astype(np.float64)
        a, *_ = np.linalg.lstsq(x, decoded, rcond=None)
        p = x @ a
        py, pu, pv = yuv(p)
        fy, fu, fv = yuv(decoded)
        chroma = (((pu - fu) ** 2).mean() + ((pv - fv) ** 2).mean()) / 2
        print(f"sigma {s:.2f}  rgb {psnr(((p - decoded) ** 2).mean()):.2f}  luma {psnr(((py - fy) ** 2).mean()):.2f}"
              f"  chroma {psnr(chroma):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
