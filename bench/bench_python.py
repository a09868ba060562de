#!/usr/bin/env python3
"""surface.tessellate called from Python against the same C++ call timed inside the module
(Surface._time_tessellate: tessellate() alone, result discarded), on a torus of about 100k quads.

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [--grid 316] [--resolution 8]

The Python figure covers the call and taking the arrays (vertices, quads, normals; uvs and
patches empty unless asked); freeing the result is outside both timings. The two are
interleaved so that drift of a shared machine affects both alike; medians are compared.
"""
import argparse
import gc
import statistics
import time

import stitch


def python_call(surface, resolution, welded):
    start = time.perf_counter()
    t = surface.tessellate(resolution, welded)
    arrays = (t.vertices, t.quads, t.normals)
    elapsed = time.perf_counter() - start
    del arrays, t
    return elapsed


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--grid", type=int, default=316, help="torus of GRID x GRID quads")
    parser.add_argument("--resolution", type=int, default=8)
    parser.add_argument("--method", default="mdc", choices=["mdc", "asc", "cc"])
    parser.add_argument("--unwelded", action="store_true")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    welded = not args.unwelded

    mesh = stitch.primitive("torus", args.grid, args.grid)
    surface = stitch.Surface(mesh, args.method)
    surface._time_tessellate(args.resolution, welded)  # warm-up: the allocator's first touch
    cpp, python = [], []
    for _ in range(args.repeats):
        gc.collect()
        cpp.append(surface._time_tessellate(args.resolution, welded))
        gc.collect()
        python.append(python_call(surface, args.resolution, welded))

    t = surface.tessellate(args.resolution, welded)
    print(f"torus {args.grid} x {args.grid}: {mesh.num_faces} faces, {mesh.num_patches} patches; "
          f"method {args.method}, resolution {args.resolution}, "
          f"{'welded' if welded else 'unwelded'}: {len(t.vertices)} vertices, {len(t.quads)} quads")
    del t
    for name, times in [("C++ tessellate()", cpp), ("Python surface.tessellate()", python)]:
        print(f"{name:<28} median {statistics.median(times):.3f} s, min {min(times):.3f} s, "
              f"max {max(times):.3f} s ({len(times)} runs)")
    ratio = statistics.median(python) / statistics.median(cpp)
    print(f"Python / C++ (medians): {ratio:.3f}")


if __name__ == "__main__":
    main()
