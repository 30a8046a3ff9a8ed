#!/usr/bin/env bash
# Builds the libFuzzer targets with clang-14 (AddressSanitizer and UndefinedBehaviorSanitizer
# on) and runs each for a bounded time, starting from the seed corpus in tests/fuzz/corpus.
#   bash tests/fuzz/run.sh                   # 60 s per target (what CI runs)
#   bash tests/fuzz/run.sh -runs=1000000     # a million executions per target
# Each run starts by replaying the seeds and the regressions (tests/fuzz/regressions/<target>)
# under the sanitizers. Extra arguments go to libFuzzer. A crash stops the run with a non-zero status and leaves the
# input as build-fuzz/crash-*: copy it into tests/fuzz/regressions/<target>/ (replayed by ctest)
# and fix the bug. New inputs found go to build-fuzz/corpus-<target>, not to the source tree.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(-max_total_time=60)
build=build-fuzz
# -g1 (line tables): enough for the sanitizers' reports, and quicker to build than -g.
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLFEM_FUZZ=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1" \
  -DLFEM_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j2 --target fuzz_gmsh fuzz_api
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# The targets fuzz side by side, one per core (each is a single-threaded program); their
# summaries are printed in a fixed order once both have ended.
fuzz() {  # fuzz TARGET: one libFuzzer run; its status in $build/fuzz_TARGET.status
  local target=$1 work="$build/corpus-$1" log="$build/fuzz_$1.log"
  mkdir -p "$work"
  # -timeout: one input may take at most 10 s (a step is capped by max_substeps);
  # -rss_limit_mb: a leak or runaway allocation is reported, not swapped.
  (cd "$build" && "./tests/fuzz/fuzz_$target" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
     "${args[@]}" "corpus-$target" "../tests/fuzz/corpus/$target" \
     "../tests/fuzz/regressions/$target") >"$log" 2>&1
  echo $? >"$build/fuzz_$target.status"
}
targets=(gmsh api)
for target in "${targets[@]}"; do
  echo "fuzz_$target: ${args[*]}"
  (set +e; fuzz "$target") &
done
wait
failed=0
for target in "${targets[@]}"; do
  log="$build/fuzz_$target.log"
  if [ "$(cat "$build/fuzz_$target.status")" != 0 ]; then
    tail -n 60 "$log"
    echo "fuzz_$target: FAILED (input saved as $build/crash-* or similar; see $log)"
    failed=1
    continue
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  corpus=$(find "$build/corpus-$target" -type f | wc -l)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1)
  echo "fuzz_$target: ${runs:-0} executions, ${cov:-cov: ?} edges, corpus $corpus inputs, 0 crashes"
done
exit $failed
