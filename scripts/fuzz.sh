#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang, ASan and UBSan into build-fuzz/ and runs each
# for SECONDS_PER_TARGET seconds (default 10: a minute for the six in CI; docs/reliability.md
# has the numbers of a longer run). New inputs go to build-fuzz/corpus/, the seeds in
# fuzz/corpus/ are only read. Exits non-zero when a target crashes, hangs or runs out of memory;
# the input that did it is in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
bash scripts/install-deps.sh clang libclang-rt-14-dev llvm-14
jobs=$(nproc 2>/dev/null || echo 2)
# The library itself is compiled with coverage instrumentation (fuzzer-no-link) and the
# sanitizers; only the fuzz targets link libFuzzer's main.
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DSTITCH_BUILD_FUZZERS=ON -DSTITCH_BUILD_APPS=OFF -DSTITCH_BUILD_TESTS=OFF \
  -DSTITCH_BUILD_RENDER=OFF -DSTITCH_BUILD_MODELER=OFF -DSTITCH_BUILD_BENCH=OFF \
  -DSTITCH_BUILD_PYTHON=OFF -DSTITCH_INSTALL=OFF >/dev/null
cmake --build build-fuzz -j"$jobs" --target fuzz-obj fuzz-off fuzz-ply fuzz-stl fuzz-gltf fuzz-operation
mkdir -p build-fuzz/findings
status=0
total=0
for target in obj off ply stl gltf operation; do
  corpus=build-fuzz/corpus/$target
  mkdir -p "$corpus"
  dict=fuzz/$target.dict
  log=build-fuzz/fuzz-$target.log
  # -timeout: an input taking 10 s is a finding (bounded everything); -rss_limit_mb likewise.
  if ! "build-fuzz/bin/fuzz-$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=8192 -dict="$dict" -print_final_stats=1 \
    -artifact_prefix="build-fuzz/findings/$target-" "$corpus" "fuzz/corpus/$target" >"$log" 2>&1; then
    status=1
    echo "fuzz.sh: fuzz-$target found a problem:" >&2
    grep -E "ERROR|SUMMARY|Test unit written|runtime error" "$log" >&2 || tail -20 "$log" >&2
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  total=$((total + ${runs:-0}))
  echo "fuzz.sh: fuzz-$target: ${runs:-0} inputs in ${seconds} s"
done
echo "fuzz.sh: $total inputs in all"
exit $status
