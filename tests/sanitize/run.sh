#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer, in build-asan/.
#   bash tests/sanitize/run.sh          configure, build (about 25 minutes on 2 cores), run ctest
# clang at -O1, as sanitizer builds usually are: g++ at -O2 with both sanitizers took over an
# hour to compile on 2 cores (nlohmann/json and OpenCV-heavy files).
# Any sanitizer report fails the test that triggered it (halt_on_error, UBSan non-recoverable).
# PoCL's own runtime is not instrumented; its known leak-at-exit reports are not ours, so leak
# detection is off (ASan still catches every overflow and use-after-free in our code).
set -euo pipefail
cd "$(dirname "$0")/../.."
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-O1 -g $flags" -DCMAKE_C_FLAGS="-O1 -g $flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-asan -j "$(nproc 2>/dev/null || echo 2)"
# The Lottie and report tests open our outputs in lottie-web/Chromium: the same pinned npm
# packages .ci/setup.sh puts into build/npm (copied from there when present).
if [[ ! -d build-asan/npm/node_modules/lottie-web ]]; then
  mkdir -p build-asan/npm
  if [[ -d build/npm/node_modules/lottie-web ]]; then cp -r build/npm/node_modules build-asan/npm/
  else
    cp tests/integration/lottie/package.json build-asan/npm/package.json
    (cd build-asan/npm && npm install --no-audit --no-fund --no-package-lock --loglevel=error >/dev/null)
  fi
fi
export ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:abort_on_error=0:detect_odr_violation=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j 2
