#!/usr/bin/env bash
# Builds the project (scripts/setup.sh) and runs the whole test suite but the
# long numerical validations (label validation); then, unless --quick, those,
# the same suite under AddressSanitizer + UndefinedBehaviorSanitizer,
# the threaded tests under ThreadSanitizer (CMakePresets.json), and the scene
# loader's fuzzer (tests/fuzz). Stops at the first failing stage, with its exit
# code. Every run ends with each stage's time and the ten slowest tests
# (docs/design/testing.md says what each stage covers).
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
# The jobs started beside the stages (`beside`), by name.
declare -A beside_pids=()

# kill_tree PID: the process and everything it started (a build or the fuzzer
# beside the stages, when a stage fails).
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
  local pid
  for pid in "${beside_pids[@]}"; do
    kill_tree "$pid"
    wait "$pid" 2>/dev/null
  done
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

# The ASan build starts beside the Release suite, niced: the suite leaves a
# third of the two cores idle (tests that wait on Slurm, on a GUI's timers, on
# starting a process), which a niced compile takes, and the ASan stage waits
# for what is left of it (36 s saved; the Release suite took 3 s longer). The
# TSan build beside the ASan suite saved 24 s of its build and cost the suite
# 33 s, so it comes after. The fuzzer's build and run go beside the rest of the
# ASan build, not niced: libFuzzer runs one process, so the build's jobs take
# the other core.

# beside NAME COMMAND...: starts the command in the background; `await NAME`
# shows its output and returns its exit code.
beside() {
  local name=$1
  shift
  (
    start=$SECONDS
    status=0
    "$@" || status=$?
    echo $((SECONDS - start)) >"$logs/$name.seconds"
    exit "$status"
  ) >"$logs/$name.out" 2>&1 &
  beside_pids[$name]=$!
}

# await NAME: the stage that waits for a job started beside; its time in the
# report is the job's own, from its start.
await() {
  local name=$1 status=0
  wait "${beside_pids[$name]}" || status=$?
  unset "beside_pids[$name]"
  cat "$logs/$name.out"
  return "$status"
}

# await_stage NAME STAGE-NAME: `stage`, reporting the job's own time.
await_stage() {
  stage "$2" await "$1"
  stage_seconds[-1]=$(cat "$logs/$1.seconds" 2>/dev/null || echo "${stage_seconds[-1]}")
}

stage "set-up and build (Release)" bash scripts/setup.sh

# GUI tests run without a display.
export QT_QPA_PLATFORM=offscreen
if ((!quick)); then
  beside asan-build eval 'nice -n 19 cmake --preset asan >/dev/null &&
    nice -n 19 cmake --build --preset asan'
fi
# --no-tests=error: a suite that registered no test must not pass.
stage "test suite (Release) but the long validations" \
  tests release --test-dir build --output-on-failure -j2 --no-tests=error -LE validation
if ((quick)); then
  exit 0
fi
stage "long numerical validations (Release)" \
  tests validation --test-dir build --output-on-failure -j2 --no-tests=error -L validation

beside fuzz eval 'CXX=clang++ cmake -S tests/fuzz -B build-fuzz -G Ninja >/dev/null &&
  cmake --build build-fuzz &&
  tests fuzz --test-dir build-fuzz --output-on-failure --no-tests=error'
await_stage asan-build "build (AddressSanitizer + UndefinedBehaviorSanitizer; begun beside the Release suite)"

stage "test suite under AddressSanitizer + UndefinedBehaviorSanitizer" tests asan --preset asan
stage "build (ThreadSanitizer: threaded tests)" \
  eval 'cmake --preset tsan >/dev/null && cmake --build --preset tsan'
stage "renderer, worker and editor tests under ThreadSanitizer" tests tsan --preset tsan

await_stage fuzz "scene loader fuzzer: build, corpus, a short run (beside the ASan build)"
