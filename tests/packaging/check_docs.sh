#!/usr/bin/env bash
# The API reference builds without a single warning: Doxygen on the configuration the docs target
# uses (<build>/docs/Doxyfile, from include_c/Doxyfile.in), with its output and warning log moved
# into a folder of the test's own. An undocumented public function, type, enum value, struct
# field or macro, or a \param that names no parameter, fails it; the warnings are printed.
#
# usage: check_docs.sh DOXYGEN DOXYFILE WORK_DIR
set -euo pipefail
doxygen=${1:?usage: check_docs.sh DOXYGEN DOXYFILE WORK_DIR}
doxyfile=${2:?usage: check_docs.sh DOXYGEN DOXYFILE WORK_DIR}
work=${3:?usage: check_docs.sh DOXYGEN DOXYFILE WORK_DIR}

command -v "$doxygen" >/dev/null 2>&1 ||
  { echo "check_docs: doxygen not found ('$doxygen'): install it (.ci/install-deps.sh lists it)"; exit 1; }
[[ -r "$doxyfile" ]] || { echo "check_docs: cannot read $doxyfile (configure the build first)"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
log="$work/warnings.log"
echo "check_docs: $("$doxygen" --version | head -n1) on $doxyfile"
# A setting given twice takes its last value: the same configuration, written into $work.
status=0
{ cat "$doxyfile"; echo "OUTPUT_DIRECTORY = \"$work\""; echo "WARN_LOGFILE = \"$log\""; } |
  "$doxygen" - > "$work/doxygen.out" 2>&1 || status=$?
warnings=0
[[ -f "$log" ]] && warnings=$(grep -c . "$log" || true)
if [[ $status -ne 0 || $warnings -ne 0 ]]; then
  [[ -f "$log" ]] && cat "$log"
  cat "$work/doxygen.out"
  echo "check_docs: FAILED: doxygen exit status $status, $warnings warning line(s)"
  exit 1
fi
[[ -f "$work/html/index.html" ]] || { echo "check_docs: FAILED: no html/index.html"; exit 1; }
echo "check_docs: no warning; $(find "$work/html" -name '*.html' | wc -l) HTML pages in $work/html"
