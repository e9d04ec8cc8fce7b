#!/usr/bin/env bash
# The `llm` grouper against a fake chat-completions server (fake_llm_server.py):
#   llm_grouper_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# A valid answer gives exactly its groups (in paint order); every failure (no url, connection
# refused, timeout, HTTP error, malformed JSON, unknown id) still runs, warns in one line naming
# the reason, and writes the structural grouping. Builds nothing. Each check prints "ok - ..." or
# "not ok - ..."; the script ends with "N passed, M failed" and exits non-zero on any failure.
# KEEP=1 keeps the scratch folder (runs, stderr, the server's request log) for a look.
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

start_server "$here/fake_llm_server.py" --lifetime 600 --hang 20 --log "$tmp/requests.log" ||
  { bad "the fake server starts"; finish; }
url="http://127.0.0.1:$port/v1/chat/completions"

# A closed port for "connection refused": bind an ephemeral port, then release it.
closed=$(closed_port)

# The target video: a few frames of the example itself.
mkdir -p "$tmp/frames"
for i in 0 1 2; do "$bin" render "$data/examples/man.svg" -o "$tmp/frames/$i.png" --size 64 2>/dev/null; done

# run_case NAME GROUPER_ARGS...: one pipeline run into $tmp/NAME; stderr in $tmp/NAME.err,
# exit status in $tmp/NAME.rc.
run_case() {
  local name=$1; shift
  "$bin" run --input "$data/examples/man.svg" -o "$tmp/$name" --quiet --prompt "waves the right arm" \
    stages.video.plugin=file "stages.video.path=$tmp/frames" stages.ranker.plugin=first "$@" \
    stages.fitter.iterations=10 stages.fitter.keyframes=3 stages.fitter.size=64 >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
}
llm() { echo "stages.grouper.options={url: \"$1\", model: \"$2\", timeout_s: 2}"; }

# The groups of a grouped.svg: "group-1:id,id;group-2:..." (runs of one part joined by data-group).
groups_of() {
  "$py" - "$1" <<'EOF'
import sys, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
parts = {}
for g in ET.parse(sys.argv[1]).getroot().iter(ns + "g"):
    key = g.get("data-group") or g.get("id")
    parts.setdefault(key, []).extend(p.get("id") for p in g.iter(ns + "path"))
print(";".join(k + ":" + ",".join(v) for k, v in parts.items()))
EOF
}

# Every case runs at once (they are independent); the structural run is the reference.
cases=()
run_case structural stages.grouper.plugin=structural & cases+=($!)
run_case valid stages.grouper.plugin=llm "$(llm "$url" valid)" & cases+=($!)
run_case fenced stages.grouper.plugin=llm "$(llm "$url" fenced)" & cases+=($!)
API_KEY_FOR_TEST=test-secret run_case auth stages.grouper.plugin=llm \
  "stages.grouper.options={url: \"$url\", model: \"auth\", api_key_env: API_KEY_FOR_TEST, timeout_s: 2}" & cases+=($!)
run_case nourl stages.grouper.plugin=llm & cases+=($!)
run_case refused stages.grouper.plugin=llm "$(llm "http://127.0.0.1:$closed/v1/chat/completions" valid)" & cases+=($!)
run_case unknown stages.grouper.plugin=llm "$(llm "$url" unknown_id)" & cases+=($!)
run_case missing stages.grouper.plugin=llm "$(llm "$url" missing)" & cases+=($!)
run_case duplicate stages.grouper.plugin=llm "$(llm "$url" duplicate)" & cases+=($!)
run_case toomany stages.grouper.plugin=llm "stages.grouper.options={url: \"$url\", model: valid, timeout_s: 2, max_groups: 3}" & cases+=($!)
run_case malformed stages.grouper.plugin=llm "$(llm "$url" malformed)" & cases+=($!)
run_case hang stages.grouper.plugin=llm "$(llm "$url" hang)" & cases+=($!)
run_case http500 stages.grouper.plugin=llm "$(llm "$url" http500)" & cases+=($!)
run_case noauth stages.grouper.plugin=llm "$(llm "$url" auth)" & cases+=($!)
echo_key="sk-live/Ab+Cd=Ef:Gh.Ij_Kl-Mn0123456789opqrstuv"
API_KEY_FOR_TEST=$echo_key run_case echokey stages.grouper.plugin=llm \
  "stages.grouper.options={url: \"$url\", model: \"echo_key\", api_key_env: API_KEY_FOR_TEST, timeout_s: 2}" & cases+=($!)
wait "${cases[@]}"

check "the structural reference run succeeds" '[[ $(cat "$tmp/structural.rc") -eq 0 && -s $tmp/structural/grouped.svg ]]'
reference=$(groups_of "$tmp/structural/grouped.svg")
expected="group-1:thigh_left,shoe_left,thigh_right,shoe_right;group-2:torso,belt,upper_arm_left,hand_left;group-3:upper_arm_right,hand_right;group-4:neck,face,hair,eye_left,eye_right,mouth"
check "the canned grouping differs from the structural one (the test can tell them apart)" '[[ $reference != "$expected" ]]'

# A valid answer: its groups exactly, in paint order, no warning.
for c in valid fenced auth; do
  got=$(groups_of "$tmp/$c/grouped.svg" 2>/dev/null)
  check "$c: the run succeeds with the answer's groups in paint order" \
    '[[ $(cat "$tmp/$c.rc") -eq 0 && $got == "$expected" && -s $tmp/$c/animation.svg ]] || { echo "  got: $got"; head -c 400 "$tmp/$c.err"; false; }'
  check "$c: no warning" '! grep -q "grouper llm" "$tmp/$c.err"'
done
check "the answer's part names reach the video stage (data-name in grouped.svg and recolored.svg)" \
  'grep -q "data-name=\"waving arm\"" "$tmp/valid/grouped.svg" && grep -q "data-name=\"waving arm\"" "$tmp/valid/recolored.svg"'
check "the structural grouper names no part" '! grep -q "data-name=" "$tmp/structural/grouped.svg"'
check "the request carries the prompt, the SVG, the path ids and a PNG render" \
  '"$py" - "$tmp/requests.log" <<EOF
import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    if r["body"]["model"] == "valid":
        text = r["body"]["messages"][1]["content"][0]["text"]
        assert "waves the right arm" in text and "<svg" in text
        ids = [l[2:].split(" ")[0] for l in text.splitlines() if l.startswith("- ")]
        assert ids[:3] == ["thigh_left", "shoe_left", "thigh_right"] and ids[-1] == "mouth", ids
        assert r["body"]["messages"][1]["content"][1]["image_url"]["url"].startswith("data:image/png;base64,iVBOR")
        assert "Authorization" not in r["headers"]
        break
else:
    sys.exit(1)
EOF'
check "api_key_env sends the key as a bearer token" \
  'grep -q "\"Authorization\": \"Bearer test-secret\"" "$tmp/requests.log"'

# Failures: the run succeeds, one warning line names the reason, grouped.svg is the structural one.
# fallback NAME REASON [GROUPS_CHECK]: GROUPS_CHECK (default: equal to the structural run) is
# evaluated with $got holding the groups.
fallback() {
  local c=$1 reason=$2 groups_check=${3:-'[[ $got == "$reference" ]]'}
  local got; got=$(groups_of "$tmp/$c/grouped.svg" 2>/dev/null)
  local warn; warn=$(grep -c "warning: grouper llm: .*; using the structural grouper" "$tmp/$c.err")
  if [[ $(cat "$tmp/$c.rc") -eq 0 && -s $tmp/$c/animation.svg && $warn -eq 1 ]] && eval "$groups_check" &&
     grep "warning: grouper llm:" "$tmp/$c.err" | grep -qF -- "$reason"; then
    ok "$c: falls back to the structural grouper with a warning naming \"$reason\""
  else
    bad "$c: fallback (exit $(cat "$tmp/$c.rc"), groups $got, stderr: $(head -c 400 "$tmp/$c.err"))"
  fi
}
fallback nourl "no url configured"
fallback refused "Couldn't connect to server"
fallback unknown "unknown path id 'left_ear'"
fallback missing "path 'mouth' is in no group"
fallback duplicate "path 'mouth' appears more than once"
# With options.max_groups 3 the structural fallback honours the same limit.
fallback toomany "4 groups (expected 1..3)" \
  '[[ $(tr ";" "\n" <<<"$got" | grep -c .) -le 3 && $(tr ";,:" "\n\n\n" <<<"$got" | grep -vc "^group-") -eq 16 && $got != "$reference" ]]'

fallback malformed "malformed JSON in the answer"
fallback hang "timeout"
fallback http500 "HTTP 500"
fallback noauth "HTTP 401"
fallback echokey "HTTP 401 from $url: $(printf 'x%.0s' {1..190})<key> is n..."
check "echokey: no 8-character piece of the echoed key on stderr, stdout or in the run folder (log.txt included)" \
  '"$py" -c "import sys; k = sys.argv[1]; [print(k[i:i + 8]) for i in range(len(k) - 7)]" "$echo_key" >"$tmp/pieces" &&
   [[ -s $tmp/echokey/log.txt ]] && ! grep -rqsF -f "$tmp/pieces" "$tmp/echokey.err" "$tmp/echokey.out" "$tmp/echokey"'
# The grouper stage's own time, from the run's summary (a fallback leaves no manifest: it is
# asked again next run).
hang_s=$(awk '$1 == "grouper" && $2 == "llm" {print $3}' "$tmp/hang.out")
check "a fallback leaves no manifest, so the next run asks again" '[[ ! -f $tmp/hang/.svgmotion/grouper.json && -f $tmp/hang/.svgmotion/fitter.json ]]'
# The fact: the 2 s timeout cut the 20 s hang short. The bound leaves a wide margin for a loaded
# machine (the stage also renders the request's PNG and groups structurally after giving up).
check "the hanging server (20 s) costs the timeout (2 s), not the hang: grouper took ${hang_s:-?} s" \
  '"$py" -c "import sys; sys.exit(not 2 <= float(sys.argv[1]) <= 15)" "${hang_s:-99}"'

finish
