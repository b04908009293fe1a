#!/bin/sh
# Runs a GUI test on the current X display, or under Xvfb when there is none: QOpenGLWidget
# needs a real (or virtual) X server, Qt 6.4's offscreen platform crashes on it.
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
  exec xvfb-run -a -s '-screen 0 1280x800x24' "$@"
fi
exec "$@"
