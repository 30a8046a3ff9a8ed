#!/usr/bin/env bash
# Install the build and test dependencies of lfem on Debian 12 (bookworm).
#
# Idempotent and non-interactive: only packages that are not installed yet are installed, and
# `apt-get update` runs only when something is missing. Runs apt-get directly as root, through
# sudo otherwise. Prints one summary line on success; on failure, apt-get's output.
#
# To add a dependency, add its Debian package name to PACKAGES below (nothing else to change).
set -euo pipefail

PACKAGES=(
  # C/C++ toolchain and build system
  g++
  cmake
  make
  pkg-config
  # compiler cache (used by CMakeLists.txt when found): tests/configs.sh builds the reduced
  # configurations mostly from the objects of the main build
  ccache
  # libraries the library itself builds against (linked privately into liblfem.so)
  libeigen3-dev
  libccd-dev
  # test framework
  libgtest-dev
  # the API reference from the public headers (the docs target; ctest's api_docs fails on any
  # Doxygen warning, such as an undocumented function or struct field)
  doxygen
  # language bindings (bindings/): Rust (cargo test --offline, no crate downloaded), C# (mcs,
  # run under mono; these two pull the mono class libraries the bindings use), Python (the
  # system python3 with numpy and pytest; venv, setuptools and wheel for the out-of-tree test's
  # pip install --no-index --no-build-isolation into a venv)
  rustc
  cargo
  mono-mcs
  mono-runtime
  python3-numpy
  python3-pytest
  python3-venv
  python3-setuptools
  python3-wheel
  # the interactive example (examples_c/playground): SDL2 and OpenGL headers; its ctest renders
  # offscreen under xvfb-run (xvfb, and xauth which xvfb-run needs but xvfb only recommends)
  # with Mesa's software OpenGL (llvmpipe: libglx-mesa0, libgl1-mesa-dri), no display or GPU
  libsdl2-dev
  libgl-dev
  xvfb
  xauth
  libglx-mesa0
  libgl1-mesa-dri
  # fuzzing (tests/fuzz/run.sh): clang with libFuzzer and the sanitizer runtimes
  clang-14
  libclang-rt-14-dev
  # the other targets (tests/platforms.sh): Windows x64 cross-built with MinGW-w64 (posix
  # threads, for std::thread; the cross builds use Ninja) and run under Wine (wine64: console programs need no display);
  # ARM64 Linux cross-built and run under qemu-user, against Debian's arm64 libccd through
  # multiarch (a package named PKG:ARCH makes this script add the architecture ARCH first)
  g++-mingw-w64-x86-64-posix
  ninja-build
  wine64
  g++-aarch64-linux-gnu
  qemu-user
  libccd-dev:arm64
)

export DEBIAN_FRONTEND=noninteractive
me="install-deps"

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "$me: error: dpkg-query/apt-get not found; this script supports Debian 12 only." >&2
  exit 1
fi

is_installed() {
  local status
  status=$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null) || return 1
  # "<want> <flag> <status>": the status word must be exactly "installed"
  # (not "half-installed", "not-installed", "config-files", ...).
  [[ "$status" == *" installed" ]]
}

missing=()
for pkg in "${PACKAGES[@]}"; do
  is_installed "$pkg" || missing+=("$pkg")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "$me: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

# Root runs apt-get directly; anyone else needs sudo (passwordless in CI; a password prompt is
# only allowed when a terminal is attached).
if [[ $(id -u) -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  as_root=(sudo -n DEBIAN_FRONTEND=noninteractive)
elif command -v sudo >/dev/null 2>&1 && [[ -t 0 ]]; then
  as_root=(sudo DEBIAN_FRONTEND=noninteractive)
else
  echo "$me: error: missing packages: ${missing[*]}" >&2
  echo "$me: error: installing them needs root or sudo (passwordless when not on a terminal);" \
       "run this script as root, or install them yourself:" >&2
  echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
  echo "(a package named PKG:ARCH needs dpkg --add-architecture ARCH before that)" >&2
  exit 1
fi

log=$(mktemp "${TMPDIR:-/tmp}/install-deps.XXXXXX")
trap 'rm -f "$log"' EXIT

run() {
  if ! "${as_root[@]}" "$@" >>"$log" 2>&1; then
    cat "$log" >&2
    echo "$me: error: '$*' failed (output above)" >&2
    exit 1
  fi
}

# Multiarch: a missing PKG:ARCH needs ARCH among dpkg's architectures before apt-get update.
for pkg in "${missing[@]}"; do
  [[ "$pkg" == *:* ]] || continue
  arch=${pkg##*:}
  if [[ "$arch" != "$(dpkg --print-architecture)" ]] &&
     ! dpkg --print-foreign-architectures | grep -qx "$arch"; then
    run dpkg --add-architecture "$arch"
  fi
done

# --no-install-recommends keeps fresh images lean; every package listed above builds and runs
# without its recommends (list a recommended package explicitly if it is ever needed).
run apt-get update -q
run apt-get install -y -q --no-install-recommends "${missing[@]}"

still_missing=()
for pkg in "${missing[@]}"; do
  is_installed "$pkg" || still_missing+=("$pkg")
done
if [[ ${#still_missing[@]} -ne 0 ]]; then
  cat "$log" >&2
  echo "$me: error: still not installed after apt-get: ${still_missing[*]}" >&2
  exit 1
fi

echo "$me: installed ${#missing[@]} of ${#PACKAGES[@]} packages: ${missing[*]}"
