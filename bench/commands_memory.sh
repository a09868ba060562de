#!/usr/bin/env bash
# Wall time, CPU time and peak memory of the stitch commands on one large mesh, one process per
# command, as a user runs them (docs/performance.md, "Every command's peak memory").
#
#   bash bench/commands_memory.sh [M N] [RESOLUTION] [DIR]
#
# M x N: the torus `stitch primitive torus M N` (default 1000 x 1000: 1M quads); RESOLUTION:
# segments per patch side (default 8); DIR: where the input and the outputs go (default a new
# folder under /tmp, on the disk). Each output is deleted after its run, so the disk needs room
# for the largest one only (the .ply: about 17 GB at the defaults). Prints one line per command:
# wall seconds, user + system seconds, peak resident GB (GNU time's %e %U %S %M); each
# command's stderr is kept in DIR/NAME.err.
set -euo pipefail
cd "$(dirname "$0")/.."
m=${1:-1000}
n=${2:-1000}
resolution=${3:-8}
dir=${4:-$(mktemp -d /tmp/stitch-commands.XXXXXX)}
stitch=build/bin/stitch
[ -x "$stitch" ] || { echo "build stitch first: bash scripts/build.sh stitch-cli" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs GNU time (apt-get install time)" >&2; exit 1; }
mkdir -p "$dir"
input=$dir/torus_${m}x${n}.obj
[ -f "$input" ] || "$stitch" primitive torus "$m" "$n" -o "$input" >/dev/null

printf '%-11s %9s %9s %8s  %s\n' case wall_s cpu_s peak_GB command
run() {
  local name=$1
  shift
  local log=$dir/$name.time
  if ! /usr/bin/time -f '%e %U %S %M' -o "$log" "$@" >/dev/null 2>"$dir/$name.err"; then
    printf '%-11s failed: %s\n' "$name" "$(head -n 1 "$dir/$name.err")"
    return
  fi
  read -r wall user system kb <"$log"
  local command="stitch ${*:2}"
  printf '%-11s %9.1f %9.1f %8.2f  %s\n' "$name" "$wall" "$(echo "$user + $system" | bc)" \
    "$(echo "scale=2; $kb / 1048576" | bc)" "${command//$dir/DIR}"
}
run smooth.ply "$stitch" smooth "$input" -o "$dir/out.ply" --resolution "$resolution" -q
rm -f "$dir/out.ply"
# glTF as .gltf + .bin: a .glb holds at most 4 GB (its chunk lengths are 32-bit), less than the
# defaults' 12 GB; the writer is the same.
run smooth.gltf "$stitch" smooth "$input" -o "$dir/out.gltf" --resolution "$resolution" -q
rm -f "$dir/out.gltf" "$dir/out.bin"
run render "$stitch" render "$input" -o "$dir/out.png" --mode zebra --resolution "$resolution" -q
run analyze "$stitch" analyze "$input" -q
run compare "$stitch" compare "$input" -o "$dir/compare" --resolution "$resolution" -q
echo "input and pictures in $dir"
