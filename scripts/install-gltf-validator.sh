#!/usr/bin/env bash
# Installs the Khronos glTF validator (npm package gltf-validator) into FOLDER/node_modules, for
# the test that validates every .glb stitch writes. Idempotent: does nothing when it is there.
# Needs node and npm (Debian: nodejs npm) and, the first time, the npm registry.
set -euo pipefail
folder=${1:?usage: install-gltf-validator.sh FOLDER}
version=2.0.0-dev.3.10
if [ -f "$folder/node_modules/gltf-validator/package.json" ]; then
  exit 0
fi
mkdir -p "$folder"
npm install --no-audit --no-fund --silent --prefix "$folder" "gltf-validator@$version" >&2
