#!/usr/bin/env bash
# The CLI tells the truth (issue 37): cli_truth_test.sh GROUP SVGMOTION_BINARY TEST_DATA_DIR BUILD_DIR
#   progress  a cheap `run` in a pseudo-terminal 80 columns wide (script(1), stty cols 80): each
#             stage's bar only moves forward and ends at 100 %, and no redraw is wider than 79
#             columns (a wider one wraps, and "\r" then scrolls a new line per redraw); long
#             steps without iterations are named on the bar. No timing is asserted (the ETA's
#             honesty: tests/bench/progress_eta.sh, and fit_progress_test.cpp on a given clock).
#   config    `svgmotion config` lists every key of default.yaml with default, type and meaning;
#             --show merges a config (a built-in one by name, from a folder without configs/)
#             and overrides, naming each setting's origin; bad names are one line.
#   run       `run X.svg "PROMPT"` takes them as input and prompt; the run directory keeps
#             resolved.yaml (which `run` takes back) and log.txt a command line that sh reads
#             back to the same words; `run fast` outside the repository uses the built-in config.
#   install   `cmake --install` into a temporary prefix: the binary there finds its plugins
#             (svgmotion plugins lists them from PREFIX/lib/svgmotion/plugins, refuses none) and
#             the configs are installed.
set -u
group=$1 bin=$2 data=$3 build=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

cheap=(stages.video.frames=12 stages.video.size=128 stages.video.candidates=2
       stages.fitter.iterations=60 stages.fitter.keyframes=4 stages.fitter.size=96)

case $group in
progress)
  command -v script >/dev/null || { bad "script(1) is not installed (util-linux)"; finish; }
  # Every iteration of a longer fit runs, so the fitter's bar is redrawn on its way.
  cmd=$(printf '%q ' "$bin" run "$data/examples/man.svg" "the man waves" -o "$tmp/run" "${cheap[@]}" \
        stages.fitter.iterations=300 stages.fitter.stop_when_converged=false)
  (cd "$tmp" && script -q -e -c "stty cols 80 rows 24; $cmd" /dev/null) >"$tmp/typescript" 2>&1
  rc=$?
  check "the run in a terminal succeeds (exit $rc)" '[[ $rc -eq 0 && -s $tmp/run/animation.svg ]]'
  # Every redraw is one "\r"-separated segment; a stage's bars follow its "run: STAGE ..." line.
  "$py" - "$tmp/typescript" >"$tmp/bars" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8", errors="replace").read().replace("\x1b[K", "")
stage, bars = None, {}
for seg in re.split(r"[\r\n]", text):
    m = re.search(r"run: (\w+) \(", seg)
    if m:
        stage = m.group(1); bars[stage] = []; continue
    m = re.match(r"  \[[# ]{20}\] +(\d+)%", seg)
    if m and stage:
        bars[stage].append((int(m.group(1)), len(seg)))
for stage, b in bars.items():
    pcts = [p for p, _ in b]
    print(stage, "redraws=%d" % len(b), "monotone=%s" % all(x <= y for x, y in zip(pcts, pcts[1:])),
          "last=%s" % (pcts[-1] if pcts else "none"), "widest=%d" % max([w for _, w in b] or [0]),
          "percentages=" + ",".join(map(str, pcts)))
PY
  sed 's/^/# /' "$tmp/bars"
  check "a bar for each of the 7 stages" '[[ $(grep -c "" "$tmp/bars") -eq 7 ]]'
  check "every bar only moves forward" '! grep -q "monotone=False" "$tmp/bars"'
  check "every bar ends at 100 %" '[[ $(grep -c " last=100 " "$tmp/bars") -eq 7 ]]'
  check "the fitter's bar was redrawn on its way" '[[ $(sed -n "s/^fitter redraws=\([0-9]*\).*/\1/p" "$tmp/bars") -ge 3 ]]'
  check "no redraw is wider than 79 columns" '! grep -Eq "widest=([89][0-9]|[1-9][0-9]{2,})" "$tmp/bars"'
  # Long steps without iterations are named on the bar, not left at "starting" (issue 37: the
  # fitter's bar stood still for 30 s before its first iteration and between its stages).
  check "the fitter names its setup on the bar" 'grep -q "%  reading the video.s keyframes at 96 px" "$tmp/typescript"'
  check "the fitter names the keyframe choice on the bar" 'grep -Eq "%  judging the [0-9]+ frames between keyframes" "$tmp/typescript"'
  check "the video stage names the candidate it makes" 'grep -q "%  making candidate 00" "$tmp/typescript"'
  ;;
config)
  "$bin" config >"$tmp/keys" 2>"$tmp/err"
  rc=$?
  keys=$("$py" -c 'import sys,yaml' 2>/dev/null && echo yes)
  check "config lists keys (exit $rc)" '[[ $rc -eq 0 && $(grep -c "" "$tmp/keys") -gt 40 ]]'
  check "a key with its default, type and meaning" \
    'grep -Eq "^stages\.fitter\.iterations +2000 +integer +the optimiser.s iteration budget" "$tmp/keys"'
  check "every key has a meaning" '! awk "NR > 1 && NF < 4" "$tmp/keys" | grep -q .'
  # Every key of default.yaml is listed, once (the leaves of its YAML, options as one).
  "$py" - "$here/../../configs/default.yaml" >"$tmp/want" <<'PY'
import re, sys
stack = []
for line in open(sys.argv[1]):
    m = re.match(r"^( *)([A-Za-z_]+):(.*)$", line)
    if not m or line.lstrip().startswith("#"): continue
    depth = len(m.group(1)) // 2
    stack = stack[:depth] + [m.group(2)]
    value = m.group(3).split("#")[0].strip()
    if value: print(".".join(stack))
PY
  check "every key of default.yaml is listed ($(grep -c "" "$tmp/want") keys)" \
    'diff <(sort "$tmp/want") <(awk "NR > 1 {print \$1}" "$tmp/keys" | sort) >/dev/null'
  mkdir "$tmp/elsewhere"
  (cd "$tmp/elsewhere" && "$bin" config --show fast stages.fitter.size=128) >"$tmp/show" 2>"$tmp/err"
  rc=$?
  check "config --show fast from a folder without configs/ (exit $rc)" '[[ $rc -eq 0 && ! -s $tmp/err ]]'
  check "the built-in fast config's setting, with its origin" 'grep -qx "    iterations: 400  # fast.yaml (built in):4" "$tmp/show"'
  check "an override, with its origin" "grep -qx \"    size: 128  # command line 'stages.fitter.size=128'\" \"\$tmp/show\""
  check "a default, without one" 'grep -qx "    max_groups: 15" "$tmp/show"'
  (cd "$tmp/elsewhere" && "$bin" config --show nonesuch) >"$tmp/out" 2>"$tmp/err"
  rc=$?
  check "config --show of no such config: exit 1, one line ($(cat "$tmp/err"))" \
    '[[ $rc -eq 1 && $(grep -c "" "$tmp/err") -eq 1 ]] && grep -qx "svgmotion: nonesuch: cannot open (built-in configs: default.yaml, fast.yaml, paper.yaml)" "$tmp/err"'
  "$bin" config --show fast stages.fitter.nope=1 >"$tmp/out" 2>"$tmp/err"
  rc=$?
  check "an unknown key: exit 1, one line naming it" \
    '[[ $rc -eq 1 && $(grep -c "" "$tmp/err") -eq 1 ]] && grep -q "unknown key .stages.fitter.nope." "$tmp/err"'
  ;;
run)
  cp "$data/examples/man.svg" "$tmp/drawing"  # an SVG by its content, without the extension
  prompt="the man's arm waves, \"twice\" \$HOME"
  mkdir "$tmp/elsewhere"
  quick=("${cheap[@]:0:4}" stages.fitter.size=96 stages.fitter.refine_size=0)  # fast's 8 keyframes stay
  (cd "$tmp/elsewhere" && "$bin" run ../drawing "$prompt" fast -o run "${quick[@]}" --quiet) >"$tmp/out" 2>"$tmp/err"
  rc=$?
  r=$tmp/elsewhere/run
  check "run FILE \"PROMPT\" fast (exit $rc: $(head -c 300 "$tmp/err"))" '[[ $rc -eq 0 && -s $r/animation.svg ]]'
  check "resolved.yaml: the input and the prompt as given" \
    'grep -qx "input: \"../drawing\"" "$r/resolved.yaml" && grep -qxF "prompt: \"the man'"'"'s arm waves, \\\"twice\\\" \$HOME\"" "$r/resolved.yaml"'
  check "resolved.yaml: the built-in fast config's keyframes" 'grep -qx "    keyframes: 8  # fast.yaml (built in):5" "$r/resolved.yaml"'
  check "resolved.yaml: the defaults too" 'grep -qx "    max_groups: 15" "$r/resolved.yaml"'
  (cd "$tmp/elsewhere" && "$bin" config --show run/resolved.yaml) >"$tmp/again" 2>"$tmp/err"
  check "resolved.yaml loads back as a config, to the same settings" \
    'diff <(grep -v "^#" "$r/resolved.yaml" | sed "s/  #.*//") <(sed "s/  #.*//" "$tmp/again") >/dev/null'
  line=$(sed -n 's/^.* ===== svgmotion [^:]*: //p' "$r/log.txt" | head -1)
  echo "# log.txt: $line"
  "$py" -c 'import shlex, sys; w = shlex.split(sys.argv[1]); sys.exit(w[1:] != sys.argv[2:])' "$line" \
    run ../drawing "$prompt" fast -o run "${quick[@]}" --quiet
  check "log.txt's command line reads back in sh to the words given" '[[ $? -eq 0 ]]'
  "$bin" run "$tmp/drawing" "$prompt" --input "$tmp/drawing" -o "$tmp/twice" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  check "an SVG given twice: exit 2, one line ($(cat "$tmp/err"))" \
    '[[ $rc -eq 2 && $(grep -c "" "$tmp/err") -eq 1 ]] && grep -q "the SVG is given twice" "$tmp/err" && [[ ! -e $tmp/twice ]]'
  "$bin" run "$tmp/nope.svg" "a prompt" -o "$tmp/nope" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  check "a missing X.svg is named as the input: exit 1, one line ($(cat "$tmp/err"))" \
    '[[ $rc -eq 1 ]] && grep -qx "svgmotion: $tmp/nope.svg: cannot open: No such file or directory" "$tmp/err" && [[ ! -e $tmp/nope ]]'
  ;;
install)
  cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install_log" 2>&1
  rc=$?
  check "cmake --install into a temporary prefix (exit $rc)" '[[ $rc -eq 0 && -x $tmp/prefix/bin/svgmotion ]]'
  check "the configs are installed" '[[ -s $tmp/prefix/share/svgmotion/configs/default.yaml && -s $tmp/prefix/share/svgmotion/configs/fast.yaml ]]'
  (cd / && env -u SVGMOTION_PLUGIN_PATH "$tmp/prefix/bin/svgmotion" plugins) >"$tmp/plugins" 2>"$tmp/err"
  rc=$?
  sed 's/^/# /' "$tmp/plugins"
  n_built=$(ls "$build"/frontends/plugins/svgm_*.so | wc -l)
  check "the installed binary lists its $n_built plugins from PREFIX/lib/svgmotion/plugins (exit $rc)" \
    '[[ $rc -eq 0 && $(grep -c " $tmp/prefix/lib/svgmotion/plugins/svgm_.*\.so$" "$tmp/plugins") -eq $n_built ]]'
  check "and refuses none, loads none from elsewhere" '! grep -q "^refused" "$tmp/plugins" && [[ $(grep -c "" "$tmp/plugins") -eq $n_built ]]'
  (cd / && "$tmp/prefix/bin/svgmotion" config --show paper) >"$tmp/out" 2>&1
  check "the installed binary has the built-in configs" '[[ $? -eq 0 ]] && grep -q "# paper.yaml (built in)" "$tmp/out"'
  ;;
*) bad "unknown group $group" ;;
esac
finish
