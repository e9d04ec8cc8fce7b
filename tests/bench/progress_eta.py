#!/usr/bin/env python3
"""How honest `svgmotion run`'s progress display is, from a terminal capture (issue 37, item 6).

Two modes. `record OUT` reads a terminal's raw output on stdin (tmux pipe-pane feeds it) and
writes one JSON line per chunk with the time it arrived, so each redraw has a time. `report
OUT` replays the chunks: a redraw is the text after a carriage return ("\\r  [#### ] 42%  ETA
40 s  note\\x1b[K"); a stage ends at its "done in" redraw. For every redraw showing an ETA after
the first 10 % of its stage's bar, the ETA is compared with the real time left until that
stage's end. Printed: per stage, the redraws, the worst ratio (shown / real, or real / shown
when the ETA was short; 1 is exact), whether the bar ever went back, whether it ended at 100
%, and the longest time without a redraw (a dead spot); and one line with the worst
ratio over all stages (the issue asks for at most 2).

The ETA is shown rounded ("40 s", "3 min", "1.2 h"): a ratio is taken to the nearest value
that rounds to the text shown, so rounding alone never counts as an error.
"""
import json
import re
import sys
import time

REDRAW = re.compile(r"\[([# ]*)\]\s+(\d+)%\s+(?:ETA (\d+(?:\.\d+)?) (s|min|h)\s+)?(.*)$")
STAGE = re.compile(r"^run: (\w+)\b.*\.\.\.$")


def record(path):
    with open(path, "a", buffering=1) as out:
        stdin = sys.stdin.buffer
        while True:
            chunk = stdin.read1(65536) if hasattr(stdin, "read1") else stdin.read(1)
            if not chunk:
                break
            out.write(json.dumps({"t": time.time(), "s": chunk.decode("utf-8", "replace")}) + "\n")


def eta_interval(value, unit):
    """The seconds an ETA text stands for: [low, high] of what rounds to it."""
    v = float(value)
    if unit == "s":
        return max(0.0, v - 0.5), v + 0.5
    if unit == "min":
        return max(0.0, (v - 0.5) * 60), (v + 0.5) * 60
    return max(0.0, (v - 0.05) * 3600), (v + 0.05) * 3600


def redraws(path):
    """(time, text) for every line drawn: what follows each \\r or \\n, up to the next."""
    text, times = "", []
    with open(path) as f:
        for line in f:
            c = json.loads(line)
            text += c["s"]
            times.extend([c["t"]] * len(c["s"]))
    out = []
    start = 0
    for i, ch in enumerate(text + "\n"):
        if ch in "\r\n":
            piece = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", text[start:i]).strip()
            if piece:
                out.append((times[min(i, len(times)) - 1], piece))  # when its last character came
            start = i + 1
    return out


def report(path):
    stages, current = [], None
    for t, piece in redraws(path):
        m = STAGE.match(piece)
        if m:
            current = {"name": m.group(1), "start": t, "draws": [], "end": None}
            stages.append(current)
            continue
        m = REDRAW.search(piece)
        if not m or current is None:
            continue
        pct = int(m.group(2))
        eta = eta_interval(m.group(3), m.group(4)) if m.group(3) else None
        note = m.group(5)
        current["draws"].append((t, pct, eta, note))
        if note.startswith("done in"):
            current["end"] = t
    worst_all = 1.0
    ok = True
    for s in stages:
        d = s["draws"]
        if not d:
            continue
        end = s["end"] if s["end"] is not None else d[-1][0]
        back = any(b[1] < a[1] for a, b in zip(d, d[1:]))
        ended = d[-1][1] == 100
        worst, worst_at, n = 1.0, "", 0
        for t, pct, eta, note in d:
            if eta is None or pct < 10 or note.startswith("done in"):
                continue
            n += 1
            real = end - t
            lo, hi = eta
            shown = min(max(real, lo), hi)  # the value nearest the truth that rounds to the text
            r = max(shown / real, real / shown) if real > 0 and shown > 0 else float("inf")
            if r > worst:
                worst, worst_at = r, f"{pct}% at {t - s['start']:.1f}s: ETA {lo:.0f}-{hi:.0f}s, real {real:.1f}s"
        gaps = [b[0] - a[0] for a, b in zip([(s["start"],)] + d, d)]
        print(f"{s['name']:10s} {end - s['start']:7.1f}s  redraws {len(d):4d}  with ETA after 10%: {n:4d}  "
              f"worst ratio {worst:5.2f}{'  (' + worst_at + ')' if worst_at else ''}  "
              f"bar back: {'YES' if back else 'no'}  ends at 100%: {'yes' if ended else 'NO'}  "
              f"longest gap between redraws {max(gaps):.1f}s")
        worst_all = max(worst_all, worst)
        ok = ok and not back and ended
    print(f"worst ETA ratio after 10%: {worst_all:.2f}  bars monotone and complete: {'yes' if ok else 'NO'}")


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("record", "report"):
        sys.exit("usage: progress_eta.py record|report CAPTURE.jsonl")
    (record if sys.argv[1] == "record" else report)(sys.argv[2])
