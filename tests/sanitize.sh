#!/usr/bin/env bash
# The C++ test suites again, built with AddressSanitizer and UndefinedBehaviorSanitizer: any
# report (out-of-bounds access, use after free, leak, undefined behaviour) ends the run with a
# non-zero status. Then the thread tests built with ThreadSanitizer (data races). Part of the
# README's test command and so of CI.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# -O1 -g1: the sanitizers' usual optimisation, with line tables for their reports; it builds in
# about 60 % of the time of -O2 -g, which matters more here than the tests' own run time.
flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1"
       -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DLFEM_BUILD_EXAMPLES=OFF)
build=build-sanitize
cmake -S . -B "$build" "${flags[@]}" -DLFEM_SANITIZE=ON >/dev/null
cmake --build "$build" -j2 --target lfem_unit_tests lfem_api_tests lfem_robustness_tests lfem_profile_tests
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
log="$build/sanitize.log"
: >"$log"

# The suites run side by side, one per core: each writes its own log; all are waited for, then
# their logs are printed in a fixed order, and any failure (a test, or a sanitizer report,
# which aborts its program) fails the script.
jobs=()
start() {  # start NAME COMMAND...: run COMMAND in the background, output to $build/NAME.out
  local name=$1
  shift
  (set +e; "$@" >"$build/$name.out" 2>&1; echo $? >"$build/$name.status") &
  jobs+=("$name")
}
finish() {  # waits for the started jobs; prints their output; returns non-zero if any failed
  local failed=0 name
  wait
  for name in "${jobs[@]}"; do
    echo "sanitizers: $name"
    tee -a "$log" <"$build/$name.out"
    if [ "$(cat "$build/$name.status")" != 0 ]; then
      echo "sanitizers: $name FAILED"
      failed=1
    fi
  done
  jobs=()
  return $failed
}

# The cantilever (1e8 tet-steps), the 10-turn spins, the 1e5 steps of resting contact and the
# stack of three cubes run the same code paths as the shorter tests but take minutes under the
# sanitizers; they run in the plain build only. The C API and physics tests, the longest
# suite, run as two shards (GoogleTest's GTEST_SHARD_INDEX), next to the other suites.
api_filter='-Cantilever.*:SpinningBody.*:Extreme.HundredThousandSteps*:RestingContact.StackOfThree*'
for shard in 0 1; do
  start "C API and physics tests, shard $((shard + 1)) of 2" \
    env GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard \
    "$build/tests/lfem_api_tests" --gtest_brief=1 --gtest_filter="$api_filter"
done
start "unit tests" "$build/tests/lfem_unit_tests" --gtest_brief=1
start "profile tests (what a scene leaves out)" "$build/tests/lfem_profile_tests" --gtest_brief=1
start "robustness tests (checkpoints, out of memory, concurrent worlds)" \
  "$build/tests/lfem_robustness_tests" --gtest_brief=1
finish

# ThreadSanitizer: separate worlds in separate threads, one world's own worker threads, and the
# thread pool's own tests (its rounds are handed out without a lock).
tsan=build-tsan
cmake -S . -B "$tsan" "${flags[@]}" -DLFEM_SANITIZE_THREAD=ON >/dev/null
cmake --build "$tsan" -j2 --target lfem_robustness_tests lfem_thread_pool_tests
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
start "thread tests under ThreadSanitizer" \
  "$tsan/tests/lfem_robustness_tests" --gtest_brief=1 --gtest_filter='ConcurrentWorlds.*'
start "thread pool tests under ThreadSanitizer" "$tsan/tests/lfem_thread_pool_tests" --gtest_brief=1
finish

# A failing test or a sanitizer report has already ended the script (set -e); count what ran.
passed=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) tests\?\.$/\1/p' "$log" | awk '{s += $1} END {print s + 0}')
echo "sanitizers: $passed passed, 0 failed"
