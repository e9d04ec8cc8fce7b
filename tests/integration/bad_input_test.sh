#!/usr/bin/env bash
# The bad-input corpus (tests/data/bad_input/): every file there goes through the commands its
# line in expected.txt names, and each must fail the way a user should see it fail: exit
# status 1, exactly one line on stderr, that line as expected.txt says, and no output at all
# (no PNG, no output folder, no run directory, no temporary file).
# usage: bad_input_test.sh GROUP SVGMOTION_BIN TEST_DATA_DIR     GROUP: svg | config | target
#   svg     each SVG through render, fit (to a good target) and run (with that target)
#   config  each config file through run
#   target  each broken target video or frames folder through fit and run (a good SVG)
set -u
group=$1 bin=$2 data=$3
source "$(cd "$(dirname "$0")" && pwd)/test_lib.sh"
corpus=$data/bad_input
table=$corpus/expected.txt

# A good drawing and a good two-frame target, made here with our renderer.
good=$tmp/good.svg
printf '<svg xmlns="http://www.w3.org/2000/svg" width="32" height="32"><path d="M4 4 L28 8 L10 28 Z" fill="#c33"/></svg>' >"$good"
mkdir -p "$tmp/frames"
for i in 0 1; do "$bin" render "$good" -o "$tmp/frames/$i.png" --size 32 2>/dev/null || bad "render the good target"; done
small=(stages.video.plugin=file stages.ranker.plugin=first stages.fitter.iterations=2 stages.fitter.keyframes=2
       stages.fitter.size=32)

# expect FILE COMMAND WANT: runs COMMAND on FILE in a fresh folder and checks the failure.
expect() {
  local file=$1 cmd=$2 want=$3 work
  work=$(mktemp -d "$tmp/w.XXXX")
  case $group/$cmd in
    svg/render) "$bin" render "$file" -o "$work/out.png" ;;
    svg/fit) "$bin" fit "$file" --target "$tmp/frames" -o "$work/out" --keyframes 2 --size 32 --iterations 2 --quiet ;;
    svg/run) "$bin" run --input "$file" -o "$work/out" --quiet "${small[@]}" "stages.video.path=$tmp/frames" ;;
    config/run) "$bin" run "$file" --input "$good" -o "$work/out" --quiet ;;
    target/fit) "$bin" fit "$good" --target "$file" -o "$work/out" --keyframes 2 --size 32 --iterations 2 --quiet ;;
    target/run) "$bin" run --input "$good" -o "$work/out" --quiet "${small[@]}" "stages.video.path=$file" ;;
    *) echo "expected.txt: no command '$cmd' for $group files"; exit 2 ;;
  esac >"$work.stdout" 2>"$work.stderr"
  local rc=$? lines line
  lines=$(grep -c '' "$work.stderr")
  line=$(head -n 1 "$work.stderr")
  # A glob: '*' is any text; a backslash in the expected line stands for itself.
  local pattern="svgmotion: ${want//\\/\\\\}"
  pattern=${pattern//\{file\}/$file}
  local name="$cmd $(basename "$file")"
  if [[ $rc -ne 1 ]]; then
    bad "$name: exit status $rc, not 1 ($(head -c 300 "$work.stderr"))"
  elif [[ $lines -ne 1 ]]; then
    bad "$name: $lines lines on stderr, not 1: $(head -c 300 "$work.stderr")"
  elif [[ $line != $pattern ]]; then
    bad "$name: the line is '$line', expected '$pattern'"
  elif [[ -n $(ls -A "$work") ]]; then
    bad "$name: output appeared: $(ls -A "$work" | head -5 | tr '\n' ' ')"
  else
    ok "$name: $want"
  fi
}

# Every file of the group is in the table (a file added without an expectation fails), and
# every line of the table names a file that is there.
listed=()
while IFS=$'\t' read -r entry commands want; do
  [[ -z $entry || $entry == \#* || $entry != $group/* ]] && continue
  [[ -e $corpus/$entry ]] || { bad "expected.txt names $entry, which is not in $corpus"; continue; }
  listed+=("$entry")
  for cmd in $commands; do expect "$corpus/$entry" "$cmd" "$want"; done
done <"$table"
for f in "$corpus/$group"/*; do
  entry=$group/$(basename "$f")
  [[ " ${listed[*]} " == *" $entry "* ]] || bad "$entry has no line in expected.txt"
done
check "the $group corpus is not empty" '[[ ${#listed[@]} -ge 5 ]]'
finish
