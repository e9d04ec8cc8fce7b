#!/usr/bin/env bash
# The user's files are safe around run directories, and any file name works (cli_run_dir_*):
#   ownership  `run -o` / `fit -o` into a folder of the user's is refused (nothing deleted);
#              --force writes beside the user's files and never over one; a killed run's
#              temporaries are cleaned, a user's "thesis.part1.pdf" never; `fit -o RUN_DIR`
#              waits for no one: it is refused while a run holds the directory; a read-only
#              folder is named as such
#   names      file names that are not UTF-8 (Latin-1): fit, run and render write every output,
#              and every JSON file is valid
#   resume     a fit stopped after its loss stopped falling resumes to the same animation.svg
#   signals    SIGTERM and SIGHUP stop `run` as Ctrl-C does, with the line saying what it holds
#   usage      usage mistakes exit 2; an option's value is never taken for --quiet/--verbose
#   inputs     an SVG named .mp4, an oversized video and a non-string plugin path: one line each
# usage: run_dir_test.sh GROUP SVGMOTION_BIN TEST_DATA_DIR
set -u
group=$1 bin=$2 data=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# A 4-frame target at 64 px: the example drawing, still.
still_frames() {
  mkdir -p "$tmp/frames"
  for i in 0 1 2 3; do "$bin" render "$data/examples/man.svg" -o "$tmp/frames/$i.png" --size 64 2>/dev/null; done
}
fast=(stages.video.plugin=file stages.ranker.plugin=first stages.fitter.iterations=30 stages.fitter.keyframes=3
      stages.fitter.size=64)
# one_line FILE: the file has exactly one line
one_line() { [[ $(grep -c '' "$1") -eq 1 ]]; }

case $group in
ownership)
  still_frames
  mine="$tmp/mine"
  mkdir -p "$mine/candidates" && echo thesis >"$mine/thesis.part1.pdf" && echo notes >"$mine/candidates/notes.txt"
  "$bin" run --input "$data/examples/man.svg" -o "$mine" --quiet "${fast[@]}" "stages.video.path=$tmp/frames" \
    >/dev/null 2>"$tmp/e1"
  rc=$?
  check "run -o into a folder of the user's: exit 1, one line saying how to proceed" \
    '[[ $rc -eq 1 ]] && one_line "$tmp/e1" && grep -qx "svgmotion: $mine: not a svgmotion run directory and not empty (2 entries); choose an empty folder or pass --force" "$tmp/e1" || { cat "$tmp/e1"; false; }'
  check "... and nothing there is deleted or added" \
    '[[ $(cat "$mine/thesis.part1.pdf") == thesis && $(cat "$mine/candidates/notes.txt") == notes && $(ls -A "$mine" | wc -l) -eq 2 ]]'
  "$bin" run --input "$data/examples/man.svg" -o "$mine" --quiet --force "${fast[@]}" "stages.video.path=$tmp/frames" \
    >/dev/null 2>"$tmp/e2"
  rc=$?
  check "--force still refuses a folder of the user's named like one the run replaces (candidates/)" \
    '[[ $rc -eq 1 ]] && one_line "$tmp/e2" && grep -qx "svgmotion: $mine/candidates: not written by svgmotion, and a run would replace it; move it away or choose an empty folder" "$tmp/e2" && [[ $(cat "$mine/candidates/notes.txt") == notes ]] || { cat "$tmp/e2"; false; }'
  mv "$mine/candidates" "$tmp/kept"
  "$bin" run --input "$data/examples/man.svg" -o "$mine" --quiet --force "${fast[@]}" "stages.video.path=$tmp/frames" \
    >/dev/null 2>"$tmp/e3"
  rc=$?
  check "--force writes the run beside the user's file" \
    '[[ $rc -eq 0 && -s $mine/animation.svg && $(cat "$mine/thesis.part1.pdf") == thesis ]] || { cat "$tmp/e3"; false; }'
  # What a kill -9 leaves: our temporaries (of a process that no longer runs), and the user's
  # files named alike in the old pattern, which must stay.
  dead=$(($(cat /proc/sys/kernel/pid_max) + 1))  # a pid no process has
  touch "$mine/.preview.mp4.svgm-tmp-$dead.mp4" "$mine/.fit.json.svgm-tmp-$dead" "$mine/candidates/.00.mp4.svgm-tmp-$dead" \
    "$mine/report.part2.pdf"
  "$bin" run --input "$data/examples/man.svg" -o "$mine" --quiet "${fast[@]}" "stages.video.path=$tmp/frames" \
    >/dev/null 2>"$tmp/e4"
  rc=$?
  check "the next run removes the temporaries a killed run left" \
    '[[ $rc -eq 0 && -z $(find "$mine" -name "*svgm-tmp*") ]] || { cat "$tmp/e4"; ls -a "$mine"; false; }'
  check "... and keeps the user's files: thesis.part1.pdf, report.part2.pdf" \
    '[[ $(cat "$mine/thesis.part1.pdf") == thesis && -e $mine/report.part2.pdf ]]'
  # fit -o: the same rules.
  mkdir -p "$tmp/fitmine" && echo keep >"$tmp/fitmine/animation.json"
  "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/fitmine" --iterations 5 --keyframes 2 --size 32 \
    --quiet 2>"$tmp/e5"
  rc=$?
  check "fit -o into a folder of the user's: exit 1, one line" \
    '[[ $rc -eq 1 ]] && one_line "$tmp/e5" && grep -qx "svgmotion: $tmp/fitmine: not a svgmotion run directory and not empty (1 entry); choose an empty folder or pass --force" "$tmp/e5" && [[ $(cat "$tmp/fitmine/animation.json") == keep ]] || { cat "$tmp/e5"; false; }'
  "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/fitmine" --iterations 5 --keyframes 2 --size 32 \
    --quiet --force 2>"$tmp/e5b"
  check "fit -o --force never writes over the user's animation.json" \
    '[[ $? -eq 1 ]] && one_line "$tmp/e5b" && grep -qx "svgmotion: $tmp/fitmine/animation.json: not written by svgmotion, and a run would replace it; move it away or choose an empty folder" "$tmp/e5b" && [[ $(cat "$tmp/fitmine/animation.json") == keep ]] || { cat "$tmp/e5b"; false; }'
  # A fit's own leftovers (a fit killed while writing its preview) go at the next fit.
  "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/fo" --iterations 5 --keyframes 2 --size 32 --quiet 2>/dev/null
  touch "$tmp/fo/.preview.mp4.svgm-tmp-$dead.mp4" "$tmp/fo/preview.part1.mp4"
  "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/fo" --iterations 5 --keyframes 2 --size 32 --quiet 2>"$tmp/e5c"
  check "the next fit removes a killed fit's temporary preview, and nothing else" \
    '[[ $? -eq 0 && ! -e $tmp/fo/.preview.mp4.svgm-tmp-$dead.mp4 && -e $tmp/fo/preview.part1.mp4 ]] || { cat "$tmp/e5c"; ls -a "$tmp/fo"; false; }'
  # A run holding the run directory (its lock taken here as a run takes it): fit -o is refused.
  (
    trap - EXIT  # killed below: this subshell must not clean up the test's folder
    exec 9<>"$mine/.svgmotion/lock"
    flock -x 9 && printf '%s' "$BASHPID" >"$mine/.svgmotion/lock" && sleep 20
  ) &
  holder=$!
  for _ in $(seq 50); do [[ $(cat "$mine/.svgmotion/lock" 2>/dev/null) == "$holder" ]] && break; sleep 0.1; done
  cp "$mine/animation.svg" "$tmp/before.svg"
  "$bin" fit "$mine/input.svg" --target "$tmp/frames" -o "$mine" --iterations 5 --keyframes 2 --size 32 --quiet 2>"$tmp/e6"
  rc=$?
  kill $holder 2>/dev/null; wait $holder 2>/dev/null
  check "fit -o RUN_DIR while a run holds it: refused in one line naming the run's pid" \
    '[[ $rc -eq 1 ]] && one_line "$tmp/e6" && grep -qx "svgmotion: $mine: another svgmotion run is using this run directory (pid $holder)" "$tmp/e6" && cmp -s "$tmp/before.svg" "$mine/animation.svg" || { cat "$tmp/e6"; false; }'
  # Read-only: a read-only file system (a tmpfs mounted so in a private namespace) and a
  # folder the user may not write (as nobody).
  if unshare -rm true 2>/dev/null; then
    mkdir -p "$tmp/ro"
    unshare -rm sh -c 'mount -t tmpfs -o ro tmpfs "$1" && shift && exec "$@"' sh "$tmp/ro" \
      "$bin" run --input "$data/examples/man.svg" -o "$tmp/ro/run" --quiet "${fast[@]}" "stages.video.path=$tmp/frames" \
      >/dev/null 2>"$tmp/e7"
    rc=$?
    check "run -o into a read-only file system names the folder and the reason" \
      '[[ $rc -eq 1 ]] && one_line "$tmp/e7" && grep -qx "svgmotion: $tmp/ro: cannot write (read-only file system)" "$tmp/e7" || { cat "$tmp/e7"; false; }'
    unshare -rm sh -c 'mount -t tmpfs -o ro tmpfs "$1" && shift && exec "$@"' sh "$tmp/ro" \
      "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/ro" --iterations 5 --keyframes 2 --size 32 --quiet \
      2>"$tmp/e8"
    rc=$?
    check "fit -o a read-only folder names it and the reason" \
      '[[ $rc -eq 1 ]] && one_line "$tmp/e8" && grep -qx "svgmotion: $tmp/ro: cannot write (read-only file system)" "$tmp/e8" || { cat "$tmp/e8"; false; }'
  else
    echo "# no user namespaces here: the read-only file system checks did not run"
  fi
  ;;
names)
  # Latin-1 names: "caf\xe9.svg" and an output folder "out\xe9" (bytes, not UTF-8).
  still_frames
  svg=$tmp/$'caf\xe9.svg' out=$tmp/$'out\xe9' fout=$tmp/$'fit\xe9' fr=$tmp/$'fr\xe9'
  png=$out/$'p\xe9.png' missing=$tmp/$'nothere\xe9.svg'
  cp "$data/examples/man.svg" "$svg"
  cp -r "$tmp/frames" "$fr"
  "$bin" fit "$svg" --target "$fr" -o "$fout" --iterations 20 --keyframes 3 --size 64 --quiet 2>"$tmp/e1"
  rc=$?
  check "fit with Latin-1 names exits 0 and writes every output" \
    '[[ $rc -eq 0 && -s $fout/animation.svg && -s $fout/animation.json && -s $fout/fit.json && -s $fout/preview.mp4 ]] || { cat "$tmp/e1"; false; }'
  check "... fit.json and animation.json are valid JSON" \
    '"$py" -c "import json, sys; [json.load(open(f, encoding=\"utf-8\")) for f in sys.argv[1:]]" "$fout/fit.json" "$fout/animation.json"'
  "$bin" run --input "$svg" -o "$out" --quiet "${fast[@]}" "stages.video.path=$tmp/frames" >/dev/null 2>"$tmp/e2"
  rc=$?
  check "run with a Latin-1 input and run directory exits 0 and writes every output" \
    '[[ $rc -eq 0 && -s $out/animation.svg && -s $out/animation.json && -s $out/fit.json && -s $out/preview.mp4 && -s $out/report.html ]] || { cat "$tmp/e2"; false; }'
  check "... every JSON file of the run is valid" \
    '"$py" -c "import json, sys, glob; fs = glob.glob(sys.argv[1] + \"/**/*.json\", recursive=True) + glob.glob(sys.argv[1] + \"/.svgmotion/*.json\"); [json.load(open(f, encoding=\"utf-8\")) for f in fs]; sys.exit(0 if len(fs) >= 10 else 1)" "$out"'
  check "... report.html is valid UTF-8" '"$py" -c "import sys; open(sys.argv[1], encoding=\"utf-8\").read()" "$out/report.html"'
  "$bin" render "$svg" -o "$png" --size 32 2>"$tmp/e3"
  rc=$?
  check "render with Latin-1 names" '[[ $rc -eq 0 && -s $png ]] && "$py" -c "import sys; open(sys.argv[1], encoding=\"utf-8\").read()" "$tmp/e3" || { cat "$tmp/e3"; false; }'
  "$bin" render "$missing" -o "$tmp/x.png" 2>"$tmp/e4"
  check "an error naming a Latin-1 file is one line of valid UTF-8" \
    'one_line "$tmp/e4" && "$py" -c "import sys; open(sys.argv[1], encoding=\"utf-8\").read()" "$tmp/e4" && grep -q "nothere" "$tmp/e4"'
  ;;
resume)
  # A square moving right: 3 frames at 128 px, fitted at 64 px, so the fit ends with a
  # refinement at 128 px after its loss stops falling (fit.json converged_at).
  mkdir -p "$tmp/sq"
  for k in 0 1 2; do
    printf '<svg xmlns="http://www.w3.org/2000/svg" width="64" height="64"><rect x="%d" y="20" width="20" height="20" fill="#36c"/></svg>' $((10 + 8 * k)) >"$tmp/sq/f.svg"
    "$bin" render "$tmp/sq/f.svg" -o "$tmp/sq/$k.png" --size 128 2>/dev/null
  done
  printf '<svg xmlns="http://www.w3.org/2000/svg" width="64" height="64"><rect id="sq" x="10" y="20" width="20" height="20" fill="#36c"/></svg>' >"$tmp/sq0.svg"
  fit=("$bin" fit "$tmp/sq0.svg" --target "$tmp/sq" --iterations 2000 --keyframes 3 --size 64 --quiet --no-track)
  "${fit[@]}" -o "$tmp/a" 2>"$tmp/e1"
  "${fit[@]}" -o "$tmp/b" 2>/dev/null
  check "the fit converges and refines (the case a kill during the refinement leaves)" \
    '"$py" -c "import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d[\"converged_at\"] and d.get(\"refined\") else 1)" "$tmp/a/fit.json" || { cat "$tmp/e1"; false; }'
  check "two fits give the same animation.svg" 'cmp -s "$tmp/a/animation.svg" "$tmp/b/animation.svg"'
  # The checkpoint a fit leaves is the one a kill during the refinement or while the outputs
  # are written leaves (the refinement is not checkpointed): resuming from it must redo exactly
  # the refinement, not more coarse iterations.
  rm "$tmp/b/animation.svg"
  "${fit[@]}" -o "$tmp/b" --resume 2>"$tmp/e2"
  check "fit --resume after convergence gives the same animation.svg bytes" \
    'cmp "$tmp/a/animation.svg" "$tmp/b/animation.svg" || { cat "$tmp/e2"; false; }'
  check "... and runs no coarse iteration more" \
    '"$py" -c "import json, sys; a, b = (json.load(open(f)) for f in sys.argv[1:]); sys.exit(0 if a[\"converged_at\"] == b[\"converged_at\"] == b[\"resumed_from\"] else 1)" "$tmp/a/fit.json" "$tmp/b/fit.json"'
  ;;
signals)
  still_frames
  for sig in TERM HUP; do
    run=("$bin" run --input "$data/examples/man.svg" -o "$tmp/$sig" --quiet stages.video.plugin=file "stages.video.path=$tmp/frames"
         stages.ranker.plugin=first stages.fitter.iterations=100000 stages.fitter.keyframes=3 stages.fitter.size=64
         stages.fitter.stop_when_converged=false)
    "${run[@]}" >/dev/null 2>"$tmp/$sig.err" &
    pid=$!
    for _ in $(seq 600); do [[ -f $tmp/$sig/checkpoint.bin ]] && break; sleep 0.05; done
    kill -$sig $pid
    wait $pid
    rc=$?
    check "SIG$sig stops run as Ctrl-C does: exit 130, the fit's state written, a line naming what the run holds" \
      '[[ $rc -eq 130 ]] && grep -q "^svgmotion: interrupted at iteration [0-9]*; wrote $tmp/$sig/animation.svg" "$tmp/$sig.err" && grep -q "^svgmotion: interrupted (SIG$sig); $tmp/$sig holds .*animation.svg.*checkpoint.bin" "$tmp/$sig.err" || { echo rc=$rc; cat "$tmp/$sig.err"; false; }'
  done
  ;;
usage)
  "$bin" render "$data/examples/man.svg" -o "$tmp/x.png" --frobnicate 2>"$tmp/e1"
  check "an unknown option exits 2" '[[ $? -eq 2 ]] && one_line "$tmp/e1" && grep -q "unknown option --frobnicate" "$tmp/e1"'
  "$bin" fit "$data/examples/man.svg" --target 2>"$tmp/e2"
  check "an option without its value exits 2" '[[ $? -eq 2 ]] && one_line "$tmp/e2" && grep -qx "svgmotion: fit: --target needs a value" "$tmp/e2"'
  "$bin" fit "$data/examples/man.svg" -o "$tmp/none" 2>"$tmp/e3"
  check "a missing required option exits 2" '[[ $? -eq 2 ]] && one_line "$tmp/e3" && grep -q "missing --target" "$tmp/e3" && [[ ! -e $tmp/none ]]'
  # `--prompt -q`: the prompt is "-q", and the console is not quietened. The run stops at a
  # setting checked before any stage, whose error would be printed anyway: the info line that
  # shows the level is the one the pipeline prints at its first stage, so the run goes on.
  still_frames
  "$bin" run --input "$data/examples/man.svg" --prompt -q -o "$tmp/p" "${fast[@]}" "stages.video.path=$tmp/frames" \
    >/dev/null 2>"$tmp/e4"
  rc=$?
  check "run --prompt -q: -q is the prompt, not --quiet" \
    '[[ $rc -eq 0 ]] && grep -q "^run: grouper" "$tmp/e4" && "$py" -c "import json, sys; sys.exit(0 if json.load(open(sys.argv[1]))[\"prompt\"] == \"-q\" else 1)" "$tmp/p/.svgmotion/command.json" || { cat "$tmp/e4"; false; }'
  "$bin" render "$data/examples/man.svg" -o "$tmp/q.png" --size 16 -q -v 2>/dev/null
  check "--quiet and --verbose together is still a usage error" '[[ $? -eq 2 ]]'
  ;;
inputs)
  cp "$data/examples/man.svg" "$tmp/man.mp4"
  "$bin" fit "$data/examples/man.svg" --target "$tmp/man.mp4" -o "$tmp/o1" --keyframes 2 --size 32 2>"$tmp/e1"
  check "an SVG named .mp4 as the target: one line saying what it holds" \
    '[[ $? -eq 1 ]] && one_line "$tmp/e1" && grep -qx "svgmotion: $tmp/man.mp4: not a readable video (it holds an SVG document)" "$tmp/e1" && [[ ! -e $tmp/o1 ]] || { cat "$tmp/e1"; false; }'
  # Frames wider than the limit are refused before one is decoded (a 2-frame clip: quick to make;
  # this one loaded in 42 s and 457 MB before).
  ffmpeg -nostdin -v error -f lavfi -i color=white:s=4112x2304:d=0.2 -r 10 -pix_fmt yuv420p "$tmp/wide.mp4"
  "$bin" fit "$data/examples/man.svg" --target "$tmp/wide.mp4" -o "$tmp/o2" --keyframes 2 --size 32 2>"$tmp/e2"
  check "a video wider than 4096 px: one line stating the limit" \
    '[[ $? -eq 1 ]] && one_line "$tmp/e2" && grep -q "^svgmotion: $tmp/wide.mp4: frames of 4112x2304 are too large (limit 4096 px a side; " "$tmp/e2" || { cat "$tmp/e2"; false; }'
  printf 'stages:\n  video:\n    plugin: [1, 2]\n' >"$tmp/bad_plugin.yaml"
  "$bin" run "$tmp/bad_plugin.yaml" --input "$data/examples/man.svg" -o "$tmp/o3" 2>"$tmp/e3"
  check "a plugin named by a list: one line naming the file, the key and the type" \
    '[[ $? -eq 1 ]] && one_line "$tmp/e3" && grep -q "^svgmotion: $tmp/bad_plugin.yaml:3: stages.video.plugin: must name a video plugin" "$tmp/e3" && ! grep -q "internal error" "$tmp/e3" || { cat "$tmp/e3"; false; }'
  printf 'plugin_paths: [true]\n' >"$tmp/bad_paths.yaml"
  "$bin" run "$tmp/bad_paths.yaml" --input "$data/examples/man.svg" -o "$tmp/o4" 2>"$tmp/e4"
  check "plugin_paths: [true]: one line naming the file, the key and the type" \
    '[[ $? -eq 1 ]] && one_line "$tmp/e4" && grep -qx "svgmotion: $tmp/bad_paths.yaml:1: plugin_paths: must be a list of folders (strings); true is not a string" "$tmp/e4" || { cat "$tmp/e4"; false; }'
  "$bin" run --input "$data/examples/man.svg" -o "$tmp/o5" "plugin_paths=[1, 2]" 2>"$tmp/e5"
  check "plugin_paths=[1, 2]: one line naming the key and the type" \
    '[[ $? -eq 1 ]] && one_line "$tmp/e5" && grep -q "plugin_paths: must be a list of folders (strings); 1 is not a string" "$tmp/e5" || { cat "$tmp/e5"; false; }'
  ;;
*) echo "unknown group $group"; exit 2 ;;
esac
finish
