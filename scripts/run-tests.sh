#!/usr/bin/env bash
# Builds the project (scripts/setup.sh) and runs the whole test suite; then,
# unless --quick, the same suite under AddressSanitizer + UndefinedBehaviorSanitizer,
# the threaded tests under ThreadSanitizer (CMakePresets.json), and the scene
# loader's fuzzer (tests/fuzz). Stops at the first failing stage, with its exit code.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
quick=0
if [[ "${1:-}" == "--quick" ]]; then
  quick=1
fi
bash scripts/setup.sh

# GUI tests run without a display.
export QT_QPA_PLATFORM=offscreen
stage() {
  echo "run-tests: $*" >&2
}

stage "test suite (Release)"
# --no-tests=error: a suite that registered no test must not pass.
ctest --test-dir build --output-on-failure -j2 --no-tests=error
if ((quick)); then
  exit 0
fi

stage "test suite under AddressSanitizer + UndefinedBehaviorSanitizer"
cmake --preset asan >/dev/null
cmake --build --preset asan
ctest --preset asan

stage "renderer, worker and editor tests under ThreadSanitizer"
cmake --preset tsan >/dev/null
cmake --build --preset tsan
ctest --preset tsan

stage "scene loader fuzzing (corpus, then a short run)"
CXX=clang++ cmake -S tests/fuzz -B build-fuzz -G Ninja >/dev/null
cmake --build build-fuzz
ctest --test-dir build-fuzz --output-on-failure --no-tests=error
