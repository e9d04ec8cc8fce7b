#!/bin/bash
# How many common motion verbs the prompt parser understands (issue 35, "understand words
# broadly"): the verbs of WordNet's body, contact and motion files (verb.body 29, verb.contact
# 35, verb.motion 38) with a sense in that file counted at least MIN times (default 5) in
# WordNet's tagged texts (cntlist.rev), each parsed in three template prompts by
# verb_coverage (tests/tools/verb_coverage.cpp; built on request). Prints one row per verb and
# template (lemma, file, template, vocabulary|lexicon|none, the motion, the prompt, the
# readings) and the counts per template on stderr. Whether a reading is a plausible motion is
# judged by hand: the tool only counts.
#
#   bash tests/bench/verb_coverage.sh [BUILD_DIR] [MIN] > rows.tsv
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
min=${2:-5}
wn=${SVGM_WORDNET_DIR:-/usr/share/wordnet}
[ -f "$wn/cntlist.rev" ] || { echo "verb_coverage.sh: $wn/cntlist.rev: no WordNet (apt install wordnet-base)" >&2; exit 1; }
cmake --build "$build" --target verb_coverage >/dev/null
awk -v min="$min" '{ split($1, a, "%"); split(a[2], b, ":");
  if (b[1] == 2 && (b[2] == 29 || b[2] == 35 || b[2] == 38) && $3 >= min) print a[1] "\t" b[2] }' "$wn/cntlist.rev" |
  sort -u -k1,1 | "$build/tests/verb_coverage"
