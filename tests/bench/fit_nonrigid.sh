#!/usr/bin/env bash
# Fit fidelity at display size on non-rigid targets (needs ../shared and librsvg through gi; not
# part of the test suite). For each SVG, tests/bench/nonrigid_target.py makes a known motion
# (moving-least-squares rigid warp of a librsvg render, a 512 px H.264 video and clean frames at
# 256 and 1024 px), `svgmotion fit` fits it, and ../shared/tools/fitcheck.py judges every keyframe
# at 1024 px (PSNR, IoU, boundary F) and every frame between keyframes at 256 px.
#   usage: [FIT_ARGS="..."] fit_nonrigid.sh [-b BIN] [-w WORKDIR] [-d DEFECT] [-s VIDEO_SIZE]
#          [-k HOLD] SVG...
# DEFECT: one of nonrigid_target.py's --degrade names (the video gets it, the judge sees clean).
# HOLD: nonrigid_target.py's --hold (handles that stay still: a body that holds; default 1).
set -u
here=$(cd "$(dirname "$0")" && pwd)
bin=$here/../../build/frontends/svgmotion
work=/tmp/svgm_nonrigid
defect=""
vsize=512
hold=1
while getopts "b:w:d:s:k:" o; do
  case $o in b) bin=$OPTARG ;; w) work=$OPTARG ;; d) defect=$OPTARG ;; s) vsize=$OPTARG ;; k) hold=$OPTARG ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
svgs=()
for a in "$@"; do svgs+=("$a"); done
shared=${SHARED_DIR:-$here/../../../shared}  # SHARED_DIR: ../shared seen from a checkout elsewhere (a worktree)
[ -d "$shared/tools" ] || { echo "$(basename "$0"): $shared: no ../shared (set SHARED_DIR)" >&2; exit 1; }
py=/usr/bin/python3
mkdir -p "$work"
printf '%-14s %7s %7s %7s %7s %7s %7s %8s %7s %7s\n' svg psnr min_iou hires min_hi bf min_bf between seconds peak_mb
for svg in "${svgs[@]}"; do
  name=$(basename "$svg" .svg)
  dir=$work/$name${defect:+_$defect}
  [[ $hold == 1 ]] || dir=${dir}_hold$hold
  [[ -f $dir/target.mp4 ]] || $py "$here/nonrigid_target.py" "$svg" "$dir" --size "$vsize" --hires 1024 \
    --hold "$hold" ${defect:+--degrade $defect} >/dev/null 2>&1
  # The judge compares with clean frames at 256 px (the fit's size) and 1024 px.
  if [[ ! -d $dir/clean_video ]]; then  # once: clean/ becomes the 256-px frames, the video-size ones move aside
    $py - "$dir" <<'PY'
import sys, os, cv2
d = sys.argv[1]
os.makedirs(d + "/clean256", exist_ok=True)
for f in sorted(os.listdir(d + "/clean_hires")):
    im = cv2.imread(d + "/clean_hires/" + f)
    cv2.imwrite(d + "/clean256/" + f, cv2.resize(im, (256, round(256 * im.shape[0] / im.shape[1])), interpolation=cv2.INTER_AREA))
PY
    mv "$dir/clean" "$dir/clean_video" && mv "$dir/clean256" "$dir/clean"
  fi
  rm -rf "$dir/out" "$dir/full"
  /usr/bin/time -f '%M' -o "$dir/rss" "$bin" fit "$svg" --target "$dir/target.mp4" -o "$dir/out" --quiet ${FIT_ARGS:-} 2>"$dir/fit.log"
  anim=$dir/out/animation.svg status=""
  [[ -f $anim ]] || { anim=$dir/out/animation.failed.svg; status=" REJECTED"; }
  [[ -f $anim ]] || { echo "$name: the fit wrote no animation (see $dir/fit.log)"; continue; }
  # The judge reads each path's animated `d`, not `animateTransform`: the compact export's
  # wrapper transforms would be scored as still parts. It judges the full export of the same fit.
  if grep -q animateTransform "$anim"; then
    "$bin" export "$dir/out" -o "$dir/full" --full --format svg --quiet && anim=$dir/full/$(basename "$anim")
  fi
  $py "$shared/tools/fitcheck.py" eval "$svg" "$dir" "$anim" --hires --between > "$dir/eval.txt"
  line=$(tail -1 "$dir/eval.txt")
  secs=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"])' "$dir/out/fit.json")  # the fit's own, not its keyframe choice's
  rss=$(( $(tail -1 "$dir/rss") / 1024 ))
  eval "$(echo "$line" | tr ' ' '\n' | grep '=')"
  min_hi=$(grep '^keyframe' "$dir/eval.txt" | grep -o 'hires_psnr=[0-9.]*' | cut -d= -f2 | sort -n | head -1)
  printf '%-14s %7.2f %7.4f %7.2f %7.2f %7.4f %7.4f %8.2f %7.1f %s\n' "$name" "$psnr" "$min_iou" "$hires_psnr" "$min_hi" "$hires_bf" "$min_hires_bf" "$between_psnr" "$secs" "$rss$status"
done
