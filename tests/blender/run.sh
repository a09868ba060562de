#!/bin/sh
# Runs a test script inside Blender, headless:  run.sh SCRIPT ARGS...  (the script reads its
# arguments after "--"). Exits 77, which CTest counts as skipped, where blender is not installed.
if ! command -v blender >/dev/null 2>&1; then
  echo "blender is not installed (Debian: scripts/install-deps.sh installs it): skipped"
  exit 77
fi
script=$1
shift
exec blender -b --factory-startup --python-exit-code 1 --python "$script" -- "$@"
