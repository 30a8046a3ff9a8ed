#!/usr/bin/env bash
# ctest bindings_outside_python: python/drop_cube.py against the installed lfem, twice: with the
# package pip installs into a venv (--system-site-packages for Debian's numpy, no network), found
# through PKG_CONFIG_PATH; and with the package cmake --install put under the prefix, found
# through PYTHONPATH, which loads the library of its own prefix with no other variable.
#
# usage: check_python.sh PREFIX LIBDIR PYTHONDIR PYTHON3   (LIBDIR, PYTHONDIR: relative to PREFIX)
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
pythondir=$3 python=$4
command -v "$python" > /dev/null || die "python3 not found ('$python')"

# Prints the package's file and the library it loaded; both must lie under $2.
check_loaded() {
  local interpreter=$1 under=$2 where
  where=$("$interpreter" -c 'import os, lfem; print(os.path.realpath(lfem.__file__)); print(os.path.realpath(lfem.library_path))') ||
    die "import lfem failed"
  sed 's/^/   loaded /' <<< "$where"
  [[ "$(sed -n 1p <<< "$where")" == "$under"/* ]] || die "lfem imported from outside $under"
  [[ "$(sed -n 2p <<< "$where")" == "$prefix/$libdir"/* ]] || die "liblfem loaded from outside $prefix/$libdir"
}

step "python3 -m venv --system-site-packages $tmp/venv"
"$python" -m venv --system-site-packages "$tmp/venv" || die "python3 -m venv failed (python3-venv)"
# pip builds in the source folder: it gets a copy of the package, as from a download.
cp -r "$bindings/python" "$tmp/lfem-python"
rm -rf "$tmp/lfem-python/tests" "$tmp/lfem-python/build" "$tmp/lfem-python"/*.egg-info
step "pip install --no-index --no-build-isolation lfem-python"
PIP_DISABLE_PIP_VERSION_CHECK=1 "$tmp/venv/bin/python" -m pip install --no-index \
  --no-build-isolation --no-cache-dir "$tmp/lfem-python" > "$tmp/pip.log" 2>&1 ||
  { cat "$tmp/pip.log"; die "pip install failed"; }
sed 's/^/   /' "$tmp/pip.log" | tail -n 1
requires=$("$tmp/venv/bin/python" -m pip show lfem | sed -n 's/^Requires: //p')
echo "   pip show lfem: Requires: $requires"
[[ "$requires" == *numpy* ]] || die "the installed lfem does not declare numpy"

cp "$outside/python/drop_cube.py" "$tmp/"
cd "$tmp"
step "venv: PKG_CONFIG_PATH=$PKG_CONFIG_PATH python drop_cube.py"
check_loaded "$tmp/venv/bin/python" "$(cd "$tmp/venv" && pwd -P)"
"$tmp/venv/bin/python" drop_cube.py || die "drop_cube.py failed (pip's package)"

step "cmake --install's package: PYTHONPATH=$prefix/$pythondir python3 drop_cube.py"
unset PKG_CONFIG_PATH
export PYTHONPATH="$prefix/$pythondir"
check_loaded "$python" "$prefix/$pythondir"
"$python" drop_cube.py || die "drop_cube.py failed (cmake --install's package)"
echo "OK: the Python program ran against the installed lfem, from pip's and from cmake's package"
