#!/usr/bin/env bash
# The procedural video's `llm` planner (stages.video.options.planner: llm) against the fake
# chat-completions server (fake_llm_server.py):
#   llm_planner_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# A base run plans offline; every case copies it and reruns from the video stage. A valid plan
# from the model (plain, or fenced and quoted) is the plan: motion.json says source "llm" and
# holds the plan, the candidates move what it names. The request holds the drawing as a PNG
# data URL, the part names, the prompt, temperature 0 and a seed. Every failure (no url,
# refused, timeout, HTTP 500, a sentence, an unknown part or verb, an empty or two-line answer,
# a 401 echoing the key, a content part whose type is no string, the key split over two parts,
# a key in the endpoint's query, which no message shows) plans offline with exit status 0, one warning line naming the reason,
# and the reason in motion.json. The API key is in no log.txt, motion.json or terminal output.
# Prints "ok - ..."/"not ok - ...", then "N passed, M failed"; exits non-zero on any failure.
# KEEP=1 keeps the scratch folder.
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

svg=$data/examples/man.svg
prompt="waves the right arm"
# Tiny candidates and fit: these runs test the planner, not the video or the fit.
small=(stages.ranker.accept_flagged=true stages.video.candidates=1 stages.video.frames=9 stages.video.size=96
       stages.layers.plugin=none stages.tracker.plugin=none
       stages.fitter.iterations=2 stages.fitter.keyframes=3 stages.fitter.size=64 stages.fitter.refine_size=0)
"$bin" run --input "$svg" -o "$tmp/base" --quiet --prompt "$prompt" "${small[@]}" >"$tmp/base.out" 2>&1
check "the base run plans offline" '[[ -s $tmp/base/motion.json && -s $tmp/base/candidates/00.mp4 ]] || { tail -3 "$tmp/base.out"; false; }'
[[ -s $tmp/base/motion.json ]] || finish

start_server "$here/fake_llm_server.py" --lifetime 300 --hang 20 --log "$tmp/requests.log" ||
  { bad "the fake server starts"; finish; }
url="http://127.0.0.1:$port/v1/chat/completions"
closed=$(closed_port)
key=test-secret

# run_case NAME OPTIONS: rerun from the video stage in a copy of the base run, with the key in
# PLANNER_KEY (named by api_key_env where OPTIONS says so).
run_case() {
  local name=$1 options=$2
  cp -r "$tmp/base" "$tmp/$name"
  PLANNER_KEY=$key timeout 120 "$bin" run --input "$svg" -o "$tmp/$name" --from video --quiet --prompt "$prompt" \
    "stages.video.options={planner: llm${options:+, $options}}" "${small[@]}" >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
}
opts() { echo "url: \"${2:-$url}\", model: \"$1\", timeout_s: 3"; }
cases=()
run_case valid "$(opts plan_auth), api_key_env: PLANNER_KEY" & cases+=($!)
run_case fenced "$(opts plan_fenced)" & cases+=($!)
run_case nourl "" & cases+=($!)
run_case refused "$(opts plan_valid "http://127.0.0.1:$closed/v1/chat/completions")" & cases+=($!)
run_case hang "$(opts hang)" & cases+=($!)
run_case http500 "$(opts http500)" & cases+=($!)
run_case garbage "$(opts plan_garbage)" & cases+=($!)
run_case unknown_part "$(opts plan_unknown_part)" & cases+=($!)
run_case unknown_verb "$(opts plan_unknown_verb)" & cases+=($!)
run_case empty "$(opts plan_empty)" & cases+=($!)
run_case two_lines "$(opts plan_two_lines)" & cases+=($!)
run_case echo_key "$(opts plan_echo_key), api_key_env: PLANNER_KEY" & cases+=($!)
run_case bad_type "$(opts plan_bad_type)" & cases+=($!)
run_case split_key "$(opts plan_split_key), api_key_env: PLANNER_KEY" & cases+=($!)
run_case url_key "$(opts plan_valid "$url?key=query-secret")" & cases+=($!)
wait "${cases[@]}"

# motion NAME EXPR: a Python expression over motion.json (j) is true.
# (further arguments: sys.argv[2:])
motion() { "$py" -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$tmp/$1/motion.json" "${@:3}"; }
# The plan's verbs and parts as "verb:part+part" items, the offline planner's for the base run.
plan_of() { "$py" -c 'import json,sys; print(", ".join(a["verb"] + ":" + "+".join(a["parts"]) for a in json.load(open(sys.argv[1]))["plan"]))' "$tmp/$1/motion.json"; }
offline=$(plan_of base)
check "the offline plan waves the right arm" '[[ $offline == "wave:arm_right" ]] || { echo "$offline"; false; }'

for c in valid fenced; do
  check "$c: the model's plan is the plan (motion.json source llm, the plan kept), exit 0, no warning" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 ]] && motion $c "j[\"source\"] == \"llm\" and j[\"planner\"][\"source\"] == \"llm\" and j[\"planner\"][\"plan\"] == \"wave:arm_left slow, kick:leg_right\"" &&
     [[ $(plan_of $c) == "wave:arm_left, kick:leg_right" ]] && ! grep -q "planner llm" "$tmp/$c.err" || { head -c 400 "$tmp/$c.err"; plan_of $c; false; }'
done
check "valid: the terminal says the model's plan" 'grep -q "the llm planner.s plan: wave:arm_left slow, kick:leg_right" "$tmp/valid/log.txt"'
check "the request: the drawing as a 512 px PNG data URL, every part by number and name, the prompt, the verbs, temperature 0, a seed, the key as a Bearer token" \
  '"$py" - "$tmp/requests.log" <<PY
import base64, json, struct, sys
for line in open(sys.argv[1]):
    e = json.loads(line)
    b = e["body"]
    if b["model"] != "plan_auth":
        continue
    assert e["headers"].get("Authorization") == "Bearer test-secret", e["headers"]
    assert b["temperature"] == 0 and b["seed"] == 0, (b["temperature"], b["seed"])
    system = b["messages"][0]["content"]
    assert "verb:part" in system and "wave (" in system and "flap (" in system, system
    text, image = b["messages"][1]["content"]
    text = text["text"]
    assert "Motion asked for: $prompt" in text, text
    for i, name in enumerate(["leg_left", "leg_right", "body", "arm_left", "arm_right", "neck", "head"]):
        assert "%d. %s (" % (i + 1, name) in text, (name, text)
    url = image["image_url"]["url"]
    assert url.startswith("data:image/png;base64,"), url[:40]
    png = base64.b64decode(url[len("data:image/png;base64,"):])
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">I", png[16:20])[0] == 512
    break
else:
    sys.exit("no planner request with the key")
PY'

declare -A why=([nourl]="no url configured (stages.video.options.url)" [refused]="127.0.0.1:$closed"
  [hang]="timeout: no answer from" [http500]="HTTP 500 from" [garbage]="unknown verb 'sure!'"
  [unknown_part]="'tentacle_left' matches no part (parts: leg_left, leg_right, body, arm_left"
  [unknown_verb]="unknown verb 'teleport'" [empty]="the model's plan is empty"
  [two_lines]="malformed plan: more than one line" [echo_key]="HTTP 401 from" [bad_type]="the model's plan is empty"
  [split_key]="wave:arm_left" [url_key]="HTTP 404 from http://127.0.0.1:$port/v1/chat/completions?...")
for c in nourl refused hang http500 garbage unknown_part unknown_verb empty two_lines echo_key bad_type split_key url_key; do
  check "$c: plans offline, exit 0, one warning line naming the reason, the reason in motion.json" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 && $(plan_of $c) == "$offline" ]] && [[ $(grep -c "planner llm" "$tmp/$c.err") -eq 1 ]] &&
     grep "video procedural: planner llm: " "$tmp/$c.err" | grep -F "${why[$c]}" | grep -q "; using the offline planner$" &&
     motion $c "j[\"source\"] == \"prompt\" and j[\"planner\"][\"source\"] == \"offline\" and sys.argv[2] in j[\"planner\"][\"fallback\"]" "${why[$c]}" ||
     { head -c 600 "$tmp/$c.err"; false; }'
done
# (The run's records of the command typed, log.txt's command line and resolved.yaml, keep the
# url as given: the key belongs in api_key_env.)
check "a key in the endpoint's query is in no message, motion.json or report.html, though the server echoes it" \
  '! grep -lF "query-secret" "$tmp"/url_key/motion.json "$tmp"/url_key/report.html "$tmp"/url_key.err "$tmp"/url_key.out &&
   grep -q "completions?<key>" "$tmp"/url_key/motion.json'
check "report.html shows the model's plan, and the planner's fallback as a warning" \
  'grep -qF "<code class=\"svgm-llm-plan\">wave:arm_left slow, kick:leg_right</code>" "$tmp/valid/report.html" &&
   grep -q "id=\"svgm-planner-fallback\">The llm planner gave no plan (HTTP 500 from" "$tmp/http500/report.html"'
check "the API key is in no log.txt, motion.json or terminal output" \
  '! grep -rlF "$key" "$tmp"/valid "$tmp"/echo_key "$tmp"/split_key "$tmp"/*.err "$tmp"/*.out'
check "a fallback is not cached: the next run asks the model again" \
  '"$bin" run --input "$svg" -o "$tmp/http500" --quiet --prompt "$prompt" "stages.video.options={planner: llm, $(opts http500)}" "${small[@]}" \
     >/dev/null 2>"$tmp/again.err" && grep -q "planner llm: HTTP 500" "$tmp/again.err"'

# Option mistakes are errors before any video is made.
bad_option() {  # NAME OPTIONS EXPECTED
  local name=$1 expected=$3
  cp -r "$tmp/base" "$tmp/$name"
  rm -rf "$tmp/$name/candidates"
  "$bin" run --input "$svg" -o "$tmp/$name" --from video --quiet --prompt "$prompt" "stages.video.options={$2}" "${small[@]}" \
    >"$tmp/$name.out" 2>"$tmp/$name.err"
  local rc=$?
  check "$name: a one-line error, no candidates" \
    '[[ $rc -ne 0 && $(grep -c "" "$tmp/$name.err") -eq 1 ]] && grep -qF "$expected" "$tmp/$name.err" && [[ ! -e $tmp/$name/candidates/00.mp4 ]] || { cat "$tmp/$name.err"; false; }'
}
bad_option badplanner 'planner: gpt' "options.planner must be offline or llm, not 'gpt'"
bad_option both "planner: llm, motion: \"bob:whole\", $(opts plan_valid)" "options.motion gives the plan and options.planner: llm"
finish
