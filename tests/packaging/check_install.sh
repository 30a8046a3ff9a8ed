#!/usr/bin/env bash
# ctest "install_find_package" / "install_pkg_config": install the build tree into a fresh
# prefix, check the installed header tree, then build and run the consumer in consumer/ the
# way a user would: through find_package(lfem) or through pkg-config.
#
# usage: check_install.sh find_package|pkg_config BUILD_DIR WORK_DIR LIBDIR INCLUDEDIR
#                         C_COMPILER CMAKE_COMMAND CMAKE_GENERATOR PKG_CONFIG
# LIBDIR and INCLUDEDIR are CMAKE_INSTALL_LIBDIR / CMAKE_INSTALL_INCLUDEDIR (relative).
# WORK_DIR is private to one test (so tests can run in parallel) and is wiped first.
set -euo pipefail
mode=$1 build=$2 work=$3 libdir=$4 includedir=$5 cc=$6 cmake=$7 generator=$8 pkg_config=$9
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
consumer_src="$here/consumer"

die() { echo "FAIL: $*"; exit 1; }
step() { echo "== $*"; }

case "$mode" in find_package|pkg_config) ;; *) die "unknown mode '$mode'";; esac
[[ "$libdir" != /* && "$includedir" != /* ]] ||
  die "CMAKE_INSTALL_LIBDIR/INCLUDEDIR must be relative to test an install with --prefix"

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
prefix="$work/prefix"

bash "$here/install_prefix.sh" "$cmake" "$build" "$prefix"

# ---- the installed header tree: lfem.h and the headers it includes (public_headers.sh), nothing
# else, and no Eigen or libccd in them ----------------------------------------------------------
step "installed headers under $includedir/"
[[ -f "$prefix/$includedir/lfem.h" ]] || die "no $includedir/lfem.h installed"
headers=$(cd "$prefix/$includedir" && find . -mindepth 1 | sed 's|^\./||' | LC_ALL=C sort)
sed 's/^/   /' <<< "$headers"
# A header lfem.h includes that was not installed makes public_headers.sh fail (set -e).
expected=$(bash "$here/public_headers.sh" "$prefix/$includedir/lfem.h" | xargs -n1 basename | LC_ALL=C sort)
[[ "$headers" == "$expected" ]] ||
  die "the installed header tree must hold lfem.h and what it includes ($(echo $expected)), found: $(echo $headers)"
for h in $headers; do
  if grep -nE '^[[:space:]]*#[[:space:]]*include.*(eigen|ccd)' -i "$prefix/$includedir/$h"; then
    die "the installed $h includes Eigen or libccd (above): they must stay private"
  fi
done

export LD_LIBRARY_PATH="$prefix/$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
exe="$work/consumer"

if [[ "$mode" == find_package ]]; then
  # ---- find_package(lfem) + lfem::lfem ------------------------------------------------------
  step "configure consumer/ with CMAKE_PREFIX_PATH=$prefix"
  "$cmake" -S "$consumer_src" -B "$work/consumer-build" -G "$generator" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="$cc" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF > "$work/configure.log" 2>&1 ||
    { cat "$work/configure.log"; die "configuring the find_package consumer failed"; }
  found=$(sed -n 's/^lfem_DIR:PATH=//p' "$work/consumer-build/CMakeCache.txt")
  echo "   lfem_DIR=$found"
  [[ "$found" == "$prefix"/* ]] || die "find_package(lfem) found '$found', not the package installed in $prefix"
  step "build consumer"
  "$cmake" --build "$work/consumer-build" --config Release > "$work/build.log" 2>&1 ||
    { cat "$work/build.log"; die "building the find_package consumer failed"; }
  exe=$(find "$work/consumer-build" -type f -name consumer -perm -u+x | head -n 1)
  [[ -n "$exe" ]] || die "consumer executable not found in $work/consumer-build"
else
  # ---- pkg-config --cflags --libs lfem ------------------------------------------------------
  export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
  step "pkg-config with PKG_CONFIG_PATH=$PKG_CONFIG_PATH"
  [[ -f "$PKG_CONFIG_PATH/lfem.pc" ]] || die "no lfem.pc installed in $libdir/pkgconfig"
  command -v "$pkg_config" > /dev/null || die "pkg-config not found ('$pkg_config')"
  cflags=$("$pkg_config" --cflags lfem) || die "pkg-config --cflags lfem failed"
  libs=$("$pkg_config" --libs lfem) || die "pkg-config --libs lfem failed"
  echo "   cflags: $cflags"
  echo "   libs:   $libs"
  # The flags must point into this prefix: lfem.pc has to stay valid wherever the install
  # tree is put (cmake --install --prefix), not name the prefix chosen at configure time.
  inc_ok=0 lib_ok=0
  for flag in $cflags; do
    [[ "$flag" == -I* && "$(cd "${flag#-I}" 2>/dev/null && pwd)" == "$prefix/$includedir" ]] && inc_ok=1
  done
  for flag in $libs; do
    [[ "$flag" == -L* && "$(cd "${flag#-L}" 2>/dev/null && pwd)" == "$prefix/$libdir" ]] && lib_ok=1
  done
  if [[ $inc_ok -eq 0 || $lib_ok -eq 0 ]]; then
    echo "installed lfem.pc:"; sed 's/^/   /' "$PKG_CONFIG_PATH/lfem.pc"
    die "lfem.pc does not point to the prefix it was installed in ($prefix): it is not relocatable"
  fi
  step "build consumer: $cc main.c \$(pkg-config --cflags --libs lfem)"
  # shellcheck disable=SC2086 # word splitting of the flags is wanted
  "$cc" "$consumer_src/main.c" $cflags $libs -o "$exe" > "$work/build.log" 2>&1 ||
    { cat "$work/build.log"; die "building the pkg-config consumer failed"; }
fi

step "run consumer with LD_LIBRARY_PATH=$prefix/$libdir"
# The consumer must load the installed library, not the one in the build tree.
if command -v ldd > /dev/null; then
  loaded=$(ldd "$exe" | sed -n 's/^[[:space:]]*liblfem\.so[^ ]* => \([^ ]*\) .*/\1/p')
  echo "   liblfem resolved to: $loaded"
  [[ "$loaded" == "$prefix/$libdir"/* ]] || die "the consumer does not load the installed liblfem"
fi
status=0
"$exe" || status=$?
[[ $status -eq 0 ]] || die "the consumer exited with status $status"
echo "OK: installed lfem builds and runs through $mode"
