#!/usr/bin/env bash
# Installs what is needed, builds everything and runs the whole test suite: the core suite again
# under ASan+UBSan (build-asan/), a minute of fuzzing the readers and the operation parser
# (build-fuzz/), then every test of the normal build (C++, Python, packaging) with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
# The Khronos glTF validator, for the test that validates every .glb (the test skips without node).
if command -v npm >/dev/null 2>&1; then
  bash scripts/install-gltf-validator.sh build/gltf-validator
fi
bash scripts/sanitize.sh
bash scripts/fuzz.sh
cd build
ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" --timeout 600
