#!/usr/bin/env bash
# Fitting acceptance on the AniClipart benchmark (needs ../shared, not part of the test suite):
# for each SVG, ../shared/tools/fitcheck.py makes a known-motion target (librsvg render, smooth
# warp, 49 frames, H.264), `svgmotion fit` fits it, fitcheck scores every keyframe with librsvg.
# Prints one row per SVG and the means: wall seconds (the fit's own clock) and CPU seconds
# (user + sys, /usr/bin/time; the comparable figure on a shared machine), the load average at
# the end of each fit, and whether the result gate passed it (a rejected fit is scored from
# animation.failed.svg).   usage: fit_aniclipart.sh [BIN] [WORKDIR] [SVG...]
set -u
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../../build/frontends/svgmotion}
work=${2:-/tmp/svgm_fitcheck}
shift 2 2>/dev/null
shared=${SHARED_DIR:-$here/../../../shared}  # SHARED_DIR: ../shared seen from a checkout elsewhere (a worktree)
[ -d "$shared/tools" ] || { echo "$(basename "$0"): $shared: no ../shared (set SHARED_DIR)" >&2; exit 1; }
svgs=("$@")
[[ ${#svgs[@]} -gt 0 ]] || svgs=("$shared"/bench/aniclipart/*.svg)
mkdir -p "$work"
printf '%-20s %7s %7s %8s %8s %6s %8s %7s %8s %5s %s\n' svg psnr iou min_psnr min_iou iters seconds peak_mb cpu_s load status
for svg in "${svgs[@]}"; do
  name=$(basename "$svg" .svg)
  dir=$work/$name
  [[ -f $dir/target.mp4 ]] || /usr/bin/python3 "$shared/tools/fitcheck.py" make "$svg" "$dir" >/dev/null 2>&1
  rm -f "$dir/out/animation.svg" "$dir/out/animation.failed.svg" "$dir/out/checkpoint.bin"
  /usr/bin/time -f '%M %U %S' -o "$dir/rss" "$bin" fit "$svg" --target "$dir/target.mp4" -o "$dir/out" --quiet 2>"$dir/fit.log"
  load=$(cut -d' ' -f1 /proc/loadavg)
  anim=$dir/out/animation.svg status=ok
  [[ -f $anim ]] || { anim=$dir/out/animation.failed.svg; status=rejected; }
  line=$(/usr/bin/python3 "$shared/tools/fitcheck.py" eval "$svg" "$dir" "$anim" | tail -1)
  secs=$(grep -o '"seconds": [0-9.]*' "$dir/out/fit.json" | awk '{print $2}')
  iters=$(grep -o '"iterations": [0-9]*' "$dir/out/fit.json" | awk '{print $2}')
  read -r kb user sys < <(grep -E '^[0-9]+ [0-9.]+ [0-9.]+$' "$dir/rss")
  rss=$(( kb / 1024 ))
  cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN {printf "%.1f", u + s}')
  eval "$(echo "$line" | tr ' ' '\n' | sed 's/=/=/' )"
  printf '%-20s %7.2f %7.4f %8.2f %8.4f %6s %8.1f %7s %8s %5s %s\n' "$name" "$psnr" "$iou" "$min_psnr" "$min_iou" "$iters" "$secs" "$rss" "$cpu" "$load" "$status"
done | tee "$work/table.txt"
awk 'NR>0 {p+=$2; i+=$3; if (NR==1 || $5<mi) mi=$5; s+=$7; c+=$9; r+=$11=="rejected"; n++} END {printf "mean psnr %.2f, mean iou %.4f, lowest keyframe iou %.4f, mean seconds %.1f, mean cpu seconds %.1f, %d rejected, over %d SVGs\n", p/n, i/n, mi, s/n, c/n, r, n}' "$work/table.txt"
