#!/usr/bin/env bash
# The real-video defects, each alone (issue 10's list), on non-rigid targets: for each SVG, a
# clean fit and one fit per defect in the target video, all judged against the clean frames by
# ../shared/tools/fitcheck.py (tests/bench/fit_nonrigid.sh does each row). Prints the table and
# each defect's PSNR and IoU against the clean fit.
#   usage: [FIT_ARGS="..."] fit_degraded.sh [-b BIN] [-w WORKDIR] [-s VIDEO_SIZE] [-k HOLD] SVG...
set -u
here=$(cd "$(dirname "$0")" && pwd)
args=()
while getopts "b:w:s:k:" o; do
  case $o in b|w|s|k) args+=("-$o" "$OPTARG") ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
for svg in "$@"; do
  for d in "" offwhite shading blur drift jpeg fps8 jitter; do
    bash "$here/fit_nonrigid.sh" "${args[@]}" ${d:+-d "$d"} "$svg" | tail -n +2 | sed "s/^/${d:-clean} /"
  done
done | tee /dev/stderr | awk '
  $1 == "clean" { base[$2] = $3 }
  { printf "%-9s %-12s psnr %6.2f (%+6.2f dB vs clean)  min iou %s\n", $1, $2, $3, $3 - base[$2], $4 }'
