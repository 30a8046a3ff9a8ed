#!/usr/bin/env bash
# The library on the other targets: cross-builds lfem for Windows x64 (MinGW-w64) and ARM64
# Linux, checks what each build is (the DLL exports exactly the LFEM_API functions and needs
# nothing but Windows' own DLLs; the ARM64 library exports the same list), then builds the
# plain-C program tests/platforms/platform_check.c for x86-64 Linux (against the main build),
# Windows and ARM64 and runs it natively, under Wine and under qemu-aarch64; the three must
# print the same figures (to 1e-12 relative, tests/platforms/compare_outputs.py), and each
# must print the same with the element kernel's baseline variant (LFEM_CPU_LEVEL=baseline) as
# with the one its CPU chose. Then the example falling_block on the three targets and
# clamped_beam under Wine, compared the same way. A missing toolchain or emulator fails.
# Part of the README's test command, after the main build. Ends with "platforms: passed".
#
#   bash tests/platforms.sh      (folders build-platforms/{linux,win64,arm64} beside build/, or
#                                 under LFEM_PLATFORMS_DIR; LFEM_PLATFORMS_JOBS sets -j, default 2)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=${LFEM_PLATFORMS_DIR:-$root}/build-platforms
jobs=${LFEM_PLATFORMS_JOBS:-2}
native=$root/build
here=$root/tests/platforms
python=/usr/bin/python3
wine=/usr/lib/wine/wine64          # Debian's wine64 package
wineserver=/usr/lib/wine/wineserver64
qemu=(qemu-aarch64 -L /usr/aarch64-linux-gnu -E LD_LIBRARY_PATH=/usr/aarch64-linux-gnu/lib)
started=$SECONDS
unset LFEM_CPU_LEVEL  # the first run of each program takes the variant the CPU chooses

fail() {
  echo "platforms: FAILED: $*" >&2
  exit 1
}
elapsed() { echo "$((SECONDS - started)) s"; }

# ---- the tools: each one missing is a failure, never a skip ------------------------------------
need() {  # need PROGRAM PACKAGE
  command -v "$1" >/dev/null 2>&1 || fail "$1 not found (Debian package $2; bash .ci/install-deps.sh installs it)"
}
need x86_64-w64-mingw32-gcc-posix gcc-mingw-w64-x86-64-posix
need x86_64-w64-mingw32-g++-posix g++-mingw-w64-x86-64-posix
need x86_64-w64-mingw32-objdump binutils-mingw-w64-x86-64
need "$wine" wine64
need aarch64-linux-gnu-gcc gcc-aarch64-linux-gnu
need aarch64-linux-gnu-g++ g++-aarch64-linux-gnu
need aarch64-linux-gnu-nm binutils-aarch64-linux-gnu
need qemu-aarch64 qemu-user
need cc gcc
need ninja ninja-build
need "$python" python3
[ -e /usr/lib/aarch64-linux-gnu/ccd/ccd-config.cmake ] ||
  fail "libccd for arm64 not found (dpkg --add-architecture arm64, Debian package libccd-dev:arm64; bash .ci/install-deps.sh does both)"
[ -f "$native/CMakeCache.txt" ] || fail "no main build in $native (run the test command's cmake steps first)"
cmake --build "$native" -j"$jobs" --target lfem > /dev/null || fail "the main build of the library failed"

mkdir -p "$work"

# ---- the cross builds: the library and two examples ------------------------------------------
cross_build() {  # cross_build NAME TOOLCHAIN [CMAKE OPTIONS...]
  local name=$1 toolchain=$2
  shift 2
  local dir=$work/$name t0=$SECONDS
  mkdir -p "$dir"
  if ! { cmake -G Ninja -S "$root" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/src/cmake/$toolchain" \
           -DCMAKE_BUILD_TYPE=Release -DLFEM_PRECOMPILE_HEADERS=ON "$@" &&
         cmake --build "$dir" -j"$jobs" --target lfem falling_block clamped_beam; } > "$dir/build.log" 2>&1; then
    tail -n 30 "$dir/build.log" | sed 's/^/   | /'
    fail "the $name build (log: $dir/build.log)"
  fi
  echo "platforms: $name: library built in $((SECONDS - t0)) s ($dir)"
}
# Ninja, not make: make compiles src/'s folders (object libraries) one after the other, so a
# folder's longest file leaves the other cores idle; Ninja compiles every folder's files at
# once. Eigen's headers precompiled (LFEM_PRECOMPILE_HEADERS): parsing them was half of each
# file's time, and these builds have no compiler cache to reuse.
cross_build win64 toolchain-mingw-w64-x86_64.cmake -DLFEM_WITH_CCD=OFF
cross_build arm64 toolchain-aarch64-linux-gnu.cmake

# ---- what the Windows DLL is ---------------------------------------------------------------------
win=$work/win64
dll=$win/bin/lfem.dll  # with the examples: Windows finds a program's DLLs beside it
[ -f "$dll" ] && [ -f "$win/liblfem.dll.a" ] && [ -f "$win/lfem.def" ] ||
  fail "the Windows build lacks lfem.dll, its import library liblfem.dll.a or lfem.def"
x86_64-w64-mingw32-objdump -p "$dll" > "$win/objdump.txt"
# The export table: exactly the LFEM_API functions of lfem.h (tests/packaging/exported_symbols.txt).
sed -n '/^\[Ordinal\/Name Pointer\] Table/,/^$/p' "$win/objdump.txt" |
  sed -nE 's/^[[:space:]]*\[[[:space:]]*[0-9]+\][[:space:]]+([^[:space:]]+)$/\1/p' | LC_ALL=C sort > "$win/exports.txt"
if ! diff -u "$root/tests/packaging/exported_symbols.txt" "$win/exports.txt" > "$win/exports.diff"; then
  cat "$win/exports.diff"
  fail "lfem.dll's exports differ from tests/packaging/exported_symbols.txt (- expected, + DLL)"
fi
# Its imports: Windows' own DLLs only (the C++ runtime, libgcc and winpthreads are linked in).
sed -nE 's/^[[:space:]]*DLL Name: (.*)$/\1/p' "$win/objdump.txt" > "$win/imports.txt"
foreign=$(grep -viE '^(kernel32|msvcrt|ucrtbase|advapi32|user32|shell32|ntdll)\.dll$|^api-ms-win-' "$win/imports.txt" || true)
[ -z "$foreign" ] || fail "lfem.dll needs DLLs that are not part of Windows: $foreign"
echo "platforms: win64: lfem.dll $(($(stat -c %s "$dll") / 1024)) KiB exports $(wc -l < "$win/exports.txt")" \
     "functions, all lfem_* and exactly lfem.h's; imports only $(paste -sd ' ' "$win/imports.txt")"

# ---- what the ARM64 library is -------------------------------------------------------------------
arm=$work/arm64
aarch64-linux-gnu-readelf -h "$arm/liblfem.so" | grep -q 'Machine:.*AArch64' || fail "liblfem.so of the arm64 build is not AArch64"
aarch64-linux-gnu-readelf -d "$arm/liblfem.so" | grep -q 'libccd' || fail "liblfem.so of the arm64 build does not link libccd"
bash "$root/tests/packaging/check_exported_symbols.sh" "$arm/liblfem.so" "$root/tests/packaging/exported_symbols.txt" \
  "$root/include_c/lfem.h" "$root/src/api/lfem.map" liblfem.so.0 aarch64-linux-gnu-nm aarch64-linux-gnu-readelf |
  sed 's/^/platforms: arm64: /'

# ---- the plain-C program, built as a game would build it: lfem.h and the library only --------------
flags=(-std=c99 -O2 -Wall -Wextra -pedantic -Werror -I"$root/include_c" "$here/platform_check.c")
mkdir -p "$work/linux"
cc "${flags[@]}" -L"$native" -llfem -lm -Wl,-rpath,"$native" -o "$work/linux/platform_check" ||
  fail "platform_check does not build for x86-64 Linux"
x86_64-w64-mingw32-gcc-posix "${flags[@]}" -L"$win" -llfem -o "$win/bin/platform_check.exe" ||
  fail "platform_check does not build for Windows"
aarch64-linux-gnu-gcc "${flags[@]}" -L"$arm" -llfem -lm -Wl,-rpath,"$arm" -o "$arm/platform_check" ||
  fail "platform_check does not build for ARM64"

# ---- run everything: natively, under Wine, under qemu --------------------------------------------
# Wine: a prefix of its own under the build tree (created on the first run, about 10 s), no
# debug chatter, no display needed for console programs.
export WINEPREFIX=$work/wineprefix WINEDEBUG=-all
run() {  # run TARGET OUTPUT PROGRAM [ARGS...]: in TARGET's run folder; stdout to OUTPUT
  local target=$1 out=$2
  shift 2
  local dir=$work/$target/run
  mkdir -p "$dir"
  local runner=()
  case $target in
    win64) runner=("$wine") ;;
    arm64) runner=("${qemu[@]}") ;;
  esac
  if ! (cd "$dir" && "${runner[@]}" "$@" > "$out" 2> "$out.stderr"); then
    cat "$out" "$out.stderr" | tail -n 30 | sed 's/^/   | /'
    fail "$target: $* failed"
  fi
}
out=$work/outputs
mkdir -p "$out"
t0=$SECONDS
run linux "$out/platform_check.linux.txt" "$work/linux/platform_check" hulls
LFEM_CPU_LEVEL=baseline run linux "$out/platform_check.linux.baseline.txt" "$work/linux/platform_check" hulls
run win64 "$out/platform_check.win64.txt" "$win/bin/platform_check.exe" no-hulls
LFEM_CPU_LEVEL=baseline run win64 "$out/platform_check.win64.baseline.txt" "$win/bin/platform_check.exe" no-hulls
run arm64 "$out/platform_check.arm64.txt" "$arm/platform_check" hulls
echo "platforms: platform_check ran on the three targets in $((SECONDS - t0)) s; x86-64 Linux printed:"
sed 's/^/   | /' "$out/platform_check.linux.txt"

# The kernel's instruction-set variants on one machine: the same bits.
for target in linux win64; do
  cmp -s "$out/platform_check.$target.txt" "$out/platform_check.$target.baseline.txt" ||
    fail "$target: the baseline kernel variant prints other results than the CPU's own" \
         "(diff $out/platform_check.$target.txt $out/platform_check.$target.baseline.txt)"
done
echo "platforms: x86-64 Linux and Windows print bit for bit the same with LFEM_CPU_LEVEL=baseline"

compare() {  # compare PROGRAM NAME=FILE...: the numbers of each to the first's, to 1e-12 relative
  local program=$1
  shift
  "$python" "$here/compare_outputs.py" "$@" | sed "s/^/platforms: $program: /" ||
    fail "the targets' $program outputs differ"
}
compare platform_check "x86-64 Linux=$out/platform_check.linux.txt" \
  "Windows x64 (Wine)=$out/platform_check.win64.txt" "ARM64 Linux (qemu)=$out/platform_check.arm64.txt"
grep -qx 'build convex hulls = LFEM_UNSUPPORTED: .*' <(tr -d '\r' < "$out/platform_check.win64.txt") ||
  fail "win64: convex hulls should answer LFEM_UNSUPPORTED (no libccd)"

# ---- the C examples where they are cheap -----------------------------------------------------------
t0=$SECONDS
run linux "$out/falling_block.linux.txt" "$native/examples_c/falling_block"
run win64 "$out/falling_block.win64.txt" "$win/bin/falling_block.exe"
run arm64 "$out/falling_block.arm64.txt" "$arm/examples_c/falling_block"
run linux "$out/clamped_beam.linux.txt" "$native/examples_c/clamped_beam"
run win64 "$out/clamped_beam.win64.txt" "$win/bin/clamped_beam.exe"
compare falling_block "x86-64 Linux=$out/falling_block.linux.txt" \
  "Windows x64 (Wine)=$out/falling_block.win64.txt" "ARM64 Linux (qemu)=$out/falling_block.arm64.txt"
compare clamped_beam "x86-64 Linux=$out/clamped_beam.linux.txt" "Windows x64 (Wine)=$out/clamped_beam.win64.txt"
echo "platforms: examples ran in $((SECONDS - t0)) s"

"$wineserver" -w  # this prefix's wineserver ends a few seconds after the last program: wait for it
echo "platforms: passed in $(elapsed)"
