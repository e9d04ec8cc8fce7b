#!/bin/bash
# The generality check of the figure class from the silhouette skeleton (motion/figure_class.h):
# 60 emoji of figure_class_sample.tsv (15 people, 15 mammals, 10 birds, 10 ground vehicles, 10
# plants; none held out), each rendered to a mask without its backdrops and classified from the
# shape alone and with its annotation as the document's name; prints a line per drawing and the
# two confusion tables (tests/tools/figure_class_probe.cpp). MASK is `fills` (the default:
# strokes dropped, outline gaps closed; better on this sample) or `all` (every painted pixel);
# DUMP=DIR writes each mask with its skeleton as a PNG. Not part of the test suite: the
# drawings are not ours to copy, and are installed by ../shared/tools/emoji_corpus.sh under
# EMOJI (default /work/emoji/node_modules).
#
#   bash tests/bench/figure_class.sh [BUILD_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
emoji=${EMOJI:-/work/emoji/node_modules}
[ -d "$emoji" ] || { echo "figure_class.sh: $emoji: no emoji folder (../shared/tools/emoji_corpus.sh)" >&2; exit 1; }
cmake --build "$build" --target figure_class_probe >/dev/null
list=$(mktemp)
trap 'rm -f "$list"' EXIT
awk -F'\t' -v e="$emoji" '!/^#/ && NF >= 4 {
  dir = $2 == "twemoji" ? e "/@twemoji/svg/" : e "/openmoji/color/svg/"
  print $1 "\t" $2 "\t" dir $3 "\t" $4 }' "$here/figure_class_sample.tsv" > "$list"
args=(--mask "${MASK:-fills}")
[ -n "${DUMP:-}" ] && args+=(--dump "$DUMP")
"$build/tests/figure_class_probe" "$list" "${args[@]}"
