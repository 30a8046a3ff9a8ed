# Sourced by check_python.sh, check_rust.sh and check_csharp.sh, the out-of-tree tests: each takes
# the prefix that the ctest fixture bindings_install filled (tests/packaging/install_prefix.sh)
# and its libdir, copies a user's program out of the repository into a temporary folder, builds
# and runs it there as a user would, with the prefix given only through PKG_CONFIG_PATH.
# LD_LIBRARY_PATH is left unset on purpose (the prefix is not a system one, so a user might set
# it): each binding must find the installed library on its own.
set -euo pipefail
die() { echo "FAIL: $*"; exit 1; }
step() { echo "== $*"; }

outside=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bindings=$(dirname "$outside")
prefix=$1 libdir=$2
[[ -f "$prefix/$libdir/pkgconfig/lfem.pc" ]] ||
  die "no lfem installed in $prefix (the test bindings_install installs it)"
prefix=$(cd "$prefix" && pwd -P)

# Nothing of the build tree or of a developer's set-up reaches the user's program.
unset LFEM_LIBRARY LFEM_LIB_DIR PYTHONPATH MONO_PATH LD_LIBRARY_PATH CARGO_TARGET_DIR PKG_CONFIG_LIBDIR
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"

# The user's folder, outside the repository: removed after a pass, kept for a look after a failure.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lfem-outside.XXXXXX")
trap 'status=$?; if [[ $status -eq 0 ]]; then rm -rf "$tmp"; else echo "(the folder $tmp is kept)"; fi' EXIT
