#!/usr/bin/env bash
# Two `svgmotion batch` shards at once on one machine, with PoCL's threads unpinned (the
# default for batch) and pinned (--pin): the wall time of each shard, and whether the kernel
# cache both shards filled at once is valid afterwards (every entry's magic, length, FNV-1a).
#   bash tests/bench/batch_shards.sh [SVGMOTION_BINARY] [ROUNDS]
# Items: the bundled man.svg, procedural target (1 candidate, 9 frames at 256 px), 200 fitter
# iterations on 5 keyframes at 128 px; 4 items, 2 per shard. Each mode starts with an empty
# kernel cache of ours, so both shards build and write the same entries at the same time
# (PoCL's own cache is warmed once first: cold, its compilation took minutes here).
# Timings on a machine others are using say little; report the load with them.
set -u
bin=$(realpath "${1:-build/frontends/svgmotion}")
rounds=${2:-1}
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  echo "id,input,prompt"
  for i in 0 1 2 3; do echo "man$i,$src/tests/data/examples/man.svg,the man waves his right arm"; done
} >"$work/m.csv"
settings=(stages.video.candidates=1 stages.video.frames=9 stages.video.size=256 stages.ranker.accept_flagged=true
          stages.fitter.iterations=200 stages.fitter.keyframes=5 stages.fitter.size=128 seed=1)
valid_cache() {
  python3 - "$1/kernels" <<'PY'
import os, struct, sys
d = sys.argv[1]; names = os.listdir(d); good = 0
def fnv(b):
    h = 1469598103934665603
    for c in b: h = ((h ^ c) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h
for n in names:
    b = open(os.path.join(d, n), "rb").read()
    size, h = struct.unpack("<QQ", b[8:24])
    good += b[:8] == b"SVGMKC1\n" and size == len(b) - 24 and h == fnv(b[24:])
print("%d of %d entries valid%s" % (good, len(names), "" if good == len(names) else " (INVALID)"))
PY
}
# Modes: "2 threads" lets each shard's PoCL use both cores (a process outside Slurm);
# "1 thread" gives each one, as a Slurm task with --cpus-per-task=1 on this node would
# (SLURM_* variables set by hand). PoCL pins worker i to core i, so pinned 1-thread shards
# both land on core 0.
slurm1=(env SLURM_JOB_ID=1 SLURM_CPUS_PER_TASK=1 SLURM_CPUS_ON_NODE=1)
export POCL_CACHE_DIR=$work/pocl-cache
SVGMOTION_CACHE_DIR=$work/warm-cache "$bin" run --input "$src/tests/data/examples/man.svg" --prompt "the man waves his right arm" \
  -o "$work/warm" --quiet "${settings[@]}" >/dev/null 2>&1 || echo "warm-up run failed"
# PoCL's cache entries depend on its thread count: warm the 1-thread device too.
"${slurm1[@]}" SVGMOTION_CACHE_DIR=$work/warm-cache "$bin" run --input "$src/tests/data/examples/man.svg" \
  --prompt "the man waves his right arm" -o "$work/warm1" --quiet "${settings[@]}" >/dev/null 2>&1 || echo "warm-up run failed"
for ((r = 1; r <= rounds; r++)); do
  for mode in "2 threads unpinned" "2 threads pinned" "1 thread unpinned" "1 thread pinned"; do
    out=$work/${mode// /_}$r
    flag=()
    [[ $mode == *" pinned" ]] && flag=(--pin)
    pre=()
    [[ $mode == "1 thread"* ]] && pre=("${slurm1[@]}")
    # A fresh kernel cache of ours for every mode (both shards build and write it at once);
    # PoCL's own cache was warmed above, so no mode pays PoCL's minutes of first compilation.
    export SVGMOTION_CACHE_DIR=$out/cache
    for s in 0 1; do
      ( start=$(date +%s%N)
        "${pre[@]}" "$bin" batch "$work/m.csv" -o "$out" --shard $s/2 "${flag[@]}" "${settings[@]}" >"$out.$s.log" 2>&1
        rc=$?
        ms=$((($(date +%s%N) - start) / 1000000))
        printf '%d.%d\n' $((ms / 1000)) $((ms % 1000 / 100)) >"$out.$s.time"
        echo $rc >"$out.$s.rc" ) &
    done
    wait
    printf 'round %d %-18s shard 0: %6.1f s (exit %s)  shard 1: %6.1f s (exit %s)  load %s  cache: %s\n' "$r" "$mode" \
      "$(cat "$out.0.time")" "$(cat "$out.0.rc")" "$(cat "$out.1.time")" "$(cat "$out.1.rc")" \
      "$(cut -d' ' -f1 /proc/loadavg)" "$(valid_cache "$out/cache")"
    tail -n +2 "$out/summary.csv" | cut -d, -f1,2,4,5,7 | tr '\n' ' ' | sed 's/^/    /;s/$/\n/'
  done
done
