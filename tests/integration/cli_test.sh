#!/usr/bin/env bash
# CLI integration tests: cli_test.sh GROUP SVGMOTION_BINARY TEST_DATA_DIR [BUILD_DIR SDK_PLUGIN_DIR]
# Each check prints "ok - ..." or "not ok - ..."; the script ends with "N passed, M failed" and
# exits non-zero on any failure.
set -u
group=$1 bin=$2 data=$3 build=${4:-} sdk_src=${5:-}
source "$(cd "$(dirname "$0")" && pwd)/test_lib.sh"

# expect_error NAME EXPECTED_SUBSTRING OUTPUT_FILE ARGS...: non-zero exit, exactly one stderr
# line containing the substring, and OUTPUT_FILE (and any temporary of it) not written.
expect_error() {
  local name=$1 want=$2 out=$3; shift 3
  "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  local lines; lines=$(grep -c '' "$tmp/stderr")
  if [[ $rc -ne 0 && $lines -eq 1 ]] && grep -qF -- "$want" "$tmp/stderr" && ! ls "$out"* >/dev/null 2>&1; then
    ok "$name"
  else
    bad "$name (exit $rc, stderr: $(head -c 300 "$tmp/stderr"))"
  fi
}

# Runs a command that must succeed: any other exit status is a failed check naming it.
must() {
  "$@"
  local rc=$?
  [[ $rc -eq 0 ]] || bad "exit status $rc from: ${*:1:4} ..."
  return $rc
}

case $group in
render)
  must "$bin" render "$data/examples/man.svg" -o "$tmp/man.png" --size 128 2>"$tmp/err"
  check "render writes a PNG" '[[ -s $tmp/man.png ]] && [[ $(head -c 8 "$tmp/man.png" | od -An -tx1 | tr -d " \n") == 89504e470d0a1a0a ]]'
  check "render leaves no temporary file" '[[ $(ls "$tmp" | grep -c part) -eq 0 ]]'
  must "$bin" render "$data/examples/man.svg" -o "$tmp/t.png" --size 64 --background transparent 2>/dev/null
  check "transparent background renders" '[[ -s $tmp/t.png ]]'
  must "$bin" render "$data/examples/man.svg" -o "$tmp/a.png" --size 100 2>/dev/null
  must "$bin" render "$data/examples/man.svg" -o "$tmp/b.png" --size 100 2>/dev/null
  check "rendering is deterministic (same bytes twice)" 'cmp -s "$tmp/a.png" "$tmp/b.png"'
  ;;
bad_input)
  # Malformed documents (broken XML, NaN numbers, absurd sizes, deep nesting, use cycles ...)
  # are the bad-input corpus, tests/data/bad_input (bad_input_test.sh); here: what needs no file.
  expect_error "missing file" "nothere.svg" "$tmp/o6.png" render "$tmp/nothere.svg" -o "$tmp/o6.png"
  head -c 70000000 /dev/zero | tr '\0' ' ' >"$tmp/big.svg"
  expect_error "oversized file" "big.svg" "$tmp/o8.png" render "$tmp/big.svg" -o "$tmp/o8.png"
  expect_error "unknown option" "--frobnicate" "$tmp/o9.png" render "$data/examples/man.svg" -o "$tmp/o9.png" --frobnicate
  expect_error "bad --size" "--size" "$tmp/o10.png" render "$data/examples/man.svg" -o "$tmp/o10.png" --size 0
  expect_error "unwritable output" "nodir" "$tmp/nodir/x.png" render "$data/examples/man.svg" -o "$tmp/nodir/x.png"
  expect_error "unknown device" "--device" "$tmp/o11.png" render "$data/examples/man.svg" -o "$tmp/o11.png" --device nosuchdevice
  for w in 2 abc 0 nan; do
    expect_error "fit --chroma-weight $w is one line" "svgmotion: fit: --chroma-weight must be auto or a number in (0, 1], not '$w'" \
      "$tmp/cw_$w" fit "$data/examples/man.svg" --target "$data/examples/man.svg" -o "$tmp/cw_$w" --chroma-weight "$w"
  done
  for r in 9 x; do
    expect_error "fit --denoise $r is one line" "svgmotion: --denoise wants an integer in 0..4, got '$r'" \
      "$tmp/dn_$r" fit "$data/examples/man.svg" --target "$data/examples/man.svg" -o "$tmp/dn_$r" --denoise "$r"
  done
  # The output path must be a regular file (or absent): a FIFO or a folder is refused and stays.
  # (Only files of our own: a broken writer must not get the chance to replace a real device.)
  mkfifo "$tmp/fifo.png"
  expect_error "a FIFO as -o is refused" "$tmp/fifo.png: not a regular file" "$tmp/fifo.png.part" render "$data/examples/man.svg" -o "$tmp/fifo.png" --size 16
  check "... and is still a FIFO" '[[ -p $tmp/fifo.png ]]'
  mkdir "$tmp/dir.png"
  expect_error "a folder as -o is refused" "$tmp/dir.png: not a regular file" "$tmp/dir.png.part" render "$data/examples/man.svg" -o "$tmp/dir.png" --size 16
  ln -s "$tmp/fifo.png" "$tmp/tofifo.png"
  expect_error "a link to a FIFO is refused" "$tmp/tofifo.png: not a regular file (it links to $tmp/fifo.png)" "$tmp/fifo.png.part" render "$data/examples/man.svg" -o "$tmp/tofifo.png" --size 16
  # A symbolic link is written through: the target gets the PNG, the link stays a link.
  mkdir "$tmp/real" && printf 'old' >"$tmp/real/t.png" && ln -s real/t.png "$tmp/link.png"
  "$bin" render "$data/examples/man.svg" -o "$tmp/link.png" --size 16 2>/dev/null
  check "-o through a symlink writes the link's target and keeps the link" '[[ -L $tmp/link.png && $(head -c 4 "$tmp/real/t.png" | od -An -tx1 | tr -d " \n") == 89504e47 && $(ls "$tmp/real") == t.png ]]'
  # fit: a FIFO where the output folder should be, and one where an output file should be.
  mkdir "$tmp/frames" && for i in 0 1; do "$bin" render "$data/examples/man.svg" -o "$tmp/frames/$i.png" --size 32 2>/dev/null; done
  expect_error "fit -o onto a FIFO is refused" "$tmp/fifo.png" "$tmp/fifo.png/" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/fifo.png" --keyframes 2 --size 32 --iterations 2
  ;;
devices)
  must "$bin" devices >"$tmp/dev" 2>&1
  check "devices lists at least one device and marks the auto pick" 'grep -q "^\*" "$tmp/dev"'
  ;;
bench)
  must "$bin" bench render "$data/examples/man.svg" --frames 3 --size 64 --repeat 2 --json >"$tmp/b.json" 2>"$tmp/err"
  check "bench render --json prints one JSON object with the promised keys" \
    '[[ $(grep -c "" "$tmp/b.json") -eq 1 ]] && grep -q "^{.*}$" "$tmp/b.json" && grep -Eq "\"ms_per_frame\": [0-9.]+" "$tmp/b.json" && grep -Eq "\"peak_rss_mb\": [0-9.]+" "$tmp/b.json" && grep -q "\"device\": \"" "$tmp/b.json"'
  # bench fit: the fitter's schedule on a 3-frame target at 64 px, timed.
  mkdir -p "$tmp/bf"
  for i in 0 1 2; do must "$bin" render "$data/examples/man.svg" -o "$tmp/bf/$i.png" --size 64 2>/dev/null; done
  must "$bin" bench fit "$data/examples/man.svg" --target "$tmp/bf" --iterations 12 --keyframes 3 --size 64 --json >"$tmp/f.json" 2>"$tmp/err"
  check "bench fit --json runs the asked iterations and reports CPU time per iteration" \
    '[[ $(grep -c "" "$tmp/f.json") -eq 1 ]] && grep -q "\"iterations\": 12," "$tmp/f.json" && grep -q "\"keyframes\": 3," "$tmp/f.json" && grep -Eq "\"cpu_ms_per_iteration\": [0-9.]+" "$tmp/f.json" && grep -Eq "\"peak_rss_mb\": [0-9.]+" "$tmp/f.json"'
  # The peak once the target is loaded and the fitter built: a high-water mark, never above the end's.
  check "bench fit --json reports the setup's peak memory, at most the whole run's" \
    'python3 -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(not 0 < j[\"setup_peak_rss_mb\"] <= j[\"peak_rss_mb\"])" "$tmp/f.json"'
  expect_error "bench fit without a target names the option" "bench fit: --target VIDEO is required" "$tmp/none" \
    bench fit "$data/examples/man.svg"
  # bench target: loading those three identical frames with the stabiliser on finds a figure
  # that holds still and no shake at all.
  must "$bin" bench target "$tmp/bf" --keyframes 3 --size 64 --stabilise --repeat 1 --json >"$tmp/t.json" 2>"$tmp/err"
  check "bench target --json reports the load's time, the stabiliser's model and no shake on still frames" \
    '[[ $(grep -c "" "$tmp/t.json") -eq 1 ]] && grep -q "\"keyframes\": 3," "$tmp/t.json" && grep -Eq "\"wall_s\": [0-9.]+" "$tmp/t.json" && grep -q "\"shake_model\": \"still\"" "$tmp/t.json" && grep -q "\"max_shake_px\": 0.000" "$tmp/t.json"'
  expect_error "bench target with two sources names the problem" "bench target: expected one video (or folder of frames)" "$tmp/none" \
    bench target "$tmp/bf" "$tmp/bf"
  ;;
fit)
  # A small target: the example rendered at 64 px into a folder of 4 frames.
  mkdir -p "$tmp/frames"
  for i in 0 1 2 3; do must "$bin" render "$data/examples/man.svg" -o "$tmp/frames/$i.png" --size 64 2>/dev/null; done
  must "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/out" --iterations 40 --keyframes 3 --size 64 2>"$tmp/err"
  check "fit writes animation.svg with keyframes (d, or a wrapper's transform)" 'grep -Eq "<animate(Transform)? attributeName=\"(d|transform)\"" "$tmp/out/animation.svg"'
  check "fit writes a preview and a report" '[[ -s $tmp/out/preview.mp4 && -s $tmp/out/fit.json && -s $tmp/out/checkpoint.bin ]]'
  check "the animation renders at a time" '"$bin" render "$tmp/out/animation.svg" -o "$tmp/t.png" --time 0.1 2>/dev/null && [[ -s $tmp/t.png ]]'
  # preview.mp4 through the clips' encoder (was OpenCV's VideoWriter: mdat first, untagged).
  atoms=$(grep -obUa -e moov -e mdat "$tmp/out/preview.mp4" | head -2 | cut -d: -f2 | tr '\n' ' ')
  check "the fit's preview.mp4 starts with its index (atoms: $atoms)" '[[ $atoms == "moov mdat " ]]'
  # A clip of the animation is at the fit's frame rate, stated on its root (was 30 fps always).
  fps=$(grep -o 'data-svgmotion-fps="[0-9.]*"' "$tmp/out/animation.svg" | head -1 | tr -dc '0-9.')
  dur=$(grep -o ' dur="[0-9.]*s"' "$tmp/out/animation.svg" | head -1 | tr -dc '0-9.')
  mkdir -p "$tmp/clip"
  must "$bin" render "$tmp/out/animation.svg" -o "$tmp/clip/%d.png" --size 16 2>"$tmp/clip.err"
  frames=$(ls "$tmp/clip" | grep -c png)
  want=$(awk -v d="$dur" -v f="$fps" 'BEGIN { printf "%d", d * f + 0.5 }')
  check "a clip of the animation is at its own frame rate ($fps fps x $dur s: $frames frames, want $want)" \
    '[[ -n $fps && $frames -eq $want ]] && grep -q "at $fps fps" "$tmp/clip.err"'
  must "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/out" --iterations 60 --keyframes 3 --size 64 --resume 2>"$tmp/err"
  # Tiny drawings (no strokes, or one stroke, a handful of control points) once failed with
  # CL_INVALID_HOST_PTR: their empty or short plan arrays went to clCreateBuffer as they were.
  tiny_svg() { printf '<svg xmlns="http://www.w3.org/2000/svg" width="32" height="32">%s</svg>' "$2" >"$tmp/$1.svg"; }
  tiny_svg triangle '<path d="M4 4 L28 8 L10 28 Z" fill="#c33"/>'
  tiny_svg rects '<rect x="2" y="2" width="12" height="12" fill="#36c"/><rect x="16" y="16" width="12" height="10" fill="#3a3"/>'
  tiny_svg stroked '<path d="M4 4 L28 8 L10 28 Z" fill="none" stroke="#222" stroke-width="2"/>'
  tiny_svg polyquad '<polygon points="2,2 14,2 8,12" fill="#c90"/><path d="M16 28 Q24 4 30 28 Z" fill="#609"/>'
  for t in triangle rects stroked polyquad; do
    mkdir -p "$tmp/tf_$t"
    for i in 0 1; do "$bin" render "$tmp/$t.svg" -o "$tmp/tf_$t/$i.png" --size 32 2>"$tmp/tr_$t"; done
    "$bin" fit "$tmp/$t.svg" --target "$tmp/tf_$t" -o "$tmp/to_$t" --iterations 3 --keyframes 2 --size 32 --quiet 2>"$tmp/te_$t"
    check "a tiny drawing ($t) renders and fits" '[[ $? -eq 0 && -s $tmp/tf_$t/1.png ]] && grep -Eq "<animate(Transform)? attributeName=\"(d|transform)\"" "$tmp/to_$t/animation.svg" || { cat "$tmp/tr_$t" "$tmp/te_$t"; false; }'
  done
  check "--resume continues from the checkpoint" 'grep -q "resuming at iteration 40" "$tmp/err" && grep -q "\"iterations\": 60" "$tmp/out/fit.json"'
  # Levels (svgmotion/log.h): --quiet hides info lines, --verbose adds debug lines.
  check "fit --quiet prints no info line" '! grep -Eq "svgmotion: fitted|^fit: iteration" "$tmp/te_rects"'
  check "fit prints its info line by default" 'grep -q "svgmotion: fitted 3 keyframes" "$tmp/err"'
  "$bin" fit "$tmp/triangle.svg" --target "$tmp/tf_triangle" -o "$tmp/to_verbose" --iterations 3 --keyframes 2 --size 32 --verbose 2>"$tmp/te_verbose"
  check "fit --verbose prints debug lines" 'grep -q "^svgmotion: debug: fit: .*tf_triangle: 2 keyframes of 2 frames" "$tmp/te_verbose"'
  check "--quiet and --verbose together is a usage error" '"$bin" render x.svg -o y.png -q -v 2>/dev/null; [[ $? -eq 2 ]]'
  # Group transforms: a square moved by (6, 3) px and turned 10 degrees about its centre; the
  # transform export and the baked one render alike at both keyframes (ffmpeg's PSNR).
  tiny_svg sq0 '<rect id="sq" x="8" y="8" width="12" height="12" fill="#36c"/>'
  tiny_svg sq1 '<rect x="8" y="8" width="12" height="12" fill="#36c" transform="translate(6 3) rotate(10 14 14)"/>'
  mkdir -p "$tmp/tf_sq"
  must "$bin" render "$tmp/sq0.svg" -o "$tmp/tf_sq/0.png" --size 32 2>/dev/null
  must "$bin" render "$tmp/sq1.svg" -o "$tmp/tf_sq/1.png" --size 32 2>/dev/null
  must "$bin" fit "$tmp/sq0.svg" --target "$tmp/tf_sq" -o "$tmp/sq_baked" --iterations 40 --keyframes 2 --size 32 --loop once --full --quiet 2>/dev/null
  cp -r "$tmp/sq_baked" "$tmp/sq_tf"
  must "$bin" fit "$tmp/sq0.svg" --target "$tmp/tf_sq" -o "$tmp/sq_tf" --iterations 40 --keyframes 2 --size 32 --loop once --resume --group-transforms --full --quiet 2>/dev/null
  check "--group-transforms writes the square's motion as animateTransform" 'grep -q "<animateTransform attributeName=\"transform\" type=\"translate\" additive=\"sum\"" "$tmp/sq_tf/animation.svg" && grep -q "\"as_transforms\": 1" "$tmp/sq_tf/fit.json" && ! grep -q animateTransform "$tmp/sq_baked/animation.svg"'
  for t in 0 100; do
    "$bin" render "$tmp/sq_baked/animation.svg" -o "$tmp/sq_b$t.png" --size 64 --time $t 2>/dev/null
    "$bin" render "$tmp/sq_tf/animation.svg" -o "$tmp/sq_t$t.png" --size 64 --time $t 2>/dev/null
    psnr=$(ffmpeg -nostdin -v info -i "$tmp/sq_b$t.png" -i "$tmp/sq_t$t.png" -lavfi psnr -f null - 2>&1 | sed -n 's/.*average:\([0-9.a-z]*\).*/\1/p')
    check "render --time $t: the transform export draws the baked one (PSNR $psnr dB >= 40)" '[[ $psnr == inf ]] || awk -v p="$psnr" "BEGIN { exit !(p >= 40) }"'
  done
  printf 'not a video' >"$tmp/bad.mp4"
  expect_error "a file that is not a video" "bad.mp4" "$tmp/out2" fit "$data/examples/man.svg" --target "$tmp/bad.mp4" -o "$tmp/out2"
  expect_error "fewer frames than keyframes" "fewer than the 15 keyframes" "$tmp/out3" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/out3"
  # A drawing of over 20,000 segments (20,001 lines and the closing one) is fitted after a
  # warning that it will be slow (it once fitted at 3 s per iteration without a word). The
  # missing target stops it right after.
  awk 'BEGIN { printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\"><path d=\"M 0 0";
               for (i = 1; i <= 20001; i++) printf " L %d %d", i % 64, (i * 7) % 64; print " Z\"/></svg>" }' >"$tmp/many.svg"
  "$bin" fit "$tmp/many.svg" --target "$tmp/nothere" -o "$tmp/out5" 2>"$tmp/many_err"
  many_rc=$?
  check "a fit of 20,002 segments warns that it will be slow" '[[ $many_rc -eq 1 ]] && grep -qx "svgmotion: warning: $tmp/many.svg: 20002 path segments (over 20000): every fitting iteration draws them all, so this fit will be slow; fewer nodes (a simplified drawing) fit faster" "$tmp/many_err" || { cat "$tmp/many_err"; false; }'
  "$bin" fit "$data/examples/man.svg" --target "$tmp/nothere" -o "$tmp/out5" 2>"$tmp/few_err"
  check "... and an ordinary drawing does not" '! grep -q "path segments" "$tmp/few_err"'
  # Ctrl-C: the best result so far is written and the exit status says interrupted.
  "$bin" fit "$data/examples/man.svg" --target "$tmp/frames" -o "$tmp/out4" --iterations 1000000 --all-iterations --keyframes 3 --size 64 --quiet 2>/dev/null &
  pid=$!
  for _ in $(seq 50); do [[ -f $tmp/out4/checkpoint.bin ]] && break; sleep 0.2; done
  kill -INT $pid
  wait $pid
  rc=$?
  check "Ctrl-C writes the animation so far and exits 130" '[[ $rc -eq 130 && -s $tmp/out4/animation.svg ]]'
  ;;
pipeline)
  mkdir -p "$tmp/frames"
  for i in 0 1 2 3; do must "$bin" render "$data/examples/man.svg" -o "$tmp/frames/$i.png" --size 64 2>/dev/null; done
  run=("$bin" run --input "$data/examples/man.svg" -o "$tmp/run" --quiet
       stages.video.plugin=file "stages.video.path=$tmp/frames" stages.ranker.plugin=first
       stages.fitter.iterations=30 stages.fitter.keyframes=3 stages.fitter.size=64)
  "${run[@]}" >"$tmp/out1" 2>"$tmp/err"
  check "run --quiet prints no info line" '! grep -q "^run: " "$tmp/err"'
  check "run writes log.txt: a header, the stage lines and debug lines" 'grep -q "===== svgmotion .*: svgmotion run --input" "$tmp/run/log.txt" && grep -q " info    run: fitter (opencl) ..." "$tmp/run/log.txt" && grep -q " debug   fitter: plugin opencl" "$tmp/run/log.txt" && grep -q " debug   fit: iteration 30/30" "$tmp/run/log.txt"'
  check "run writes animation.svg and every intermediate" '[[ -s $tmp/run/animation.svg && -s $tmp/run/grouped.svg && -s $tmp/run/recolored.png && -s $tmp/run/palette.json && -s $tmp/run/target.mp4 && -s $tmp/run/ranking.json && -s $tmp/run/layers.json ]] && grep -Eq "<animate(Transform)? attributeName=\"(d|transform)\"" "$tmp/run/animation.svg"'
  check "run writes animation.json (Lottie) with the user's own ids and groups" '[[ -s $tmp/run/animation.json ]] && grep -q "\"ty\":4,\"nm\":\"thigh_left\"" "$tmp/run/animation.json" && grep -q "\"ty\":3,\"nm\":\"body\"" "$tmp/run/animation.json"'
  "${run[@]}" >"$tmp/out2" 2>&1
  check "a second run reports every stage up to date" 'grep -q "every stage is up to date" "$tmp/out2" && [[ $(grep -c "up to date" "$tmp/out2") -eq 8 ]]'
  "${run[@]}" --from fitter >"$tmp/out3" 2>&1
  check "--from fitter refits only" '[[ $(grep -c "up to date" "$tmp/out3") -eq 6 ]] && grep -Eq "fitter +opencl +[0-9.]+ s" "$tmp/out3"'
  # Another valid target: the same drawing as a video of another size (from a second run).
  mkdir -p "$tmp/frames80"
  for i in 0 1 2 3; do must "$bin" render "$data/examples/man.svg" -o "$tmp/frames80/$i.png" --size 80 2>/dev/null; done
  must "$bin" run --input "$data/examples/man.svg" -o "$tmp/run80" --quiet stages.video.plugin=file \
    "stages.video.path=$tmp/frames80" stages.ranker.plugin=first stages.fitter.iterations=30 \
    stages.fitter.keyframes=3 stages.fitter.size=64 >/dev/null 2>&1
  cp "$tmp/run80/target.mp4" "$tmp/run/target.mp4"
  "${run[@]}" >"$tmp/out4" 2>&1
  # The stages that read target.mp4 (layers, tracker, fitter) run again; the ones before do not.
  check "replacing target.mp4 by hand refits to it" '[[ $(grep -c "up to date" "$tmp/out4") -eq 4 ]] && grep -Eq "ranker +first +up to date" "$tmp/out4" && grep -Eq "fitter +opencl +[0-9.]+ s" "$tmp/out4"'
  expect_error "an unknown config key names its line and the near key" "did you mean 'stages.fitter'" "$tmp/none1" \
    run --input "$data/examples/man.svg" -o "$tmp/none1" stages.fiter.iterations=3
  printf 'stages:\n  fitter:\n    iterationz: 5\n' >"$tmp/bad.yaml"
  expect_error "an unknown key in a config file" "bad.yaml:3: unknown key 'stages.fitter.iterationz' (did you mean 'stages.fitter.iterations'?)" "$tmp/none2" \
    run "$tmp/bad.yaml" --input "$data/examples/man.svg" -o "$tmp/none2"
  # The defaults need no video: the procedural library makes candidates, the pixel ranker picks.
  # (Tiny 96 px candidates read as colour drift: fitted anyway, this checks the providers.)
  must "$bin" run --input "$data/examples/man.svg" -o "$tmp/prompt" --quiet --prompt "the man waves his right arm" \
    stages.ranker.accept_flagged=true stages.video.candidates=2 stages.video.frames=9 stages.video.size=96 \
    stages.fitter.iterations=30 stages.fitter.keyframes=3 stages.fitter.size=64 >"$tmp/out6" 2>&1
  check "a prompt alone runs the whole pipeline with the default plugins" '[[ -s $tmp/prompt/animation.svg && -s $tmp/prompt/candidates/00.mp4 && -s $tmp/prompt/candidates/01.mp4 ]] && grep -q "\"motion\"" "$tmp/prompt/ranking.json" && grep -Eq "<animate(Transform)? attributeName=\"(d|transform)\"" "$tmp/prompt/animation.svg"'
  check "the procedural video says what moves in motion.json (the arm named right)" 'grep -q "\"verb\": \"wave\"" "$tmp/prompt/motion.json" && grep -A3 "\"parts\": \[" "$tmp/prompt/motion.json" | grep -q "\"arm_right\""'
  expect_error "an explicit motion plan with an unknown verb is refused before any stage" "stages.video.options.motion: motion plan 'zoom:arm': unknown verb 'zoom'" "$tmp/none4" \
    run --input "$data/examples/man.svg" -o "$tmp/none4" --quiet "stages.video.options.motion=zoom:arm"
  expect_error "an explicit motion plan naming no part says which parts there are" "'tail*' matches no part (parts: " "$tmp/none5/animation.svg" \
    run --input "$data/examples/man.svg" -o "$tmp/none5" --quiet "stages.video.options.motion=flap:tail*"
  expect_error "a video path with the procedural provider says how to fit it" "stages.video.path is set" "$tmp/none3/animation.svg" \
    run --input "$data/examples/man.svg" -o "$tmp/none3" --quiet "stages.video.path=$tmp/frames"
  # A hanging generator under video `command`: one line within its timeout, earlier stages kept.
  # It sleeps far longer than the 60 s margin below, so an unenforced timeout fails the check.
  printf '#!/bin/sh\nsleep 300\n' >"$tmp/hang.sh" && chmod +x "$tmp/hang.sh"
  start=$SECONDS
  expect_error "a hanging generator fails in one line at its timeout" "candidate 00: $tmp/hang.sh" "$tmp/hang/animation.svg" \
    run --input "$data/examples/man.svg" -o "$tmp/hang" --quiet stages.video.plugin=command \
    "stages.video.options={argv: [\"$tmp/hang.sh\", \"{out}\"], timeout_s: 1, candidates: 1}"
  check "... within the timeout, keeping the earlier stages' outputs" '[[ $((SECONDS - start)) -lt 60 && -s $tmp/hang/grouped.svg && -s $tmp/hang/recolored.png && -s $tmp/hang/candidates/00.log ]]'
  expect_error "a missing plugin" "stages.layers.plugin: no layers plugin 'nosuch'" "$tmp/run/nothing" "${run[@]:1}" stages.layers.plugin=nosuch
  # Drop-in plugin: install the SDK, build a C plugin out of tree, run the pipeline with it.
  if [[ -n $build && -n $sdk_src ]]; then
    cmake --install "$build" --prefix "$tmp/prefix" >/dev/null 2>&1
    cmake -S "$sdk_src" -B "$tmp/plug" -DCMAKE_PREFIX_PATH="$tmp/prefix" >"$tmp/plug.log" 2>&1 &&
      cmake --build "$tmp/plug" >>"$tmp/plug.log" 2>&1
    check "a plugin builds out of tree against the installed SDK" '[[ -f $tmp/plug/svgm_grouper_single.so && -f $tmp/prefix/include/svgmotion/plugin.h ]]'
    rm -f "$tmp/plug/svgm_grouper_future.so.keep"
    "${run[@]}" stages.grouper.plugin=single "plugin_paths=[\"$tmp/plug\"]" >"$tmp/out5" 2>&1
    check "the out-of-tree plugin is used" 'grep -q "<g id=\"everything\">" "$tmp/run/grouped.svg" && grep -q "\"plugin\": \"single\"" "$tmp/run/.svgmotion/grouper.json"'
    SVGMOTION_PLUGIN_PATH="$tmp/plug" "$bin" plugins >"$tmp/plugins" 2>&1
    check "a plugin built for another ABI is refused with the reason" 'grep -q "svgm_grouper_future.so: built against plugin ABI 2, this svgmotion speaks ABI 1; rebuild it" "$tmp/plugins"'
    expect_error "running a refused plugin names the reason" "built against plugin ABI 2" "$tmp/run/nothing2" \
      "${run[@]:1}" stages.grouper.plugin=future "plugin_paths=[\"$tmp/plug\"]"
  fi
  ;;
plugins)
  # Broken modules on the plugin path: one refusal line each, and the other plugins still load.
  real=$(dirname "$bin")/plugins/svgm_grouper_none.so
  mkdir "$tmp/plug"
  size=$(stat -c %s "$real")
  # Where its loaded segments end (PT_LOAD: p_offset + p_filesz): cut inside them, the loader
  # maps pages past the end of the file and dies of SIGBUS touching them.
  seg_end=$("$py" -c 'import struct, sys
d = open(sys.argv[1], "rb").read()
phoff, = struct.unpack_from("<Q", d, 32); ent, num = struct.unpack_from("<HH", d, 54)
print(max(o + f for t, o, f in (struct.unpack_from("<I4xQ16xQ", d, phoff + i * ent) for i in range(num)) if t == 1))' "$real")
  head -c $((seg_end / 2)) "$real" >"$tmp/plug/svgm_grouper_seg.so"
  # Cut after the segments (a build with debug info keeps the section headers at the end).
  head -c $(((size + seg_end) / 2)) "$real" >"$tmp/plug/svgm_grouper_cut.so"
  head -c 64 "$real" >"$tmp/plug/svgm_grouper_stub.so"
  head -c 10 "$real" >"$tmp/plug/svgm_grouper_tiny.so"
  : >"$tmp/plug/svgm_grouper_empty.so"
  printf 'garbage, not a module at all; garbage, not a module at all; garbage\n' >"$tmp/plug/svgm_grouper_junk.so"
  mkfifo "$tmp/plug/svgm_grouper_fifo.so"
  SVGMOTION_PLUGIN_PATH="$tmp/plug" timeout 60 "$bin" plugins >"$tmp/list" 2>"$tmp/err"
  rc=$?
  check "svgmotion plugins survives broken modules (exit 0, nothing on stderr)" '[[ $rc -eq 0 && ! -s $tmp/err ]] && grep -Eq "^grouper +none " "$tmp/list"'
  check "a module cut inside its segments is refused as truncated" 'grep -qx "refused: $tmp/plug/svgm_grouper_seg.so: not a loadable module (truncated: $((seg_end / 2)) bytes, but its segments end at $seg_end)" "$tmp/list"'
  check "a module cut after its segments is refused as truncated" 'grep -qx "refused: $tmp/plug/svgm_grouper_cut.so: not a loadable module (truncated: $(((size + seg_end) / 2)) bytes, but its section headers end at $size)" "$tmp/list"'
  check "a module cut after its ELF header is refused as truncated" 'grep -Eq "^refused: $tmp/plug/svgm_grouper_stub.so: not a loadable module \(truncated: 64 bytes, but its program headers end at [0-9]+\)$" "$tmp/list"'
  check "a module shorter than an ELF header is refused" 'grep -qx "refused: $tmp/plug/svgm_grouper_tiny.so: not a loadable module (shorter than an ELF header: 10 bytes)" "$tmp/list" && grep -qx "refused: $tmp/plug/svgm_grouper_empty.so: not a loadable module (shorter than an ELF header: 0 bytes)" "$tmp/list"'
  check "a text file is refused as not ELF" 'grep -qx "refused: $tmp/plug/svgm_grouper_junk.so: not a loadable module (not an ELF file)" "$tmp/list"'
  check "a FIFO is refused, not opened" 'grep -qx "refused: $tmp/plug/svgm_grouper_fifo.so: not a loadable module (not a regular file)" "$tmp/list"'
  check "exactly the seven broken modules are refused" '[[ $(grep -c "^refused: $tmp/plug/" "$tmp/list") -eq 7 ]]'
  # run: the truncated module on the path does not stop the pipeline from starting; asking for
  # it names the reason.
  SVGMOTION_PLUGIN_PATH="$tmp/plug" timeout 60 "$bin" run --input "$data/examples/man.svg" -o "$tmp/run" --quiet stages.grouper.plugin=seg >"$tmp/out" 2>"$tmp/err"
  rc=$?
  check "run asking for the truncated plugin fails in one line with the reason" '[[ $rc -ne 0 && $rc -lt 128 && $(grep -c "" "$tmp/err") -eq 1 ]] && grep -q "svgm_grouper_seg.so: not a loadable module (truncated" "$tmp/err"'
  ;;
*) echo "unknown group $group"; exit 2 ;;
esac
finish
