#!/usr/bin/env bash
# Builds the project (scripts/setup.sh) and runs the whole test suite but the
# long numerical validations (label validation); then, unless --quick, those,
# the same suite under AddressSanitizer + UndefinedBehaviorSanitizer,
# the threaded tests under ThreadSanitizer (CMakePresets.json), and the scene
# loader's fuzzer (tests/fuzz). Stops at the first failing stage, with its exit
# code. Every run ends with each stage's time and the ten slowest tests
# (docs/testing.md says what each stage covers).
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
quick=0
if [[ "${1:-}" == "--quick" ]]; then
  quick=1
fi

# Each stage's ctest output, for the ten slowest tests at the end.
logs=$(mktemp -d)
stage_names=()
stage_seconds=()
run_start=$SECONDS

# kill_tree PID: the process and everything it started (the fuzzer's build or
# run, when an earlier stage fails).
kill_tree() {
  local child
  for child in $(cat /proc/"$1"/task/*/children 2>/dev/null); do
    kill_tree "$child"
  done
  kill "$1" 2>/dev/null
}

report() {
  local status=$?
  # A failure while reporting must not replace the suite's own exit code.
  set +e +o pipefail
  if [[ -n "${fuzz_pid:-}" ]]; then
    kill_tree "$fuzz_pid"
    wait "$fuzz_pid" 2>/dev/null
  fi
  echo
  echo "run-tests: time by stage"
  local i
  for i in "${!stage_names[@]}"; do
    printf '  %5d s  %s\n' "${stage_seconds[$i]}" "${stage_names[$i]}"
  done
  printf '  %5d s  in all\n' $((SECONDS - run_start))
  echo "run-tests: the ten slowest tests"
  # ctest's lines: "12/521 Test  #45: Suite.Name .......   Passed    2.95 sec"
  local log
  for log in "$logs"/*.log; do
    [[ -e "$log" ]] || continue
    awk -v OFS='\t' -v stage="$(basename "$log" .log)" \
      '/ Test +#[0-9]+: / && / sec$/ { print $(NF - 1), $4, stage }' "$log"
  done | sort -rn |
    awk -F'\t' 'NR <= 10 { printf "  %7.2f s  %s (%s)\n", $1, $2, $3 }'
  rm -rf "$logs"
  if ((status != 0)); then
    echo "run-tests: FAILED in stage \"${current_stage:-set-up}\" (exit code $status)" >&2
  fi
  exit "$status"
}
trap report EXIT

# stage NAME COMMAND...: runs the command, timing it under NAME.
stage() {
  current_stage=$1
  shift
  echo "run-tests: $current_stage" >&2
  local start=$SECONDS
  "$@"
  stage_names+=("$current_stage")
  stage_seconds+=($((SECONDS - start)))
}

# tests LOGNAME CTEST-ARGS...: ctest, its output also kept for the report.
tests() {
  local log="$logs/$1.log"
  shift
  ctest "$@" | tee "$log"
}

stage "set-up and build (Release)" bash scripts/setup.sh

# GUI tests run without a display.
export QT_QPA_PLATFORM=offscreen
# --no-tests=error: a suite that registered no test must not pass.
stage "test suite (Release) but the long validations" \
  tests release --test-dir build --output-on-failure -j2 --no-tests=error -LE validation
if ((quick)); then
  exit 0
fi
stage "long numerical validations (Release)" \
  tests validation --test-dir build --output-on-failure -j2 --no-tests=error -L validation

configure_quietly() {
  cmake --preset "$1" >/dev/null
}

# The fuzzer's build and run go beside the AddressSanitizer build: libFuzzer
# runs one process, which left a core idle for its 30 s, and the build's jobs,
# niced, take what it leaves, so the fuzzer tries as many inputs as alone. Its
# output is shown, and its exit code taken, when it ends.
fuzz_out="$logs/fuzz-stage.out"
fuzz_seconds_file="$logs/fuzz-stage.seconds"
(
  start=$SECONDS
  CXX=clang++ cmake -S tests/fuzz -B build-fuzz -G Ninja >/dev/null &&
    cmake --build build-fuzz &&
    tests fuzz --test-dir build-fuzz --output-on-failure --no-tests=error
  status=$?
  echo $((SECONDS - start)) >"$fuzz_seconds_file"
  exit "$status"
) >"$fuzz_out" 2>&1 &
fuzz_pid=$!

stage "build (AddressSanitizer + UndefinedBehaviorSanitizer)" \
  eval 'configure_quietly asan && nice -n 10 cmake --build --preset asan'
stage "test suite under AddressSanitizer + UndefinedBehaviorSanitizer" tests asan --preset asan

stage "build (ThreadSanitizer: threaded tests)" \
  eval 'configure_quietly tsan && cmake --build --preset tsan'
stage "renderer, worker and editor tests under ThreadSanitizer" tests tsan --preset tsan

# wait_for_fuzzing: the fuzzer's output and exit code; its stage's time is
# its own, not this wait's.
wait_for_fuzzing() {
  local status=0
  wait "$fuzz_pid" || status=$?
  fuzz_pid=
  cat "$fuzz_out"
  return "$status"
}
stage "scene loader fuzzer: build, corpus, a short run (beside the ASan build)" wait_for_fuzzing
stage_seconds[-1]=$(cat "$fuzz_seconds_file" 2>/dev/null || echo "${stage_seconds[-1]}")
