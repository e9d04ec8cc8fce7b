#!/usr/bin/env bash
# Export checks: export_test.sh GROUP SVGMOTION_BINARY TEST_DATA_DIR TOOLS_DIR [NODE_MODULES]
#   clip    render -o clip.mp4|.webm|.gif|frames/%04d.png: frame count and duration as ffprobe
#           reads them, frames equal to `render --time`, the GIF's colours, bad requests refused
#   lottie  fit writes animation.json beside animation.svg; lottie-web (headless Chromium) and
#           librlottie draw it like `svgmotion render --time` at 5 times (PSNR bar below)
#   lottie_paint  the same for gradients (tests/data/lottie/gradients.svg) and clip-path, mask
#           and group opacity (man_clip_mask.svg), drawn by lottie-web (svg and canvas renderers),
#           librlottie and, from animation.lottie, dotlottie-web,
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
  expect_error "an unknown clip format" "render writes .png images, .mp4, .webm, .gif or .webp clips" "$tmp/x.avi" render "$svg" -o "$tmp/x.avi"
  expect_error "a static SVG has no clip" "no SMIL animation" "$tmp/static.gif" render "$data/examples/man.svg" -o "$tmp/static.gif"
  expect_error "--time with a clip" "--time is for a still image" "$tmp/t.mp4" render "$svg" -o "$tmp/t.mp4" --time 1
  expect_error "two frame-number fields" "one frame-number field" "$tmp/seq" render "$svg" -o "$tmp/seq/%d_%d.png"
  expect_error "a bad frame rate" "--fps wants a frame rate" "$tmp/r.gif" render "$svg" -o "$tmp/r.gif" --fps 0
  expect_error "a transparent mp4" "--background transparent needs PNG, GIF, WebM or WebP output; mp4 (H.264) has no alpha" "$tmp/tr.mp4" render "$svg" -o "$tmp/tr.mp4" --background transparent
  expect_error "a quality out of range" "--quality" "$tmp/q.mp4" render "$svg" -o "$tmp/q.mp4" --quality 52
  expect_error "a quality for a GIF" "--quality is for mp4 and webm clips" "$tmp/q.gif" render "$svg" -o "$tmp/q.gif" --quality 20

  # GIF against FFmpeg's palettegen/paletteuse GIF of the same frames: no larger, and as close
  # to the frames (PSNR of every frame, summed).
  ffmpeg -nostdin -v error -framerate 10 -i "$tmp/frames/%04d.png" -vf "split[a][b];[a]palettegen[p];[b][p]paletteuse" "$tmp/ff.gif"
  ffmpeg -nostdin -v error -i "$tmp/ff.gif" -start_number 0 "$tmp/ff_%d.png"
  ffmpeg -nostdin -v error -i "$tmp/clip.gif" -start_number 0 "$tmp/our_%d.png"
  ours=0 theirs=0
  for i in $(seq 0 9); do
    ours=$(awk -v a="$ours" -v b="$(psnr "$tmp/frames/$(printf %04d "$i").png" "$tmp/our_$i.png")" 'BEGIN { print a + b }')
    theirs=$(awk -v a="$theirs" -v b="$(psnr "$tmp/frames/$(printf %04d "$i").png" "$tmp/ff_$i.png")" 'BEGIN { print a + b }')
  done
  check "the GIF is no larger than FFmpeg's palette GIF ($(stat -c %s "$tmp/clip.gif") <= $(stat -c %s "$tmp/ff.gif") bytes)" \
    '[[ $(stat -c %s "$tmp/clip.gif") -le $(stat -c %s "$tmp/ff.gif") ]]'
  check "the GIF's frames are as close to the renders as FFmpeg's (PSNR summed over 10 frames: $ours >= $theirs)" 'at_least "$ours" "$theirs"'
  # A transparent GIF: pixels outside the drawing decode with alpha 0, pixels of it with 255.
  sed 's/<rect width="60" height="40" fill="#fdf6e3"\/>//' "$svg" >"$tmp/bare.svg"
  must "$bin" render "$tmp/bare.svg" -o "$tmp/bare.gif" --fps 10 --size 60 --background transparent 2>/dev/null
  alpha() {  # alpha() CLIP X Y [DECODER...]: the alpha at (X, Y) of the clip's frame 0 (60 px wide)
    local clip=$1 x=$2 y=$3; shift 3
    ffmpeg -nostdin -v error "$@" -i "$clip" -frames:v 1 -f rawvideo -pix_fmt rgba - |
      od -An -v -tu1 -j $(((y * 60 + x) * 4 + 3)) -N1 | tr -d ' '
  }
  check "a transparent GIF is transparent outside the drawing and opaque on it ($(alpha "$tmp/bare.gif" 1 1), $(alpha "$tmp/bare.gif" 25 15))" \
    '[[ $(alpha "$tmp/bare.gif" 1 1) == 0 && $(alpha "$tmp/bare.gif" 25 15) == 255 ]]'
  # A transparent WebM (VP9 with alpha), decoded by libvpx as a browser would.
  must "$bin" render "$tmp/bare.svg" -o "$tmp/bare.webm" --fps 10 --size 60 --background transparent 2>/dev/null
  check "a transparent WebM decodes with alpha ($(alpha "$tmp/bare.webm" 1 1 -c:v libvpx-vp9), $(alpha "$tmp/bare.webm" 25 15 -c:v libvpx-vp9))" \
    '[[ $(alpha "$tmp/bare.webm" 1 1 -c:v libvpx-vp9) -le 2 && $(alpha "$tmp/bare.webm" 25 15 -c:v libvpx-vp9) -ge 253 ]]'

  # An animated WebP, lossless and transparent: every frame is the render's, alpha included
  # (FFmpeg 5.1 cannot decode animated WebP; Pillow's libwebp can: Debian's python3-pil).
  must "$bin" render "$tmp/bare.svg" -o "$tmp/bare.webp" --fps 10 --size 60 --background transparent 2>/dev/null
  must "$bin" render "$tmp/bare.svg" -o "$tmp/bare/%d.png" --fps 10 --size 60 --background transparent 2>/dev/null
  webp=$(/usr/bin/python3 - "$tmp/bare.webp" "$tmp/bare" <<'PY' 2>&1
import sys
from PIL import Image, ImageSequence
clip = Image.open(sys.argv[1])
def pixels(image):  # RGBA with the colour of fully transparent pixels dropped (WebP drops it)
    return [p if p[3] else (0, 0, 0, 0) for p in image.convert("RGBA").getdata()]
frames = [pixels(f) for f in ImageSequence.Iterator(clip)]
same = sum(f == pixels(Image.open(f"{sys.argv[2]}/{i}.png")) for i, f in enumerate(frames))
print(f"{len(frames)} frames, {same} identical, loop {clip.info.get('loop')}")
PY
)
  check "an animated WebP is lossless and transparent, frame for frame the render ($webp)" '[[ $webp == "10 frames, 10 identical, loop 0" ]]'

  # mp4: the index (moov) before the data (mdat), BT.709 tags, white decoded as white.
  sed 's/#fdf6e3/#ffffff/' "$svg" >"$tmp/white.svg"
  must "$bin" render "$tmp/white.svg" -o "$tmp/white.mp4" --fps 10 --size 60 --quality 18 2>/dev/null
  atoms=$(grep -obUa -e moov -e mdat "$tmp/white.mp4" | head -2 | cut -d: -f2 | tr '\n' ' ')
  check "the mp4 starts with its index (atoms: $atoms)" '[[ $atoms == "moov mdat " ]]'
  tags=$(ffprobe -v error -select_streams v:0 -show_entries stream=color_primaries,color_transfer,color_space,color_range \
    -of default=noprint_wrappers=1 "$tmp/white.mp4" | sort | tr '\n' ' ')
  check "the mp4 is tagged BT.709, limited range ($tags)" \
    '[[ $tags == "color_primaries=bt709 color_range=tv color_space=bt709 color_transfer=bt709 " ]]'
  white=$(ffmpeg -nostdin -v error -i "$tmp/white.mp4" -frames:v 1 -f rawvideo -pix_fmt rgb24 - | od -An -v -tu1 -N3 | xargs)
  check "white decodes as white (pixel 0,0: $white)" '[[ $white == "255 255 255" ]]'
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
    must node "$here/lottie/lottie_web_frames.js" "$node_modules" "$out/animation.json" $W $H "$tmp/$name/canvas_" canvas "${frames[@]}"
    must "$tools/rlottie_frames" "$out/animation.json" $W $H "$tmp/$name/rl_" "${frames[@]}"
    must node "$here/lottie/dotlottie_web_frames.js" "$node_modules" "$out/animation.lottie" $W $H "$tmp/$name/dl_" "${frames[@]}"
    for player in web canvas rl dl; do
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
