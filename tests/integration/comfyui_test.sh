#!/usr/bin/env bash
# The `comfyui` video provider against a fake ComfyUI server (fake_comfyui_server.py):
#   comfyui_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# A base run with the procedural provider supplies a real mp4 (served by the fake server from
# /view) and the earlier stages' outputs; each case then reruns from the video stage with
# `comfyui`. ok/webm: the run succeeds with real videos in candidates/, the server saw the PNG
# upload and the filled workflow; hang, http500, bad_output, refused, bad workflow: one-line
# error naming the cause, earlier outputs untouched. Builds nothing. Prints "N passed, M failed"
# and exits non-zero on any failure. KEEP=1 keeps the scratch folder.
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# Tiny 96 px candidates read as colour drift to the pixel ranker; these runs test the
# providers, not the ranking, so a flagged set is fitted anyway.
small=(stages.ranker.accept_flagged=true stages.fitter.iterations=5 stages.fitter.keyframes=3 stages.fitter.size=64 stages.video.size=96)
"$bin" run --input "$data/examples/man.svg" -o "$tmp/base" --quiet --prompt "waves the right arm" \
  stages.video.plugin=procedural stages.video.candidates=1 "${small[@]}" >"$tmp/base.out" 2>&1
check "the procedural base run gives a video to serve" '[[ -s $tmp/base/candidates/00.mp4 && -s $tmp/base/recolored.png ]]'
[[ -s $tmp/base/candidates/00.mp4 ]] || finish

start_server "$here/fake_comfyui_server.py" --video "$tmp/base/candidates/00.mp4" --lifetime 600 \
  --log "$tmp/requests.log" || { bad "the fake server starts"; finish; }
url="http://127.0.0.1:$port"
closed=$(closed_port)

# workflow MODE: a workflow in API format with every placeholder and a "mode" input.
workflow() {
  cat >"$tmp/wf_$1.json" <<JSON
{"10": {"class_type": "LoadImage", "inputs": {"image": "{image}"}},
 "20": {"class_type": "FakeI2V", "inputs": {"seed": "{seed}", "length": "{frames}", "text": "{prompt}",
        "mode": "$1", "start_image": ["10", 0]}}}
JSON
  echo "$tmp/wf_$1.json"
}
echo '{"10": {"inputs": {"image": "{image}"}},' >"$tmp/wf_broken.json"

# run_case NAME OPTIONS: rerun from the video stage in a copy of the base run.
run_case() {
  local name=$1 options=$2
  cp -r "$tmp/base" "$tmp/$name"
  local start=$(date +%s%N)
  # timeout: a plugin that ignored its own timeout_s would otherwise hang the test forever.
  timeout 120 "$bin" run --input "$data/examples/man.svg" -o "$tmp/$name" --from video --prompt "waves the right arm" \
    stages.video.plugin=comfyui "stages.video.options={$options}" "${small[@]}" >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
  echo $(( ($(date +%s%N) - start) / 1000000 )) >"$tmp/$name.time"  # ms
}
cases=()
run_case ok "url: \"$url\", workflow: \"$(workflow ok)\", candidates: 2, frames: 17, poll_s: 0.2" & cases+=($!)
run_case webm "url: \"$url/\", workflow: \"$(workflow webm)\", candidates: 1, poll_s: 0.2" & cases+=($!)
run_case hang "url: \"$url\", workflow: \"$(workflow hang)\", candidates: 1, timeout_s: 3, poll_s: 0.2" & cases+=($!)
run_case http500 "url: \"$url\", workflow: \"$(workflow http500)\", candidates: 1, retries: 1" & cases+=($!)
run_case bad_output "url: \"$url\", workflow: \"$(workflow bad_output)\", candidates: 1, poll_s: 0.2" & cases+=($!)
run_case refused "url: \"http://127.0.0.1:$closed\", workflow: \"$(workflow ok)\", retries: 1, timeout_s: 10" & cases+=($!)
run_case broken "url: \"$url\", workflow: \"$tmp/wf_broken.json\"" & cases+=($!)
wait "${cases[@]}"

readable() { "$bin" fit "$tmp/base/input.svg" --target "$1" -o "$tmp/probe_$(basename "$1")" --iterations 1 --keyframes 2 --size 32 --no-gate >/dev/null 2>&1; }
check "ok: the run succeeds" '[[ $(cat "$tmp/ok.rc") -eq 0 && -s $tmp/ok/animation.svg ]] || { head -c 400 "$tmp/ok.err"; false; }'
check "ok: candidates/00.mp4 and 01.mp4 are the served video" \
  'cmp -s "$tmp/ok/candidates/00.mp4" "$tmp/base/candidates/00.mp4" && cmp -s "$tmp/ok/candidates/01.mp4" "$tmp/base/candidates/00.mp4" && [[ $(ls "$tmp/ok/candidates" | wc -l) -eq 2 ]]'
check "ok: the candidates are readable videos" 'readable "$tmp/ok/candidates/00.mp4"'
check "webm: saved as candidates/00.webm (the returned extension)" '[[ $(cat "$tmp/webm.rc") -eq 0 && -s $tmp/webm/candidates/00.webm ]] || { head -c 400 "$tmp/webm.err"; false; }'
check "the server saw PNG uploads in field image" \
  '"$py" -c "import json,sys; u=[json.loads(l)[\"body\"] for l in open(sys.argv[1]) if \"/upload/image\" in l]; assert len(u)>=3 and all(b[\"png\"] and b[\"field\"]==\"image\" for b in u), u" "$tmp/requests.log"'
check "ok: the queued workflow is filled (image name, prompt, seed and frames as numbers, client_id)" \
  '"$py" - "$tmp/requests.log" <<PY
import json, sys
bodies = [json.loads(l)["body"] for l in open(sys.argv[1]) if "\"/prompt\"" in l]
ok = [b for b in bodies if b["prompt"]["20"]["inputs"]["mode"] == "ok"]
assert len(ok) == 2, ok
seeds = sorted(b["prompt"]["20"]["inputs"]["seed"] for b in ok)
for b in ok:
    n = b["prompt"]
    assert b["client_id"] == "svgmotion"
    assert n["10"]["inputs"]["image"] == "svgm_upload.png", n
    i = n["20"]["inputs"]
    assert i["length"] == 17 and type(i["seed"]) is int, i
    assert i["text"].startswith("A flat 2D vector") and i["text"].endswith("waves the right arm"), i["text"]
    assert i["start_image"] == ["10", 0]
assert seeds[1] == seeds[0] + 1, seeds
PY'
check "ok: /view asked with filename, subfolder and type" 'grep -q "/view?filename=svgm_[0-9]*.mp4&subfolder=sub%20dir&type=output" "$tmp/requests.log"'

# failure CASE PATTERN: the time bound is a wide margin (60 s against timeouts of 3 to 10 s) so
# that a loaded machine cannot fail it; it catches a timeout that is not enforced at all.
failure() {
  local c=$1 pattern=$2 max=60
  check "$c: fails with one line matching '$pattern'" \
    '[[ $(cat "$tmp/$c.rc") -ne 0 ]] && [[ $(grep -c "^svgmotion: " "$tmp/$c.err") -eq 1 ]] && grep "^svgmotion: " "$tmp/$c.err" | grep -qE "$pattern" || { cat "$tmp/$c.err"; false; }'
  check "$c: earlier outputs untouched" \
    'cmp -s "$tmp/$c/grouped.svg" "$tmp/base/grouped.svg" && cmp -s "$tmp/$c/recolored.png" "$tmp/base/recolored.png"'
  check "$c: done within $max s" '(( $(cat "$tmp/$c.time") < max * 1000 ))'
}
failure hang "video comfyui: candidate 00: no result within 3 s \(prompt [0-9]+\)"
failure http500 "video comfyui: candidate 00: HTTP 500 from $url/prompt"
check "http500: retried (2 attempts with retries: 1)" \
  '[[ $("$py" -c "import json,sys; print(sum(1 for l in open(sys.argv[1]) if \"\\\"/prompt\\\"\" in l and json.loads(l)[\"body\"][\"prompt\"][\"20\"][\"inputs\"][\"mode\"]==\"http500\"))" "$tmp/requests.log") -eq 2 ]]'
failure bad_output "video comfyui: candidate 00: prompt [0-9]+ finished without a video"
failure refused "video comfyui: candidate 00: cannot connect to http://127.0.0.1:$closed/upload/image: "
failure broken "video comfyui: the workflow file .*wf_broken.json is not valid JSON"
finish
