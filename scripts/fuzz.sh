#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang, ASan and UBSan into build-fuzz/ and runs them.
#
#   scripts/fuzz.sh            CI: each target for a fixed number of inputs from a fixed seed,
#                              starting from the seeds in fuzz/corpus/ only, so that every run
#                              tries the same inputs (about ten seconds a target on 2 cores).
#   scripts/fuzz.sh SECONDS    exploring: each target for SECONDS seconds from a random seed,
#                              growing build-fuzz/corpus/ from run to run (docs/reliability.md
#                              has the numbers of a longer run).
#
# Exits non-zero when a target crashes, hangs (10 s on one input) or runs out of memory; the
# input that did it is in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-}
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
# Inputs per target in CI: about ten seconds each on 2 cores.
declare -A ci_runs=([obj]=150000 [off]=300000 [ply]=200000 [stl]=250000 [gltf]=80000
  [operation]=20000)
# A fixed seed alone does not repeat a run: libFuzzer mutates with the values the code compares,
# pointers among them, so address randomisation changes the inputs. Without it (setarch -R) and
# without corpus reloading (-reload=0) two CI runs try the same inputs.
same_addresses=()
if [[ -z "$seconds" ]] && setarch "$(uname -m)" -R true 2>/dev/null; then
  same_addresses=(setarch "$(uname -m)" -R)
fi
for target in obj off ply stl gltf operation; do
  if [[ -z "$seconds" ]]; then
    corpus=build-fuzz/ci-corpus/$target
    rm -rf "$corpus"
    budget=(-seed=1 -runs="${ci_runs[$target]}" -reload=0)
  else
    corpus=build-fuzz/corpus/$target
    budget=(-max_total_time="$seconds")
  fi
  mkdir -p "$corpus"
  dict=fuzz/$target.dict
  log=build-fuzz/fuzz-$target.log
  started=$SECONDS
  # -timeout: an input taking 10 s is a finding (bounded everything); -rss_limit_mb likewise.
  if ! "${same_addresses[@]}" "build-fuzz/bin/fuzz-$target" "${budget[@]}" -timeout=10 -rss_limit_mb=2048 \
    -max_len=8192 -dict="$dict" -print_final_stats=1 \
    -artifact_prefix="build-fuzz/findings/$target-" "$corpus" "fuzz/corpus/$target" >"$log" 2>&1; then
    status=1
    echo "fuzz.sh: fuzz-$target found a problem:" >&2
    grep -E "ERROR|SUMMARY|Test unit written|runtime error" "$log" >&2 || tail -20 "$log" >&2
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  total=$((total + ${runs:-0}))
  echo "fuzz.sh: fuzz-$target: ${runs:-0} inputs in $((SECONDS - started)) s"
done
echo "fuzz.sh: $total inputs in all"
exit $status
