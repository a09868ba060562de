"""Bad input raises ValueError (stitch.StitchError for the library's own refusals) with a
message, and never brings the interpreter down."""
import math

import numpy as np
import pytest

import stitch

from meshes import CUBE_FACES, CUBE_VERTICES


def test_stitch_error_is_a_value_error():
    assert issubclass(stitch.StitchError, ValueError)


@pytest.mark.parametrize("vertices,message", [
    (np.array(CUBE_VERTICES, dtype=complex), "vertices must be real numbers"),
    ([["a", "b", "c"]] * 8, "vertices must be real numbers"),
    (np.zeros((8, 2)), r"vertices must have shape \(n, 3\), not \(8, 2\)"),
    (np.zeros(24), r"vertices must have shape \(n, 3\)"),
    ([[0, 0, 0], [1, 1]], "vertices must be an array of numbers"),
    (None, "vertices must be"),
])
def test_bad_vertices(vertices, message):
    with pytest.raises(ValueError, match=message):
        stitch.Mesh(vertices, CUBE_FACES)


@pytest.mark.parametrize("faces,message", [
    (np.array(CUBE_FACES, dtype=float), "faces must be integers, not an array of float64"),
    (np.array(CUBE_FACES).ravel(), r"shape \(m, k\), not \(24,\)"),
    ("0 1 2", "faces must be a sequence"),
    (7, "faces must be a sequence"),
    ([[0, 1, 2], 5], r"faces\[1\] must be a sequence of vertex indices, not int"),
    ([[0, 3, 2.0, 1]] + CUBE_FACES[1:], r"faces\[0\]\[2\] is not an integer \(float\)"),
    ([[0, 3, 2, 2**40]] + CUBE_FACES[1:], r"faces\[0\]\[3\] is out of range"),
    ([], "the mesh has no faces"),
])
def test_bad_face_data(faces, message):
    with pytest.raises(ValueError, match=message):
        stitch.Mesh(CUBE_VERTICES, faces)


@pytest.mark.parametrize("faces,message", [
    # Messages number vertices and faces from 1, as files and edit operations do.
    ([[0, 3, 2, 8]] + CUBE_FACES[1:], "face 1 refers to vertex 9, but there are 8 vertices"),
    ([[0, 3, 2, -1]] + CUBE_FACES[1:], "face 1 refers to vertex 0, but there are 8 vertices"),
])
def test_invalid_meshes(faces, message):
    with pytest.raises(stitch.StitchError, match=message):
        stitch.Mesh(CUBE_VERTICES, faces)


# Defects repair fixes by default, each named in a warning, and refuses with repair=False.
REPAIRABLE = [
    ([[0, 1, 2], [0, 4, 5]], "non-manifold", "non-manifold vertex"),
    ([[1, 2, 3, 0]] + CUBE_FACES[1:], "orient", "flipped 1 face"),
    (CUBE_FACES + [[0, 1, 5]], "non-manifold edge", "non-manifold edge"),
    ([[0, 3, 3, 1]] + CUBE_FACES[1:], "repeats vertex", "repeats a vertex"),
]


@pytest.mark.parametrize("faces,refusal,repair", REPAIRABLE)
def test_repairable_meshes(faces, refusal, repair):
    with pytest.raises(stitch.StitchError, match=refusal):
        stitch.Mesh(CUBE_VERTICES, faces, repair=False)
    with pytest.warns(UserWarning, match=repair):
        mesh = stitch.Mesh(CUBE_VERTICES, faces)
    assert mesh.num_faces > 0


def test_non_finite_coordinates():
    vertices = np.array(CUBE_VERTICES, dtype=float)
    vertices[3, 1] = math.nan
    with pytest.raises(stitch.StitchError, match="vertex 4 has a non-finite coordinate"):
        stitch.Mesh(vertices, CUBE_FACES)


def test_bad_files(tmp_path):
    with pytest.raises(stitch.StitchError, match="missing.obj"):
        stitch.read(str(tmp_path / "missing.obj"))
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
    with pytest.raises(stitch.StitchError, match="line 4"):
        stitch.read(str(bad))
    with pytest.raises(stitch.StitchError):
        stitch.primitive("cube").write(str(tmp_path / "no_such_folder" / "cube.obj"))


@pytest.mark.parametrize("ops,message", [
    (["frobnicate 1"], "operation 1 \\('frobnicate 1'\\)"),
    (["insert-edge 1@1 1@1"], "operation 1"),
    (["extrude-face 1 nan"], "operation 1"),
    (["delete-face 99"], "operation 1"),
])
def test_refused_operations(ops, message):
    mesh = stitch.primitive("cube")
    with pytest.raises(stitch.StitchError, match=message):
        mesh.edit(*ops)
    assert mesh.faces == CUBE_FACES


def test_edit_takes_strings():
    with pytest.raises(ValueError, match="operation strings"):
        stitch.primitive("cube").edit(["insert-edge 1@1 5@2"])


@pytest.mark.parametrize("name,params", [("blob", ()), ("torus", (2, 5)), ("prism", ()),
                                         ("prism", ("5",)), ("prism", (5.0,)), ("prism", (2**40,)),
                                         ("torus", (10**4, 10**4))])
def test_bad_primitives(name, params):
    with pytest.raises(ValueError, match=name):
        stitch.primitive(name, *params)


@pytest.mark.parametrize("kwargs,message", [
    # Names are parsed with the library's tables, which list the known ones.
    (dict(method="loop"), "unknown method 'loop' \\(known: mdc, asc, cc\\)"),
    (dict(kgon_scale=0), "kgon_scale must be a number from 1e-06 to 1e\\+06, not 0"),
    (dict(kgon_scale=math.nan), "kgon_scale must be a number from .*, not nan"),
    (dict(kgon_rotate=math.inf), "kgon_rotate must be a number from -3600 to 3600, not inf"),
    (dict(kgon_construction="exact"),
     "unknown kgon_construction 'exact' \\(known: openings, doo-sabin\\)"),
    (dict(boundary="soft"), "unknown boundary 'soft' \\(known: edge-and-corner, edge-only\\)"),
    (dict(sharp_from=11), "sharp_from must be a number from 0 to 10, not 11"),
])
def test_bad_surface_options(kwargs, message):
    with pytest.raises(ValueError, match=message):
        stitch.Surface(stitch.primitive("cube"), **kwargs)


@pytest.fixture(scope="module")
def surface():
    return stitch.Surface(stitch.primitive("cube"))


@pytest.mark.parametrize("resolution", [0, -3, 1025])
def test_bad_resolution(surface, resolution):
    with pytest.raises(ValueError, match="resolution must be 1 to 1024"):
        surface.tessellate(resolution)


@pytest.mark.parametrize("patches,u,v,message", [
    ([0, 24], 0.5, 0.5, r"patches\[1\] = 24 is not a patch of the surface \(0 to 23\)"),
    (-1, 0.5, 0.5, r"patches\[0\] = -1 is not a patch"),
    (0, [0.5, 1.5], 0.5, r"\(u, v\)\[1\] = \(1.5, 0.5\) is outside \[0, 1\]\^2"),
    (0, 0.5, math.nan, r"is outside \[0, 1\]\^2"),
    (np.array([0.0, 1.0]), 0.5, 0.5, "patches must be integers, not an array of float64"),
    (0, "half", 0.5, "u must be real numbers"),
    ([0, 1, 2], [0.1, 0.2], 0.5, "broadcast"),
])
def test_bad_evaluation(surface, patches, u, v, message):
    with pytest.raises(ValueError, match=message):
        surface.evaluate(patches, u, v)


def test_bad_analysis(surface):
    with pytest.raises(ValueError, match="samples_per_side must be 1 to 1000"):
        surface.analyze(samples_per_side=0)


def test_bad_export(surface, tmp_path):
    with pytest.raises(stitch.UsageError, match="cannot tell the output format of .*out.xyz"):
        surface.export(str(tmp_path / "out.xyz"), resolution=2)
    with pytest.raises(stitch.UsageError,
                       match=r"unwelded samples are written to binary PLY \(.ply\) only"):
        surface.export(str(tmp_path / "out.obj"), resolution=2, welded=False)
    with pytest.raises(ValueError, match="resolution must be 1 to 1024"):
        surface.export(str(tmp_path / "out.obj"), resolution=0)
    with pytest.raises(ValueError, match="contradict"):
        surface.export(str(tmp_path / "out.ply"), welded=True, unwelded=True)
    assert list(tmp_path.iterdir()) == []  # nothing half-written
