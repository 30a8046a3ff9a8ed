#!/usr/bin/env bash
# Print the public headers a program that includes lfem.h reads: the given lfem.h, then every
# project header reached through quoted includes ("lfem_types.h"), each once, in the order
# first met, as paths beside lfem.h. System includes (<stdint.h>) are not followed. Serves the
# exported-symbols list (header_symbols.sh) and the check of the installed header tree
# (check_install.sh), so both read the same set.
#
# usage: public_headers.sh path/to/lfem.h
set -euo pipefail
top=${1:?usage: public_headers.sh path/to/lfem.h}
[[ -r "$top" ]] || { echo "public_headers.sh: cannot read $top" >&2; exit 1; }
dir=$(dirname "$top")
queue=("$(basename "$top")")
declare -A seen=()
while ((${#queue[@]} > 0)); do
  name=${queue[0]}
  queue=("${queue[@]:1}")
  [[ -n "${seen[$name]:-}" ]] && continue
  seen[$name]=1
  [[ -r "$dir/$name" ]] || { echo "public_headers.sh: \"$name\" is included but not found in $dir" >&2; exit 1; }
  echo "$dir/$name"
  while read -r included; do
    queue+=("$included")
  done < <(sed -nE 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/p' "$dir/$name")
done
