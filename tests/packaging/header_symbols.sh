#!/usr/bin/env bash
# Print, sorted (C locale) and one per line, the names of the functions that lfem.h declares
# with LFEM_API, in it and in the project headers it includes (public_headers.sh;
# "lfem_types.h" holds the *_default functions): the dynamic symbols liblfem.so must export, no
# more, no less.
#
# Regenerate the committed list after an API change (from the repository root):
#   bash tests/packaging/header_symbols.sh include_c/lfem.h > tests/packaging/exported_symbols.txt
#
# Convention relied on: every exported declaration starts a line with LFEM_API, and the
# function name is the identifier right before the first "(" (on that line or a following
# one). Preprocessor lines (#define LFEM_API ...) are not declarations and are skipped.
set -euo pipefail
header=${1:?usage: header_symbols.sh path/to/lfem.h}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
list=$(bash "$here/public_headers.sh" "$header")
mapfile -t headers <<< "$list"
awk '
  FNR == 1 { collecting = 0 }
  /^[ \t]*LFEM_API[ \t]/ { decl = ""; collecting = 1 }
  collecting {
    decl = decl " " $0
    if (index(decl, "(") > 0) {
      sub(/[ \t]*\(.*/, "", decl)
      n = split(decl, words, /[^A-Za-z0-9_]+/)
      print words[n]
      collecting = 0
    }
  }
' "${headers[@]}" | LC_ALL=C sort -u
