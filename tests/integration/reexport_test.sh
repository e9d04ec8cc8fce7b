#!/usr/bin/env bash
# `svgmotion export`: a finished fit written again from its checkpoint.bin without fitting, and
# the compact export's editability. reexport_test.sh SVGMOTION_BINARY
#   - a fast fit of a square that moves (and a disc that does not), then `export` with another
#     precision: no optimiser iteration, checkpoint.bin untouched, the SVG differs only in its
#     numbers; `export --full` is byte for byte the fit's own --full export
#   - compact: the still disc is the user's element unchanged; the moving square is wrapped in a
#     new <g> whose animateTransform moves it, so an edit of the square's rest geometry shows in
#     playback (render --time, and Chromium's own SMIL playback when it is installed), as does an
#     edit of the wrapper group's transform
#   - bad input: one line naming the path, exit 1 (usage: 2), nothing written
set -u
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

svg() { printf '<svg xmlns="http://www.w3.org/2000/svg" width="32" height="32">%s</svg>' "$2" >"$tmp/$1.svg"; }
disc='<circle id="disc" cx="25" cy="25" r="4" fill="#c33"/>'
svg sq0 "<rect id=\"sq\" x=\"6\" y=\"6\" width=\"10\" height=\"10\" fill=\"#36c\"/>$disc"
svg sq1 "<rect x=\"6\" y=\"6\" width=\"10\" height=\"10\" fill=\"#36c\" transform=\"translate(5 2) rotate(8 11 11)\"/>$disc"
mkdir -p "$tmp/frames"
"$bin" render "$tmp/sq0.svg" -o "$tmp/frames/0.png" --size 32 2>/dev/null
"$bin" render "$tmp/sq1.svg" -o "$tmp/frames/1.png" --size 32 2>/dev/null
fit=(--target "$tmp/frames" --iterations 100 --keyframes 2 --size 32 --max-segment 0 --loop once --no-gate --quiet)
"$bin" fit "$tmp/sq0.svg" "${fit[@]}" -o "$tmp/fit" 2>"$tmp/fit.err"
check "the fit writes the compact animation and a checkpoint" '[[ -s $tmp/fit/animation.svg && -s $tmp/fit/checkpoint.bin ]] || { cat "$tmp/fit.err"; false; }'
sum_before=$(sha256sum <"$tmp/fit/checkpoint.bin")

# Re-export with another precision, into another folder.
"$bin" export "$tmp/fit" -o "$tmp/p1" --precision 1 >"$tmp/e1.out" 2>"$tmp/e1.err"
rc=$?
check "export exits 0 and says it did not fit" '[[ $rc -eq 0 ]] && grep -q "without fitting" "$tmp/e1.err" || { cat "$tmp/e1.err"; false; }'
check "... no optimiser iteration ran (no iteration line, checkpoint.bin unchanged)" \
  '! grep -qi "iteration" "$tmp/e1.err" && [[ $(sha256sum <"$tmp/fit/checkpoint.bin") == "$sum_before" ]]'
numbers() { sed -E 's/-?[0-9]+(\.[0-9]+)?/N/g' "$1"; }
check "... the SVG differs from the fit's only in its numbers" \
  '! cmp -s "$tmp/fit/animation.svg" "$tmp/p1/animation.svg" && [[ "$(numbers "$tmp/fit/animation.svg")" == "$(numbers "$tmp/p1/animation.svg")" ]]'
check "... its coordinates at one decimal place" \
  '! grep -o "values=\"M[^\"]*\"" "$tmp/p1/animation.svg" | grep -Eq "[0-9]\.[0-9]{2}" && [[ -s $tmp/p1/animation.json ]]'

# The full export from the checkpoint is the fit's own --full export.
"$bin" fit "$tmp/sq0.svg" "${fit[@]}" -o "$tmp/full" --full 2>/dev/null
"$bin" export "$tmp/fit" -o "$tmp/refull" --full 2>/dev/null
check "export --full is byte for byte fit --full" 'cmp -s "$tmp/full/animation.svg" "$tmp/refull/animation.svg" && cmp -s "$tmp/full/animation.json" "$tmp/refull/animation.json"'

# Compact: the disc is left as written; the square moves by a transform on a new <g>. A
# 100-iteration fit at 32 px jitters by about a tenth of a pixel (the disc "moves"): judged at
# 64 px per 1024 (2 px here: the square it fits is bent by up to 1.4 px), as a careful fit is
# at the default quarter pixel.
"$bin" export "$tmp/fit" -o "$tmp/loose" --tolerance 64 2>/dev/null
cp "$tmp/loose/animation.svg" "$tmp/fit/animation.svg"
check "the still disc is the user's element, unanimated" 'grep -qF "$disc" "$tmp/fit/animation.svg"'
check "the moving square is wrapped in a new <g> with animateTransform; the rect itself is untouched" \
  'grep -q "<g><rect id=\"sq\" x=\"6\" y=\"6\" width=\"10\" height=\"10\" fill=\"#36c\"/><animateTransform attributeName=\"transform\"" "$tmp/fit/animation.svg"'
# An edit of the rest shape shows in playback: the square made 4 units wider.
sed 's/id="sq" x="6" y="6" width="10"/id="sq" x="6" y="6" width="14"/' "$tmp/fit/animation.svg" >"$tmp/edited.svg"
"$bin" render "$tmp/fit/animation.svg" -o "$tmp/a.png" --size 32 --time 0.5 2>/dev/null
"$bin" render "$tmp/edited.svg" -o "$tmp/b.png" --size 32 --time 0.5 2>/dev/null
"$bin" render "$tmp/fit/animation.svg" -o "$tmp/a0.png" --size 32 --time 0 2>/dev/null
"$bin" render "$tmp/fit/animation.svg" -o "$tmp/a1.png" --size 32 --time 0.9 2>/dev/null
check "the square moves in playback" '! cmp -s "$tmp/a0.png" "$tmp/a1.png"'
check "an edit of the rest shape shows in playback at 0.5 s" '! cmp -s "$tmp/a.png" "$tmp/b.png"'
# The same in a browser's own SMIL playback: Chromium paused at 0.5 s (skipped without it).
if command -v chromium >/dev/null; then
  shot() {  # SVG PNG: the SVG inlined in a page, 64 px, its animations paused at 0.5 s
    local d=$tmp/shot_$RANDOM
    mkdir -p "$d"
    { echo '<!doctype html><html><body style="margin:0;background:#fff">'; sed '1{/^<?xml/d}' "$1"
      echo "<script>const s=document.querySelector('svg');s.setAttribute('width','64');s.setAttribute('height','64');s.pauseAnimations();s.setCurrentTime(0.5);</script></body></html>"; } >"$d/page.html"
    chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
      --disable-component-update --disable-sync --user-data-dir="$d/profile" --hide-scrollbars --window-size=64,64 \
      --virtual-time-budget=2000 --screenshot="$2" "file://$d/page.html" >/dev/null 2>&1
  }
  sed 's/<g><rect id="sq"/<g transform="translate(6 0)"><rect id="sq"/' "$tmp/fit/animation.svg" >"$tmp/moved.svg"
  shot "$tmp/fit/animation.svg" "$tmp/c_a.png"
  shot "$tmp/fit/animation.svg" "$tmp/c_a2.png"
  shot "$tmp/edited.svg" "$tmp/c_b.png"
  shot "$tmp/moved.svg" "$tmp/c_c.png"
  check "Chromium: two screenshots of the same file at 0.5 s are the same" '[[ -s $tmp/c_a.png ]] && cmp -s "$tmp/c_a.png" "$tmp/c_a2.png"'
  check "Chromium plays an edit of the rest shape (at 0.5 s)" '[[ -s $tmp/c_b.png ]] && ! cmp -s "$tmp/c_a.png" "$tmp/c_b.png"'
  check "Chromium plays an edit of the wrapper group's transform (at 0.5 s)" '[[ -s $tmp/c_c.png ]] && ! cmp -s "$tmp/c_a.png" "$tmp/c_c.png"'
fi

# Clips at the fit's own frame rate (a folder of frames has 24 fps), or at --fps.
rate() { ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of default=nw=1:nk=1 "$1"; }
"$bin" export "$tmp/fit" -o "$tmp/clip24" --format mp4 >/dev/null 2>&1
"$bin" export "$tmp/fit" -o "$tmp/clip12" --format mp4 --fps 12 --quality 30 >/dev/null 2>&1
check "an exported mp4 is at the fit's frame rate ($(rate "$tmp/clip24/animation.mp4")), or at --fps ($(rate "$tmp/clip12/animation.mp4"))" \
  '[[ $(rate "$tmp/clip24/animation.mp4") == 24/1 && $(rate "$tmp/clip12/animation.mp4") == 12/1 ]]'

# The default tolerance is measured (fit/output/tolerance_choice.h). This fit has two values:
# the full export blends them along chords, the compact one turns the square along its arc, 43 dB
# apart at a quarter pixel, so no tolerance holds 46 dB and the full export (1.2 kB, smaller than
# the compact 2.6 kB) is written, byte for byte `export --full`, and export says so.
"$bin" export "$tmp/fit" -o "$tmp/auto" 2>"$tmp/auto.err"
line=$(grep "without fitting" "$tmp/auto.err")
check "export measures its tolerance and, none holding 46 dB, writes the full export ($line)" \
  '[[ $line == *"no tolerance keeps 46 dB of the full export (worst "*" dB at 0.25 px at 1024): wrote it in full"* ]] && cmp -s "$tmp/auto/animation.svg" "$tmp/refull/animation.svg"'

# Bad input.
one_error() {  # NAME EXIT LINE ARGS...
  local name=$1 want_rc=$2 line=$3; shift 3
  "$bin" "$@" >/dev/null 2>"$tmp/err"
  local rc=$?
  check "$name" '[[ $rc -eq $want_rc && $(grep -c "" "$tmp/err") -eq 1 ]] && grep -qxF -- "$line" "$tmp/err" || { echo "exit $rc: $(cat "$tmp/err")"; false; }'
}
mkdir -p "$tmp/plain"
one_error "export of a folder that is not a run or fit directory" 1 "svgmotion: $tmp/plain: not a svgmotion run or fit directory" export "$tmp/plain"
one_error "export of a file" 1 "svgmotion: $tmp/sq0.svg: not a folder" export "$tmp/sq0.svg"
mkdir -p "$tmp/nockpt/.svgmotion"
one_error "export without a checkpoint" 1 "svgmotion: $tmp/nockpt/checkpoint.bin: no checkpoint (no fit has run in $tmp/nockpt)" export "$tmp/nockpt"
one_error "export of an unknown format" 1 "svgmotion: export: unknown format 'png' (svg, lottie, dotlottie, gif, mp4, webm, webp)" export "$tmp/fit" -o "$tmp/never" --format svg,png
check "... writes nothing" '[[ ! -e $tmp/never ]]'
one_error "export of a transparent mp4" 1 "svgmotion: export: --transparent is for gif, webm and webp clips (mp4's H.264 has no alpha)" export "$tmp/fit" -o "$tmp/never" --format svg,mp4 --transparent
one_error "export --quality for a GIF" 1 "svgmotion: export: --quality is for mp4 and webm clips (a CRF, lower is better)" export "$tmp/fit" -o "$tmp/never" --format gif --quality 20
one_error "export --fps without a clip" 1 "svgmotion: export: --fps, --quality and --transparent are for clips (--format gif, mp4, webm or webp)" export "$tmp/fit" -o "$tmp/never" --fps 12
check "... none of them writes anything" '[[ ! -e $tmp/never ]]'
one_error "export without a directory is a usage error" 2 "svgmotion: export: expected one run or fit directory (svgmotion export RUN_DIR|FIT_DIR [-o OUT_DIR])" export
finish
