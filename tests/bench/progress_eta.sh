#!/usr/bin/env bash
# Captures `svgmotion run` in an 80-column tmux terminal and judges its progress display
# (progress_eta.py: the ETA shown against the real time left at every redraw, the bar never
# going back, dead spots). One run on the bundled man by default; the capture is kept.
#   usage: progress_eta.sh [-b BIN] [-o RUN_DIR] [-c CAPTURE.jsonl] [RUN_ARGS...]
#   (RUN_ARGS default: tests/data/examples/man.svg "the man waves his right arm")
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=$root/build/frontends/svgmotion
run_dir=$(mktemp -d /tmp/progress_eta.XXXXXX)/run
capture=""
while getopts "b:o:c:" o; do
  case $o in b) bin=$OPTARG ;; o) run_dir=$OPTARG ;; c) capture=$OPTARG ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
[ $# -gt 0 ] || set -- "$root/tests/data/examples/man.svg" "the man waves his right arm"
capture=${capture:-$(dirname "$run_dir")/capture.jsonl}
: > "$capture"
session=progress_eta_$$
cmd=$(printf '%q ' "$bin" run "$@" -o "$run_dir" --force)
tmux new-session -d -s "$session" -x 80 -y 24 "sleep 0.5; $cmd; echo \"exit \$?\"; sleep 1"
tmux pipe-pane -t "$session" "python3 $(printf '%q' "$here/progress_eta.py") record $(printf '%q' "$capture")"
while tmux has-session -t "$session" 2>/dev/null; do sleep 1; done
echo "capture: $capture" >&2
python3 "$here/progress_eta.py" report "$capture"
