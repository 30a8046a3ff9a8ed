#!/usr/bin/env bash
# Installs a build tree into a fresh prefix the way a user would (cmake --install BUILD --prefix
# PREFIX) and prints what went where. Shared by check_install.sh (the C consumer) and the
# bindings' out-of-tree tests (bindings/outside/, the ctest fixture bindings_install).
#
# usage: install_prefix.sh CMAKE_COMMAND BUILD_DIR PREFIX     (PREFIX is wiped first)
set -euo pipefail
cmake=$1 build=$2 prefix=$3

rm -rf "$prefix"
mkdir -p "$prefix"
echo "== cmake --install $build --prefix $prefix"
log=$(mktemp "${TMPDIR:-/tmp}/lfem-install.XXXXXX")
trap 'rm -f "$log"' EXIT
if ! "$cmake" --install "$build" --prefix "$prefix" >"$log" 2>&1; then
  cat "$log"
  echo "FAIL: cmake --install failed"
  exit 1
fi
sed 's/^/   /' "$log"
