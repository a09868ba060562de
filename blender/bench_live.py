"""How long a live update takes: a torus of 10k quads, live at each resolution, one vertex moved
in edit mode at a time, timed three ways: stitch's IncrementalSurface.update_positions alone; the
add-on's whole update (reading the edit mesh, stitch, writing the smooth mesh); and Blender's
whole depsgraph update around it (which also evaluates the 16 resolution^2 x 10k-quad mesh).

    STITCH_PYTHON_DIR=build/python blender -b --factory-startup --python blender/bench_live.py \\
        -- [RESOLUTION ...] [--moves N]
"""

import pathlib
import statistics
import sys
import time

import addon_utils
import bmesh
import bpy

args = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
moves = 20
if "--moves" in args:
    at = args.index("--moves")
    moves = int(args[at + 1])
    del args[at : at + 2]
resolutions = [int(a) for a in args] or [2, 4]
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
addon_utils.enable("stitch_addon", default_set=True)
from stitch_addon import smooth  # noqa: E402

bpy.ops.mesh.primitive_torus_add(major_segments=100, minor_segments=100)
obj = bpy.context.object


def ms(values):
    return (
        f"median {statistics.median(values):6.1f} ms (min {min(values):.1f}, max {max(values):.1f})"
    )


for n in resolutions:
    bpy.ops.object.mode_set(mode="OBJECT")
    obj.stitch.resolution = n
    start = time.perf_counter()
    obj.stitch.live = False
    obj.stitch.live = True  # smooths and makes the live surface
    built = time.perf_counter() - start
    live = smooth.LIVE[obj.as_pointer()]
    bpy.ops.object.mode_set(mode="EDIT")
    stitch_ms, addon_ms, blender_ms, patches = [], [], [], []
    for k in range(moves):
        bm = bmesh.from_edit_mesh(obj.data)
        bm.verts.ensure_lookup_table()
        bm.verts[
            (k * 997) % len(bm.verts)
        ].co.z += 0.01  # spread over the torus, the same every run
        bmesh.update_edit_mesh(obj.data)
        start = time.perf_counter()
        bpy.context.view_layer.update()
        blender_ms.append(1000 * (time.perf_counter() - start))
        addon_ms.append(1000 * live.seconds)
        stitch_ms.append(1000 * live.stitch_seconds)
        patches.append(live.recomputed)
    quads = len(obj.stitch.target.data.polygons)
    print(
        f"resolution {n}: {quads} quads, smoothed and made live in {built:.2f} s; "
        f"{statistics.median(patches):.0f} patches per move"
    )
    print(f"  stitch update_positions        {ms(stitch_ms)}")
    print(f"  add-on update (read, stitch, write) {ms(addon_ms)}")
    print(f"  Blender depsgraph update       {ms(blender_ms)}")
bpy.ops.object.mode_set(mode="OBJECT")
