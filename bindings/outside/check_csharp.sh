#!/usr/bin/env bash
# ctest bindings_outside_csharp: csharp/DropCube.cs compiled with mcs -pkg:lfem-sharp outside
# the repository, Lfem.dll and its Lfem.dll.config (the dllmap to the installed liblfem.so.0)
# copied beside it as pkg-config names them, run under mono without LD_LIBRARY_PATH. The
# installed source Lfem.cs must compile on its own too.
#
# usage: check_csharp.sh PREFIX LIBDIR MCS MONO PKG_CONFIG
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
mcs=$3 mono=$4 pkg_config=$5
command -v "$mcs" > /dev/null || die "mcs not found ('$mcs')"
command -v "$mono" > /dev/null || die "mono not found ('$mono')"

cp "$outside/csharp/DropCube.cs" "$tmp/"
cd "$tmp"
step "PKG_CONFIG_PATH=$PKG_CONFIG_PATH mcs -pkg:lfem-sharp DropCube.cs"
"$mcs" -nologo -warn:4 -warnaserror+ -pkg:lfem-sharp -out:DropCube.exe DropCube.cs ||
  die "mcs -pkg:lfem-sharp failed"
assembly=$("$pkg_config" --variable=Libraries lfem-sharp) || die "pkg-config lfem-sharp failed"
echo "   Libraries: $assembly"
cp "$assembly" "$assembly.config" .
step "mono DropCube.exe"
"$mono" DropCube.exe || die "DropCube.exe failed"

step "mcs -target:library <prefix>/share/lfem/csharp/Lfem.cs"
"$mcs" -nologo -warn:4 -warnaserror+ -target:library -out:LfemFromSource.dll \
  "$prefix/share/lfem/csharp/Lfem.cs" || die "the installed Lfem.cs does not compile"
echo "OK: the C# program built and ran against the installed lfem"
