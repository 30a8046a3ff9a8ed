#!/bin/sh
# The playground's ctest: renders FRAMES frames offscreen under xvfb-run (Xvfb with Mesa's
# software OpenGL, no display or GPU needed), then decodes the PNG written and checks that it
# shows the scene (check_screenshot.py). With --blank the program only clears its frames and
# the check must call the result blank: the check's own test, so that it is seen to fail on an
# all-one-colour image.
#
#   headless_test.sh PLAYGROUND CHECKER PYTHON OUT.png FRAMES [--blank]
set -eu
playground=$1 checker=$2 python=$3 out=$4 frames=$5
rm -f "$out"
if [ "${6:-}" = "--blank" ]; then
  xvfb-run -a -s "-screen 0 1280x720x24" "$playground" --headless "$frames" "$out" --blank
  exec "$python" "$checker" --expect-blank "$out"
fi
xvfb-run -a -s "-screen 0 1280x720x24" "$playground" --headless "$frames" "$out"
exec "$python" "$checker" "$out"
