#!/usr/bin/env bash
# The main job on a bundled example: installs what is needed, builds, and smooths the cube with
# a hole through it (one edge inserted between two opposite faces) into out/cube_hole_smooth.obj.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh stitch-cli
mkdir -p out
build/bin/stitch info examples/cube_hole.obj
build/bin/stitch smooth examples/cube_hole.obj -o out/cube_hole_smooth.obj --resolution 8
build/bin/stitch analyze examples/cube_hole.obj
echo "The smooth surface is in $(pwd)/out/cube_hole_smooth.obj"
