#!/usr/bin/env bash
# Run the falling-block example in C, Rust, C# and Python and check that they print exactly the
# same lines (the same scene through four front ends of one library).
#
# usage: check_examples_agree.sh <c-example> <lib-dir> <work-dir> <cargo> <mcs> <mono> <python3>
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
c_example=$1 lib_dir=$2 work=$3 cargo=$4 mcs=$5 mono=$6 python=$7
mkdir -p "$work"

"$c_example" >"$work/c.txt"

LFEM_LIB_DIR="$lib_dir" CARGO_TARGET_DIR="$work/../cargo" \
  "$cargo" run --offline --quiet --manifest-path "$here/rust/Cargo.toml" -p lfem \
  --example falling_block >"$work/rust.txt"

"$mcs" -warn:4 -warnaserror+ -target:exe -out:"$work/FallingBlock.exe" \
  "$here/csharp/Lfem.cs" "$here/csharp/examples/FallingBlock.cs"
LD_LIBRARY_PATH="$lib_dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$mono" "$work/FallingBlock.exe" \
  >"$work/csharp.txt"

LFEM_LIBRARY="$lib_dir" PYTHONDONTWRITEBYTECODE=1 "$python" \
  "$here/python/examples/falling_block.py" >"$work/python.txt"

status=0
lines=$(wc -l <"$work/c.txt")
if [[ $lines -ne 5 ]]; then
  echo "the C example printed $lines lines, expected 5" >&2
  status=1
fi
for lang in rust csharp python; do
  if ! diff -u "$work/c.txt" "$work/$lang.txt"; then
    echo "the $lang example differs from the C one (diff above)" >&2
    status=1
  fi
done
cat "$work/c.txt"
[[ $status -eq 0 ]] && echo "C, Rust, C# and Python print the same $lines lines"
exit $status
