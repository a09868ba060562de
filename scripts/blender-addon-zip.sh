#!/usr/bin/env bash
# Packs the Blender add-on (blender/stitch_addon) into a zip for Blender's Preferences > Add-ons >
# Install:  scripts/blender-addon-zip.sh [BUILD_DIR [ZIP]]  (default build/, BUILD_DIR/stitch_addon.zip).
# The zip records BUILD_DIR/python, where `cmake --build BUILD_DIR --target stitch_python` puts the
# module, as the folder the add-on loads it from unless its preference or $STITCH_PYTHON_DIR
# names another (docs/blender.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
zip=$(realpath -m "${2:-$build/stitch_addon.zip}")
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
cp -r "$root/blender/stitch_addon" "$stage/"
find "$stage" -name __pycache__ -prune -exec rm -rf {} +
echo "$build/python" >"$stage/stitch_addon/build_dir.txt"
if ! compgen -G "$build/python/stitch*.so" >/dev/null; then
  echo "note: no stitch module in $build/python yet: cmake --build $build --target stitch_python" >&2
fi
rm -f "$zip"
(cd "$stage" && python3 -m zipfile -c "$zip" stitch_addon)
echo "$zip"
