#!/usr/bin/env bash
# Regenerates the Hertz benchmark's sphere meshes with Gmsh (a benchmark-only tool, Debian
# package gmsh; nothing at build or test time needs it: the meshes are committed). Each file is
# named by its element kind and its element size at the pole in tenths of a millimetre.
set -euo pipefail
cd "$(dirname "$0")"
mesh() {  # name order lc_min (m)
  gmsh -3 hertz_sphere.geo -setnumber order "$2" -setnumber lc_min "$3" \
       -setnumber lc_max "$(awk "BEGIN { print 10 * $3 }")" -format msh41 -o "$1.msh" > /dev/null
  echo "$1.msh: $(grep -c . "$1.msh") lines"
}
mesh hertz_tet4_10 1 0.001
mesh hertz_tet4_07 1 0.0007
mesh hertz_tet4_05 1 0.0005
mesh hertz_tet10_20 2 0.002
mesh hertz_tet10_15 2 0.0015
mesh hertz_tet10_10 2 0.001
