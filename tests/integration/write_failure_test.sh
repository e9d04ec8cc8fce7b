#!/usr/bin/env bash
# A disk that refuses a video while it is encoded: `svgmotion render ANIMATION.svg -o clip.mp4`
# (the preview writer every encoded video goes through: previews, candidates, clips) under a
# file-size limit, which stands in for a full disk without root or a filesystem to fill: a
# write(2) past it fails (EFBIG, SIGXFSZ ignored) exactly where ENOSPC would. Whether the limit
# stops the encoder from opening (0 KiB) or cuts the mp4 short of its index (8 KiB of ~10), the
# run fails with one line naming the file and the write failure, never a missing encoder or a
# success, and leaves no file (nor its temporary) behind.
#   write_failure_test.sh SVGMOTION_BINARY TEST_DATA_DIR
# Prints "N passed, M failed" and exits non-zero on any failure.
set -u
bin=$1 data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"
svg=$data/export/pulse.svg

# render_limited NAME.EXT LIMIT_KIB: render under the limit; stderr through a pipe (the limit
# applies to every regular file the command writes, its stderr file included).
render_limited() {
  local out=$1 limit=$2
  ( trap '' XFSZ; ulimit -f "$limit"; exec "$bin" render "$svg" -o "$tmp/out/$out" --size 256 ) 2>&1 | cat >"$tmp/$out.err"
  echo "${PIPESTATUS[0]}" >"$tmp/$out.rc"
}
mkdir -p "$tmp/out"
# Unlimited first: the control, and it fills the OpenCL kernel cache, which the limited runs
# could not write.
"$bin" render "$svg" -o "$tmp/full.mp4" --size 256 2>"$tmp/full.err"
check "without a limit the clip is written (10 KiB or so, more than the 8 KiB limit below)" \
  '[[ $(stat -c %s "$tmp/full.mp4") -gt 9000 ]]'
render_limited open.mp4 0
render_limited cut.mp4 8
render_limited open.webm 0
for c in open.mp4 cut.mp4 open.webm; do
  check "$c: one line naming the file and the write failure" \
    '[[ $(cat "$tmp/$c.rc") -eq 1 ]] && [[ $(grep -c "^svgmotion: " "$tmp/$c.err") -eq 1 ]] &&
     grep -qx "svgmotion: $tmp/out/$c: cannot write: File too large" "$tmp/$c.err" || { cat "$tmp/$c.err"; false; }'
done
check "nothing left behind, not even a temporary file" '[[ -z $(ls -A "$tmp/out") ]] || { ls -A "$tmp/out"; false; }'
finish
