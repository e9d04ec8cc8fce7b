#!/usr/bin/env bash
# report.html: report_test.sh SVGMOTION_BINARY TEST_DATA_DIR TOOLS_DIR NODE_MODULES
#   A cheap run (procedural video, 3 small candidates, a short fit) writes report.html; headless
#   Chromium (puppeteer-core, report/report_page_check.js) opens it: every section is there,
#   has a size, text and ink in a full-page screenshot; the prompt shows as text (escaped); every
#   candidate's video is embedded; moving the scrubber pauses the SVG at that time and the page
#   shows what `svgmotion render --time` draws then (PSNR); Play runs it again. The command that
#   "Use this one" shows is run as written: it fits that candidate (target.mp4 is it, the stages
#   before the ranker are up to date, ranking.json records the choice, the page marks it).
#   `svgmotion report` rewrites the page; bad choices and non-run directories are one line. A
#   page that cannot be written is one warning line of `run` (exit 0), and its summary does not
#   list it.
# TOOLS_DIR holds png_psnr (tests/tools); NODE_MODULES holds puppeteer-core (.ci/setup.sh
# installs it into build/npm). Debian's chromium.
set -u
bin=$1 data=$2 tools=$3 node_modules=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# Our renderer and Chromium differ only in anti-aliasing along edges (export_test.sh's Lottie
# bar); the frame of another time is far below it (measured: 47.9 dB at the right time, 26.7
# at time 0).
bar=35
psnr() { "$tools/png_psnr" "$1" "$2" | sed -n 's/^psnr=\([0-9.]*\).*/\1/p'; }
at_least() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 >= b + 0) }'; }
one_line_error() {  # NAME WANT ARGS...: exit 1, one stderr line holding WANT
  local name=$1 want=$2; shift 2
  "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  if [[ $rc -eq 1 && $(grep -c '' "$tmp/stderr") -eq 1 ]] && grep -qF -- "$want" "$tmp/stderr"; then ok "$name"
  else bad "$name (exit $rc, stderr: $(head -c 300 "$tmp/stderr"))"; fi
}

missing=
command -v chromium >/dev/null || missing+=" chromium (Debian)"
command -v node >/dev/null || missing+=" node (Debian nodejs)"
[[ -d $node_modules/puppeteer-core ]] || missing+=" puppeteer-core (npm, in $node_modules)"
if [[ -n $missing ]]; then
  bad "the page checker's tools are not installed:$missing; bash .ci/setup.sh test installs them"
  finish
fi

# A prompt with markup in it: the page must show it as text. 'zorbles' is a word nothing knows.
prompt='the man waves his right arm and zorbles <b id="x">&amp;</b> "it'"'"'s"'
run=("$bin" run --input "$data/examples/man.svg" --prompt "$prompt" -o "$tmp/run" --quiet
     stages.video.frames=12 stages.video.size=128 stages.video.candidates=3
     stages.fitter.iterations=40 stages.fitter.keyframes=4 stages.fitter.size=96 stages.fitter.max_keyframes=4)
# (max_keyframes=4: no keyframes are added from the target, so the fit keeps those the motion asks.)
(cd "$tmp" && "${run[@]}") >"$tmp/run_out" 2>"$tmp/run_err"
rc=$?
check "run writes report.html beside animation.svg (exit $rc)" '[[ $rc -eq 0 && -s $tmp/run/report.html && -s $tmp/run/animation.svg ]]'
check "run names report.html among its outputs" 'grep -q "report.html" "$tmp/run_out"'
check "the page fetches nothing: no http(s) or file address in it" '! grep -Eq "(src|href)=\"(https?|file):" "$tmp/run/report.html"'
# (The wave asks the fitter for more than 4 keyframes, up to twice as many gaps: 7.)
check "fit.json has the loss over iterations (every 10, up to 40) and the keyframes' frames (4-7, as motion.json asks)" \
  '"$py" -c "import json,sys; j=json.load(open(sys.argv[1])); m=json.load(open(sys.argv[2])); h=j[\"loss_history\"]; k=j[\"keyframes\"]; sys.exit(not (h[\"every\"]==10 and h[\"iteration\"][-1]==40 and len(h[\"total\"])==len(h[\"iteration\"])==4 and 4<=k<=7 and k==max(4,[c for c in m[\"candidates\"] if c[\"name\"]==json.load(open(sys.argv[3]))[\"chosen\"]][0][\"keyframes\"]) and len(j[\"keyframe_frames\"])==k and j[\"keyframe_frames\"][0]==0))" "$tmp/run/fit.json" "$tmp/run/motion.json" "$tmp/run/ranking.json"'

t=0.2
node "$here/report/report_page_check.js" "$node_modules" "$tmp/run/report.html" "$tmp/p_" "$t" >"$tmp/facts" 2>"$tmp/facts_err"
rc=$?
check "Chromium opens the page (exit $rc: $(head -c 200 "$tmp/facts_err"))" '[[ $rc -eq 0 ]]'
sed 's/^/# /' "$tmp/facts"
for id in svgm-downloads svgm-player svgm-motion svgm-input svgm-candidates svgm-compare svgm-losses svgm-timings; do
  line=$(grep "^section $id " "$tmp/facts")
  check "section $id is drawn with text and ink (${line#section $id })" \
    '[[ $line =~ \ ([0-9]+)x([0-9]+)\ text=([0-9]+)\ ink=([0-9.]+)$ ]] && (( BASH_REMATCH[1] > 100 && BASH_REMATCH[2] > 100 && BASH_REMATCH[3] > 20 )) && at_least "${BASH_REMATCH[4]}" 0.01'
done
check "the prompt is shown as the text it is, markup included" '[[ $(grep "^prompt " "$tmp/facts") == "prompt $prompt" ]]'
check "3 candidates, each video embedded, \"Use this one\" on the 2 not fitted" 'grep -qx "candidates 3 videos=3 use=2" "$tmp/facts"'
w=$(grep "^seek " "$tmp/facts" | sed -n 's/.* size=\([0-9]*\)x.*/\1/p')
check "the scrubber pauses the animation at $t s and shows the time" 'grep -Eq "^seek $t time=0\.2000 paused=true label=0\.20 size=360x360$" "$tmp/facts"'
check "Play runs the animation again" 'grep -qx "play paused=false advanced=true" "$tmp/facts"'
"$bin" render "$tmp/run/animation.svg" -o "$tmp/ours_t.png" --time "$t" --size "${w:-360}" 2>/dev/null
"$bin" render "$tmp/run/animation.svg" -o "$tmp/ours_0.png" --time 0 --size "${w:-360}" 2>/dev/null
at_t=$(psnr "$tmp/ours_t.png" "$tmp/p_seek.png") at_0=$(psnr "$tmp/ours_0.png" "$tmp/p_seek.png")
echo "# the page after seeking to $t s against svgmotion render: --time $t $at_t dB, --time 0 $at_0 dB"
check "the page shows the frame at $t s: render --time $t within $bar dB ($at_t)" 'at_least "$at_t" "$bar"'
check "and not the frame at 0 ($at_0 dB < $bar)" '! at_least "$at_0" "$bar"'

# Outputs people ship from (issue 37): every file with its size and a link that resolves to it in
# the run directory, the Lottie beside the SVG, candidates in the user's colours, keyframes folded.
n_files=$( (cd "$tmp/run" && find . -maxdepth 1 -type f ! -name '.*' ! -name report.html; ls candidates) | grep -c '')
check "the outputs list every file of the run ($n_files) and nothing outside it or missing ($(grep "^links " "$tmp/facts"))" \
  'grep -qx "links $n_files outside=0 missing=0" "$tmp/facts"'
check "every href and src on the page is a data: URI or a file of the run ($(grep "^addresses " "$tmp/facts"))" \
  'grep -Eqx "addresses [0-9]+ data=[0-9]+ files=$n_files unresolved=0" "$tmp/facts"'
# The motion (issue 35): the plan's rows, each with its parts outlined on the drawing; the words
# not understood as motion.json lists them (less those the lexicon read, "'man': biped"); the
# fit's status not a plain "ok" when there are any.
rows=$("$py" -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["plan"]))' "$tmp/run/motion.json")
check "the plan's $rows actions are rows, each outlined on the drawing, the wave among them ($(grep "^motion " "$tmp/facts"))" \
  '(( rows > 0 )) && grep -Eqx "motion rows=$rows outlined=$rows verbs=(.*,)?wave(,.*)?" "$tmp/facts"'
unknown=$("$py" -c 'import json,sys; m=json.load(open(sys.argv[1])); r=m["readings"]; print(", ".join(w for w in m["not_understood"] if not any(x.startswith(chr(39)+w+chr(39)+":") for x in r)))' "$tmp/run/motion.json")
check "the words not understood are named ($unknown) and the status says so ($(grep "^status " "$tmp/facts"))" \
  '[[ $unknown == *zorbles* ]] && grep -qxF "not_understood Not understood: $unknown " "$tmp/facts" && grep -qx "status ok, but words not understood" "$tmp/facts"'
for f in animation.svg animation.json preview.mp4 fit.json resolved.yaml log.txt; do
  check "a download link to $f, its size on the page" \
    'size=$(stat -c %s "$tmp/run/$f") && grep -qx "link $f $size" "$tmp/facts" && grep -q "href=\"$f\" download>$f</a></td><td>" "$tmp/run/report.html"'
done
lottie=$(grep "^lottie " "$tmp/facts")
check "the Lottie beside the SVG: its frames drawn by librlottie, the one for $t s shown alone ($lottie)" \
  '[[ $lottie =~ ^lottie\ frames=([0-9]+)\ shown=([0-9]+)\ want=([0-9]+)\ visible=1$ ]] && (( BASH_REMATCH[1] >= 10 && BASH_REMATCH[2] == BASH_REMATCH[3] && BASH_REMATCH[2] > 0 ))'
# The frame shown is what rlottie draws then: our render of the SVG at that frame's time, within
# the bar the Lottie export is held to (export_test.sh), far from the frame at time 0.
if [[ $lottie =~ frames=([0-9]+)\ shown=([0-9]+) ]]; then
  dur=$("$py" -c 'import json,sys; j=json.load(open(sys.argv[1])); print((j["op"]-j["ip"])/j["fr"])' "$tmp/run/animation.json")
  lt=$("$py" -c "print($dur * ${BASH_REMATCH[2]} / ${BASH_REMATCH[1]})")
  "$bin" render "$tmp/run/animation.svg" -o "$tmp/ours_l.png" --time "$lt" --size 360 2>/dev/null
  at_l=$(psnr "$tmp/ours_l.png" "$tmp/p_lottie.png") at_l0=$(psnr "$tmp/ours_0.png" "$tmp/p_lottie.png")
  echo "# the Lottie frame shown against svgmotion render --time $lt: $at_l dB (--time 0: $at_l0 dB)"
  check "the Lottie frame shown is the animation at its time ($at_l dB >= $bar)" 'at_least "$at_l" "$bar"'
fi
check "every candidate has 4 frames in the user's colours ($(grep "^user_colours " "$tmp/facts"))" 'grep -qx "user_colours 12" "$tmp/facts"'
check "the keyframe rows are folded ($(grep "^keyframes " "$tmp/facts"))" 'grep -Eqx "keyframes folded=true rows=[4-7]" "$tmp/facts"'

# A page that cannot be written (report.html is a folder) is one line, and no summary lists it.
rm "$tmp/run/report.html" && mkdir "$tmp/run/report.html"
one_line_error "report when report.html is a folder" "$tmp/run/report.html: not a regular file" report "$tmp/run"
(cd "$tmp" && "${run[@]}") >"$tmp/rerun_out" 2>"$tmp/rerun_err"
rc=$?
check "run with report.html a folder: exit $rc, one warning line ($(head -c 300 "$tmp/rerun_err"))" \
  '[[ $rc -eq 0 && $(grep -c "" "$tmp/rerun_err") -eq 1 ]] && grep -qxF "svgmotion: warning: report.html not written: $tmp/run/report.html: not a regular file" "$tmp/rerun_err"'
check "and its summary does not list report.html ($(grep "^outputs in" "$tmp/rerun_out"))" \
  'grep -q "^outputs in $tmp/run: animation.svg" "$tmp/rerun_out" && ! grep -q "report.html" "$tmp/rerun_out"'
rmdir "$tmp/run/report.html"  # the run of "Use this one" below writes it again

# "Use this one": the command as the page shows it, run as written.
chosen=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["chosen"])' "$tmp/run/ranking.json")
other=$(ls "$tmp"/p_cmd_*.sh 2>/dev/null | head -1)
name=${other#"$tmp/p_cmd_"}
name=${name%.sh}
check "the command for $name re-runs this run's command with stages.ranker.choose=$name" \
  'grep -qF -- "stages.ranker.choose=$name" "$other" && grep -qF -- "-o $tmp/run" "$other"'
bash "$other" >"$tmp/use_out" 2>"$tmp/use_err"
rc=$?
check "it runs (exit $rc): grouper to ranker up to date, layers, tracker and fitter run again" \
  '[[ $rc -eq 0 && $(grep -c "up to date" "$tmp/use_out") -eq 4 ]] && grep -Eq "fitter +opencl +[0-9.]+ s" "$tmp/use_out"'
check "target.mp4 is now $name, byte for byte" 'cmp -s "$tmp/run/target.mp4" "$tmp/run/candidates/$name"'
check "ranking.json keeps the ranker's pick ($chosen) and says who chose $name" \
  '"$py" -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(not (j[\"chosen\"]==sys.argv[2] and j[\"ranker_chosen\"]==sys.argv[3] and j[\"chosen_by\"]==\"stages.ranker.choose\"))" "$tmp/run/ranking.json" "$name" "$chosen"'
check "the page now marks $name as fitted" 'grep -qF "svgm-candidate svgm-chosen\" data-name=\"$name\"" "$tmp/run/report.html"'

# svgmotion report rewrites the page; bad input is one line.
rm "$tmp/run/report.html"
"$bin" report "$tmp/run" >"$tmp/rep_out" 2>"$tmp/rep_err"
check "svgmotion report RUN_DIR writes the page again" '[[ -s $tmp/run/report.html ]] && grep -q "^wrote $tmp/run/report.html" "$tmp/rep_out"'
one_line_error "report on a folder that is not a run" "$data/examples: not a run directory (no input.svg" report "$data/examples"
one_line_error "a choice that is a path" "stages.ranker.choose: must be a plain file name in the run's candidates/ folder (such as 01.mp4), not ../x.mp4" \
  run --input "$data/examples/man.svg" -o "$tmp/none" stages.ranker.choose=../x.mp4
check "and nothing was made for it" '[[ ! -e $tmp/none ]]'
one_line_error "a choice that is no candidate" "stages.ranker.choose: no candidate 'nope.mp4' in $tmp/run/candidates (candidates: 00.mp4, 01.mp4, 02.mp4)" \
  "${run[@]:1}" stages.ranker.choose=nope.mp4
check "and target.mp4 stays $name" 'cmp -s "$tmp/run/target.mp4" "$tmp/run/candidates/$name"'
finish
