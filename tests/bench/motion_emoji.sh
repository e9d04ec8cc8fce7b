#!/bin/bash
# The motion-from-words suite (issue 35): for every labelled case of motion_emoji.tsv (a drawing of
# the two emoji sets or of ../shared/bench, a prompt worded as a designer would, the regions that
# must move and those that must stay), runs `svgmotion run` with the default config (its number of
# candidates; the fitter at one iteration) up to the target video, then scores candidate 00's
# motion from motion.json (motion_score.py --verdict) and reads the ranker's verdict on every
# candidate from ranking.json. One row per case: share of the motion on the parts named, still
# ratio, paths out of the canvas, the farthest travel of a point that must move (% of the figure's
# diagonal; the issue's floor is 8, a bar unless the verb is exempt or the canvas held it:
# motion_score.py), flagged candidates (k/N and the first reason), the plan, the
# prompt's words not understood ("(fallback sway)": none was a motion word), pass or FAIL(the bars
# missed); then the totals, with the passes that only the fallback sway earned. The issue's bar:
# share >= 0.7 in at least 90 % of the cases, still parts still, nothing out of the frame, no
# candidate flagged.
#
# A run is killed (SIGKILL) once the ranker has written ranking.json: the layers, tracker and
# fitter do not change what is scored and took half of each case's time. (SIGINT, as Ctrl-C, let
# the run finish its current stage and then write the animation so far, as a user wants: every
# case ran its fitter's set-up and the exports, about three times as long.) FIT=1 lets
# every run finish. Runs go one at a time, nice'd. CASES (a regular expression over the case
# names) picks some cases; SETTINGS (space-separated key=value) adds settings to every run;
# RESCORE=1 scores the run directories already in OUT_DIR again without running (after a label
# is corrected). Not part of the test suite: the drawings are not ours to copy; EMOJI_DIR is the
# folder given to ../shared/tools/emoji_corpus.sh (its node_modules/ holds both sets).
#
#   bash tests/bench/motion_emoji.sh BUILD_DIR EMOJI_DIR OUT_DIR
set -u
here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 3 ] || { echo "usage: bash tests/bench/motion_emoji.sh BUILD_DIR EMOJI_DIR OUT_DIR" >&2; exit 2; }
build=$1 emoji=$2 out=$3
# ../shared beside the repository (a worktree one level deeper: BENCH_DIR names it).
bench=${BENCH_DIR:-$here/../../../shared/bench}
[ -d "$bench" ] || bench=$here/../../../../shared/bench
B=$build/frontends/svgmotion
[ -x "$B" ] || { echo "motion_emoji.sh: $B: not built" >&2; exit 1; }
for d in "$emoji/node_modules/@twemoji/svg" "$emoji/node_modules/openmoji/color/svg"; do
  [ -d "$d" ] || { echo "motion_emoji.sh: $d: no such folder (install with ../shared/tools/emoji_corpus.sh $emoji)" >&2; exit 1; }
done
cases=${CASES:-.}
mkdir -p "$out"

# Runs one case into $1 (the run directory) and returns when the ranker has decided (or the run
# ended on its own: every candidate flagged, an error).
run_case() {
  local d=$1 svg=$2 prompt=$3 pid
  rm -rf "$d"
  nice "$B" run --input "$svg" --prompt "$prompt" -o "$d" stages.fitter.iterations=1 ${SETTINGS:-} --quiet \
    < /dev/null > "$d.log" 2>&1 &
  pid=$!
  if [ "${FIT:-0}" != 1 ]; then
    # log.txt's line for the ranker's end comes after ranking.json is in place.
    while kill -0 "$pid" 2>/dev/null; do
      if grep -q "ranker: done" "$d/log.txt" 2>/dev/null; then
        kill -KILL "$pid" 2>/dev/null
        break
      fi
      sleep 0.5
    done
  fi
  wait "$pid"
}

printf 'case\tshare\tstill_ratio\tout_of_canvas\ttravel%%\tflagged\tplan\tnot_understood\tresult\n'
total=0 pass=0 bars=0 unflagged=0 fallback=0 seconds=$SECONDS
while IFS=$'\t' read -r name set file prompt move still backdrop; do
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  [[ "$name" =~ $cases ]] || continue
  case "$set" in
    twemoji) svg=$emoji/node_modules/@twemoji/svg/$file ;;
    openmoji) svg=$emoji/node_modules/openmoji/color/svg/$file ;;
    bench) svg=$bench/$file
      [ -d "$bench" ] || { echo "motion_emoji.sh: $bench: no bench folder (set BENCH_DIR)" >&2; exit 1; } ;;
    data) svg=$here/../data/$file ;;  # our own test drawings (a helicopter: both emoji are held out)
    *) echo "motion_emoji.sh: $name: unknown set '$set' (twemoji, openmoji, bench or data)" >&2; exit 1 ;;
  esac
  d=$out/$name
  total=$((total + 1))
  [ "${RESCORE:-0}" = 1 ] || run_case "$d" "$svg" "$prompt"
  if [ ! -f "$d/motion.json" ]; then
    printf '%s\tno motion.json (see %s.log)\t\t\t\t\t\tFAIL(run)\n' "$name" "$d"
    continue
  fi
  flags=--verdict
  [ "$backdrop" = none ] && flags="$flags --no-backdrop"
  line=$(python3 "$here/motion_score.py" "$d" "$move" "$still" $flags)
  printf '%s\t%s\n' "$name" "$line"
  case "$line" in
    *"(fallback sway)"*pass) fallback=$((fallback + 1)) ;;
  esac
  case "$line" in
    *pass) pass=$((pass + 1)) bars=$((bars + 1)) unflagged=$((unflagged + 1)) ;;
    *"FAIL(flagged)") bars=$((bars + 1)) ;;
    *flagged*) ;;
    *) unflagged=$((unflagged + 1)) ;;
  esac
done < "$here/motion_emoji.tsv"
echo "cases: $total; share/still/out/travel bars met: $bars; no candidate flagged: $unflagged; both (pass): $pass," \
  "of which $fallback on the fallback sway (no motion word understood) ($((SECONDS - seconds)) s)"
