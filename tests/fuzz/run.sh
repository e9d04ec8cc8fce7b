#!/usr/bin/env bash
# The parsers under libFuzzer (ASan+UBSan), in build-fuzz/:
#   bash tests/fuzz/run.sh [SECONDS_PER_TARGET] [TARGET ...]     (default: 30 s, every target; 0: replay)
#   bash tests/fuzz/run.sh fixed [TARGET ...]                     (CI: replay, then a fixed-seed run)
# Builds the targets with clang (tests/fuzz/CMakeLists.txt), then runs each for the given time,
# two at a time, from the seeds: our own files (tests/data, configs/, the regression inputs in
# tests/fuzz/corpus/<target>/) plus what earlier runs found (build-fuzz/corpus/<target>/, kept
# between runs). Each target first replays every seed, so a regression input that crashes again
# fails at once. A finding (crash, sanitizer report, broken property, a 60 s hang, 2 GB of
# memory) is saved in build-fuzz/findings/<target>/ with its log in build-fuzz/logs/<target>.log.
# Prints executions, corpus size, findings and slow inputs (over 10 s, kept beside the findings
# but not counted) per target; exit status 1 if anything was found.
# 0 seconds replays every seed and regression input once without mutating (deterministic, so a
# random new finding never fails an unrelated change); longer runs find more.
# `fixed` replays the seeds and then makes a fixed number of mutations per target (kFixedRuns
# below, a few seconds each) from a fixed random seed, starting from the seeds only (not from
# build-fuzz/corpus): what CI runs. The same sources give the same inputs, and the fuzz
# binaries hold only the parsers, so a change elsewhere replays exactly what passed before;
# a change to a parser is fuzzed a little with inputs derived from its new code.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-30}
shift || true
all=(svg_reader path_data color transform css config)
# Mutations per target in the `fixed` mode: a few seconds of each. Measured on a loaded 2-core
# machine: the six together, replay included, 9 s of CPU (4.8 s user, 4.3 s system).
declare -A kFixedRuns=([svg_reader]=200 [path_data]=5000 [color]=10000 [transform]=10000 [css]=5000 [config]=150)
kFixedSeed=1
fixed=0
if [[ $seconds == fixed ]]; then fixed=1; seconds=0; fi
targets=("$@")
((${#targets[@]})) || targets=("${all[@]}")
[[ $seconds =~ ^[0-9]+$ ]] || { echo "usage: run.sh [SECONDS_PER_TARGET | fixed] [TARGET ...]" >&2; exit 2; }
for t in "${targets[@]}"; do
  [[ " ${all[*]} " == *" $t "* ]] || { echo "run.sh: no fuzz target '$t' (${all[*]})" >&2; exit 2; }
done

out=build-fuzz
cmake -S . -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSVGM_FUZZ=ON -DSVGMOTION_BUILD_TESTS=OFF \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$out" --target fuzz_targets -j 2 >"$out/fuzz_build.log" 2>&1 || { cat "$out/fuzz_build.log"; exit 1; }

# Seeds from our own files, refreshed every run.
seeds=$out/seeds
rm -rf "$seeds"
mkdir -p "$seeds"/{svg_reader,path_data,color,transform,css,config}
svgs=$(find tests/data -name '*.svg' -size -64k | LC_ALL=C sort)  # sorted: the same seeds everywhere
n=0
for f in $svgs; do cp "$f" "$seeds/svg_reader/$((n++)).svg"; done
# Attribute values and <style> text out of those documents, one per file.
split_values() {  # DIR GROUP PATTERN: group GROUP of every match of PATTERN becomes a file
  local dir=$1 group=$2 pattern=$3 i=0
  while IFS= read -r v; do printf '%s' "$v" >"$dir/$((i++))"; done < <(
    grep -ohE "$pattern" $svgs | sed -E "s/$pattern/\\$group/" | sort -u | head -200)
}
split_values "$seeds/path_data" 1 ' d="([^"]*)"'
split_values "$seeds/transform" 1 'transform="([^"]*)"'
split_values "$seeds/color" 2 '(fill|stroke|stop-color|color)="([^"]*)"'
split_values "$seeds/css" 1 'style="([^"]*)"'
for f in configs/*.yaml examples/video_models/*.yaml tests/data/bad_input/*.yaml; do
  [[ -f $f ]] && cp "$f" "$seeds/config/$(basename "$f")"
done

rm -rf "$out/findings" "$out/logs"
mkdir -p "$out/findings" "$out/logs"
fuzz_one() {
  local t=$1
  mkdir -p "$out/corpus/$t" "$out/findings/$t"
  local dict=()
  [[ -f tests/fuzz/$t.dict ]] && dict=(-dict="tests/fuzz/$t.dict")
  # -timeout: an input that runs 60 s is a finding (a hang; the slowest seed needs about 1 s of
  # CPU under ASan, and the wall-clock limit must survive a loaded machine); -rss_limit_mb: so is
  # 2 GB. Inputs slower than 10 s are kept as slow-unit-* for a look, not counted as findings.
  local budget=(-max_total_time="$seconds")
  ((seconds > 0)) || budget=(-runs=0)  # 0 s: replay every seed once, no mutation (deterministic)
  local corpus=$out/corpus/$t
  if ((fixed)); then
    # New inputs go to a fresh folder, so the run starts from the seeds alone. Entropic
    # scheduling and comparison-guided mutation (operands recorded at run time, heap addresses
    # among them) made two runs from one seed differ; without them they repeat exactly.
    budget=(-runs="${kFixedRuns[$t]}" -seed="$kFixedSeed" -entropic=0 -use_cmp=0 -use_memmem=0)
    corpus=$out/fixed_corpus/$t
    rm -rf "$corpus"
    mkdir -p "$corpus"
  fi
  "$out/tests/fuzz/fuzz_$t" "${budget[@]}" -timeout=60 -rss_limit_mb=2048 -max_len=8192 \
    -print_final_stats=1 "${dict[@]}" -artifact_prefix="$out/findings/$t/" \
    "$corpus" "$seeds/$t" "tests/fuzz/corpus/$t" >"$out/logs/$t.log" 2>&1 || true
}
running=0
for t in "${targets[@]}"; do
  fuzz_one "$t" &
  if ((++running >= 2)); then wait -n; running=$((running - 1)); fi
done
wait

found=0
printf '%-11s %12s %8s %9s %5s\n' target executions corpus findings slow
for t in "${targets[@]}"; do
  execs=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$out/logs/$t.log" | tail -1)
  corpus=$(find "$out/corpus/$t" -type f | wc -l)
  ((fixed)) && corpus=$(find "$out/fixed_corpus/$t" -type f | wc -l)
  n=$(find "$out/findings/$t" -type f ! -name 'slow-unit-*' | wc -l)
  slow=$(find "$out/findings/$t" -type f -name 'slow-unit-*' | wc -l)
  printf '%-11s %12s %8s %9s %5s\n' "$t" "${execs:-?}" "$corpus" "$n" "$slow"
  if ((n)) || [[ -z $execs ]]; then
    found=1
    echo "  $t: see $out/logs/$t.log and $out/findings/$t/"
    grep -m3 -E "ERROR|runtime error|fuzz property broken|deadly signal" "$out/logs/$t.log" | sed 's/^/    /' || true
  fi
done
exit $found
