#!/usr/bin/env bash
# The `llm` ranker against the fake chat-completions server (fake_llm_server.py):
#   llm_ranker_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# A base run makes 3 procedural candidates; every case copies it and re-runs from the ranker.
# A valid answer makes its candidate the target (even one the pixel ranker put last); every
# failure (no url, refused, timeout, HTTP error, malformed answer, unknown candidate) warns in
# one line naming the reason and keeps the pixel choice. Prints "ok - ..."/"not ok - ...", then
# "N passed, M failed"; exits non-zero on any failure. KEEP=1 keeps the scratch folder.
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# Tiny 96 px candidates read as colour drift to the pixel ranker; these runs test the
# providers, not the ranking, so a flagged set is fitted anyway.
small=(stages.ranker.accept_flagged=true stages.video.candidates=3 stages.video.frames=9 stages.video.size=96
       stages.fitter.iterations=5 stages.fitter.keyframes=3 stages.fitter.size=64)
"$bin" run --input "$data/examples/man.svg" -o "$tmp/base" --quiet --prompt "waves the right arm" \
  "${small[@]}" >"$tmp/base.out" 2>&1
check "the base run ranks 3 procedural candidates by pixels" '[[ -s $tmp/base/ranking.json && -s $tmp/base/candidates/02.mp4 ]]'
[[ -s $tmp/base/ranking.json ]] || finish
# The pixel ranker's last choice: the judge's pick in the valid case, so the test can tell.
last=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["candidates"][-1]["name"])' "$tmp/base/ranking.json")
pixel_best=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["chosen"])' "$tmp/base/ranking.json")
check "the pixel ranker's first and last differ" '[[ $last != "$pixel_best" ]]'

start_server "$here/fake_llm_server.py" --lifetime 600 --hang 20 --log "$tmp/requests.log" ||
  { bad "the fake server starts"; finish; }
url="http://127.0.0.1:$port/v1/chat/completions"
closed=$(closed_port)

run_case() {
  local name=$1 options=$2
  cp -r "$tmp/base" "$tmp/$name"
  "$bin" run --input "$data/examples/man.svg" -o "$tmp/$name" --quiet --prompt "waves the right arm" \
    stages.ranker.plugin=llm ${options:+"stages.ranker.options={$options}"} "${small[@]}" \
    >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
}
opts() { echo "url: \"$1\", model: \"$2\", timeout_s: 3, frames: 2, size: 64"; }
cases=()
run_case pick "$(opts "$url" "pick_${last%.mp4}")" & cases+=($!)
run_case fenced "$(opts "$url" "fenced_pick_${last%.mp4}")" & cases+=($!)
run_case nourl "" & cases+=($!)
run_case refused "$(opts "http://127.0.0.1:$closed/v1/chat/completions" pick_00)" & cases+=($!)
run_case hang "$(opts "$url" hang)" & cases+=($!)
run_case http500 "$(opts "$url" http500)" & cases+=($!)
run_case malformed "$(opts "$url" malformed)" & cases+=($!)
run_case unknown "$(opts "$url" pick_unknown)" & cases+=($!)
wait "${cases[@]}"

chosen() { "$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["chosen"])' "$tmp/$1/ranking.json" 2>/dev/null; }
for c in pick fenced; do
  check "$c: the model's choice ($last) becomes the target" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 && $(chosen $c) == "$last" ]] && cmp -s "$tmp/$c/target.mp4" "$tmp/base/candidates/$last" && grep -q "\"source\": \"llm\"" "$tmp/$c/ranking.json" || { head -c 400 "$tmp/$c.err"; false; }'
  check "$c: no warning" '! grep -q "ranker llm" "$tmp/$c.err"'
done
check "the request shows every candidate with 2 PNG frames and the pixel findings" \
  '"$py" - "$tmp/requests.log" <<PY
import json, sys
for line in open(sys.argv[1]):
    b = json.loads(line)["body"]
    if b["model"].startswith("pick_"):
        parts = b["messages"][1]["content"]
        assert "waves the right arm" in parts[0]["text"] and "00.mp4" in parts[0]["text"], parts[0]
        labels = [p["text"] for p in parts[1:] if p["type"] == "text"]
        assert labels == ["Candidate 00.mp4:", "Candidate 01.mp4:", "Candidate 02.mp4:"], labels
        assert sum(p["type"] == "image_url" for p in parts) == 6
        break
else:
    sys.exit(1)
PY'
declare -A why=([nourl]="no url configured (stages.ranker.options.url)" [refused]="failed" \
  [hang]="timeout: no answer from" [http500]="HTTP 500 from" [malformed]="malformed JSON in the answer" \
  [unknown]="names '07.mp4', which is not a readable candidate")
for c in nourl refused hang http500 malformed unknown; do
  check "$c: warns in one line and keeps the pixel choice" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 && $(chosen $c) == "$pixel_best" ]] && [[ $(grep -c "ranker llm" "$tmp/$c.err") -eq 1 ]] && grep -F "ranker llm" "$tmp/$c.err" | grep -qF "${why[$c]}" && grep -q "; using the pixel ranking" "$tmp/$c.err" || { head -c 400 "$tmp/$c.err"; false; }'
done
"$bin" run --input "$data/examples/man.svg" -o "$tmp/badopt" --quiet --prompt "waves" stages.ranker.plugin=llm \
  "stages.ranker.options={url: \"$url\", framez: 2}" "${small[@]}" >"$tmp/badopt.out" 2>"$tmp/badopt.err"
rc=$?
check "an unknown option is a one-line error naming it" '[[ $rc -ne 0 && $(grep -c "" "$tmp/badopt.err") -eq 1 ]] && grep -q "ranker llm: unknown option .framez." "$tmp/badopt.err" && [[ ! -e $tmp/badopt/target.mp4 ]]'
finish
