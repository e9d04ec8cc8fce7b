#!/bin/bash
# The procedural motion's acceptance suite (issue 11): for every labelled case of
# motion_prompts.tsv (a drawing of ../shared/bench, its prompt, the regions that should move
# and those that should stay), runs `svgmotion run` up to the target video and scores the
# motion of the target's known control points from motion.json (motion_score.py): the share of
# the motion on the expected regions, how much the still regions move, and whether anything
# leaves the canvas. With ITERATIONS 1 (the default) the fitter runs one iteration only and the
# TARGET is scored (motion.json); with more, the FITTED animation is scored (animation.json, the
# Lottie export of animation.svg: motion_score.py --fitted), the fitter reduced to ITERATIONS
# (the full 2000 do not fit a shared CPU's budget; say so with the numbers). CASES (a regular
# expression over the case names) picks some cases; SETTINGS (space-separated key=value) adds
# settings to every run (SETTINGS=stages.ranker.accept_flagged=true fits a video the ranker
# flagged, to measure the motion of a case the ranker stops). Fits run one at a time, nice'd. Not part of
# the test suite: the drawings are not ours to copy (see ../shared/bench/*/LICENSES.md).
#
#   bash tests/bench/motion_prompts.sh [BUILD_DIR] [OUT_DIR] [ITERATIONS]
set -u
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
out=${2:-/tmp/motion_prompts}
bench=${BENCH_DIR:-$here/../../../shared/bench}
B=$build/frontends/svgmotion
[ -x "$B" ] || { echo "motion_prompts.sh: $B: not built" >&2; exit 1; }
[ -d "$bench" ] || { echo "motion_prompts.sh: $bench: no bench folder" >&2; exit 1; }
iters=${3:-1}
cases=${CASES:-.}
fitted=""
[ "$iters" -gt 1 ] && fitted="--fitted"
mkdir -p "$out"
printf 'case\tshare\tstill_ratio\tstill_max_%%diag\tout_of_canvas\tresult\tmove/still/points\tplan\n'
pass=0 total=0
while IFS=$'\t' read -r name svg prompt move still; do
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  [[ "$name" =~ $cases ]] || continue
  d=$out/$name
  rm -rf "$d"
  nice "$B" run --input "$bench/$svg" --prompt "$prompt" -o "$d" stages.fitter.iterations="$iters" \
    stages.video.candidates=1 ${SETTINGS:-} --quiet < /dev/null > "$d.log" 2>&1
  if [ ! -f "$d/motion.json" ] || { [ -n "$fitted" ] && [ ! -f "$d/animation.json" ]; }; then
    printf '%s\tno motion.json or animation.json (see %s.log)\n' "$name" "$d"
    total=$((total + 1))
    continue
  fi
  line=$(python3 "$here/motion_score.py" "$d" "$move" "$still" $fitted)
  printf '%s\t%s\n' "$name" "$line"
  total=$((total + 1))
  case "$line" in *pass*) pass=$((pass + 1)) ;; esac
done < "$here/motion_prompts.tsv"
echo "passed $pass of $total"
