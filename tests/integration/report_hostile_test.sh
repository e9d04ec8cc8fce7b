#!/usr/bin/env bash
# report.html of hostile animations: report_hostile_test.sh SVGMOTION_BINARY TEST_DATA_DIR NODE_MODULES
#   Each file of tests/data/hostile (script vectors that HTML reads differently from XML, loads
#   of outside files, meta refresh, SMIL that sets an href) becomes the animation.svg of a run
#   directory, with SERVER in it replaced by a local server that logs every request;
#   `svgmotion report` writes its page (exit 0, one warning line naming what it dropped). The
#   page holds none of the file's addresses or scripts, and headless Chromium
#   (report/hostile_page_check.js) opening it and clicking the drawing's links sees no dialog,
#   no output of injected script, no request, no navigation; the animation is in the DOM,
#   animated, drawn only inside its box (however it is transformed), and the page's HTML parser
#   built the tree an XML parser builds from the markup.
#   The server received nothing.
# NODE_MODULES holds puppeteer-core (.ci/setup.sh installs it into build/npm). Debian's chromium.
set -u
bin=$1 data=$2 node_modules=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

missing=
command -v chromium >/dev/null || missing+=" chromium (Debian)"
command -v node >/dev/null || missing+=" node (Debian nodejs)"
[[ -d $node_modules/puppeteer-core ]] || missing+=" puppeteer-core (npm, in $node_modules)"
if [[ -n $missing ]]; then
  bad "the page checker's tools are not installed:$missing; bash .ci/setup.sh test installs them"
  finish
fi
start_server "$here/logging_http_server.py" "$tmp/requests.log" --lifetime 300 || { bad "the logging server did not start"; finish; }
server=127.0.0.1:$port

names=()
for f in "$data"/hostile/*.svg; do
  name=$(basename "$f" .svg)
  names+=("$name")
  mkdir -p "$tmp/runs/$name"
  sed "s#SERVER#$server#g" "$f" >"$tmp/runs/$name/animation.svg"
  printf '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100"><rect width="50" height="50" fill="#36c"/></svg>\n' \
    >"$tmp/runs/$name/input.svg"
done
check "the corpus is there (${#names[@]} files)" '(( ${#names[@]} >= 20 ))'
check "its files name the server" 'grep -q "$server" "$tmp/runs/fetch_css_import/animation.svg"'

# The pages, a few at a time (most of a report's time is the device's start-up, not CPU).
printf '%s\n' "${names[@]}" | xargs -P 4 -I{} sh -c '"$0" report "$1/{}" >"$1/{}.out" 2>"$1/{}.err"; echo $? >"$1/{}.rc"' "$bin" "$tmp/runs"
pages=()
for name in "${names[@]}"; do
  r=$tmp/runs/$name
  pages+=("$name=$r/report.html")
  check "$name: report exits 0 and writes the page ($(cat "$r.rc"))" '[[ $(cat "$r.rc") == 0 && -s $r/report.html ]]'
  # Each file's exact line is tests/unit/inline_svg_test.cpp's; an overlay drops nothing.
  check "$name: one warning line names what was dropped ($(head -c 300 "$r.err"))" \
    '[[ $name == overlay_* && ! -s $r.err ]] ||
     { [[ $(grep -c "" "$r.err") -eq 1 ]] && grep -Eq "^svgmotion: warning: report.html: dropped from the inlined animation: [0-9]+ " "$r.err"; }'
  check "$name: the page holds none of its addresses, scripts, comments or CDATA" \
    '! grep -Eqi "$server|javascript:|svgm-xss|file:" "$r/report.html" && ! grep -Eq "<!--|<!\[CDATA\[|http-equiv=\"refresh" "$r/report.html"'
done

# The page's policy on its own: markup that gets past the sanitiser (put into a page by hand here)
# still neither runs nor loads anything.
sed "s#</body>#<img src=\"http://$server/csp-img\" onerror=\"alert('svgm-xss csp-onerror')\"><script>alert('svgm-xss csp-script')</script><iframe src=\"javascript:alert('svgm-xss csp-iframe')\"></iframe><link rel=\"stylesheet\" href=\"http://$server/csp.css\"><video src=\"http://$server/csp.mp4\"></video></body>#" \
  "$tmp/runs/script_uppercase/report.html" >"$tmp/csp_only.html"
check "the hand-made page holds the injected markup" 'grep -q "csp-onerror" "$tmp/csp_only.html"'
pages+=("csp_only=$tmp/csp_only.html")

node "$here/report/hostile_page_check.js" "$node_modules" "${pages[@]}" >"$tmp/facts" 2>"$tmp/facts_err"
rc=$?
check "Chromium opens the pages (exit $rc: $(head -c 200 "$tmp/facts_err"))" '[[ $rc -eq 0 ]]'
grep -v "^svg \|^tree \|^overlay " "$tmp/facts" | sed 's/^/# /'
for name in "${names[@]}"; do
  check "$name: no dialog" '! grep -q "^dialog $name " "$tmp/facts"'
  check "$name: no output of injected script" '! grep -q "^console $name .*svgm-xss" "$tmp/facts"'
  check "$name: no request" '! grep -q "^request $name " "$tmp/facts"'
  check "$name: no navigation" '! grep -q "^navigated $name " "$tmp/facts"'
  check "$name: the animation is in the DOM, animated ($(grep "^svg $name " "$tmp/facts"))" \
    'grep -Eq "^svg $name count=1 paths=[1-9][0-9]* animations=[1-9][0-9]* player=true$" "$tmp/facts"'
  check "$name: the drawing stays in its box" 'grep -qx "overlay $name clear" "$tmp/facts"'
  check "$name: HTML builds the tree XML builds ($(grep "^tree $name " "$tmp/facts"))" 'grep -qx "tree $name same" "$tmp/facts"'
done
check "csp_only: no dialog, the player works, the policy refused the rest" \
  '! grep -q "^dialog csp_only " "$tmp/facts" && grep -q "^svg csp_only count=1 .* player=true$" "$tmp/facts" && grep -q "^console csp_only error .*violates the following Content Security Policy directive" "$tmp/facts"'
check "the server received nothing ($(head -c 300 "$tmp/requests.log" | tr '\n' ' '))" '[[ ! -s $tmp/requests.log ]]'
finish
