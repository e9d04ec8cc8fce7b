#!/usr/bin/env bash
# The hosted video clients against a hostile server (fake_hosted_video_server.py's /evil/ modes,
# driven through the `http-job` plugin, whose transport and session the other clients share):
#   hosted_video_hostile_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# Refused, with one line naming the scheme: a redirect to file:///etc/passwd (nothing of it
# shown or logged), a redirect to dict:// (the local TCP port it names is never connected to), a
# status_url of file:///etc/passwd. Followed: relative redirects ("/video.mp4", "video.mp4"), a
# redirect to another host (which never sees the key). The key, echoed by the server across the
# 200-character cut of the error excerpt (verbatim and percent-encoded), leaves no 8-character
# piece of itself on stderr, stdout or in the run folder. Bodies without end (a status reply, a
# video) or announcing 100 MiB are cut off at their limit with one line; a download the disk
# cannot take (a file-size limit, standing in for a full disk: the same failed write(2)) is
# reported as a write failure naming the candidate file. Prints "N passed, M failed".
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# 46 characters with /, +, =, : and . so that its percent-encoded and JSON forms differ from it.
key="sk-live/Ab+Cd=Ef:Gh.Ij_Kl-Mn0123456789opqrstuv"
small=(stages.ranker.accept_flagged=true stages.fitter.iterations=5 stages.fitter.keyframes=3 stages.fitter.size=64 stages.video.size=96)
"$bin" run --input "$data/examples/man.svg" -o "$tmp/base" --quiet --prompt "waves the right arm" \
  stages.video.plugin=procedural stages.video.candidates=1 "${small[@]}" >"$tmp/base.out" 2>&1
check "the procedural base run gives a video to serve" '[[ -s $tmp/base/candidates/00.mp4 && -s $tmp/base/recolored.png ]]'
[[ -s $tmp/base/candidates/00.mp4 ]] || finish

start_server "$here/fake_hosted_video_server.py" --video "$tmp/base/candidates/00.mp4" --key unused --lifetime 240 \
  --log "$tmp/requests.log" || { bad "the fake server starts"; finish; }
api="http://127.0.0.1:$port"

# run_case NAME MODE [EXTRA_OPTIONS [ULIMIT_F_KIB]]: rerun from the video stage in a copy of the
# base run, http-job against /evil/MODE with the key in $EVIL_KEY.
run_case() {
  local name=$1 mode=$2 extra=${3:-} fsize=${4:-unlimited}
  cp -r "$tmp/base" "$tmp/$name"
  local opts="{submit_url: \"$api/evil/$mode\", headers: {Authorization: \"Bearer {api_key}\"}, api_key_env: EVIL_KEY,
    body: {prompt: \"{prompt}\", image: \"{image_data_url}\", seed: \"{seed}\"}, id_field: id,
    status_url: \"{submit.status_url}\", done_values: [done], video_url_field: video_url, candidates: 1,
    retries: 1, poll_s: 0.2, poll_max_s: 0.5, timeout_s: 30$extra}"
  # The file-size limit: SIGXFSZ ignored, so a write past it fails with EFBIG instead of
  # killing the run. timeout: a client that ignored its own timeout_s would hang the test.
  ( trap '' XFSZ; ulimit -f "$fsize"
    EVIL_KEY=$key exec timeout 120 "$bin" run --input "$data/examples/man.svg" -o "$tmp/$name" --from video \
      --prompt "waves the right arm" "${small[@]}" stages.video.plugin=http-job "stages.video.options=$opts" ) \
    >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
}
cases=()
for mode in redirect-file redirect-dict status-file redirect-absolute-path redirect-relative-path redirect-other-host \
            echo-key echo-key-encoded endless-status big-status; do
  run_case "$mode" "$mode" & cases+=($!)
done
run_case endless-video endless-video ", max_video_mib: 1" & cases+=($!)
run_case disk-full endless-video ", max_video_mib: 64" 2048 & cases+=($!)
wait "${cases[@]}"

# failure CASE PATTERN: exit 1, one line, matching PATTERN (an ERE, anchored by the caller).
failure() {
  local c=$1 pattern=$2
  check "$c: fails with one line matching '$pattern'" \
    '[[ $(cat "$tmp/$c.rc") -eq 1 ]] && [[ $(grep -c "^svgmotion: " "$tmp/$c.err") -eq 1 ]] && grep "^svgmotion: " "$tmp/$c.err" | grep -qE "$pattern" || { cat "$tmp/$c.err"; false; }'
  check "$c: no candidate and no temporary file left" '[[ -z $(ls -A "$tmp/$c/candidates" 2>/dev/null) ]]'
}
succeeded() {
  local c=$1
  check "$c: the run succeeds with the served video as its candidate" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 ]] && cmp -s "$tmp/$c/candidates/00.mp4" "$tmp/base/candidates/00.mp4" || { head -c 600 "$tmp/$c.err"; false; }'
}

h="127\.0\.0\.1:$port"
failure redirect-file "^svgmotion: .*video http-job: candidate 00: $h redirected to a file: URL \(only http and https are followed\)\)?$"
check "redirect-file: nothing of /etc/passwd shown or logged" '! grep -rqs "root:" "$tmp/redirect-file.err" "$tmp/redirect-file.out" "$tmp/redirect-file"'
failure redirect-dict "^svgmotion: .*video http-job: candidate 00: $h redirected to a dict: URL \(only http and https are followed\)\)?$"
check "redirect-dict: nothing connected to the raw TCP port" '! grep -q "\"host\": \"trap\"" "$tmp/requests.log"'
failure status-file "^svgmotion: .*video http-job: candidate 00: refused to fetch a file: URL \(only http and https\)\)?$"
check "status-file: nothing of /etc/passwd shown or logged" '! grep -rqs "root:" "$tmp/status-file.err" "$tmp/status-file.out" "$tmp/status-file"'
succeeded redirect-absolute-path
succeeded redirect-relative-path
check "relative redirects were resolved against the URL that answered" \
  'grep -q "\"path\": \"/evil/redirect-absolute-path/video.mp4\"" "$tmp/requests.log" && grep -q "\"path\": \"/evil/redirect-relative-path/video.mp4\"" "$tmp/requests.log"'
succeeded redirect-other-host
check "redirect-other-host: the other host was asked, without the key" \
  '"$py" - "$tmp/requests.log" <<PY
import json, sys
other = [e for e in map(json.loads, open(sys.argv[1])) if e["host"] == "storage" and e["headers"].get("Host", "").startswith("localhost:")]
assert other and not any("Authorization" in e["headers"] or "authorization" in e["headers"] for e in other), other
PY'
failure echo-key "^svgmotion: .*video http-job: candidate 00: HTTP 500 from $api/evil/echo-key: x{190}<key> is n\.\.\.\)?$"
failure echo-key-encoded "^svgmotion: .*video http-job: candidate 00: HTTP 500 from $api/evil/echo-key-encoded: x{190}<key> is n\.\.\.\)?$"
# No 8-character piece of the key (or of its percent-encoding) in any message, output or log.
pieces() { "$py" -c 'import sys, urllib.parse
for k in (sys.argv[1], urllib.parse.quote(sys.argv[1], safe="")):
    for i in range(len(k) - 7): print(k[i:i + 8])' "$key" | sort -u; }
pieces >"$tmp/pieces"
for c in echo-key echo-key-encoded; do
  check "$c: no 8-character piece of the key on stderr, stdout or in the run folder (log.txt included)" \
    '[[ -s $tmp/$c/log.txt ]] && ! grep -rqsF -f "$tmp/pieces" "$tmp/$c.err" "$tmp/$c.out" "$tmp/$c"'
done
check "echo-key: the retry was logged (log.txt holds the scrubbed excerpt too)" 'grep -q "HTTP 500 from .*<key>.*retrying" "$tmp/echo-key/log.txt"'
failure endless-status "^svgmotion: .*video http-job: candidate 00: the reply from $h is larger than 16 MiB\)?$"
check "endless-status: the client hung up" 'grep -q "\"method\": \"closed\", \"path\": \"/evil/endless-status/status\"" "$tmp/requests.log"'
failure big-status "^svgmotion: .*video http-job: candidate 00: the reply from $h is larger than 16 MiB\)?$"
failure endless-video "^svgmotion: .*video http-job: candidate 00: the download from $h is larger than 1 MiB\)?$"
failure disk-full "^svgmotion: .*video http-job: candidate 00: candidates/00.mp4: cannot write: File too large\)?$"
finish
