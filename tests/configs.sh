#!/usr/bin/env bash
# Builds and tests each reduced configuration of lfem: the library without libccd
# (LFEM_WITH_CCD=OFF), without file I/O (LFEM_WITH_IO=OFF), without both, and without threads
# (LFEM_WITH_THREADS=OFF: no std::thread, every world steps on the caller's thread). Each one is
# configured in its own folder, built with -j2 and tested with ctest; bindings, examples and the
# fuzz replays are left out so it stays quick. A build without libccd must also not link it.
# Ends with "configs: N passed, M failed"; exits non-zero when any configuration failed.
#
#   bash tests/configs.sh            (folders build-config-NAME/ beside build/, or under
#                                     LFEM_CONFIGS_DIR; LFEM_CONFIGS_JOBS sets -j, default 2)
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
base=${LFEM_CONFIGS_DIR:-$root}
jobs=${LFEM_CONFIGS_JOBS:-2}
common=(-DCMAKE_BUILD_TYPE=Release -DLFEM_BUILD_TESTS=ON -DLFEM_BUILD_EXAMPLES=OFF
        -DLFEM_BUILD_BINDINGS=OFF -DLFEM_BUILD_FUZZ_REPLAY=OFF)
# name | extra CMake options (add new reduced configurations here)
configs=(
  "no-ccd|-DLFEM_WITH_CCD=OFF -DLFEM_WITH_IO=ON"
  "no-io|-DLFEM_WITH_CCD=ON -DLFEM_WITH_IO=OFF"
  "no-ccd-no-io|-DLFEM_WITH_CCD=OFF -DLFEM_WITH_IO=OFF"
  "no-threads|-DLFEM_WITH_THREADS=OFF"
)

# CMakeLists.txt compiles through ccache when it is installed: only files that test an option
# (LFEM_WITH_*) differ from the main build's, so the rest comes from the cache. The folders
# sit at the same depth as build/ (ccache hashes paths relative to them).

# The two longest physics tests (a cantilever of 1e8 tet-steps, 1e5 steps of resting contact)
# use no shape and no file: they run in the full build only.
long_tests='^(Cantilever\.TipDeflectionMatchesBeamTheory|Extreme\.HundredThousandSteps.*)$'

passed=0
failed=0
failed_names=()
for entry in "${configs[@]}"; do
  name=${entry%%|*}
  read -r -a extra <<< "${entry#*|}"
  dir=$base/build-config-$name
  log=$dir/configs.log
  mkdir -p "$dir"
  echo "== $name: ${extra[*]}"
  ok=1
  {
    cmake -S "$root" -B "$dir" "${common[@]}" "${extra[@]}" &&
      cmake --build "$dir" -j"$jobs" &&
      ctest --test-dir "$dir" --output-on-failure -j"$jobs" -E "$long_tests"
  } > "$log" 2>&1 || ok=0
  # Without threads the library must not start any (neither pthread_create nor std::thread's start among its imports).
  if [ $ok = 1 ] && [[ " ${extra[*]} " == *" -DLFEM_WITH_THREADS=OFF "* ]]; then
    if nm -D --undefined-only "$dir/liblfem.so" | grep -qE 'pthread_create|_M_start_thread'; then
      echo "liblfem.so still creates threads" >> "$log"
      ok=0
    fi
  fi
  # Without libccd the shared library must not depend on it.
  if [ $ok = 1 ] && [[ " ${extra[*]} " == *" -DLFEM_WITH_CCD=OFF "* ]]; then
    if readelf -d "$dir/liblfem.so" | grep -q 'libccd'; then
      echo "liblfem.so still links libccd" >> "$log"
      ok=0
    fi
  fi
  if [ $ok = 1 ]; then
    passed=$((passed + 1))
    echo "   passed: $(grep -E 'tests passed' "$log" | tail -1)"
  else
    failed=$((failed + 1))
    failed_names+=("$name")
    echo "   FAILED (log: $log); its end:"
    tail -n 30 "$log" | sed 's/^/   | /'
  fi
done

[ $failed -gt 0 ] && echo "failed: ${failed_names[*]}"
echo "configs: $passed passed, $failed failed"
[ $failed -eq 0 ]
