#!/usr/bin/env bash
# The user's own drawing back, and no broken result reported as success (cli_trust):
#  - `run` returns the user's document (ids, groups, a gradient, a transform, <use>, comments,
#    root attributes) with only `d` animated; a run directory named with a quote works;
#  - a target of noise and a motion that leaves the frame end with exit 3, no animation.svg,
#    animation.failed.svg and fit.json "status": "rejected";
#  - candidates that are all flagged stop the run before fitting with exit 4;
#  - every bad setting fails before any stage runs, in one line naming the key;
#  - render refuses formats it cannot write and never writes over its input.
# usage: trust_test.sh SVGMOTION_BIN TEST_DATA_DIR
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"
own=$data/own/own_document.svg
small=(stages.video.candidates=1 stages.video.frames=13 stages.video.size=128
       stages.fitter.iterations=150 stages.fitter.keyframes=4 stages.fitter.size=64)

# 1. The own document, through the default pipeline (procedural video), into a directory whose
#    name has a quote and a backslash (once pasted into YAML and cut at the quote).
out="$tmp/own\"_y\\z"
"$bin" run --input "$own" --prompt 'the figure says "hi" and waves its arm' -o "$out" --quiet \
  stages.ranker.accept_flagged=true stages.fitter.compact=false "${small[@]}" >"$tmp/own.out" 2>"$tmp/own.err"
rc=$?
check "run on the own document exits 0" '[[ $rc -eq 0 ]] || { cat "$tmp/own.err"; false; }'
check "... into the directory named with a quote, as typed" '[[ -s $out/animation.svg ]]'
check "animation.svg (the full export) is the user's document with only d animated" \
  '"$py" "$here/same_document.py" "$own" "$out/animation.svg" >"$tmp/same.out" || { cat "$tmp/same.out"; false; }'
check "... every drawn shape that is not a <use> is animated" 'grep -q "same document, 4 paths animated" "$tmp/same.out"'
check "... the gradient, the use elements and the comments are there" \
  'grep -q "<linearGradient id=\"shirt\"" "$out/animation.svg" && [[ $(grep -c "<use " "$out/animation.svg") -eq 2 ]] && grep -q "<!-- a closing comment -->" "$out/animation.svg"'
check "fit.json says ok, with the key times of the fitted frames" \
  'grep -q "\"status\": \"ok\"" "$out/fit.json" && grep -q "\"key_times\"" "$out/fit.json"'

# Targets made with our renderer: frames as numbered PNGs.
frames() {  # NAME COUNT BODY_FN: BODY_FN k prints the SVG body of frame k
  mkdir -p "$tmp/$1"
  for ((k = 0; k < $2; k++)); do
    printf '<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">%s</svg>' "$($3 $k)" >"$tmp/$1/f.svg"
    "$bin" render "$tmp/$1/f.svg" -o "$tmp/$1/$(printf %03d $k).png" --size 128 2>/dev/null
  done
  rm "$tmp/$1/f.svg"
}
noise_body() {  # 60 random rectangles in random colours, a fresh draw per frame
  RANDOM=$((1000 + $1))
  for _ in $(seq 60); do
    printf '<rect x="%d" y="%d" width="%d" height="%d" fill="#%02x%02x%02x"/>' $((RANDOM % 200)) $((RANDOM % 200)) \
      $((10 + RANDOM % 60)) $((10 + RANDOM % 60)) $((RANDOM % 256)) $((RANDOM % 256)) $((RANDOM % 256))
  done
}
leave_body() { printf '<circle cx="%d" cy="100" r="30" fill="#2f6fd0"/>' $((100 + 60 * $1)); }
still_body() { printf '<circle cx="100" cy="100" r="30" fill="#2f6fd0"/>'; }
frames noise 6 noise_body
frames leave 6 leave_body
frames still 6 still_body
printf '<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200"><circle id="ball" cx="100" cy="100" r="30" fill="#2f6fd0"/></svg>' >"$tmp/ball.svg"

# 2. Targets that cannot be fitted.
rejected() {  # NAME SVG FRAMES_DIR
  local n=$1
  "$bin" run --input "$2" -o "$tmp/r_$n" --quiet stages.video.plugin=file "stages.video.path=$3" \
    stages.ranker.plugin=first stages.fitter.iterations=200 stages.fitter.keyframes=6 stages.fitter.size=64 \
    >"$tmp/r_$n.out" 2>"$tmp/r_$n.err"
  local rc=$?
  check "$n: exit status 3 (rejected)" '[[ $rc -eq 3 ]] || { echo "rc=$rc"; cat "$tmp/r_$n.err"; false; }'
  check "$n: one line says it was rejected" '[[ $(grep -vc "warning:" "$tmp/r_$n.err") -eq 1 ]] && grep -q "the fit was rejected: keyframe" "$tmp/r_$n.err"'
  check "$n: no animation.svg, animation.failed.svg to inspect" '[[ ! -e $tmp/r_$n/animation.svg && -s $tmp/r_$n/animation.failed.svg ]]'
  check "$n: fit.json records the status and the reasons" \
    'grep -q "\"status\": \"rejected\"" "$tmp/r_$n/fit.json" && grep -q "\"reasons\"" "$tmp/r_$n/fit.json"'
}
rejected noise "$own" "$tmp/noise"
rejected leave "$tmp/ball.svg" "$tmp/leave"
# `fit` alone: the same verdict and exit status; --no-gate writes animation.svg with a warning.
"$bin" fit "$tmp/ball.svg" --target "$tmp/leave" -o "$tmp/fit_leave" --iterations 200 --keyframes 6 --size 64 --quiet 2>"$tmp/fl.err"
rc=$?
check "fit: a motion leaving the frame exits 3 without animation.svg" '[[ $rc -eq 3 && ! -e $tmp/fit_leave/animation.svg ]]'
"$bin" fit "$tmp/ball.svg" --target "$tmp/leave" -o "$tmp/fit_leave" --iterations 200 --keyframes 6 --size 64 --quiet --no-gate 2>"$tmp/fl2.err"
rc=$?
check "fit --no-gate: exit 0, animation.svg, a warning" '[[ $rc -eq 0 && -s $tmp/fit_leave/animation.svg && ! -e $tmp/fit_leave/animation.failed.svg ]] && grep -q "would reject" "$tmp/fl2.err"'

# 3. Every candidate flagged ("no motion": a still video) stops before fitting.
"$bin" run --input "$tmp/ball.svg" -o "$tmp/flagged" --quiet stages.video.plugin=file "stages.video.path=$tmp/still" \
  stages.fitter.iterations=50 stages.fitter.keyframes=3 stages.fitter.size=64 >"$tmp/flagged.out" 2>"$tmp/flagged.err"
rc=$?
check "all candidates flagged: exit 4 before fitting, naming the defect" \
  '[[ $rc -eq 4 && ! -e $tmp/flagged/fit.json && ! -e $tmp/flagged/layered.svg ]] && grep -q "every candidate video was flagged by the ranker (00: no motion" "$tmp/flagged.err"'
"$bin" run --input "$tmp/ball.svg" -o "$tmp/flagged" --quiet stages.video.plugin=file "stages.video.path=$tmp/still" \
  stages.fitter.iterations=50 stages.fitter.keyframes=3 stages.fitter.size=64 stages.ranker.accept_flagged=true >/dev/null 2>&1
rc=$?
check "... stages.ranker.accept_flagged=true fits it anyway" '[[ $rc -eq 0 && -s $tmp/flagged/animation.svg ]]'

# 4. Bad settings: one line naming the key, before any stage (no run directory appears).
bad_setting() {  # NAME EXPECTED ARGS...
  local name=$1 want=$2; shift 2
  "$bin" run --input "$own" -o "$tmp/none" "$@" >"$tmp/bs.out" 2>"$tmp/bs.err"
  local rc=$?
  check "bad setting $name: one line naming it, nothing run" \
    '[[ $rc -eq 1 && $(wc -l <"$tmp/bs.err") -eq 1 && ! -e $tmp/none ]] && grep -qF -- "$want" "$tmp/bs.err" || { echo "rc=$rc"; cat "$tmp/bs.err"; false; }'
}
bad_setting iterations "command line 'stages.fitter.iterations=-5': stages.fitter.iterations: must be a whole number from 1 to 1000000, not -5" stages.fitter.iterations=-5
bad_setting huge_iterations "stages.fitter.iterations: must be a whole number" stages.fitter.iterations=1e12
bad_setting colors "stages.fitter.colors: must be one of auto, palette, original, not rainbow" stages.fitter.colors=rainbow
bad_setting loop "stages.fitter.loop: must be one of loop, once, mirror, not sideways" stages.fitter.loop=sideways
bad_setting size "stages.fitter.size: must be a whole number from 32 to 4096, not 1.5" stages.fitter.size=1.5
bad_setting small_size "stages.fitter.size: must be a whole number from 32 to 4096, not 8" stages.fitter.size=8
bad_setting keyframes "stages.fitter.keyframes: must be a whole number from 2 to 1000, not 1" stages.fitter.keyframes=1
bad_setting mask "stages.fitter.mask_threshold: must be a number in (0, 1]" stages.fitter.mask_threshold=1.5
bad_setting chroma "stages.fitter.chroma_weight: must be auto or a number in (0, 1], not 2" stages.fitter.chroma_weight=2
bad_setting chroma_word "stages.fitter.chroma_weight: must be auto or a number in (0, 1], not often" stages.fitter.chroma_weight=often
bad_setting denoise "stages.fitter.denoise: must be a whole number from 0 to 4, not 7" stages.fitter.denoise=7
bad_setting device "device: no OpenCL device matches" --device nosuchdevice
bad_setting bare_key "'stages.fitter.iterations' is not a config file; a setting needs a value" stages.fitter.iterations
bad_setting from "--from fittr: no such stage" --from fittr
bad_setting plugin "stages.video.plugin: no video plugin 'nosuch'" stages.video.plugin=nosuch
bad_setting video_path "stages.video.path: video: file needs the video" stages.video.plugin=file
bad_setting prompt_utf8 "prompt: is not valid UTF-8 text" --prompt $'waves \xff\xfe'
"$bin" run --input "$data/svg/broken.svg" -o "$tmp/none" >"$tmp/bs.out" 2>"$tmp/bs.err"
check "a malformed input is named as the user's file, before any stage" \
  '[[ $? -eq 1 && ! -e $tmp/none ]] && grep -q "^svgmotion: $data/svg/broken.svg: " "$tmp/bs.err"'

printf '<svg xmlns="http://www.w3.org/2000/svg" width="20" height="20"><rect id="a\xff" width="5" height="5"/></svg>' >"$tmp/badid.svg"
"$bin" run --input "$tmp/badid.svg" -o "$tmp/none" >"$tmp/bs.out" 2>"$tmp/bs.err"
check "an id that is not UTF-8: one line, before any stage" \
  '[[ $? -eq 1 && ! -e $tmp/none && $(wc -l <"$tmp/bs.err") -eq 1 ]] && grep -q "badid.svg: <rect> has an id that is not valid UTF-8 text" "$tmp/bs.err"'

# 5. render: the format follows the extension; the input is never overwritten.
cp "$own" "$tmp/in.svg"
before=$(cksum <"$tmp/in.svg")
"$bin" render "$tmp/in.svg" -o "$tmp/in.svg" 2>"$tmp/re.err"
check "render -o INPUT is refused and the input is unchanged" '[[ $? -eq 1 && $(cksum <"$tmp/in.svg") == "$before" ]] && grep -q "choose another output name" "$tmp/re.err"'
"$bin" render "$tmp/in.svg" -o "$tmp/out.svg" 2>"$tmp/re.err"
check "render -o X.svg is refused (PNG images and clips only), nothing written" '[[ $? -eq 1 && ! -e $tmp/out.svg ]] && grep -q "render writes .png images, .mp4, .webm, .gif or .webp clips" "$tmp/re.err"'
"$bin" render "$tmp/in.svg" -o "$tmp/OUT.PNG" 2>/dev/null
check "render -o X.PNG writes a PNG" '[[ $? -eq 0 && $(head -c 4 "$tmp/OUT.PNG" | od -An -c | tr -d " ") == "211PNG" ]]'

# 6. Ctrl-C in run: one line saying what the run directory holds, exit 130; the next run
#    resumes the fit from its checkpoint instead of starting again (at a fixed number of
#    keyframes: keyframes added from the target refit with iterations of their own).
int=("$bin" run --input "$tmp/ball.svg" -o "$tmp/int" --quiet stages.video.plugin=file "stages.video.path=$tmp/leave"
     stages.ranker.plugin=first stages.fitter.iterations=3000 stages.fitter.keyframes=3 stages.fitter.size=64
     stages.fitter.gate=false stages.fitter.stop_when_converged=false stages.fitter.max_keyframes=3)
"${int[@]}" >/dev/null 2>"$tmp/int.err" &
pid=$!
# Interrupted as soon as the first checkpoint (iteration 250 of 3000) is on disk, so the fit is
# surely still running however fast the machine is.
for _ in $(seq 600); do [[ -f $tmp/int/checkpoint.bin ]] && break; sleep 0.05; done
kill -INT $pid
wait $pid
rc=$?
check "Ctrl-C in run: exit 130 and one line naming what was written" \
  '[[ $rc -eq 130 ]] && grep -q "interrupted; $tmp/int holds .*checkpoint.bin" "$tmp/int.err" || { echo rc=$rc; cat "$tmp/int.err"; false; }'
# Left by a kill -9 (of a process that no longer runs), beside a file of the user's named alike.
dead=$(($(cat /proc/sys/kernel/pid_max) + 1))  # a pid no process has
touch "$tmp/int/.preview.mp4.svgm-tmp-$dead.mp4" "$tmp/int/.fit.json.svgm-tmp-$dead" "$tmp/int/thesis.part1.pdf"
"${int[@]}" >/dev/null 2>&1 &
pid=$!
# A second run on the same directory while the first resumes: refused in one line naming the
# holder (its pid is in the lock file once it holds the lock), and the first goes on.
for _ in $(seq 600); do [[ $(cat "$tmp/int/.svgmotion/lock" 2>/dev/null) == "$pid" ]] && break; sleep 0.05; done
"${int[@]}" >/dev/null 2>"$tmp/second.err"
rc2=$?
check "a second run on a busy run directory: one line, exit 1" \
  '[[ $rc2 -eq 1 && $(wc -l <"$tmp/second.err") -eq 1 ]] && grep -q "another svgmotion run is using this run directory (pid $pid)" "$tmp/second.err"'
wait $pid
check "the next run removes temporary files a killed run left, and no file of the user's" '[[ -z $(ls -a "$tmp/int" | grep "svgm-tmp") && -e $tmp/int/thesis.part1.pdf ]]'
check "... and the next run resumes the fit" \
  '"$py" -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d[\"resumed_from\"] >= 250 and d[\"iterations\"] == 3000 + d.get(\"refined\", {}).get(\"iterations\", 0) else 1)" "$tmp/int/fit.json"'

# 7. Help and version.
check "svgmotion --version" '"$bin" --version | grep -Eq "^svgmotion [0-9]+\.[0-9]+\.[0-9]+$"'
for c in run fit render plugins devices palette bench; do
  check "svgmotion $c --help" '"$bin" $c --help | grep -q "^usage: svgmotion $c"'
done
check "fit --help lists every option" '"$bin" fit --help >"$tmp/h" && for o in --target --iterations --keyframes --size --palette --mask-threshold --loop --no-gate --resume --no-track --device --quiet; do grep -q -- "$o" "$tmp/h" || exit 1; done'
finish
