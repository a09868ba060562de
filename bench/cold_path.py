#!/usr/bin/env python3
"""The cold path of issue 40: mesh -> Surface -> welded tessellation into new arrays (stitch)
against OpenSubdiv Bfr's tessellation of about the same point count with positions and normals,
each side in a fresh process (BM_cold_path runs one case once), interleaved over the three tori,
best of N rounds. Prints a table of wall and CPU seconds and the ratios of points per second,
stitch / Bfr (above 1: stitch faster), with the load average before the first run.

    python3 bench/cold_path.py [--faces 100000] [--rounds 3] [--bench build/bin/stitch-bench]
"""
import argparse
import json
import os
import subprocess

MESHES = {0: "quad torus", 1: "tris+quads torus", 2: "triangle torus"}
SIDES = {0: "stitch", 1: "Bfr"}


def run_case(bench, mesh, faces, side):
    name = f"BM_cold_path/mesh:{mesh}/faces:{faces}/bfr:{side}/iterations:1"
    out = subprocess.run(
        [bench, f"--benchmark_filter=^{name}$", "--benchmark_format=json"],
        check=True, capture_output=True, text=True).stdout
    runs = json.loads(out)["benchmarks"]
    if len(runs) != 1:
        raise SystemExit(f"{name}: expected one run, got {len(runs)}")
    return runs[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--faces", type=int, default=100000)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--bench", default="build/bin/stitch-bench")
    args = parser.parse_args()
    load = os.getloadavg()[0]
    best = {}
    for _ in range(args.rounds):
        for mesh in MESHES:
            for side in SIDES:
                r = run_case(args.bench, mesh, args.faces, side)
                key = (mesh, side)
                if key not in best or r["wall_s"] < best[key]["wall_s"]:
                    best[key] = r
    print(f"best of {args.rounds} fresh processes per side, {args.faces} faces, "
          f"load average {load:.2f} before the first")
    print("| mesh | stitch wall / CPU s | Bfr wall / CPU s | points stitch / Bfr "
          "| stitch / Bfr, wall | stitch / Bfr, CPU |")
    print("|---|---|---|---|---|---|")
    for mesh, label in MESHES.items():
        s, b = best[(mesh, 0)], best[(mesh, 1)]
        points = s["points"] / b["points"]
        print(f"| {label} | {s['wall_s']:.3f} / {s['cpu_s']:.3f} | {b['wall_s']:.3f} / "
              f"{b['cpu_s']:.3f} | {s['points'] / 1e6:.1f} M / {b['points'] / 1e6:.1f} M | "
              f"{points * b['wall_s'] / s['wall_s']:.2f} | {points * b['cpu_s'] / s['cpu_s']:.2f} |")


if __name__ == "__main__":
    main()
