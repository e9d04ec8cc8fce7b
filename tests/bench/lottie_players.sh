#!/usr/bin/env bash
# Lottie export on AniClipart drawings (needs ../shared, not part of the test suite): for each
# SVG, ../shared/tools/fitcheck.py makes a known-motion target (49 frames), `svgmotion fit`
# fits it (ITERS iterations: the players' agreement does not depend on the fit's quality),
# then our render, lottie-web (svg and canvas renderers, headless Chromium), librlottie and
# dotlottie-web (animation.lottie, ThorVG in WebAssembly) draw 5 frames of the result; one row per SVG and player with the PSNR of each frame against ours.
# Then the size of animation.svg/.json at --precision 3, 2, 1 (the same fit written again).
#   usage: lottie_players.sh [BIN] [WORKDIR] [ITERS] [SVG...]   (build/npm from .ci/setup.sh)
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
bin=${1:-$root/build/frontends/svgmotion}
work=${2:-/tmp/svgm_lottie}
iters=${3:-300}
shift 3 2>/dev/null
shared=$root/../shared
svgs=("$@")
[[ ${#svgs[@]} -gt 0 ]] || svgs=("$shared"/bench/aniclipart/{man_dance,octopus,balloon}.svg)
tools=$root/build/tests
modules=${NODE_MODULES:-$root/build/npm/node_modules}  # .ci/setup.sh installs them there
mkdir -p "$work"
frames=(0 6 12 30 45)
for svg in "${svgs[@]}"; do
  name=$(basename "$svg" .svg)
  dir=$work/$name
  [[ -f $dir/target.mp4 ]] || /usr/bin/python3 "$shared/tools/fitcheck.py" make "$svg" "$dir" >/dev/null 2>&1
  [[ -f $dir/out/animation.json ]] ||
    "$bin" fit "$svg" --target "$dir/target.mp4" -o "$dir/out" --iterations "$iters" --no-gate --quiet 2>"$dir/fit.log"
  read -r w h fr < <(/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["w"], d["h"], d["fr"])' "$dir/out/animation.json")
  W=512 H=$(( (512 * h + w / 2) / w ))
  times=()
  for f in "${frames[@]}"; do times+=("$(awk -v f="$f" -v r="$fr" 'BEGIN { printf "%.6f", f / r }')"); done
  for i in "${!frames[@]}"; do "$bin" render "$dir/out/animation.svg" -o "$dir/ours_$i.png" --time "${times[$i]}" --size $W 2>/dev/null; done
  node "$root/tests/integration/lottie/lottie_web_frames.js" "$modules" "$dir/out/animation.json" $W $H "$dir/web_" svg "${frames[@]}"
  node "$root/tests/integration/lottie/lottie_web_frames.js" "$modules" "$dir/out/animation.json" $W $H "$dir/canvas_" canvas "${frames[@]}"
  "$tools/rlottie_frames" "$dir/out/animation.json" $W $H "$dir/rl_" "${frames[@]}"
  node "$root/tests/integration/lottie/dotlottie_web_frames.js" "$modules" "$dir/out/animation.lottie" $W $H "$dir/dl_" "${frames[@]}"
  for player in web canvas rl dl; do
    row=()
    for i in "${!frames[@]}"; do row+=("$("$tools/png_psnr" "$dir/ours_$i.png" "$dir/${player}_$i.png" | sed 's/^psnr=\([0-9.]*\).*/\1/')"); done
    printf '%-12s %-7s %sx%s frames %s: %s\n' "$name" "$player" $W $H "${frames[*]}" "${row[*]}"
  done
  for p in 3 2 1; do
    "$bin" fit "$svg" --target "$dir/target.mp4" -o "$dir/out" --iterations "$iters" --no-gate --quiet --resume --precision $p 2>/dev/null
    printf '%-12s precision %s: input %s B, animation.svg %s B, animation.json %s B\n' "$name" $p "$(stat -c %s "$svg")" \
      "$(stat -c %s "$dir/out/animation.svg")" "$(stat -c %s "$dir/out/animation.json")"
    "$bin" render "$dir/out/animation.svg" -o "$dir/p${p}.png" --time "${times[3]}" --size $W 2>/dev/null
  done
  for p in 2 1; do echo "$name precision $p vs 3 at frame ${frames[3]}: $("$tools/png_psnr" "$dir/p3.png" "$dir/p$p.png")"; done
done
