#!/usr/bin/env bash
# Export checks: export_test.sh GROUP SVGMOTION_BINARY TEST_DATA_DIR TOOLS_DIR [NODE_MODULES]
#   clip    render -o clip.mp4|.webm|.gif|frames/%04d.png: frame count and duration as ffprobe
#           reads them, frames equal to `render --time`, the GIF's colours, bad requests refused
#   lottie  fit writes animation.json beside animation.svg; lottie-web (headless Chromium) and
#           librlottie draw it like `svgmotion render --time` at 5 times (PSNR bar below)
#   lottie_paint  the same for gradients (tests/data/lottie/gradients.svg) and clip-path, mask
#           and group opacity (man_clip_mask.svg), with animation.lottie drawn by dotlottie-web,
#           both files valid against the lottie-spec schema (ajv), every player >= 40 dB
# TOOLS_DIR holds png_psnr and rlottie_frames (tests/tools); NODE_MODULES holds lottie-web and
# puppeteer-core, and for lottie_paint dotlottie-web, ajv and the lottie-spec schema
# (.ci/setup.sh installs them into build/npm). Debian's ffmpeg and chromium.
set -u
group=$1 bin=$2 data=$3 tools=$4 node_modules=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# The bar a player's frame must reach against ours (dB over RGB, as ../shared/tools/imgdiff.py
# measures): players differ from our renderer only in anti-aliasing along edges.
lottie_bar=35

must() {
  "$@"
  local rc=$?
  [[ $rc -eq 0 ]] || bad "exit status $rc from: ${*:1:4} ..."
  return $rc
}
# expect_error NAME EXPECTED_SUBSTRING OUTPUT ARGS...: non-zero exit, one stderr line holding
# the substring, nothing written at OUTPUT.
expect_error() {
  local name=$1 want=$2 out=$3; shift 3
  "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  if [[ $rc -ne 0 && $(grep -c '' "$tmp/stderr") -eq 1 ]] && grep -qF -- "$want" "$tmp/stderr" && ! ls "$out"* >/dev/null 2>&1; then
    ok "$name"
  else
    bad "$name (exit $rc, stderr: $(head -c 300 "$tmp/stderr"))"
  fi
}
# probe FILE: "<frames> <duration>" as ffprobe counts them (decoding every frame).
probe() {
  ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames:format=duration \
    -of default=noprint_wrappers=1:nokey=1 "$1" | tr '\n' ' '
}
psnr() { "$tools/png_psnr" "$1" "$2" | sed -n 's/^psnr=\([0-9.]*\).*/\1/p'; }
at_least() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 >= b + 0) }'; }

case $group in
clip)
  svg=$data/export/pulse.svg
  for ext in mp4 webm gif; do
    must "$bin" render "$svg" -o "$tmp/clip.$ext" --fps 10 --size 60 2>"$tmp/err_$ext"
    read -r frames duration <<<"$(probe "$tmp/clip.$ext")"
    check "a .$ext clip of a 1 s loop at 10 fps has 10 frames lasting 1 s (ffprobe: $frames, $duration)" \
      '[[ $frames == 10 ]] && awk -v d="$duration" "BEGIN { exit !(d > 0.95 && d < 1.05) }"'
  done
  check "the clip is reported with its frames, rate and size" 'grep -q "wrote $tmp/clip.gif (10 frames at 10 fps, 1 s, 60x40, loops)" "$tmp/err_gif"'
  check "no temporary file is left" '[[ $(ls -a "$tmp" | grep -c part) -eq 0 ]]'
  must "$bin" render "$svg" -o "$tmp/frames/%04d.png" --fps 10 --size 60 2>/dev/null
  check "a frame sequence writes frames 0000..0009" '[[ $(ls "$tmp/frames" | wc -l) -eq 10 && -s $tmp/frames/0000.png && -s $tmp/frames/0009.png ]]'
  read -r frames duration <<<"$(probe "$tmp/frames/%04d.png")"
  check "ffprobe reads the sequence as 10 frames" '[[ $frames == 10 ]]'
  must "$bin" render "$svg" -o "$tmp/still.png" --time 0.3 --size 60 2>/dev/null
  check "frame 3 is exactly render --time 0.3 (same bytes)" 'cmp -s "$tmp/frames/0003.png" "$tmp/still.png"'
  # The GIF's palette: every frame decoded by FFmpeg against our own render of it.
  ffmpeg -v error -i "$tmp/clip.gif" -start_number 0 "$tmp/gif_%d.png"
  worst=99
  for i in 0 3 7; do
    p=$(psnr "$tmp/frames/000$i.png" "$tmp/gif_$i.png")
    worst=$(awk -v a="$p" -v b="$worst" 'BEGIN { print (a == "" ? 0 : (a < b ? a : b)) }')
  done
  check "GIF frames decoded by FFmpeg match our renders (worst of 3: $worst dB >= 40)" 'at_least "$worst" 40'
  # An animation that plays once ends on its last pose: one frame more.
  sed 's/repeatCount="indefinite"/repeatCount="1" fill="freeze"/g' "$svg" >"$tmp/once.svg"
  must "$bin" render "$tmp/once.svg" -o "$tmp/once/%02d.png" --fps 10 --size 60 2>/dev/null
  must "$bin" render "$tmp/once.svg" -o "$tmp/end.png" --time 1 --size 60 2>/dev/null
  check "a clip of a once-only animation has 11 frames, the last its final pose" '[[ $(ls "$tmp/once" | wc -l) -eq 11 ]] && cmp -s "$tmp/once/10.png" "$tmp/end.png"'
  expect_error "an unknown clip format" "render writes .png images, .mp4, .webm or .gif clips" "$tmp/x.avi" render "$svg" -o "$tmp/x.avi"
  expect_error "a static SVG has no clip" "no SMIL animation" "$tmp/static.gif" render "$data/examples/man.svg" -o "$tmp/static.gif"
  expect_error "--time with a clip" "--time is for a still image" "$tmp/t.mp4" render "$svg" -o "$tmp/t.mp4" --time 1
  expect_error "two frame-number fields" "one frame-number field" "$tmp/seq" render "$svg" -o "$tmp/seq/%d_%d.png"
  expect_error "a bad frame rate" "--fps wants a frame rate" "$tmp/r.gif" render "$svg" -o "$tmp/r.gif" --fps 0
  expect_error "a transparent video" "--background transparent needs PNG output" "$tmp/tr.mp4" render "$svg" -o "$tmp/tr.mp4" --background transparent
  ;;
lottie)
  # Dependencies of the check: installed by .ci/setup.sh.
  missing=
  command -v chromium >/dev/null || missing+=" chromium (Debian)"
  command -v node >/dev/null || missing+=" node (Debian nodejs)"
  [[ -n $node_modules && -d $node_modules/lottie-web && -d $node_modules/puppeteer-core ]] || missing+=" lottie-web and puppeteer-core (npm, in $node_modules)"
  [[ -x $tools/rlottie_frames ]] || missing+=" rlottie_frames (build with Debian's librlottie-dev)"
  if [[ -n $missing ]]; then
    bad "the Lottie players are not installed:$missing; bash .ci/setup.sh test installs them"
    finish
  fi
  # A target with motion: the drawing's figure shifted and turned over 7 frames (there and
  # back), fitted with 4 keyframes (frames 0, 2, 4, 6; 1, 3 and 5 are in-betweens).
  mkdir -p "$tmp/target"
  shifts=(0 5 10 15 10 5 0)
  for i in "${!shifts[@]}"; do
    s=${shifts[$i]}
    sed "s/TRANSFORM/translate($s $((s / 2))) rotate($((s / 4)) 96 64)/" "$data/export/moving.svg" >"$tmp/t$i.svg"
    must "$bin" render "$tmp/t$i.svg" -o "$tmp/target/$i.png" --size 96 2>/dev/null
  done
  sed "s/TRANSFORM/translate(0 0)/" "$data/export/moving.svg" >"$tmp/moving.svg"
  must "$bin" fit "$tmp/moving.svg" --target "$tmp/target" -o "$tmp/out" --iterations 120 --keyframes 4 --size 96 \
    --no-gate --quiet 2>"$tmp/fit_err"
  check "fit writes animation.json beside animation.svg" '[[ -s $tmp/out/animation.json && -s $tmp/out/animation.svg ]]'
  # The Lottie timeline is 24 fps (a folder of frames has no rate of its own), 6 frames long
  # (a seamless loop: frame 6 is frame 0): our frames, as `render --time` draws them, against
  # the two players' at 5 of those times.
  check "the Lottie timeline is the target's: 24 fps, 6 frames" 'grep -q "\"fr\":24,\"ip\":0,\"op\":6," "$tmp/out/animation.json"'
  frames=(0 1 2 3 5)
  # At twice the canvas size (192 x 128): players scale the 96 x 64 canvas as we do.
  must "$bin" render "$tmp/out/animation.svg" -o "$tmp/ours_%d.png" --fps 24 --size 192 2>/dev/null
  must node "$here/lottie/lottie_web_frames.js" "$node_modules" "$tmp/out/animation.json" 192 128 "$tmp/web_" svg "${frames[@]}"
  must "$tools/rlottie_frames" "$tmp/out/animation.json" 192 128 "$tmp/rl_" "${frames[@]}"
  web=() rl=()
  for i in "${!frames[@]}"; do
    web+=("$(psnr "$tmp/ours_${frames[$i]}.png" "$tmp/web_$i.png")")
    rl+=("$(psnr "$tmp/ours_${frames[$i]}.png" "$tmp/rl_$i.png")")
  done
  echo "# PSNR vs svgmotion render at frames ${frames[*]}: lottie-web ${web[*]}; rlottie ${rl[*]}"
  all_above() { local v; for v in "$@"; do at_least "$v" "$lottie_bar" || return 1; done; }
  check "lottie-web (headless Chromium) draws animation.json like our render at 5 times (>= $lottie_bar dB)" 'all_above "${web[@]}"'
  check "librlottie draws animation.json like our render at 5 times (>= $lottie_bar dB)" 'all_above "${rl[@]}"'
  # The figure moved: frames 0 and 3 differ (the checks above are not of a still picture).
  p=$(psnr "$tmp/ours_0.png" "$tmp/ours_3.png")
  check "the fitted animation moves (frames 0 and 3 differ: $p dB < 30)" '! at_least "$p" 30'
  ;;
lottie_paint)
  # The bar of issue 37: players draw paint servers and compositing as we do (anti-aliasing
  # apart), as they draw flat art (46-61 dB).
  paint_bar=40
  missing=
  command -v chromium >/dev/null || missing+=" chromium (Debian)"
  command -v node >/dev/null || missing+=" node (Debian nodejs)"
  for m in lottie-web puppeteer-core @lottiefiles/dotlottie-web ajv @lottie-animation-community/lottie-specs; do
    [[ -n $node_modules && -d $node_modules/$m ]] || missing+=" $m (npm, in ${node_modules:-build/npm/node_modules})"
  done
  [[ -x $tools/rlottie_frames ]] || missing+=" rlottie_frames (build with Debian's librlottie-dev)"
  if [[ -n $missing ]]; then
    bad "the Lottie players are not installed:$missing; bash .ci/setup.sh test installs them"
    finish
  fi
  # Each drawing: its figure (TRANSFORM) turned over 7 frames there and back, fitted with 4
  # keyframes at 128 px (the players' agreement does not depend on the fit's quality).
  for name in gradients man_clip_mask; do
    svg=$data/lottie/$name.svg
    mkdir -p "$tmp/$name/target"
    shifts=(0 5 10 15 10 5 0)
    for i in "${!shifts[@]}"; do
      s=${shifts[$i]}
      sed "s/TRANSFORM/translate($s $((s / 2))) rotate($((s / 2)) 128 96)/" "$svg" >"$tmp/$name/t$i.svg"
      must "$bin" render "$tmp/$name/t$i.svg" -o "$tmp/$name/target/$i.png" --size 128 2>/dev/null
    done
    sed "s/TRANSFORM/translate(0 0)/" "$svg" >"$tmp/$name/in.svg"
    out=$tmp/$name/out
    must "$bin" fit "$tmp/$name/in.svg" --target "$tmp/$name/target" -o "$out" --iterations 40 --keyframes 4 --size 128 \
      --no-gate --quiet 2>"$tmp/$name/fit_err"
    check "$name: fit writes animation.json and animation.lottie beside animation.svg" '[[ -s $out/animation.json && -s $out/animation.lottie ]]'
    check "$name: every paint and layer is expressed (no 'cannot express' warning)" '! grep -q "cannot express" "$tmp/$name/fit_err"'
    node "$here/lottie/lottie_schema_check.js" "$node_modules" "$out/animation.json" "$out/animation.lottie" >"$tmp/$name/schema" 2>&1
    check "$name: animation.json and the .lottie's animation are valid against the lottie-spec schema ($(tr '\n' ' ' <"$tmp/$name/schema" | head -c 300))" \
      '[[ $(grep -c ": valid$" "$tmp/$name/schema") -eq 2 && $(grep -vc ": valid$" "$tmp/$name/schema") -eq 0 ]]'
    read -r w h < <(sed -n 's/.*"w":\([0-9]*\),"h":\([0-9]*\),.*/\1 \2/p' "$out/animation.json" | head -1)
    W=256 H=$((256 * h / w))
    frames=(0 1 2 3 5)
    must "$bin" render "$out/animation.svg" -o "$tmp/$name/ours_%d.png" --fps 24 --size $W 2>/dev/null
    must node "$here/lottie/lottie_web_frames.js" "$node_modules" "$out/animation.json" $W $H "$tmp/$name/web_" svg "${frames[@]}"
    must "$tools/rlottie_frames" "$out/animation.json" $W $H "$tmp/$name/rl_" "${frames[@]}"
    must node "$here/lottie/dotlottie_web_frames.js" "$node_modules" "$out/animation.lottie" $W $H "$tmp/$name/dl_" "${frames[@]}"
    for player in web rl dl; do
      row=()
      for i in "${!frames[@]}"; do row+=("$(psnr "$tmp/$name/ours_${frames[$i]}.png" "$tmp/$name/${player}_$i.png")"); done
      echo "# $name: PSNR vs svgmotion render at frames ${frames[*]}: $player ${row[*]}"
      all_above() { local v; for v in "$@"; do at_least "$v" "$paint_bar" || return 1; done; }
      check "$name: $player draws it like our render at 5 times (>= $paint_bar dB: ${row[*]})" 'all_above "${row[@]}"'
    done
    p=$(psnr "$tmp/$name/ours_0.png" "$tmp/$name/ours_3.png")
    check "$name: the fitted animation moves (frames 0 and 3 differ: $p dB < 35)" '! at_least "$p" 35'
  done
  ;;
*) echo "unknown group $group"; exit 2 ;;
esac
finish
