#!/usr/bin/env bash
# The `llm` ranker against the fake chat-completions server (fake_llm_server.py):
#   llm_ranker_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# A base run makes 3 procedural candidates; every case copies it and re-runs from the ranker.
# Two stages: each candidate is scored alone (four constraints, viable or not), then the viable
# ones are compared. A valid answer makes its candidate the target (even one the pixel ranker
# put last); a candidate found not viable is left out of the comparison and flagged; none
# viable stops the run (exit 4); every answer is kept in ranking.json. Every failure (no url, refused, timeout, HTTP error, malformed answer, unknown candidate) warns in
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
run_case reject "$(opts "$url" "reject_${pixel_best%.mp4}_pick_${last%.mp4}")" & cases+=($!)
run_case single "$(opts "$url" "pick_${last%.mp4}"), two_stage: false" & cases+=($!)
# No accept_flagged here: a set the judge finds unusable must stop the run.
( cp -r "$tmp/base" "$tmp/none"
  "$bin" run --input "$data/examples/man.svg" -o "$tmp/none" --quiet --prompt "waves the right arm" \
    stages.ranker.plugin=llm "stages.ranker.options={$(opts "$url" none_viable)}" "${small[@]:1}" \
    >"$tmp/none.out" 2>"$tmp/none.err"
  echo $? >"$tmp/none.rc" ) & cases+=($!)
# The example configs (examples/llm), unchanged but for the urls: the fake server knows neither
# model and answers 404, so both stages fall back; the requests show what the configs send.
example_case() {  # NAME CONFIG
  cp -r "$tmp/base" "$tmp/$1"
  GEMINI_API_KEY=gem-test-key-81 "$bin" run "$data/../../examples/llm/$2" --input "$data/examples/man.svg" -o "$tmp/$1" \
    --quiet --prompt "waves the right arm" stages.grouper.options.url="$url" stages.ranker.options.url="$url" \
    "${small[@]}" >"$tmp/$1.out" 2>"$tmp/$1.err"
  echo $? >"$tmp/$1.rc"
}
example_case gemini_example gemini.yaml & cases+=($!)
example_case ollama_example ollama.yaml & cases+=($!)
wait "${cases[@]}"

chosen() { "$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["chosen"])' "$tmp/$1/ranking.json" 2>/dev/null; }
for c in pick fenced; do
  check "$c: the model's choice ($last) becomes the target" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 && $(chosen $c) == "$last" ]] && cmp -s "$tmp/$c/target.mp4" "$tmp/base/candidates/$last" && grep -q "\"source\": \"llm\"" "$tmp/$c/ranking.json" || { head -c 400 "$tmp/$c.err"; false; }'
  check "$c: no warning" '! grep -q "ranker llm" "$tmp/$c.err"'
done
check "the comparison shows every candidate with 2 PNG frames and the pixel findings" \
  '"$py" - "$tmp/requests.log" <<PY
import json, sys
for line in open(sys.argv[1]):
    b = json.loads(line)["body"]
    if b["model"].startswith("pick_") and "\"best\"" in b["messages"][0]["content"]:
        parts = b["messages"][1]["content"]
        assert "waves the right arm" in parts[0]["text"] and "00.mp4" in parts[0]["text"], parts[0]
        labels = [p["text"] for p in parts[1:] if p["type"] == "text"]
        assert labels == ["Candidate 00.mp4:", "Candidate 01.mp4:", "Candidate 02.mp4:"], labels
        assert sum(p["type"] == "image_url" for p in parts) == 6
        break
else:
    sys.exit(1)
PY'
check "stage 1: each candidate scored alone with 2 PNG frames, every answer kept in ranking.json" \
  '"$py" - "$tmp/requests.log" "$tmp/pick/ranking.json" "pick_${last%.mp4}" <<PY
import json, sys
seen = []
for line in open(sys.argv[1]):
    b = json.loads(line)["body"]
    if b["model"] == sys.argv[3] and "\"viable\"" in b["messages"][0]["content"]:
        parts = b["messages"][1]["content"]
        assert "waves the right arm" in parts[0]["text"], parts[0]
        seen.append(parts[1]["text"])
        assert sum(p["type"] == "image_url" for p in parts) == 2
assert sorted(seen) == ["Candidate 00.mp4:", "Candidate 01.mp4:", "Candidate 02.mp4:"], seen
j = json.load(open(sys.argv[2]))["judge"]
assert [s["candidate"] for s in j["scores"]] == ["00.mp4", "01.mp4", "02.mp4"], j
assert all(s["viable"] and s["points"] == 8 and "fake stage 1" in s["answer"] for s in j["scores"]), j
assert "fake judge" in j["comparison"]["answer"] and len(j["comparison"]["candidates"]) == 3, j
PY'
check "reject: the candidate found not viable is flagged and left out of the comparison" \
  '"$py" - "$tmp/requests.log" "$tmp/reject/ranking.json" "$pixel_best" "$last" <<PY
import json, sys
_, log, ranking, rejected, last = sys.argv
for line in open(log):
    b = json.loads(line)["body"]
    if b["model"].startswith("reject_") and "\"best\"" in b["messages"][0]["content"]:
        labels = [p["text"] for p in b["messages"][1]["content"][1:] if p["type"] == "text"]
        assert "Candidate %s:" % rejected not in labels and len(labels) == 2, labels
        break
else:
    sys.exit("no comparison request")
r = json.load(open(ranking))
assert r["chosen"] == last, r["chosen"]
c = [c for c in r["candidates"] if c["name"] == rejected][0]
assert "not viable for the judge: the arm turns in depth" in c["defects"], c
s = [s for s in r["judge"]["scores"] if s["candidate"] == rejected][0]
assert s["no_3d_rotation"] == "Partial" and s["continuity"] == "No" and not s["viable"] and s["points"] == 5, s
PY'
check "single (two_stage: false): one comparison of all, no stage 1" \
  '[[ $(cat "$tmp/single.rc") -eq 0 && $(chosen single) == "$last" ]] && "$py" -c "import json,sys; j=json.load(open(sys.argv[1]))[\"judge\"]; assert \"scores\" not in j and len(j[\"comparison\"][\"candidates\"]) == 3" "$tmp/single/ranking.json"'
check "none viable: the run stops before fitting (exit 4), the judge's finding named for every candidate" \
  '[[ $(cat "$tmp/none.rc") -eq 4 && $(grep -o "not viable for the judge" "$tmp/none.err" | wc -l) -eq 3 ]] || { head -c 600 "$tmp/none.err"; false; }'
check "examples/llm/gemini.yaml: grouper and ranker ask gemini-2.5-flash with the key as a Bearer token" \
  '[[ $(cat "$tmp/gemini_example.rc") -eq 0 ]] && "$py" - "$tmp/requests.log" gemini-2.5-flash "Bearer gem-test-key-81" <<PY
import json, sys
kinds = set()
for line in open(sys.argv[1]):
    e = json.loads(line)
    if e["body"].get("model") == sys.argv[2]:
        assert e["headers"].get("Authorization") == sys.argv[3], e["headers"]
        kinds.add("rank" if "\"viable\"" in e["body"]["messages"][0]["content"] else "group")
assert kinds == {"rank", "group"}, kinds
PY'
check "examples/llm/ollama.yaml: grouper and ranker ask qwen2.5vl:7b with no key" \
  '[[ $(cat "$tmp/ollama_example.rc") -eq 0 ]] && "$py" - "$tmp/requests.log" qwen2.5vl:7b <<PY
import json, sys
kinds = set()
for line in open(sys.argv[1]):
    e = json.loads(line)
    if e["body"].get("model") == sys.argv[2]:
        assert "Authorization" not in e["headers"], e["headers"]
        kinds.add("rank" if "\"viable\"" in e["body"]["messages"][0]["content"] else "group")
assert kinds == {"rank", "group"}, kinds
PY'
check "the Gemini key is in no output of the example run" '! grep -rqF gem-test-key-81 "$tmp/gemini_example" "$tmp/gemini_example.out" "$tmp/gemini_example.err"'
declare -A why=([nourl]="no url configured (stages.ranker.options.url)" [refused]="failed" \
  [hang]="timeout: no answer from" [http500]="HTTP 500 from" [malformed]="malformed answer for 00.mp4: not a JSON object" \
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
