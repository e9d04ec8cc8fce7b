#!/usr/bin/env bash
# `svgmotion batch` integration tests: batch_test.sh MODE SVGMOTION_BINARY SOURCE_DIR
#   local  the command itself: manifest errors, a failing item among good ones, the summary,
#          the re-run that skips finished items, two shards of one manifest
#   robust bad Slurm variables (exit 2), a folder as the manifest, options among overrides,
#          a reason that is not UTF-8, a second batch of a running shard, SIGKILL of a batch
#          (its item's run ends too), a re-run waiting for a run still in the item's folder,
#          the summary on demand
#   slurm  a real one-node Slurm (munged, slurmctld, slurmd on localhost, from the Debian
#          packages, with a config written here and stopped on exit) runs
#          examples/slurm/svgmotion_array.sbatch as a 3-task array over 6 items with
#          `sbatch --wait`; every item is taken exactly once, the summary is complete, the
#          broken item is reported and the others are done, the shared kernel cache is valid.
#          Needs root; without Slurm or root it is skipped (exit 77) unless SVGM_REQUIRE_SLURM=1
#          (set by .ci/setup.sh test, which installs the packages).
# Items are tiny: 48-px drawings made here, a 3-frame target each, 30 fitter iterations.
set -u
mode=$1 bin=$2 src=$3
source "$(cd "$(dirname "$0")" && pwd)/test_lib.sh"

# A small drawing: a coloured square and a blue disc.
drawing() {
  printf '<svg xmlns="http://www.w3.org/2000/svg" width="48" height="48" viewBox="0 0 48 48">'
  printf '<rect id="box" x="6" y="14" width="16" height="16" fill="%s"/>' "$1"
  printf '<circle id="dot" cx="32" cy="24" r="7" fill="#3050d0"/></svg>\n'
}

# frames COLOUR DIR: the drawing's target, 3 PNG frames moving right by 0, 1, 2 px, painted
# here (one python process instead of an OpenCL start-up per frame): white, the square, the disc.
frames() {
  "$py" - "$1" "$2" <<'PY'
import os, struct, sys, zlib
colour, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
box = tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
for f in range(3):
    rows = b""
    for y in range(48):
        row = bytearray(b"\0")
        for x in range(48):
            px, py_ = x + 0.5 - f, y + 0.5
            rgb = (255, 255, 255)
            if 6 <= px < 22 and 14 <= py_ < 30: rgb = box
            if (px - 32) ** 2 + (py_ - 24) ** 2 < 49: rgb = (0x30, 0x50, 0xd0)
            row += bytes(rgb)
        rows += bytes(row)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 48, 48, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
    open(os.path.join(out, "%d.png" % f), "wb").write(png)
PY
}

# make_items N: N drawings with a 3-frame target each (the drawing moving right by 0..2 px),
# a broken SVG, and manifest.csv listing them (the broken one second).
make_items() {
  local n=$1 colours=("#d03030" "#30a040" "#c0a020" "#9030c0" "#20a0a0" "#e07020")
  mkdir -p "$tmp/in"
  echo "id,input,prompt,target,overrides" >"$tmp/in/manifest.csv"
  for ((i = 0; i < n; i++)); do
    drawing "${colours[i]}" >"$tmp/in/d$i.svg"
    frames "${colours[i]}" "$tmp/in/t$i" || bad "frames of item $i"
    echo "d$i,d$i.svg,it moves right,t$i," >>"$tmp/in/manifest.csv"
    if ((i == 0)); then
      printf '<svg xmlns="http://www.w3.org/2000/svg"><g><rect width="5"></svg>' >"$tmp/in/broken.svg"
      echo "broken,broken.svg,it moves,t0," >>"$tmp/in/manifest.csv"
    fi
  done
}
small=(stages.ranker.plugin=first stages.fitter.iterations=30 stages.fitter.keyframes=3 stages.fitter.size=48
       stages.tracker.plugin=none)

# field N of the summary row for item ID
field() { awk -F, -v id="$1" -v n="$2" '$1 == id { print $n }' "$3"; }

case $mode in
local)
  make_items 2  # d0, broken, d1
  export SVGMOTION_CACHE_DIR=$tmp/cache
  "$bin" batch "$tmp/in/manifest.csv" -o "$tmp/out" "${small[@]}" >"$tmp/o1" 2>"$tmp/e1"
  rc=$?
  check "a batch with a broken item exits 1 naming the count and the summary" \
    '[[ $rc -eq 1 ]] && grep -qx "svgmotion: batch: 1 of 3 items of shard 0/1 not done (see $tmp/out/summary.csv)" "$tmp/e1"'
  check "the item after the broken one still runs" '[[ $(grep -c ": done in" "$tmp/o1") -eq 2 ]] && [[ -s $tmp/out/d1/animation.svg ]]'
  check "the summary has a row per item, in manifest order" \
    '[[ $(cut -d, -f1,2 "$tmp/out/summary.csv" | tr "\n" " ") == "id,status d0,done broken,failed d1,done " ]]'
  check "the broken item's reason is the run's error line naming its file" \
    '[[ $(field broken 3 "$tmp/out/summary.csv") == *"broken.svg"* ]] && grep -q "\"status\": \"failed\"" "$tmp/out/broken/batch.json"'
  check "done items have seconds, fidelity (PSNR, IoU) and peak memory" \
    'awk -F, '"'"'$2 == "done" && !($4 > 0 && $5 > 10 && $6 > 0.5 && $6 <= 1 && $7 > 10) { bad = 1 } END { exit bad }'"'"' "$tmp/out/summary.csv"'
  check "summary.json agrees (counts and total)" \
    '"$py" -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(not (j[\"total\"]==3 and j[\"counts\"]==dict(done=2, failed=1)))" "$tmp/out/summary.json"'
  cp "$tmp/out/summary.csv" "$tmp/first.csv"
  "$bin" batch "$tmp/in/manifest.csv" -o "$tmp/out" "${small[@]}" >"$tmp/o2" 2>"$tmp/e2"
  check "a re-run skips the finished items (up to date) and retries the broken one" \
    '[[ $(grep -c ": done.*(up to date)$" "$tmp/o2") -eq 2 ]] && grep -q "broken: failed" "$tmp/o2"'
  check "a skipped item keeps the seconds of the run that fitted it" \
    '[[ $(field d1 4 "$tmp/out/summary.csv") == $(field d1 4 "$tmp/first.csv") ]]'
  # Two shards of one manifest at once into the same folder (up to date by now, so quick):
  # each takes its own items, and the summary both rewrite under the lock stays complete.
  "$bin" batch "$tmp/in/manifest.csv" -o "$tmp/out" --shard 0/2 "${small[@]}" >"$tmp/s0" 2>&1 &
  p0=$!
  "$bin" batch "$tmp/in/manifest.csv" -o "$tmp/out" --shard 1/2 "${small[@]}" >"$tmp/s1" 2>&1
  rc1=$?
  wait $p0
  rc0=$?
  check "shard 0/2 takes items 1 and 3 (d0, d1), shard 1/2 item 2 (broken)" \
    '[[ $(grep -o "] [a-z0-9]*: running" "$tmp/s0" | tr "\n" " ") == "] d0: running ] d1: running " &&
       $(grep -o "] [a-z0-9]*: running" "$tmp/s1" | tr "\n" " ") == "] broken: running " && $rc0 -eq 0 && $rc1 -eq 1 ]]'
  check "two shards at once leave a complete summary" \
    '[[ $(cut -d, -f2 "$tmp/out/summary.csv" | sort | uniq -c | tr -s " " | tr "\n" ";") == " 2 done; 1 failed; 1 status;" ]]'
  printf 'input,colour\nx.svg,red\n' >"$tmp/bad.csv"
  "$bin" batch "$tmp/bad.csv" -o "$tmp/none" >/dev/null 2>"$tmp/e3"
  rc=$?
  check "a malformed manifest: one line naming file and line, exit 1, nothing written" \
    '[[ $rc -eq 1 && $(grep -c "" "$tmp/e3") -eq 1 && ! -e $tmp/none ]] && grep -q "bad.csv:1: unknown column '"'"'colour'"'"'" "$tmp/e3"'
  "$bin" batch "$tmp/in/manifest.csv" -o "$tmp/none" --shard 2/2 >/dev/null 2>"$tmp/e4"
  rc=$?
  check "a bad --shard is one line, exit 1" '[[ $rc -eq 1 && ! -e $tmp/none ]] && grep -qx "svgmotion: --shard 2/2: I must be in 0..1 and N at least 1" "$tmp/e4"'
  finish
  ;;
robust)
  # Bad input and crossed batches, each one line and nothing half-done; the items here never
  # fit (they fail at their config check or wait on a generator that sleeps), so this is quick.
  make_items 1  # d0, broken
  export SVGMOTION_CACHE_DIR=$tmp/cache
  alive() { [[ -e /proc/$1 ]] && ! grep -q '^[0-9]* ([^)]*) Z' "/proc/$1/stat" 2>/dev/null; }
  # Slurm's variables, full-string and range-checked: 2^32 tasks was a count of 0 (SIGFPE).
  SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=4294967296 "$bin" batch "$tmp/in/manifest.csv" -o "$tmp/none" \
    >"$tmp/o1" 2>"$tmp/e1"
  rc=$?
  check "SLURM_ARRAY_TASK_COUNT=4294967296: exit 2, one line naming the variable and value, nothing written" \
    '[[ $rc -eq 2 && ! -s $tmp/o1 && ! -e $tmp/none &&
       $(cat "$tmp/e1") == "svgmotion: SLURM_ARRAY_TASK_COUNT=4294967296: must be a whole number from 1 to 1000000" ]]'
  mkdir "$tmp/in/folder.csv"
  "$bin" batch "$tmp/in/folder.csv" -o "$tmp/none" >/dev/null 2>"$tmp/e2"
  rc=$?
  check "a folder given as the manifest: one line" \
    '[[ $rc -eq 1 && ! -e $tmp/none && $(cat "$tmp/e2") == "svgmotion: $tmp/in/folder.csv: is a directory, not a manifest" ]]'
  # An override that `svgmotion run` would read as its own -o: the item ran elsewhere, "done".
  printf 'id,input,prompt,target,overrides\nd0,d0.svg,it moves,t0,-o=%s\n' "$tmp/elsewhere" >"$tmp/in/opt.csv"
  "$bin" batch "$tmp/in/opt.csv" -o "$tmp/none" "${small[@]}" >/dev/null 2>"$tmp/e3"
  rc=$?
  want="svgmotion: $tmp/in/opt.csv:2: override '-o=$tmp/elsewhere' is a command-line option, not a setting (overrides are key.path=value)"
  check "an option among an item's overrides is refused before anything runs" \
    '[[ $rc -eq 1 && ! -e $tmp/none && ! -e $tmp/elsewhere && $(cat "$tmp/e3") == "$want" ]]'
  # A reason that is not UTF-8 (a Latin-1 file name in the run's error line) stopped the batch
  # with "internal error: [json.exception.type_error.316]" and no record.
  printf 'id,input\nlatin,caf\xe9.svg\n' >"$tmp/in/latin.csv"
  "$bin" batch "$tmp/in/latin.csv" -o "$tmp/latin" >/dev/null 2>"$tmp/e4"
  rc=$?
  check "an item whose error line is not UTF-8 is recorded failed, the summary written" \
    '[[ $rc -eq 1 ]] && ! grep -q "internal error" "$tmp/e4" && grep -q "\"status\": \"failed\"" "$tmp/latin/latin/batch.json" &&
       grep -q "\"failed\": 1" "$tmp/latin/summary.json"'
  # An item whose run waits on a generator that sleeps (video `command`): the batch stays busy.
  printf '#!/bin/sh\necho $$ >"%s"\nexec sleep 300\n' "$tmp/sleeper.pid" >"$tmp/sleeper.sh"
  chmod +x "$tmp/sleeper.sh"
  printf 'id,input,prompt\nh,d0.svg,it moves\n' >"$tmp/in/hang.csv"
  hang=(stages.video.plugin=command "stages.video.options={argv: [\"$tmp/sleeper.sh\", \"{out}\"], timeout_s: 600, candidates: 1}")
  "$bin" batch "$tmp/in/hang.csv" -o "$tmp/h" "${hang[@]}" >"$tmp/h1" 2>&1 &
  batch_pid=$!
  for _ in $(seq 300); do [[ -s $tmp/sleeper.pid ]] && break; sleep 0.1; done
  run_pid=$(cat "$tmp/h/h/.svgmotion/lock" 2>/dev/null)
  sleeper=$(cat "$tmp/sleeper.pid" 2>/dev/null)
  check "the item's run is working (its generator started)" '[[ -n $run_pid && -n $sleeper ]] && alive "$run_pid"'
  "$bin" batch "$tmp/in/hang.csv" -o "$tmp/h" "${hang[@]}" >/dev/null 2>"$tmp/e5"
  rc=$?
  check "a second batch of the same shard into the same folder is refused, naming the first one's pid" \
    '[[ $rc -eq 1 && $(cat "$tmp/e5") == "svgmotion: $tmp/h: shard 0/1 is already running into this folder (batch pid $batch_pid)" ]]'
  kill -9 "$batch_pid"
  wait "$batch_pid" 2>/dev/null
  for _ in $(seq 100); do alive "$run_pid" || alive "$sleeper" || break; sleep 0.1; done
  check "SIGKILL of the batch ends its item's run and the run's generator (no orphan)" \
    '! alive "$run_pid" && ! alive "$sleeper"'
  for p in $run_pid $sleeper; do alive "$p" && kill "$p" 2>/dev/null; done  # (only if the check failed)
  # A run still holding the item's run directory (an orphan of some earlier batch): the lock
  # file holds its pid. The re-run waits for it instead of recording "another svgmotion run".
  flock "$tmp/h/h/.svgmotion/lock" sh -c 'echo 4242 >"$0"; while [ ! -e "$1" ]; do sleep 0.1; done' \
    "$tmp/h/h/.svgmotion/lock" "$tmp/release" &
  holder=$!
  for _ in $(seq 100); do [[ $(cat "$tmp/h/h/.svgmotion/lock") == 4242 ]] && break; sleep 0.1; done
  "$bin" batch "$tmp/in/hang.csv" -o "$tmp/h" stages.video.plugin=file >"$tmp/h3" 2>&1 &
  rerun=$!
  for _ in $(seq 300); do grep -q "waiting for" "$tmp/h3" && break; sleep 0.1; done
  check "a re-run finding the item's run directory in use waits, naming that run's pid" \
    'grep -qx "batch: \[1/1\] h: waiting for svgmotion run pid 4242, still working in $tmp/h/h (an earlier batch.s?)" "$tmp/h3"'
  touch "$tmp/release"
  wait "$holder"
  wait "$rerun"
  rc=$?
  check "... then runs the item itself: the run's own result, not 'another svgmotion run'" \
    '[[ $rc -eq 1 ]] && grep -q "waiting for" "$tmp/h3" && grep -q "h: failed (stages.video.path: " "$tmp/h3" &&
       ! grep -q "another svgmotion run" "$tmp/h3" "$tmp/h/summary.csv"'
  # The summary on demand, from the items' records.
  rm -f "$tmp/h/summary.csv" "$tmp/h/summary.json"
  "$bin" batch "$tmp/in/hang.csv" -o "$tmp/h" --summary >"$tmp/o6" 2>&1
  rc=$?
  check "batch --summary rebuilds the summary from the records without running anything" \
    '[[ $rc -eq 0 && $(cat "$tmp/o6") == "batch: 0 of 1 items done; summary in $tmp/h/summary.csv" &&
       $(cut -d, -f1,2 "$tmp/h/summary.csv" | tr "\n" " ") == "id,status h,failed " ]]'
  finish
  ;;
slurm)
  missing=
  for p in munged mungekey slurmctld slurmd sbatch scontrol; do command -v "$p" >/dev/null || missing+=" $p"; done
  if [[ -n $missing || $(id -u) -ne 0 ]]; then
    why=${missing:+missing$missing}
    [[ $(id -u) -ne 0 ]] && why+=" (needs root)"
    if [[ -n ${SVGM_REQUIRE_SLURM:-} ]]; then bad "Slurm test cannot run: $why"; finish; fi
    echo "skipped: $why (apt-get install munge slurmctld slurmd slurm-client; run as root)"
    exit 77
  fi
  make_items 5  # 6 items: d0, broken, d1, d2, d3, d4
  chmod 755 "$tmp"  # munged refuses a socket folder others cannot reach
  s=$tmp/slurm
  mkdir -p "$s/state" "$s/spool"
  export SLURM_CONF=$s/slurm.conf
  daemons_up=
  stop_daemons() {
    [[ -n $daemons_up ]] && timeout 10 scontrol shutdown >/dev/null 2>&1
    for f in slurmd slurmctld munged; do
      [[ -s $s/$f.pid ]] || continue
      pid=$(cat "$s/$f.pid")
      kill "$pid" 2>/dev/null
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
      kill -9 "$pid" 2>/dev/null
    done
    cleanup
  }
  trap stop_daemons EXIT
  mungekey -c -k "$s/munge.key" >/dev/null 2>&1 || bad "mungekey"
  munged --key-file="$s/munge.key" --socket="$s/munge.sock" --pid-file="$s/munged.pid" \
    --log-file="$s/munged.log" --seed-file="$s/munged.seed" || bad "munged did not start"
  # Two ports the kernel hands out at once (port + 1 may be anybody's: a parallel test's
  # connection once held it and slurmd could not bind).
  read -r port dport < <("$py" -c 'import socket
a, b = socket.socket(), socket.socket()
a.bind(("127.0.0.1", 0)); b.bind(("127.0.0.1", 0))
print(a.getsockname()[1], b.getsockname()[1])')
  host=$(hostname -s)
  cat >"$s/slurm.conf" <<CONF
ClusterName=svgmtest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$dport
AuthType=auth/munge
AuthInfo=socket=$s/munge.sock
CredType=cred/munge
StateSaveLocation=$s/state
SlurmdSpoolDir=$s/spool
SlurmctldPidFile=$s/slurmctld.pid
SlurmdPidFile=$s/slurmd.pid
SlurmctldLogFile=$s/slurmctld.log
SlurmdLogFile=$s/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  daemons_up=1
  slurmctld || bad "slurmctld did not start"
  slurmd -N "$host" || bad "slurmd did not start"
  for _ in $(seq 100); do sinfo -h -o %t 2>/dev/null | grep -q idle && break; sleep 0.2; done
  check "a one-node Slurm is up (node idle)" 'sinfo -h -o %t | grep -q idle'
  if ! sinfo -h -o %t | grep -q idle; then tail -n 5 "$s/slurmctld.log" "$s/slurmd.log"; finish; fi
  export SVGMOTION=$bin SVGMOTION_CACHE_DIR=$tmp/out/.kernel-cache
  # Three tasks on a 2-CPU node: one CPU each, so two run at once and the third queues. The
  # script's own --time and --mem are for real clusters; this node has no memory limits.
  start=$SECONDS
  timeout 240 sbatch --wait --quiet --array=0-2 --cpus-per-task=1 --mem=0 --time=10 --output="$tmp/task-%a.out" \
    "$src/examples/slurm/svgmotion_array.sbatch" "$tmp/in/manifest.csv" "$tmp/out" "${small[@]}" >"$tmp/sbatch.out" 2>&1
  rc=$?
  echo "# sbatch --wait returned $rc after $((SECONDS - start)) s"
  [[ $rc -eq 124 ]] && squeue -o "# %i %t %r" && tail -n 5 "$s/slurmctld.log" "$s/slurmd.log"
  check "sbatch --wait returns (non-zero: one task had the broken item)" '[[ $rc -ne 0 && $rc -ne 124 ]]'
  for a in 0 1 2; do echo "# task $a:"; sed 's/^/#   /' "$tmp/task-$a.out"; done
  check "each task took its shard: 2 items each" \
    'for a in 0 1 2; do [[ $(grep -c ": running$" "$tmp/task-$a.out") -eq 2 ]] && grep -q "batch: shard $a/3 of" "$tmp/task-$a.out" || exit 1; done'
  check "every item was run exactly once across the tasks" \
    '[[ $(cat "$tmp"/task-*.out | grep -o "] [a-z0-9]*: running" | sort | uniq -c | awk "\$1 == 1" | wc -l) -eq 6 ]]'
  check "the summary is complete: 5 done, the broken item failed" \
    '[[ $(cut -d, -f2 "$tmp/out/summary.csv" | sort | uniq -c | tr -s " " | tr "\n" ";") == " 5 done; 1 failed; 1 status;" ]]'
  check "the broken item's reason names its file" '[[ $(field broken 3 "$tmp/out/summary.csv") == *broken.svg* ]]'
  check "items record the shard that ran them (0/3, 1/3, 2/3 twice each)" \
    '[[ $(cat "$tmp"/out/*/batch.json | grep -o "\"shard\": \"[0-9]/3\"" | sort | uniq -c | tr -s " " | tr "\n" ";") == " 2 \"shard\": \"0/3\"; 2 \"shard\": \"1/3\"; 2 \"shard\": \"2/3\";" ]]'
  check "under the job PoCL gets 1 thread (SLURM_CPUS_PER_TASK) and no pinning" \
    'for a in 0 1 2; do grep -qx "PoCL CPU threads: 1, not pinned (the job may use 1 of $(nproc) CPUs)" "$tmp/task-$a.out" || exit 1; done'
  # The kernel cache the tasks wrote at once: every entry whole (magic, length, FNV-1a hash),
  # no temporary left.
  check "the shared kernel cache is valid (every entry's length and hash check, no temporaries)" \
    '"$py" - "$SVGMOTION_CACHE_DIR/kernels" <<PY
import os, struct, sys
d = sys.argv[1]; names = os.listdir(d)
def fnv(b):
    h = 1469598103934665603
    for c in b: h = ((h ^ c) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h
# Beside the programs: compile_seconds.txt (how long builds took here, written the same way).
names = [n for n in names if n != "compile_seconds.txt"]
ok = bool(names) and all(n.endswith(".bin") for n in names)
for n in names:
    b = open(os.path.join(d, n), "rb").read()
    size, h = struct.unpack("<QQ", b[8:24])
    ok = ok and b[:8] == b"SVGMKC1\n" and size == len(b) - 24 and h == fnv(b[24:])
print("# kernel cache:", len(names), "entries")
sys.exit(not ok)
PY'
  finish
  ;;
*)
  echo "usage: batch_test.sh local|robust|slurm SVGMOTION_BINARY SOURCE_DIR" >&2
  exit 2
  ;;
esac
