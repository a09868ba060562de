"""The Blender add-on (blender/stitch_addon), inside Blender:

    blender -b --factory-startup --python-exit-code 1 --python test_addon.py -- CLI WORK_DIR

with STITCH_PYTHON_DIR naming the build's python/ folder. Meshes are made with bpy, smoothed with
the add-on's operator and compared with what `stitch smooth` writes for the same mesh (written
as OBJ with its crease tags and texture coordinates): vertex counts, positions to 1e-6 (Blender
stores float32), UVs, creases, materials, the exact export, errors as reports, live updates."""

import json
import math
import pathlib
import re
import subprocess
import sys
import time

import addon_utils
import bmesh
import bpy
import numpy as np

CLI, WORK = sys.argv[sys.argv.index("--") + 1 :]
WORK = pathlib.Path(WORK)
WORK.mkdir(parents=True, exist_ok=True)
ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "blender"))
addon_utils.enable("stitch_addon", default_set=True)

from stitch_addon import locate, smooth  # noqa: E402

stitch = smooth.module()  # as the add-on finds it (STITCH_PYTHON_DIR)

TESTS = []


def test(function):
    TESTS.append(function)
    return function


# ---------------------------------------------------------------------------------------- helpers


def read(collection, name, count, dtype=np.float32, width=1):
    values = np.empty(count * width, dtype)
    collection.foreach_get(name, values)
    return values.reshape(count, width) if width > 1 else values


def new_object(name, vertices, faces):
    me = bpy.data.meshes.new(name)
    me.from_pydata([list(map(float, v)) for v in vertices], [], faces)
    me.update()
    obj = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def activate(obj):
    if bpy.context.object is not None and bpy.context.object.mode != "OBJECT":
        bpy.ops.object.mode_set(mode="OBJECT")
    bpy.context.view_layer.objects.active = obj


def creased_cube():
    """The unit cube, its top loop creased (1.0), a vertical edge semi-sharp (0.5) and a bottom
    vertex a corner (vertex crease 1.0)."""
    vertices = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    obj = new_object("cube", vertices, faces)
    for e in obj.data.edges:
        a, b = (vertices[i] for i in e.vertices)
        if a[2] == b[2] == 1:
            e.crease = 1.0
        elif a[:2] == b[:2] == (1, 1):
            e.crease = 0.5
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    layers = bm.verts.layers  # a new layer moves the vertices: look them up after
    crease = (
        layers.crease.verify() if hasattr(layers, "crease") else layers.float.new("crease_vert")
    )
    bm.verts.ensure_lookup_table()
    bm.verts[0][crease] = 1.0
    bm.to_mesh(obj.data)
    bm.free()
    return obj


def vertex_creases(me):
    attribute = me.attributes.get("crease_vert")
    if attribute is not None:
        return read(attribute.data, "value", len(me.vertices))
    if len(me.vertex_creases):
        return read(me.vertex_creases[0].data, "value", len(me.vertices))
    return np.zeros(len(me.vertices), np.float32)


def write_obj(path, me):
    """The mesh as `stitch smooth` reads it: positions (the float32 values exactly), faces, the
    first UV map joined where a vertex's corners agree, and the creases as OpenSubdiv tags with
    Blender's sharpness 10 c^2 (test_crease_mapping_is_blenders checks that rule)."""
    lines = [
        f"v {float(x)!r} {float(y)!r} {float(z)!r}"
        for x, y, z in read(me.vertices, "co", len(me.vertices), width=3)
    ]
    uvs = read(me.uv_layers[0].data, "uv", len(me.loops), width=2) if me.uv_layers else None
    index = {}
    for poly in me.polygons:
        corners = []
        for loop in poly.loop_indices:
            v = me.loops[loop].vertex_index
            if uvs is None:
                corners.append(f"{v + 1}")
                continue
            key = (v, float(uvs[loop][0]), float(uvs[loop][1]))
            if key not in index:
                index[key] = len(index) + 1
                lines.append(f"vt {key[1]!r} {key[2]!r}")
            corners.append(f"{v + 1}/{index[key]}")
        lines.append("f " + " ".join(corners))
    for e in me.edges:
        if e.crease > 0:
            c = float(np.float32(e.crease))
            lines.append(f"t crease 2/1/0 {e.vertices[0]} {e.vertices[1]} {10.0 * c * c!r}")
    for v, c in enumerate(vertex_creases(me)):
        if c > 0:
            lines.append(f"t corner 1/1/0 {v} {10.0 * float(c) * float(c)!r}")
    path.write_text("\n".join(lines) + "\n")


def cli_smooth(me, name, *options, extension=".obj"):
    """Runs `stitch smooth` on the mesh; returns the output's positions and per-corner UVs, or
    for another extension the file and what stitch printed."""
    source = WORK / f"{name}.obj"
    write_obj(source, me)
    out = WORK / f"{name}-cli{extension}"
    # The add-on's default, as stitch smooth's: semi-sharp creases honoured by refinement.
    result = subprocess.run(
        [CLI, "smooth", str(source), "-o", str(out), *options],
        capture_output=True,
        text=True,
        check=True,
    )
    if extension != ".obj":
        return out, result.stderr + result.stdout
    positions, texcoords, corners = [], [], []
    for line in out.read_text().splitlines():
        words = line.split()
        if words and words[0] == "v":
            positions.append([float(w) for w in words[1:4]])
        elif words and words[0] == "vt":
            texcoords.append([float(w) for w in words[1:3]])
        elif words and words[0] == "f":
            corners.extend(w.split("/") for w in words[1:])
    uv = None
    if texcoords:
        uv = np.array(texcoords)[[int(c[1]) - 1 for c in corners]]
    return np.array(positions), uv


def smooth_with_operator(obj, **settings):
    activate(obj)
    for name, value in settings.items():
        setattr(obj.stitch, name, value)
    assert bpy.ops.object.stitch_smooth() == {"FINISHED"}
    return obj.stitch.target


def positions(obj):
    return read(obj.data.vertices, "co", len(obj.data.vertices), width=3)


def loop_normals(me):
    if hasattr(me, "calc_normals_split"):
        me.calc_normals_split()
    return read(me.loops, "normal", len(me.loops), width=3)


def normal_spread_deg(me):
    """Per vertex, the largest angle between the normals of its corners as Blender shades them
    (split at sharp edges), so 0 where the surface is smooth and the crease's angle on one."""
    vertex = read(me.loops, "vertex_index", len(me.loops), np.int32)
    normals = loop_normals(me)
    order = np.argsort(vertex, kind="stable")
    spread = np.zeros(len(me.vertices))
    first = {}
    for loop in order:
        v = vertex[loop]
        if v not in first:
            first[v] = normals[loop]
        angle = np.degrees(np.arccos(np.clip(np.dot(first[v], normals[loop]), -1, 1)))
        spread[v] = max(spread[v], angle)
    return spread


# ------------------------------------------------------------------------------------------ tests


@test
def creased_cube_matches_the_command_line():
    obj = creased_cube()
    n = 5
    for method in ("mdc", "cc"):
        target = smooth_with_operator(obj, method=method, resolution=n)
        expected, _ = cli_smooth(
            obj.data, f"cube-{method}", "--method", method, "--resolution", str(n)
        )
        got = positions(target)
        assert got.shape == expected.shape, (method, got.shape, expected.shape)
        error = np.abs(got - expected).max()
        assert error < 1e-6, (method, error)
        print(
            f"  cube {method}: {len(got)} vertices as stitch smooth, positions within {error:.1e}"
        )
    # Without the tags the surface is another one: the creases were passed on.
    plain, _ = cli_smooth(
        new_object("plain", positions(obj), [list(p.vertices) for p in obj.data.polygons]).data,
        "cube-plain",
        "--method",
        "cc",
        "--resolution",
        str(n),
    )
    assert np.abs(plain - positions(obj.stitch.target)).max() > 0.05


@test
def creases_stay_sharp():
    """mdc, rounding semi-sharp creases: the creased top loop (crease 1: sharpness 10) keeps its
    angle, the semi-sharp edge (0.5: sharpness 2.5, below sharp_from 4) is smooth, and the corner (vertex crease 1) is a
    point the surface passes through. The smooth object's edges along the creases are marked
    sharp, so Blender's shading shows the angle."""
    obj = bpy.data.objects["cube"]
    n = 4
    target = smooth_with_operator(obj, method="mdc", resolution=n, round_semi_sharp=True)
    obj.stitch.round_semi_sharp = False  # the default, for the tests after this one
    spread = normal_spread_deg(target.data)
    sharp = np.flatnonzero(spread > 30)
    # The top loop: 4 edges of 2 n segments each, all at the top.
    assert len(sharp) == 8 * n and np.all(positions(target)[sharp][:, 2] > 0.5), len(sharp)
    # Elsewhere one normal per vertex (up to the 0.02 degree steps Blender stores them in).
    assert np.sort(spread)[-len(sharp) - 1] < 0.1, np.sort(spread)[-len(sharp) - 1]
    marked = read(target.data.edges, "use_edge_sharp", len(target.data.edges), bool)
    assert marked.sum() == 8 * n, marked.sum()
    # The surface's first vertices are the mesh vertices' limit points: the corner interpolates.
    corner = positions(target)[0]
    assert np.abs(corner - (-1, -1, -1)).max() < 1e-6, corner
    assert np.abs(positions(target)[1] - (1, -1, -1)).max() > 0.1
    print(
        f"  {len(sharp)} vertices on the creases, at least {spread[sharp].min():.0f} degrees; "
        f"the corner at {corner}"
    )


@test
def crease_mapping_is_blenders():
    """Blender's Subdivision Surface modifier and the add-on's cc surface agree on the creased
    cube's limit points, so a crease c is sharpness 10 c^2 in both (0.5 -> 2.5)."""
    obj = new_object(
        "semi",
        [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)],
        [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]],
    )
    for e in obj.data.edges:
        if all(obj.data.vertices[i].co.z > 0 for i in e.vertices):
            e.crease = 0.5
    target = smooth_with_operator(obj, method="cc", resolution=2)
    modifier = obj.modifiers.new("subsurf", "SUBSURF")
    modifier.levels = 3
    modifier.use_limit_surface = True
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh()
    blender = read(evaluated.vertices, "co", len(evaluated.vertices), width=3)
    # The tessellation's first vertices are the mesh vertices' limit points.
    limits = positions(target)[:8]
    distance = max(np.linalg.norm(blender - p, axis=1).min() for p in limits)
    obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh_clear()
    obj.modifiers.remove(modifier)
    assert distance < 1e-5, distance
    print(f"  Blender's subdivision and stitch cc meet at the corners within {distance:.1e}")


@test
def torus_uvs_and_materials():
    bpy.ops.mesh.primitive_torus_add(major_segments=12, minor_segments=8, generate_uvs=True)
    obj = bpy.context.object
    obj.name = "torus"
    me = obj.data
    second = me.uv_layers.new(name="Doubled")
    second.data.foreach_set(
        "uv", 2 * read(me.uv_layers[0].data, "uv", len(me.loops), width=2).ravel()
    )
    me.uv_layers.active_index = 0
    for name in ("red", "blue"):
        me.materials.append(bpy.data.materials.new(name))
    material = (np.arange(len(me.polygons)) % 3 == 0).astype(np.int32)
    me.polygons.foreach_set("material_index", material)
    n = 3
    target = smooth_with_operator(obj, method="mdc", resolution=n, uv_mode="smooth")
    expected, expected_uv = cli_smooth(me, "torus", "--resolution", str(n))
    got = positions(target)
    assert got.shape == expected.shape and np.abs(got - expected).max() < 1e-6
    tme = target.data
    assert [layer.name for layer in tme.uv_layers] == [me.uv_layers[0].name, "Doubled"]
    uv = read(tme.uv_layers[0].data, "uv", len(tme.loops), width=2)
    assert np.abs(uv - expected_uv).max() < 1e-6, np.abs(uv - expected_uv).max()
    doubled = read(tme.uv_layers["Doubled"].data, "uv", len(tme.loops), width=2)
    assert np.abs(doubled - 2 * uv).max() < 1e-5  # the smooth UV surface commutes with scaling
    assert [m.name for m in tme.materials] == ["red", "blue"]
    quads = read(tme.polygons, "material_index", len(tme.polygons), np.int32)
    for m in (0, 1):  # each corner of a face is a patch of n^2 quads with the face's material
        assert np.sum(quads == m) == n * n * 4 * np.sum(material == m)
    print(
        f"  torus: {len(got)} vertices, UVs as stitch smooth's within "
        f"{np.abs(uv - expected_uv).max():.1e}, 2 UV maps, materials per face"
    )


@test
def uv_maps_of_a_refined_surface():
    """A semi-sharp crease refines the surface (the creased cube's 0.5: sharpness 2.5, three
    levels); every UV map is refined with it, the second as the first."""
    obj = creased_cube()
    obj.name = "cube-uvs"
    me = obj.data
    corners = read(me.vertices, "co", len(me.vertices), width=3)[
        read(me.loops, "vertex_index", len(me.loops), np.int32)
    ]
    for name, scale in (("Planar", 1), ("Doubled", 2)):
        me.uv_layers.new(name=name).data.foreach_set("uv", scale * corners[:, :2].ravel())
    me.uv_layers.active_index = 0
    n = 2
    target = smooth_with_operator(obj, method="mdc", resolution=n)
    tme = target.data
    assert len(tme.polygons) == 24 * 4**3 * n * n, len(tme.polygons)
    assert [layer.name for layer in tme.uv_layers] == ["Planar", "Doubled"]
    uv = read(tme.uv_layers["Planar"].data, "uv", len(tme.loops), width=2)
    doubled = read(tme.uv_layers["Doubled"].data, "uv", len(tme.loops), width=2)
    assert np.abs(uv).max() > 0.5
    assert np.abs(doubled - 2 * uv).max() < 1e-5  # the smooth UV surface commutes with scaling
    print(f"  refined cube: {len(tme.polygons)} quads, both UV maps refined with it")


@test
def exact_export():
    obj = bpy.data.objects["cube"]
    obj.stitch.method = "mdc"
    activate(obj)
    for extension in (".bez.json", ".step"):
        path = WORK / f"cube-blender{extension}"
        assert bpy.ops.export_scene.stitch_exact(filepath=str(path), format=extension) == {
            "FINISHED"
        }
        cli_file, report = cli_smooth(obj.data, "cube-exact", extension=extension)
        if extension == ".bez.json":  # written as `stitch smooth -o` writes it, byte for byte
            patches = json.loads(path.read_text())["patches"]
            assert path.read_bytes() == cli_file.read_bytes()
            assert len(patches) > 24 and all(
                surface in patches[0] for surface in ("corner", "corner_name")
            )
            print(f"  .bez.json: {len(patches)} patches, the bytes stitch smooth writes")
        else:
            faces = len(re.findall(r"ADVANCED_FACE\(", path.read_text()))
            reported = int(re.search(r"(\d+) B-spline faces", report).group(1))
            # The cube's 6: the mesh is refined for its semi-sharp edge first, and the refined
            # patches of each of its quads pack into one face again.
            assert faces == reported == 6, (faces, reported)
            print(f"  .step: {faces} B-spline faces, as stitch smooth reports")
    # The format's extension replaces another one.
    assert bpy.ops.export_scene.stitch_exact(
        filepath=str(WORK / "renamed.json"), format=".igs"
    ) == {"FINISHED"}
    assert (WORK / "renamed.igs").exists()


@test
def refusals_are_reports():
    # A Möbius strip: repair on reading fixes what can be fixed (faces flipped, non-manifold
    # edges split), but no flips orient this one, so stitch refuses it; Blender reports it.
    n = 5
    strip = []
    for i in range(n):
        t = 2 * math.pi * i / n
        centre = (2 * math.cos(t), 2 * math.sin(t), 0)
        across = (0.5 * math.cos(t / 2) * math.cos(t), 0.5 * math.cos(t / 2) * math.sin(t),
                  0.5 * math.sin(t / 2))
        strip += [tuple(c + w for c, w in zip(centre, across)),
                  tuple(c - w for c, w in zip(centre, across))]
    quads = [[2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1] for i in range(n - 1)]
    quads.append([2 * n - 2, 1, 0, 2 * n - 1])  # the half twist: a_4, b_0, a_0, b_4
    obj = new_object("strip", strip, quads)
    activate(obj)
    try:
        bpy.ops.object.stitch_smooth()
        raise AssertionError("a Möbius strip was smoothed")
    except RuntimeError as e:  # what bpy.ops raises for an error report
        assert "Stitch:" in str(e) and "not orientable" in str(e), e
        print(f"  reported: {str(e).strip()}")
    assert obj.stitch.target is None
    # The module not found: the message says where it was looked for and what to do.
    saved, candidates = sys.modules.pop("stitch"), locate.candidates
    locate.candidates = lambda preference="": [(pathlib.Path("/nonexistent"), "a test")]
    try:
        activate(bpy.data.objects["cube"])
        bpy.ops.object.stitch_smooth()
        raise AssertionError("smoothed without the module")
    except RuntimeError as e:
        assert "/nonexistent (a test): no stitch module" in str(e) and "Preferences" in str(e), e
    finally:
        sys.modules["stitch"], locate.candidates = saved, candidates


@test
def live_updates_only_what_moved():
    """A 10k-face torus, live at resolution 4: a vertex moved in edit mode updates the patches
    around it alone, to the surface a rebuild gives."""
    bpy.ops.mesh.primitive_torus_add(major_segments=100, minor_segments=100, generate_uvs=True)
    obj = bpy.context.object
    obj.name = "big torus"
    assert len(obj.data.polygons) == 10000
    n = 4
    obj.stitch.resolution = n
    start = time.perf_counter()
    target = smooth_with_operator(obj, live=True)
    seconds = time.perf_counter() - start
    print(f"  smoothed 10k faces at resolution {n} (and made it live) in {seconds:.2f} s")
    before = positions(target).copy()
    live = smooth.LIVE[obj.as_pointer()]
    bpy.ops.object.mode_set(mode="EDIT")
    bm = bmesh.from_edit_mesh(obj.data)
    bm.verts.ensure_lookup_table()
    bm.verts[0].co.z += 0.1
    bmesh.update_edit_mesh(obj.data)
    start = time.perf_counter()
    bpy.context.view_layer.update()  # the depsgraph update the handler follows
    seconds = time.perf_counter() - start
    assert obj.stitch.status.startswith("live: "), obj.stitch.status
    after = positions(target)
    changed = np.flatnonzero(np.any(after != before, axis=1))
    recomputed = set(live.surface.recomputed.tolist())
    assert 0 < len(recomputed) < 0.01 * live.surface.num_patches, len(recomputed)
    samples_of_recomputed = np.isin(live.vertex_rows // (n + 1) ** 2, list(recomputed))
    assert len(changed) and samples_of_recomputed[changed].all()
    # Equal to the surface of the moved mesh built from scratch.
    bpy.ops.object.mode_set(mode="OBJECT")
    co = read(obj.data.vertices, "co", len(obj.data.vertices), width=3).astype(np.float64)
    faces = read(obj.data.loops, "vertex_index", len(obj.data.loops), np.int32).reshape(-1, 4)
    fresh = stitch.Surface(stitch.Mesh(co, faces), "mdc").tessellate(n).vertices
    error = np.abs(after - fresh).max()
    assert error < 1e-6, error
    print(
        f"  a moved vertex: {len(recomputed)} of {live.surface.num_patches} patches evaluated "
        f"again, {len(changed)} of {len(after)} vertices changed, as a rebuild within {error:.1e}; "
        f"the update took {live.seconds * 1000:.1f} ms in the add-on, {seconds * 1000:.1f} ms with "
        f"Blender's depsgraph (timings are measured, not asserted: bench_live.py)"
    )
    # A change of topology smooths again from scratch.
    bpy.ops.object.mode_set(mode="EDIT")
    bm = bmesh.from_edit_mesh(obj.data)
    bm.faces.ensure_lookup_table()
    bmesh.ops.delete(bm, geom=[bm.faces[0]], context="FACES_ONLY")  # a hole: a boundary
    bmesh.update_edit_mesh(obj.data)
    bpy.context.view_layer.update()
    bpy.ops.object.mode_set(mode="OBJECT")
    assert len(target.data.polygons) == (4 * 10000 - 4) * n * n, len(target.data.polygons)
    # So does a change of settings.
    obj.stitch.resolution = 2
    assert len(target.data.polygons) == (4 * 10000 - 4) * 4, len(target.data.polygons)
    obj.stitch.live = False


# ------------------------------------------------------------------------------------------- main

failed = []
for function in TESTS:
    print(f"{function.__name__}")
    try:
        function()
    except Exception as e:  # report every test, then fail
        import traceback

        traceback.print_exc()
        failed.append(function.__name__)
        print(f"FAILED {function.__name__}: {e!r}")
addon_utils.disable("stitch_addon")
print(
    f"{len(TESTS) - len(failed)} of {len(TESTS)} passed"
    + (f"; failed: {', '.join(failed)}" if failed else "")
)
if failed:
    raise SystemExit(1)
