#!/usr/bin/env bash
# The compact export against the full one, from a finished run or fit directory (not part of the
# test suite; the numbers in the README's table and docs/commands.md). Writes both again from the
# checkpoint (`svgmotion export`, no fitting) into WORK/full and WORK/compact, then draws each at
# 1024 px (the larger side) at ten times of one pass, (k + 0.5) / 10: animation.svg with
# `svgmotion render --time`, animation.json with librlottie (build/tests/rlottie_frames; it
# draws whole frames: frame floor((k + 0.5) / 10 * op)). One line per file: its size, compact
# and full, and the PSNR of each time (build/tests/png_psnr, as ../shared/tools/imgdiff.py) and
# the worst.
#   usage: compact_psnr.sh RUN_DIR WORK [BIN] [EXPORT_OPTION...]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
run=$1 work=$2
bin=${3:-$root/build/frontends/svgmotion}
shift 3 2>/dev/null || shift $#
tools=$(dirname "$bin")/../tests  # png_psnr and rlottie_frames of the same build
rm -rf "$work/full" "$work/compact"
mkdir -p "$work/full" "$work/compact"
"$bin" export "$run" -o "$work/full" --full --format svg,lottie >"$work/full.log" 2>&1
"$bin" export "$run" -o "$work/compact" --format svg,lottie "$@" >"$work/compact.log" 2>&1
read -r w h op < <(/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["w"], d["h"], d["op"] - d.get("ip", 0))' "$work/full/animation.json")
if (( w >= h )); then W=1024 H=$(( (1024 * h + w / 2) / w )); else H=1024 W=$(( (1024 * w + h / 2) / h )); fi
dur=$(grep -o 'dur="[0-9.]*s"' "$work/full/animation.svg" | head -1 | tr -dc '0-9.')
times=() frames=()
for k in 0 1 2 3 4 5 6 7 8 9; do
  times+=("$(awk -v k=$k -v d="$dur" 'BEGIN { printf "%.6f", (k + 0.5) * d / 10 }')")
  frames+=("$(awk -v k=$k -v o="$op" 'BEGIN { printf "%d", (k + 0.5) * o / 10 }')")
done
for kind in full compact; do
  for i in "${!times[@]}"; do
    "$bin" render "$work/$kind/animation.svg" -o "$work/$kind/svg_$i.png" --time "${times[$i]}" --size "$(( W > H ? W : H ))" >/dev/null 2>&1
  done
  "$tools/rlottie_frames" "$work/$kind/animation.json" $W $H "$work/$kind/json_" "${frames[@]}"
done
for file in svg json; do
  row=() worst=99
  for i in "${!times[@]}"; do
    p=$("$tools/png_psnr" "$work/full/${file}_$i.png" "$work/compact/${file}_$i.png" | sed 's/^psnr=\([0-9.]*\).*/\1/')
    row+=("$p")
    worst=$(awk -v a="$worst" -v b="$p" 'BEGIN { print (b < a ? b : a) }')
  done
  printf '%s animation.%s: %s / %s B (compact / full), min %s dB over %s: %s\n' "$(basename "$run")" "$file" \
    "$(stat -c %s "$work/compact/animation.$file")" "$(stat -c %s "$work/full/animation.$file")" "$worst" \
    "$([[ $file == svg ]] && echo "times ${times[*]} s" || echo "frames ${frames[*]}")" "${row[*]}"
done
grep -i "tolerance\|full" "$work/compact.log" | head -3 || true
