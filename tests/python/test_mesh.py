"""stitch.Mesh: building from Python data, reading, inspecting, editing and writing."""
import threading

import numpy as np
import pytest

import stitch

from meshes import CUBE_FACES, CUBE_VERTICES, pyramid


def test_mesh_from_faces_of_mixed_degree():
    vertices, faces = pyramid()
    mesh = stitch.Mesh(vertices, faces)
    assert (mesh.num_vertices, mesh.num_edges, mesh.num_faces) == (5, 8, 5)
    assert (mesh.euler, mesh.genus, mesh.components) == (2, 0, 1)
    assert mesh.num_patches == 16
    assert mesh.faces == faces
    np.testing.assert_array_equal(mesh.vertices, vertices)  # stored as given, exactly


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint16])
def test_mesh_from_face_array_matches_primitive(dtype):
    mesh = stitch.Mesh(np.array(CUBE_VERTICES, dtype=np.float32),
                       np.array(CUBE_FACES, dtype=dtype))
    cube = stitch.primitive("cube")
    assert mesh.faces == cube.faces == CUBE_FACES
    np.testing.assert_array_equal(mesh.vertices, cube.vertices)


def test_read_matches_primitive(examples):
    mesh = stitch.read(str(examples / "cube.obj"))
    cube = stitch.primitive("cube")
    assert mesh.faces == cube.faces
    np.testing.assert_array_equal(mesh.vertices, cube.vertices)
    assert mesh.topology() == {
        "vertices": 8, "edges": 12, "faces": 6, "components": 1, "euler": 2, "genus": 0,
        "boundary_loops": 0, "crease_edges": 0, "corner_vertices": 0,
        "valence_histogram": {3: 8}, "degree_histogram": {4: 6},
        "extraordinary_vertices": 8, "extraordinary_faces": 0}


def test_vertices_are_a_read_only_view_that_outlives_edits():
    mesh = stitch.primitive("cube")
    vertices = mesh.vertices
    assert vertices.dtype == np.float64 and vertices.shape == (8, 3)
    assert not vertices.flags.writeable
    assert not vertices.flags.owndata
    with pytest.raises(ValueError):
        vertices[0, 0] = 5.0
    mesh.edit("delete-face 1")  # replaces the mesh: the view keeps the old snapshot alive
    del mesh
    np.testing.assert_array_equal(vertices, CUBE_VERTICES)


def test_edit_hole_through_cube():
    mesh = stitch.primitive("cube")
    summary = mesh.edit("insert-edge 1@1 5@2")
    # The line `stitch edit` prints for the same operation (docs/editing.md).
    assert summary == ["insert-edge 1@1 5@2: new edge 13 merged faces 1 and 2 into face 1 "
                       "(10 sides); V 8 E 13 F 5, Euler 0, genus 1, components 1"]
    assert (mesh.num_faces, mesh.genus) == (5, 1)
    assert mesh.faces[0] == [0, 3, 2, 1, 0, 4, 5, 6, 7, 4]


def test_edit_runs_share_one_numbering():
    ops = ["extrude-face 1 -0.4 0.5", "extrude-face 2 -0.4 0.5", "connect-faces 1 2"]
    separate = stitch.primitive("cube")
    lines = separate.edit(*ops)
    as_file = stitch.primitive("cube")
    assert as_file.edit("\n".join(ops) + "\n# a comment line\n") == lines
    assert len(lines) == 3
    assert separate.genus == as_file.genus == 1
    assert separate.faces == as_file.faces


def test_refused_edit_leaves_mesh_unchanged():
    mesh = stitch.primitive("cube")
    with pytest.raises(stitch.StitchError, match=r"^operation 2 \('delete-edge 1 7'\): .*"
                                                 r"\(the mesh is unchanged\)$"):
        mesh.edit("subdivide-edge 1 2", "delete-edge 1 7")
    assert mesh.faces == CUBE_FACES
    assert mesh.num_vertices == 8


def test_edit_compacts_numbering():
    mesh = stitch.primitive("cube")
    mesh.edit("collapse-edge 1 2")
    assert mesh.num_vertices == 7
    assert max(max(f) for f in mesh.faces) == 6  # no gap left by the removed vertex


@pytest.mark.parametrize("ext", [".obj", ".off", ".ply"])
def test_write_read_round_trip(tmp_path, ext):
    mesh = stitch.primitive("cube")
    mesh.edit("insert-edge 1@1 5@2")
    path = str(tmp_path / ("holed" + ext))
    mesh.write(path)
    back = stitch.read(path)
    assert back.faces == mesh.faces
    # Exact: the coordinates are small integers, which any decimal output keeps.
    np.testing.assert_array_equal(back.vertices, mesh.vertices)


def test_build_warnings_become_python_warnings():
    vertices = np.vstack([CUBE_VERTICES, [[5, 5, 5]]])
    with pytest.warns(UserWarning, match="unused vert"):
        mesh = stitch.Mesh(vertices, CUBE_FACES)
    assert mesh.num_vertices == 8


def test_boundaries_are_kept_or_filled():
    open_box = CUBE_FACES[:1] + CUBE_FACES[2:]
    mesh = stitch.Mesh(CUBE_VERTICES, open_box)
    assert (mesh.num_faces, mesh.genus, mesh.topology()["boundary_loops"]) == (5, 0, 1)
    assert mesh.num_patches == 20
    with pytest.warns(UserWarning, match="filled 1 hole"):
        mesh = stitch.Mesh(CUBE_VERTICES, open_box, fill_holes=True)
    assert (mesh.num_faces, mesh.genus, mesh.topology()["boundary_loops"]) == (6, 0, 0)


@pytest.mark.parametrize("name,params,counts", [
    ("tetrahedron", (), (4, 6, 4)), ("prism", (5,), (10, 15, 7)), ("torus", (4, 3), (12, 24, 12))])
def test_primitives(name, params, counts):
    mesh = stitch.primitive(name, *params)
    assert (mesh.num_vertices, mesh.num_edges, mesh.num_faces) == counts


def test_reading_while_another_thread_edits():
    # The snapshot a call works on stays alive while the GIL is released, however often another
    # thread replaces the mesh meanwhile.
    mesh = stitch.primitive("cube")
    seen = []

    def read():
        for _ in range(30):
            seen.append((mesh.genus, stitch.Surface(mesh).tessellate(1).vertices.shape[1]))

    reader = threading.Thread(target=read)
    reader.start()
    for _ in range(30):
        mesh.edit("extrude-face 1 0.01")
    reader.join()
    assert mesh.num_vertices == 8 + 4 * 30
    assert seen == [(0, 3)] * 30


def test_refusal_says_why_without_editing():
    mesh = stitch.primitive("cube")
    assert mesh.refusal("insert-edge 1@1 5@2") is None
    why = mesh.refusal("insert-edge 1@1 1@3")
    assert "the edge would be a loop" in why
    assert mesh.genus == 0  # nothing was applied
    with pytest.raises(stitch.UsageError, match="unknown operation"):
        mesh.refusal("frobnicate 1")
    with pytest.raises(stitch.TopologyError, match="the edge would be a loop"):
        mesh.edit("insert-edge 1@1 1@3")
    assert issubclass(stitch.TopologyError, stitch.StitchError)
