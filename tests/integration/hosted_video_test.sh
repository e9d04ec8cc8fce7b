#!/usr/bin/env bash
# The hosted video providers `veo` (Gemini API) and `http-job` (the fal.ai and Replicate example
# configs, unchanged but for the URL and small counts) against fake_hosted_video_server.py:
#   hosted_video_test.sh SVGMOTION_BINARY TEST_DATA_DIR EXAMPLES_DIR
# A base run with the procedural provider supplies a real mp4 (served by the fake storage host)
# and the earlier stages' outputs; each case reruns from the video stage. Successes: slow
# operations polled to the end with at most `concurrency` in flight, a 429 waited out as
# Retry-After says, a failed candidate among good ones (one warning naming it). Failures (key
# refused, key missing, operation error, endless operation, a result that is not a video, a
# failed job, no server): one line naming the candidate, earlier outputs untouched. The API key
# appears in no output, log, manifest or ranking.json, and never reaches the storage host.
# Prints "N passed, M failed" and exits non-zero on any failure. KEEP=1 keeps the scratch folder.
set -u
bin=$1 data=$2 examples=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

key="AIza-fake-SECRET-7c1e9d"
wrong_key="AIza-wrong-SECRET-0b2f"
# Tiny candidates read as colour drift to the pixel ranker; these runs test the providers, not
# the ranking, so a flagged set is fitted anyway.
small=(stages.ranker.accept_flagged=true stages.fitter.iterations=5 stages.fitter.keyframes=3 stages.fitter.size=64 stages.video.size=96)
"$bin" run --input "$data/examples/man.svg" -o "$tmp/base" --quiet --prompt "waves the right arm" \
  stages.video.plugin=procedural stages.video.candidates=1 "${small[@]}" >"$tmp/base.out" 2>&1
check "the procedural base run gives a video to serve" '[[ -s $tmp/base/candidates/00.mp4 && -s $tmp/base/recolored.png ]]'
[[ -s $tmp/base/candidates/00.mp4 ]] || finish

start_server "$here/fake_hosted_video_server.py" --video "$tmp/base/candidates/00.mp4" --key "$key" --lifetime 240 \
  --log "$tmp/requests.log" || { bad "the fake server starts"; finish; }
api="http://127.0.0.1:$port"
closed=$(closed_port)

# run_case NAME KEY ARGS...: rerun from the video stage in a copy of the base run, with
# GEMINI_API_KEY, FAL_KEY and REPLICATE_API_TOKEN set to KEY ("" = unset).
run_case() {
  local name=$1 k=$2; shift 2
  cp -r "$tmp/base" "$tmp/$name"
  local start=$(date +%s%N)
  # timeout: a plugin that ignored its own timeout_s would otherwise hang the test forever.
  env -u GEMINI_API_KEY -u FAL_KEY -u REPLICATE_API_TOKEN ${k:+GEMINI_API_KEY=$k FAL_KEY=$k REPLICATE_API_TOKEN=$k} \
    timeout 120 "$bin" run "$@" --input "$data/examples/man.svg" -o "$tmp/$name" --from video \
    --prompt "waves the right arm" "${small[@]}" >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
  echo $(( ($(date +%s%N) - start) / 1000000 )) >"$tmp/$name.time"  # ms
}
veo() {  # veo NAME KEY OPTIONS
  run_case "$1" "$2" stages.video.plugin=veo \
    "stages.video.options={base_url: \"$api/v1beta\", poll_s: 0.2, poll_max_s: 0.5, retries: 1, $3}"
}
job() {  # job NAME EXAMPLE SUBMIT_URL CANDIDATES
  run_case "$1" "$key" "$examples/$2" "stages.video.options.submit_url=$3" "stages.video.options.candidates=$4" \
    stages.video.options.poll_s=0.2 stages.video.options.poll_max_s=0.5
}
cases=()
veo parallel "$key" "model: veo-slow, candidates: 3, concurrency: 2" & cases+=($!)
veo mixed "$key" "model: veo-mixed, candidates: 3, concurrency: 3" & cases+=($!)
veo ratelimit "$key" "model: veo-ratelimit, candidates: 1" & cases+=($!)
veo badkey "$wrong_key" "model: veo-slow, candidates: 1" & cases+=($!)
veo nokey "" "model: veo-slow, candidates: 1" & cases+=($!)
veo error "$key" "model: veo-error, candidates: 1" & cases+=($!)
veo hang "$key" "model: veo-hang, candidates: 1, timeout_s: 3" & cases+=($!)
veo notvideo "$key" "model: veo-notvideo, candidates: 1" & cases+=($!)
run_case refused "$key" stages.video.plugin=veo \
  "stages.video.options={base_url: \"http://127.0.0.1:$closed/v1beta\", candidates: 1, retries: 1, timeout_s: 10}" & cases+=($!)
run_case refused_all "$key" stages.video.plugin=veo \
  "stages.video.options={base_url: \"http://127.0.0.1:$closed/v1beta\", candidates: 2, retries: 0}" & cases+=($!)
job fal fal_wan.yaml "$api/fal-ai/wan-i2v" 2 & cases+=($!)
job fal_ratelimit fal_wan.yaml "$api/fal-ai/ratelimit" 1 & cases+=($!)
job replicate replicate_wan.yaml "$api/v1/models/wan-video/wan-2.2-i2v-fast/predictions" 1 & cases+=($!)
job replicate_failed replicate_wan.yaml "$api/v1/models/wan-video/failed/predictions" 1 & cases+=($!)
wait "${cases[@]}"

served() {  # served DIR: every file in DIR is the served video
  local f
  for f in "$1"/*; do cmp -s "$f" "$tmp/base/candidates/00.mp4" || return 1; done
}
succeeded() {  # succeeded CASE N: exit 0, an animation, N candidates that are the served video
  local c=$1 n=$2
  check "$c: the run succeeds with $n candidate(s), each the served video" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 && -s $tmp/$c/animation.svg && $(ls "$tmp/$c/candidates" | wc -l) -eq $n ]] &&
     served "$tmp/$c/candidates" || { head -c 600 "$tmp/$c.err"; false; }'
}
succeeded parallel 3
succeeded ratelimit 1
succeeded fal 2
succeeded fal_ratelimit 1
succeeded replicate 1
check "parallel: slow operations polled until done (each 2.5 s), at most 2 in flight, and 2 at once" \
  '"$py" - "$tmp/requests.log" <<PY
import json, re, sys
# Other cases run at the same time and download from the same storage host: only the blobs of
# veo-slow operations (their ids are in the poll paths) end an operation in flight.
log = [json.loads(line) for line in open(sys.argv[1])]
slow = {m.group(1) for e in log for m in [re.search(r"/veo-slow/operations/([^/?:]+)", e["path"])] if m}
events = []
for e in log:
    if e["host"] == "api" and e["method"] == "POST" and "/veo-slow:" in e["path"] and e["headers"].get("x-goog-api-key") == "$key":
        events.append((e["t"], 1))
    if e["host"] == "storage" and e["path"].startswith("/blob/") and e["path"][6:].split(".")[0] in slow:
        events.append((e["t"], -1))
events.sort()
level = peak = 0
for _, d in events:
    level += d
    peak = max(peak, level)
assert sum(d > 0 for _, d in events) == 3 and peak == 2, (events, peak)
PY'
check "parallel: the image and prompt went as documented (bytesBase64Encoded PNG, the paper's template)" \
  '"$py" - "$tmp/requests.log" <<PY
import json
for line in open("$tmp/requests.log"):
    e = json.loads(line)
    if "/veo-slow:" in e["path"] and e["method"] == "POST" and e["headers"].get("x-goog-api-key") == "$key":
        i = e["body"]["instances"][0]
        assert i["image"]["mimeType"] == "image/png" and i["image"]["bytesBase64Encoded"].startswith("<"), i
        assert i["prompt"].startswith("A flat 2D vector") and i["prompt"].endswith("waves the right arm"), i
        p = e["body"]["parameters"]
        assert p["aspectRatio"] == "16:9" and p["durationSeconds"] == 8 and type(p["seed"]) is int, p
PY'
check "the storage host never received an API key" \
  '"$py" -c "import json,sys; s=[json.loads(l) for l in open(sys.argv[1]) if \"\\\"storage\\\"\" in l]; assert s and not any(\"x-goog-api-key\" in e[\"headers\"] or \"Authorization\" in e[\"headers\"] for e in s)" "$tmp/requests.log"'
check "mixed: candidate 01 failed alone: one warning naming it, 00 and 02 kept" \
  '[[ $(cat "$tmp/mixed.rc") -eq 0 && -s $tmp/mixed/candidates/00.mp4 && -s $tmp/mixed/candidates/02.mp4 && ! -e $tmp/mixed/candidates/01.mp4 ]] &&
   [[ $(grep -c "warning: video veo" "$tmp/mixed.err") -eq 1 ]] &&
   grep -qE "^svgmotion: warning: video veo: candidate 01: operation models/veo-mixed/operations/id[0-9]+ failed: Internal error while generating the video. \(code 13\)$" "$tmp/mixed.err" || { cat "$tmp/mixed.err"; false; }'
check "ratelimit: the 429 was waited out for Retry-After (1 s) and the submit repeated once" \
  '"$py" -c "import json,sys; t=[json.loads(l)[\"t\"] for l in open(sys.argv[1]) if \"/veo-ratelimit:\" in l]; assert len(t)==2 and t[1]-t[0] >= 0.95, t" "$tmp/requests.log"'
check "fal_ratelimit: a 429 on a status poll was answered (and the run above succeeded)" \
  'grep -qE "\"method\": \"429\", \"path\": \"/fal-ai/requests/id[0-9]+/status\"" "$tmp/requests.log"'

# failure CASE PATTERN: one line, earlier outputs untouched, and done within a wide margin (60 s
# against time limits of 3 to 10 s) that catches a limit that is not enforced at all. The
# margin counts from what the nokey case took (it fails before any request): on a loaded
# machine starting the run alone can take tens of seconds.
failure() {
  local c=$1 pattern=$2 max=60
  check "$c: fails with one line matching '$pattern'" \
    '[[ $(cat "$tmp/$c.rc") -eq 1 ]] && [[ $(grep -c "^svgmotion: " "$tmp/$c.err") -eq 1 ]] && grep "^svgmotion: " "$tmp/$c.err" | grep -qE "$pattern" || { cat "$tmp/$c.err"; false; }'
  check "$c: earlier outputs untouched" \
    'cmp -s "$tmp/$c/grouped.svg" "$tmp/base/grouped.svg" && cmp -s "$tmp/$c/recolored.png" "$tmp/base/recolored.png"'
  [[ $c == nokey ]] ||
    check "$c: done within $max s of the start-up" '(( $(cat "$tmp/$c.time") - $(cat "$tmp/nokey.time") < max * 1000 ))'
}
failure badkey 'video veo: candidate 00: the API key in \$GEMINI_API_KEY was refused: HTTP 400 from http://127.0.0.1:[0-9]+/v1beta/models/veo-slow:predictLongRunning: API key not valid. Please pass a valid API key. \(<key>\)$'
failure nokey 'video veo: \$GEMINI_API_KEY is not set \(the Gemini API key; options.api_key_env names the variable\)$'
failure error 'video veo: candidate 00: operation models/veo-error/operations/id[0-9]+ failed: Internal error while generating the video. \(code 13\)$'
failure hang 'video veo: candidate 00: no result within 3 s \(operation models/veo-hang/operations/id[0-9]+\)$'
failure notvideo 'video veo: candidate 00: the result of operation models/veo-notvideo/operations/id[0-9]+ \(candidates/00.mp4\) is not a readable video: '
failure refused "video veo: candidate 00: cannot connect to http://127.0.0.1:$closed/v1beta/models/veo-3.1-generate-preview:predictLongRunning: "
failure replicate_failed 'video http-job: candidate 00: job id[0-9]+ failed \(status failed\): CUDA out of memory$'
check "refused_all: a warning per candidate, then one error naming the first failure" \
  '[[ $(cat "$tmp/refused_all.rc") -eq 1 && $(grep -c "^svgmotion: " "$tmp/refused_all.err") -eq 3 ]] &&
   grep -q "^svgmotion: warning: video veo: candidate 00: cannot connect to " "$tmp/refused_all.err" &&
   grep -q "^svgmotion: warning: video veo: candidate 01: cannot connect to " "$tmp/refused_all.err" &&
   grep -qE "^svgmotion: video plugin .veo.: video veo: all 2 candidates failed \(the first: video veo: candidate 00: cannot connect to " "$tmp/refused_all.err" &&
   cmp -s "$tmp/refused_all/grouped.svg" "$tmp/base/grouped.svg" || { cat "$tmp/refused_all.err"; false; }'
check "notvideo: the HTML page was not kept as a candidate" '[[ ! -e $tmp/notvideo/candidates/00.mp4 ]]'

# The key: in no output, log, manifest (.svgmotion/), ranking.json or message, in any case. The
# fake server's own request log holds it (the server checks it) and is left out.
check "no API key (right or wrong) in any output, log, manifest or message" \
  '! grep -rlF -e "$key" -e "$wrong_key" "$tmp" --exclude=requests.log'
check "the manifests and ranking.json exist to be searched" '[[ -s $tmp/parallel/ranking.json && -s $tmp/parallel/.svgmotion/video.json ]]'
finish
