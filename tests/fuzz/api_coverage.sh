#!/usr/bin/env bash
# Which exported lfem_* functions a fuzz_api harness calls on a set of inputs.
#   bash tests/fuzz/api_coverage.sh [BUILD] [HARNESS.cpp] [INPUT_DIR_OR_FILE...]
# BUILD (default build) holds liblfem.so (cmake --build build --target lfem); HARNESS defaults to
# tests/fuzz/fuzz_api.cpp and the inputs to tests/fuzz/corpus/api.
# The list of exported functions is read from the library (nm -D). A header generated from it
# is force-included into the harness (-include, not the library): it includes lfem.h and then
# defines each function's name as (note(k), name), so each call from the harness ticks a
# counter before the call is made (also through a conditional such as (q ? f : g)(...)). The
# harness, replayed over the inputs, prints which functions were called at least once.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build}"
harness="${2:-$root/tests/fuzz/fuzz_api.cpp}"
shift $(( $# >= 2 ? 2 : $# ))
inputs=("$@")
[ ${#inputs[@]} -eq 0 ] && inputs=("$root/tests/fuzz/corpus/api")
lib="$build/liblfem.so"
[ -f "$lib" ] || { echo "api_coverage: no $lib (build the lfem target first)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
nm -D --defined-only "$lib" | awk '$3 ~ /^lfem_/ {sub(/@.*/, "", $3); print $3}' | sort -u >"$work/exported"
{
  echo '#include "lfem.h"'
  echo '#include <cstdio>'
  echo 'namespace lfem_fuzz_count {'
  echo 'static const char* const names[] = {'
  sed 's/.*/  "&",/' "$work/exported"
  echo '};'
  echo 'static bool called[sizeof names / sizeof names[0]];'
  echo 'static inline void note(int k) { called[k] = true; }'
  echo 'static struct Report {'
  echo '  ~Report() {'
  echo '    std::FILE* f = std::fopen(LFEM_FUZZ_COUNT_OUT, "w");'
  echo '    if (!f) return;'
  echo '    for (unsigned k = 0; k < sizeof names / sizeof names[0]; ++k)'
  echo '      std::fprintf(f, "%d %s\n", called[k] ? 1 : 0, names[k]);'
  echo '    std::fclose(f);'
  echo '  }'
  echo '} report;'
  echo '}  // namespace lfem_fuzz_count'
  awk '{printf "#define %s (lfem_fuzz_count::note(%d), %s)\n", $1, NR - 1, $1}' "$work/exported"
} >"$work/count_calls.h"
${CXX:-g++} -std=c++17 -O1 -w -I"$root/include_c" -I"$root/tests" \
  -DLFEM_FUZZ_COUNT_OUT="\"$work/called\"" -include "$work/count_calls.h" \
  "$harness" "$root/tests/fuzz/replay_main.cpp" -L"$build" -llfem -Wl,-rpath,"$build" \
  -o "$work/replay" -pthread 2>"$work/compile.log" || { head -n 30 "$work/compile.log" >&2; exit 1; }
"$work/replay" "${inputs[@]}" >/dev/null
total=$(wc -l <"$work/exported")
reached=$(grep -c '^1 ' "$work/called" || true)
echo "called at least once: $reached of $total exported functions"
echo "never called:"
grep '^0 ' "$work/called" | sed 's/^0 /  /'
