#!/usr/bin/env bash
# The README's two set-up commands in one script:
#   bash .ci/setup.sh example   installs what is missing, builds, animates the bundled example
#   bash .ci/setup.sh test      installs what is missing, builds, runs the whole test suite
#                               and a short fuzzing run (tests/fuzz/run.sh)
# Works as root or through sudo on Debian 12; installs only packages that are not there yet.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
case "$mode" in example|test) ;; *) echo "usage: bash .ci/setup.sh example|test" >&2; exit 2 ;; esac

packages=(
  cmake ninja-build g++ pkg-config ccache
  ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers pocl-opencl-icd
  libeigen3-dev libpugixml-dev libopencv-dev libyaml-cpp-dev
  libavcodec-dev libavformat-dev libavfilter-dev libavutil-dev libswscale-dev
  libpng-dev zlib1g-dev doctest-dev nlohmann-json3-dev libcurl4-openssl-dev libspdlog-dev
  clang libclang-rt-dev
  wordnet-base
)
# Test-only: ffprobe for clip checks, Pillow to decode animated WebP (FFmpeg 5.1 cannot), the two Lottie players the export is checked in
# (Chromium for lottie-web, librlottie), node and npm for lottie-web (tests/integration/export_test.sh),
# and a one-node Slurm for the batch test (tests/integration/batch_test.sh slurm). Chromium
# and puppeteer-core also open report.html (tests/integration/report_test.sh).
if [[ $mode == test ]]; then
  packages+=(ffmpeg chromium librlottie-dev munge slurmd slurmctld slurm-client python3-pil)
  command -v node >/dev/null && command -v npm >/dev/null || packages+=(nodejs npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  if [[ $(id -u) -eq 0 ]]; then as_root=(); else as_root=(sudo); fi
  "${as_root[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j "$jobs"

if [[ $mode == example ]]; then
  ./build/frontends/svgmotion devices
  # The OpenCL kernels a default run uses (six programs; docs/commands.md) compiled once, here,
  # rather than during the first run: that run then compiles nothing.
  ./build/frontends/svgmotion devices --warm
  # The main job, offline: the procedural video provider stands in for a video model.
  ./build/frontends/svgmotion run --input tests/data/examples/man.svg \
    --prompt "the man waves his right arm" -o build/example
  echo "setup: the animated example is $(pwd)/build/example/animation.svg" \
       "(open it in a browser; preview.mp4 shows target | fit, report.html the whole run)"
else
  # lottie-web, dotlottie-web, puppeteer-core, ajv and the lottie-spec schema (pinned in
  # tests/integration/lottie/package.json) go into build/npm, never into the repository.
  mkdir -p build/npm
  cp tests/integration/lottie/package.json build/npm/package.json
  (cd build/npm && npm install --no-audit --no-fund --no-package-lock --loglevel=error >/dev/null)
  # Tests share the one OpenCL device; two at a time keeps both cores busy.
  # The Slurm batch test may not skip here: its packages were installed above.
  SVGM_REQUIRE_SLURM=1 ctest --test-dir build --output-on-failure -j 2
  # The parsers under libFuzzer (clang, ASan+UBSan): every seed and regression input replayed
  # once, then a few seconds of mutation per target from a fixed seed, deterministic for given
  # sources (exploratory fuzzing: bash tests/fuzz/run.sh 600, by hand).
  bash tests/fuzz/run.sh fixed
fi
