#!/usr/bin/env bash
# The source tree's shape (docs/layout.md): no engine folder includes one that depends on it,
# the include-graph script finds a cycle when there is one, no file is over 800 lines nor a
# function over 150 unless tests/tools/code_sizes.allow keeps it (and says why), and every
# relative link of the README and docs/ resolves.
# Usage: tree_test.sh SOURCE_DIR
set -u
src=$1
graph="$src/tests/tools/include_graph.py"
fails=0
check() {  # check NAME CONDITION
  if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fails=$((fails + 1)); fi
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

python3 "$graph" "$src/engine/src" >"$tmp/graph" 2>&1
rc=$?
check "engine/src has no include cycle between folders" '[[ $rc -eq 0 ]] && ! grep -q "^cycle:" "$tmp/graph"'

mkdir -p "$tmp/tree/a" "$tmp/tree/b" "$tmp/tree/c"
printf '#include "b/y.h"\n' >"$tmp/tree/a/x.h"
printf '#include "a/x.h"\n#include "c/z.h"\n' >"$tmp/tree/b/y.h"
printf '#include <vector>\n' >"$tmp/tree/c/z.h"
python3 "$graph" "$tmp/tree" >"$tmp/cyclic" 2>&1
rc=$?
check "a made-up a <-> b cycle is found, and only it" '[[ $rc -eq 1 ]] && grep -qx "cycle: a -> b, b -> a" "$tmp/cyclic" && [[ $(grep -c "cycle" "$tmp/cyclic") -eq 1 ]]'

# Relative markdown links ([text](path) and [text](path#anchor)) of README.md and docs/*.md.
missing=""
for md in "$src/README.md" "$src"/docs/*.md; do
  while IFS= read -r link; do
    target=${link%%#*}
    [[ -z $target || $target == http* || $target == mailto:* ]] && continue
    [[ -e "$(dirname "$md")/$target" ]] || missing+="$md -> $target; "
  done < <(grep -oE '\]\([^)]+\)' "$md" | sed -E 's/^\]\(//; s/\)$//')
done
check "every relative link of the README and docs/ resolves ${missing:+($missing)}" '[[ -z $missing ]]'
python3 "$src/tests/tools/code_sizes.py" "$src" >"$tmp/sizes" 2>&1
rc=$?
check "no file over 800 lines nor function over 150 that code_sizes.allow does not keep ($(tail -1 "$tmp/sizes"))" '[[ $rc -eq 0 ]]'
mkdir -p "$tmp/sized/engine/src"
{ echo 'int long_one() {'; for i in $(seq 1 160); do echo "  int v$i = $i;"; done; echo '  return 0;'; echo '}'; } >"$tmp/sized/engine/src/long.cpp"
python3 "$src/tests/tools/code_sizes.py" "$tmp/sized" --allow /dev/null >"$tmp/sized.out" 2>&1
rc=$?
check "a made-up function of 163 lines is found, and only it" '[[ $rc -eq 1 ]] && grep -q "^engine/src/long.cpp:1: long_one: 163 lines$" "$tmp/sized.out" && [[ $(grep -c "lines$" "$tmp/sized.out") -eq 1 ]]'
check "the README is a five-minute read (at most 150 lines)" '[[ $(wc -l <"$src/README.md") -le 150 ]]'

echo "$fails failed"
[[ $fails -eq 0 ]]
