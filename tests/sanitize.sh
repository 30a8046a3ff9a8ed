#!/usr/bin/env bash
# The C++ test suites again, built with AddressSanitizer and UndefinedBehaviorSanitizer: any
# report (out-of-bounds access, use after free, leak, undefined behaviour) ends the run with a
# non-zero status. Then the thread tests built with ThreadSanitizer (data races). Part of the
# README's test command and so of CI.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=build-sanitize
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLFEM_SANITIZE=ON -DLFEM_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j2 --target lfem_unit_tests lfem_api_tests lfem_robustness_tests lfem_profile_tests
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
log="$build/sanitize.log"
: >"$log"
echo "sanitizers: unit tests"
"$build/tests/lfem_unit_tests" --gtest_brief=1 | tee -a "$log"
# The cantilever (1e8 tet-steps), the 10-turn spins, the 1e5 steps of resting contact and the
# stack of three cubes run the same code paths as the shorter tests but take minutes under the
# sanitizers; they run in the plain build only.
echo "sanitizers: C API and physics tests"
"$build/tests/lfem_api_tests" --gtest_brief=1 \
  --gtest_filter='-Cantilever.*:SpinningBody.*:Extreme.HundredThousandSteps*:RestingContact.StackOfThree*' |
  tee -a "$log"
echo "sanitizers: profile tests (what a scene leaves out)"
"$build/tests/lfem_profile_tests" --gtest_brief=1 | tee -a "$log"
echo "sanitizers: robustness tests (checkpoints, out of memory, concurrent worlds)"
"$build/tests/lfem_robustness_tests" --gtest_brief=1 | tee -a "$log"

# ThreadSanitizer: separate worlds in separate threads, and one world's own worker threads.
tsan=build-tsan
cmake -S . -B "$tsan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLFEM_SANITIZE_THREAD=ON -DLFEM_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$tsan" -j2 --target lfem_robustness_tests
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
echo "sanitizers: thread tests under ThreadSanitizer"
"$tsan/tests/lfem_robustness_tests" --gtest_brief=1 --gtest_filter='ConcurrentWorlds.*' | tee -a "$log"

# A failing test or a sanitizer report has already ended the script (pipefail); count what ran.
passed=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) tests\?\.$/\1/p' "$log" | awk '{s += $1} END {print s + 0}')
echo "sanitizers: $passed passed, 0 failed"

