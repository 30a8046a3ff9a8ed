#!/usr/bin/env bash
# Compile the C# bindings and their tests with mcs (every warning an error) and run them under
# mono; prints "N passed, N failed" and exits non-zero on any failure.
#
# usage: bindings/csharp/run_tests.sh [lib-dir [out-dir [mcs [mono]]]]
#   lib-dir  the folder holding liblfem.so (default: build/ at the repository root)
#   out-dir  where the .exe goes (default: <lib-dir>/bindings/csharp)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lib_dir=${1:-$here/../../build}
out_dir=${2:-$lib_dir/bindings/csharp}
mcs=${3:-mcs}
mono=${4:-mono}

mkdir -p "$out_dir"
"$mcs" -warn:4 -warnaserror+ -target:exe -out:"$out_dir/LfemTests.exe" \
  "$here/Lfem.cs" "$here/tests/LfemTests.cs"
# DllImport("lfem") resolves to liblfem.so through the loader path.
LD_LIBRARY_PATH="$lib_dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$mono" "$out_dir/LfemTests.exe"
