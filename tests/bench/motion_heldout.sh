#!/bin/bash
# The held-out look of issue 35 (motion_heldout.tsv): runs every held-out drawing and prompt with
# the default config to its target video (the fitter reduced to one iteration: the fit follows
# the target) and writes OUT/NAME/sheet.png, six frames of the target side by side (t = 0, 0.4,
# 0.8, 1.2, 1.6, 1.95 s), to be looked at by eye: does it read as the prompt, would a designer
# ship it. With FIT=1 the full fit runs and the sheet shows animation.svg rendered at 1024 px
# instead (the issue's final judgement). Never tune on these drawings. Not part of the test
# suite (the emoji sets are not ours to copy: ../shared/tools/emoji_corpus.sh installs them).
#
#   bash tests/bench/motion_heldout.sh BUILD_DIR EMOJI_DIR OUT_DIR
set -u
here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 3 ] || { echo "usage: bash tests/bench/motion_heldout.sh BUILD_DIR EMOJI_DIR OUT_DIR" >&2; exit 2; }
B=$1/frontends/svgmotion; E=$2/node_modules; out=$3
[ -x "$B" ] || { echo "motion_heldout.sh: $B: not built" >&2; exit 1; }
[ -d "$E/openmoji" ] || { echo "motion_heldout.sh: $2: no emoji corpus (bash ../shared/tools/emoji_corpus.sh $2)" >&2; exit 1; }
mkdir -p "$out"
while IFS=$'\t' read -r set file prompt; do
  [[ -z "$set" || "$set" == \#* ]] && continue
  dir=$E/openmoji/color/svg; [[ $set == twemoji ]] && dir=$E/@twemoji/svg
  name=${set}_${file%.svg}; d=$out/$name
  rm -rf "$d"
  if [ "${FIT:-0}" = 1 ]; then
    nice "$B" run --input "$dir/$file" --prompt "$prompt" -o "$d" --quiet </dev/null >"$d.log" 2>&1
  else
    nice "$B" run --input "$dir/$file" --prompt "$prompt" -o "$d" stages.fitter.iterations=1 --quiet </dev/null >"$d.log" 2>&1
  fi
  mkdir -p "$d/frames"
  k=0
  for t in 0 0.4 0.8 1.2 1.6 1.95; do
    k=$((k + 1))
    if [ "${FIT:-0}" = 1 ]; then
      "$B" render "$d/animation.svg" -o "$d/frames/$k.png" --size 1024 --time "$t" >/dev/null 2>&1
    else
      ffmpeg -nostdin -loglevel error -y -ss "$t" -i "$d/target.mp4" -frames:v 1 "$d/frames/$k.png"
    fi
  done
  ffmpeg -nostdin -loglevel error -y -i "$d/frames/%d.png" -vf "scale=320:-1,tile=6x1" -frames:v 1 "$d/sheet.png" &&
    echo "$name	$prompt	$d/sheet.png" || echo "$name	$prompt	no sheet (see $d.log)"
done < "$here/motion_heldout.tsv"
