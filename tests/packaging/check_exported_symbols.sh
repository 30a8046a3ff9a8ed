#!/usr/bin/env bash
# ctest "exported_symbols": the dynamic symbols liblfem.so defines are exactly the committed
# list tests/packaging/exported_symbols.txt (itself exactly the LFEM_API functions of lfem.h),
# all start with lfem_, and the SONAME is the expected one.
#
# usage: check_exported_symbols.sh LIBRARY EXPECTED_LIST HEADER VERSION_SCRIPT SONAME [NM] [READELF]
set -euo pipefail
lib=$1 expected=$2 header=$3 map=$4 soname=$5
nm=${6:-nm} readelf=${7:-readelf}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
regen="bash tests/packaging/header_symbols.sh include_c/lfem.h > tests/packaging/exported_symbols.txt"
export LC_ALL=C
fail=0
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lfem-symbols.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# 1. The committed list is up to date with the header.
bash "$here/header_symbols.sh" "$header" > "$tmp/header.txt"
if ! diff -u "$expected" "$tmp/header.txt" > "$tmp/header.diff"; then
  echo "FAIL: exported_symbols.txt differs from the LFEM_API functions of lfem.h" \
       "(- committed list, + header):"
  cat "$tmp/header.diff"
  echo "If the API change is intended, regenerate the list from the repository root:"
  echo "  $regen"
  fail=1
fi

# 2. What the shared object defines, as names only. nm prints "ADDRESS TYPE NAME[@@VERSION]".
# The version script's node names (LFEM_0, ...) appear as absolute (A) symbols: they are the
# symbol version definitions, not functions, so they (and only they) are filtered out here.
version_nodes=$(sed -nE 's/^[[:space:]]*([A-Za-z_][A-Za-z0-9_.]*)[[:space:]]*\{.*/\1/p' "$map")
"$nm" -D --defined-only "$lib" > "$tmp/nm.txt"
awk -v nodes="$version_nodes" '
  BEGIN { n = split(nodes, list, /[ \t\n]+/); for (i = 1; i <= n; i++) if (list[i] != "") node[list[i]] = 1 }
  NF >= 2 {
    name = $NF; type = $(NF - 1)
    sub(/@.*/, "", name)
    if (type == "A" && (name in node)) next
    print name
  }
' "$tmp/nm.txt" | sort -u > "$tmp/library.txt"

if ! diff -u "$expected" "$tmp/library.txt" > "$tmp/library.diff"; then
  echo "FAIL: the dynamic symbols defined by $(basename "$lib") differ from exported_symbols.txt" \
       "(- expected, + library):"
  cat "$tmp/library.diff"
  echo "A '-' line is declared in lfem.h but not defined (or not exported) by the library;"
  echo "a '+' line leaks from the library without being part of the API."
  fail=1
fi

# 3. Nothing but the C API: every exported name starts with lfem_.
if grep -v '^lfem_' "$tmp/library.txt" > "$tmp/foreign.txt"; then
  echo "FAIL: exported names that do not start with lfem_:"
  cat "$tmp/foreign.txt"
  fail=1
fi
if [[ ! -s "$tmp/library.txt" ]]; then
  echo "FAIL: $(basename "$lib") exports no symbol at all"
  fail=1
fi

# 4. SONAME.
actual_soname=$("$readelf" -d "$lib" | sed -nE 's/.*\(SONAME\).*\[(.*)\].*/\1/p')
if [[ "$actual_soname" != "$soname" ]]; then
  echo "FAIL: SONAME of $(basename "$lib") is '${actual_soname}', expected '$soname'"
  fail=1
fi

if [[ $fail -eq 0 ]]; then
  echo "OK: $(wc -l < "$tmp/library.txt") symbols exported, all lfem_*, matching exported_symbols.txt; SONAME $actual_soname"
fi
exit $fail
