"""One request, one surface, one file: stitch.Surface builds through the library's recipe and
Surface.export writes through its table of output formats, so Python and `stitch smooth` give the
same bytes; every format of the table is written, the exact ones included; a patch is a corner of
the mesh, named "V@F" as in `stitch eval`, Bezier JSON and STEP."""
import json
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

import stitch


@pytest.fixture(scope="module")
def cli():
    path = os.environ.get("STITCH_CLI")
    if not path:
        pytest.skip("STITCH_CLI (the stitch binary) is not set; ctest sets it")
    return path


def run(cli, *args, cwd):
    r = subprocess.run([cli, *map(str, args)], cwd=cwd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def available(extension):
    return next(f for f in stitch.output_formats() if extension in f["extensions"])["available"]


@pytest.fixture(scope="module")
def hole():
    path = str(pathlib.Path(__file__).resolve().parents[2] / "examples" / "cube_hole.obj")
    return path, stitch.Surface(stitch.read(path))


# (input, `stitch smooth` options, Surface keywords, export keywords, output name)
REQUESTS = [
    ("cube_hole.obj", [], {}, {}, "out.ply"),
    ("cube_hole.obj", ["--method", "asc", "--kgon-scale", "0.7", "--resolution", "5", "--ascii"],
     dict(method="asc", kgon_scale=0.7), dict(resolution=5, ascii=True), "out.ply"),
    ("cube_hole.obj", ["--kgon-construction", "doo-sabin", "--kgon-rotate", "15", "--unwelded",
                       "--resolution", "3"],
     dict(kgon_construction="doo-sabin", kgon_rotate=15), dict(unwelded=True, resolution=3),
     "out.ply"),
    ("cube_hole.obj", ["--tolerance", "1e-3"], {}, dict(tolerance=1e-3), "out.obj"),
    ("open_box.obj", ["--boundary", "edge-only", "--resolution", "4"],
     dict(boundary="edge-only"), dict(resolution=4), "out.off"),
    ("cube_creased.obj", ["--sharp-from", "1", "--float"], dict(sharp_from=1),
     {"float": True}, "out.ply"),
    ("cube_uv.obj", ["--uv", "linear", "--resolution", "3"], {}, dict(uv="linear", resolution=3),
     "out.obj"),
    ("cube_uv.obj", ["--resolution", "2"], {}, dict(resolution=2), "out.glb"),
    ("cube_hole.obj", [], {}, {}, "out.bez.json"),
]


@pytest.mark.parametrize("source,options,surface_kwargs,export_kwargs,out", REQUESTS)
def test_python_writes_the_file_the_cli_writes(cli, examples, tmp_path, source, options,
                                               surface_kwargs, export_kwargs, out):
    path = str(examples / source)
    printed = run(cli, "smooth", path, "-o", "cli_" + out, "-q", *options, cwd=tmp_path)
    report = stitch.Surface(stitch.read(path), **surface_kwargs).export(
        str(tmp_path / ("py_" + out)), **export_kwargs)
    assert (tmp_path / ("cli_" + out)).read_bytes() == (tmp_path / ("py_" + out)).read_bytes()
    assert printed == f"wrote cli_{out} ({report['summary']})\n"


def test_a_tube_unfolded_the_same_way(cli, tmp_path):
    # Prism 30's straight tube folds with its fitted K-gons: both front ends unfold it with the
    # same controls (build_surface's policy), or both keep the fitted ones when asked.
    mesh = stitch.primitive("prism", 30)
    mesh.edit("insert-edge 1@1 31@2")
    mesh.write(str(tmp_path / "tube.obj"))
    tube = stitch.read(str(tmp_path / "tube.obj"))
    files = {}
    for unfold in [True, False]:
        surface = stitch.Surface(tube, unfold_tubes=unfold)
        assert bool(surface.unfolded_tubes) == unfold
        surface.export(str(tmp_path / f"py_{unfold}.ply"), resolution=4)
        run(cli, "smooth", "tube.obj", "-o", f"cli_{unfold}.ply", "--resolution", "4", "-q",
            *([] if unfold else ["--no-unfold-tubes"]), cwd=tmp_path)
        files[unfold] = (tmp_path / f"py_{unfold}.ply").read_bytes()
        assert files[unfold] == (tmp_path / f"cli_{unfold}.ply").read_bytes()
    assert files[True] != files[False]


def test_output_formats_are_the_table_smooth_lists(cli, tmp_path):
    formats = stitch.output_formats()
    assert {"name", "extensions", "kind", "help", "memory", "available"} <= set(formats[0])
    assert {f["kind"] for f in formats} == {"tessellated", "exact"}
    listed = set()
    help_text = run(cli, "smooth", "--help", cwd=tmp_path)
    footer = help_text.split("Output formats, by extension")[1]
    for line in footer.splitlines()[1:]:  # "  .bez.json .json  Bezier JSON: ..."
        for token in line.split() if line.startswith("  .") else []:
            if not token.startswith("."):
                break
            listed.add(token)
    assert listed == {e for f in formats for e in f["extensions"]}
    assert ".step" in listed and ".bez.json" in listed


def test_bezier_json_names_every_patch_by_its_corner(hole, tmp_path):
    _, surface = hole
    path = tmp_path / "hole.bez.json"
    report = surface.export(str(path))
    doc = json.loads(path.read_text())
    assert report["faces"] == doc["patch_count"] == len(doc["patches"])
    assert report["summary"].startswith(f"{doc['patch_count']} Bezier patches")
    assert any("depth" in note for note in report["notes"])
    for patch in doc["patches"]:
        name = patch["corner_name"]
        assert surface.corner_name(patch["corner"]) == name
        assert surface.patch(name) == patch["corner"]
        assert name.split("#")[0] == f"{patch['vertex']}@{patch['face']}"
    assert {p["corner"] for p in doc["patches"]} == set(surface.patches.tolist())
    assert any("#" in p["corner_name"] for p in doc["patches"])  # the 10-sided face's
    with_kgons = tmp_path / "kgons.json"
    surface.export(str(with_kgons), kgons=True, tolerance=1e-4, angle_tolerance=1.0)
    assert "kgons" in json.loads(with_kgons.read_text())


@pytest.mark.parametrize("name", ["hole.step", "hole.stp", "hole.igs", "hole.iges"])
@pytest.mark.parametrize("faces", ["quads", "corners"])
def test_cad_export(hole, tmp_path, name, faces):
    if not available(name[name.index("."):]):
        pytest.skip("built without OpenCASCADE")
    _, surface = hole
    path = tmp_path / name
    report = surface.export(str(path), faces=faces, units="cm")
    assert path.stat().st_size > 0
    mesh = surface.mesh
    # quads: one face per quad (4 of them) and one per corner of the 10-sided face.
    count = 4 + 10 if faces == "quads" else mesh.num_patches
    assert report["faces"] == count
    assert report["summary"].startswith(f"{count} B-spline faces ({faces})")
    assert "units cm" in report["summary"]
    if name.endswith((".step", ".stp")):
        names = set(re.findall(r"ADVANCED_FACE\('([^']*)'", path.read_text()))
        decagon = [p for p in surface.patches
                   if re.fullmatch(r"\d+@1(#\d+)?", surface.corner_name(p))]
        assert len(decagon) == 10
        if faces == "quads":
            expected = {f"face {f}" for f in range(2, 6)}
            expected |= {"corner " + surface.corner_name(p) for p in decagon}
        else:
            expected = {"corner " + surface.corner_name(p) for p in surface.patches}
        assert names == expected


def test_exact_export_refusals(hole, tmp_path):
    path, surface = hole
    with pytest.raises(stitch.UsageError, match="not a set of Bezier patches"):
        stitch.Surface(stitch.read(path), "cc").export(str(tmp_path / "cc.bez.json"))
    with pytest.raises(stitch.UsageError, match="unknown face packing 'tris'"):
        surface.export(str(tmp_path / "x.step"), faces="tris")
    with pytest.raises(stitch.UsageError, match="tolerances .* must be numbers > 0"):
        surface.export(str(tmp_path / "x.bez.json"), angle_tolerance=0)
    with pytest.raises(stitch.UsageError, match="exclude each other"):
        surface.export(str(tmp_path / "x.obj"), tolerance=1e-3, resolution=4)
    with pytest.raises(stitch.UsageError, match="does not take"):
        surface.export(str(tmp_path / "x.glb"), tolerance=1e-3)
    if available(".step"):
        with pytest.raises(stitch.UsageError, match="unknown unit 'furlong'"):
            surface.export(str(tmp_path / "x.step"), units="furlong")
    assert list(tmp_path.iterdir()) == []


def test_corner_names_map_both_ways(hole):
    path, surface = hole
    mesh = surface.mesh
    names = [surface.corner_name(p) for p in surface.patches]
    assert len(set(names)) == len(names) == mesh.num_patches
    for p, name in zip(surface.patches, names):
        assert surface.patch(name) == mesh.corner(name) == p
        assert mesh.corner_name(p) == name
    # patch_of takes 0-based face and vertex, as mesh.faces lists them.
    for f, loop in enumerate(mesh.faces):
        for i, v in enumerate(loop):
            k = loop[:i + 1].count(v) if loop.count(v) > 1 else 0
            p = surface.patch_of(face=f, vertex=v, occurrence=k)
            assert surface.corner_name(p) == f"{v + 1}@{f + 1}" + (f"#{k}" if k else "")
            assert mesh.corner_of(face=f, vertex=v, occurrence=k) == p
    with pytest.raises(stitch.UsageError, match="ambiguous"):
        surface.patch("1@1")  # vertex 1 appears twice on the 10-sided face
    missing = next(v for v in range(mesh.num_vertices) if v not in mesh.faces[1])
    with pytest.raises(stitch.UsageError, match=f"vertex {missing + 1} is not on face 2"):
        surface.patch_of(face=1, vertex=missing)
    with pytest.raises(ValueError, match="is not a patch"):
        surface.corner_name(10**6)


def test_evaluate_by_name_equals_by_number(hole):
    _, surface = hole
    rng = np.random.default_rng(4)
    u, v = rng.random(len(surface.patches)), rng.random(len(surface.patches))
    names = [surface.corner_name(p) for p in surface.patches]
    by_number = surface.evaluate(surface.patches, u, v)
    by_name = surface.evaluate(names, u, v)
    for key in ["position", "du", "dv", "normal", "level"]:
        np.testing.assert_array_equal(getattr(by_name, key), getattr(by_number, key))
    one = surface.evaluate("2@1", 0.25, 0.5)
    np.testing.assert_array_equal(one.position, surface.evaluate(surface.patch("2@1"), 0.25,
                                                                 0.5).position)
    grid = surface.evaluate(np.array([["2@1", "5@1#2"]]), 0.5, 0.5)
    assert grid.position.shape == (1, 2, 3)


def test_stitch_eval_names_the_same_patches(cli, hole, tmp_path):
    path, surface = hole
    names = [surface.corner_name(p) for p in surface.patches]
    assert any("#" in name for name in names)
    (tmp_path / "at.txt").write_text("".join(f"{n} 0.25 0.75\n" for n in names))
    doc = json.loads(run(cli, "eval", path, "--at", "at.txt", "--format", "json", cwd=tmp_path))
    e = surface.evaluate(names, 0.25, 0.75)
    for i, (name, point) in enumerate(zip(names, doc["points"])):
        assert point["corner"] == name and point["patch"] == surface.patch(name)
        assert point["position"] == e.position[i].tolist()  # shortest round-trip text: exact


def test_texture_coordinates_stay_until_an_edit(examples, tmp_path):
    mesh = stitch.read(str(examples / "cube_uv.obj"))
    assert mesh.has_uvs and not stitch.read(str(examples / "cube.obj")).has_uvs
    surface = stitch.Surface(mesh)
    assert surface.export(str(tmp_path / "uv.obj"), resolution=2)["texcoords"] > 0
    assert surface.export(str(tmp_path / "none.obj"), resolution=2, uv="none")["texcoords"] == 0
    with pytest.warns(UserWarning, match="no place for them"):
        surface.export(str(tmp_path / "uv.off"), resolution=2, uv="smooth")
    with pytest.raises(stitch.UsageError, match="unknown UV mode|known: smooth, linear"):
        surface.export(str(tmp_path / "bad.obj"), uv="cubic")
    with pytest.warns(UserWarning, match="not kept by edits"):
        mesh.edit("extrude-face 1 0.2")
    assert not mesh.has_uvs and surface.mesh.has_uvs
    with pytest.warns(UserWarning, match="has no texture coordinates"):
        stitch.Surface(mesh).export(str(tmp_path / "edited.obj"), resolution=2, uv="linear")


def test_docstrings_list_the_tables():
    doc = stitch.Surface.__init__.__doc__
    for name in ["mdc", "asc", "cc", "openings", "doo-sabin", "edge-and-corner", "edge-only"]:
        assert name + ":" in doc
    doc = stitch.Surface.export.__doc__
    for f in stitch.output_formats():
        for e in f["extensions"]:
            assert e in doc
    for name in ["quads:", "corners:", "smooth:", "linear:"]:
        assert name in doc
    for e in [".obj", ".off", ".ply", ".stl", ".glb", ".gltf"]:
        assert e in stitch.read.__doc__


def test_older_export_keywords_are_aliases(hole, tmp_path):
    _, surface = hole
    for old, new in [(dict(welded=False), dict(unwelded=True)),
                     (dict(ascii_ply=True), dict(ascii=True))]:
        surface.export(str(tmp_path / "old.ply"), resolution=2, **old)
        surface.export(str(tmp_path / "new.ply"), resolution=2, **new)
        assert (tmp_path / "old.ply").read_bytes() == (tmp_path / "new.ply").read_bytes()
