"""stitch.IncrementalSurface: after every vertex moved, update_positions gives exactly the
surface built from scratch (the same C++ code on the same numbers, so compared with ==), and keeps
the layout."""
import numpy as np
import pytest

import stitch


def meshes():
    holed = stitch.primitive("cube")
    holed.edit("insert-edge 1@1 5@2")
    mixed = stitch.primitive("torus", 6, 5)
    mixed.edit("insert-edge 1@1 7@1")  # face 1 is (1, 6, 7, 2): its diagonal
    cube = stitch.primitive("cube")
    open_box = stitch.Mesh(cube.vertices, cube.faces[:-1])  # a boundary: a hole face
    return {"holed cube": holed, "tris+quads torus": mixed, "open box": open_box,
            "icosahedron": stitch.primitive("icosahedron")}


def expect_same_as_fresh(live, method):
    """The live blocks equal an unwelded tessellation of a fresh Surface of the same mesh."""
    # The incremental surface keeps the fitted K-gons of tubes (it does not run the search that
    # stitch.Surface runs where they fold), and moving the holed cube's vertices folds its tube.
    fresh = stitch.Surface(live.mesh, method, unfold_tubes=False).tessellate(
        live.resolution, welded=False, uvs=True, patches=True)
    t = live.tessellation
    blocks = t.patches >= 0  # every patch's block; holes' half-edges have empty ones
    assert blocks.sum() == len(fresh.vertices)
    assert np.array_equal(t.vertices[blocks], fresh.vertices)
    assert np.array_equal(t.normals[blocks], fresh.normals)
    assert np.array_equal(t.uvs[blocks], fresh.uvs)
    assert np.array_equal(t.patches[blocks], fresh.patches)


@pytest.mark.parametrize("method", ["mdc", "asc", "cc"])
@pytest.mark.parametrize("name", sorted(meshes()))
def test_update_positions_after_every_vertex_moved_equals_a_rebuild(name, method):
    mesh = meshes()[name]
    live = stitch.IncrementalSurface(mesh, method, 3)
    assert live.num_patches == mesh.num_patches and live.method == method
    quads = live.tessellation.quads.copy()
    rng = np.random.default_rng(4)
    vertices = mesh.vertices.copy()
    for _ in range(2):
        vertices += rng.uniform(-0.2, 0.2, vertices.shape)
        assert live.update_positions(vertices) > 0
        assert np.array_equal(live.mesh.vertices, vertices)
        expect_same_as_fresh(live, method)
        assert np.array_equal(live.tessellation.quads, quads)


def test_one_moved_vertex_reevaluates_only_the_patches_near_it():
    mesh = stitch.primitive("torus", 20, 20)
    live = stitch.IncrementalSurface(mesh, resolution=2)
    view = live.tessellation.vertices  # a view of the buffer the update rewrites in place
    before = view.copy()
    vertices = mesh.vertices.copy()
    vertices[7] += [0.0, 0.0, 0.1]
    recomputed = live.update_positions(vertices)
    assert 0 < recomputed < 100 and len(live.recomputed) == recomputed
    changed_rows = np.any(view != before, axis=1)
    assert changed_rows.any()
    # Only the recomputed patches' samples changed.
    assert set(np.unique(live.tessellation.patches[changed_rows])) <= set(live.recomputed)
    expect_same_as_fresh(live, "mdc")


def test_bad_positions_are_refused_and_change_nothing():
    mesh = stitch.primitive("cube")
    live = stitch.IncrementalSurface(mesh, resolution=2)
    before = live.tessellation.vertices.copy()
    with pytest.raises(ValueError, match="3 vertices given, the mesh has 8"):
        live.update_positions(mesh.vertices[:3])
    bad = mesh.vertices.copy()
    bad[5, 1] = np.nan
    with pytest.raises(stitch.StitchError, match="vertex 6"):
        live.update_positions(bad)
    assert np.array_equal(live.tessellation.vertices, before)
    with pytest.raises(ValueError, match="resolution must be 1 to 1024"):
        stitch.IncrementalSurface(mesh, resolution=0)


def test_semi_sharp_tags_are_honoured_as_stitch_surface_honours_them():
    """A semi-sharp crease: the live surface is Surface's, on the same refined mesh, before and
    after a move; sharp_from rounds it, one patch per corner."""
    cube = stitch.primitive("cube")
    with pytest.warns(UserWarning, match="semi-sharp"):
        mesh = stitch.Mesh(cube.vertices, cube.faces, creases=[[0, 1]], crease_sharpness=[1.5])
    live = stitch.IncrementalSurface(mesh, "mdc", 2)
    built = stitch.Surface(mesh, "mdc")
    assert live.refinement["levels"] == built.refinement["levels"] == 2
    assert live.num_patches == len(built.patches) == 16 * mesh.num_patches
    # Each patch comes from a face of the input: 4 corners of 16 patches each per face.
    assert np.array_equal(np.bincount(built.patch_faces), [64] * 6)
    vertices = mesh.vertices.copy()
    vertices[3] += [0.1, -0.05, 0.2]
    assert 0 < live.update_positions(vertices) < live.num_patches
    moved = stitch.Surface(live.mesh, "mdc").tessellate(2, welded=False)
    t = live.tessellation
    assert np.array_equal(t.vertices[t.patches >= 0], moved.vertices)
    rounded = stitch.IncrementalSurface(mesh, "mdc", 2, sharp_from=4)
    assert rounded.refinement["levels"] == 0 and rounded.num_patches == mesh.num_patches


def test_a_tessellation_too_large_to_number_is_refused_for_the_refined_mesh():
    """Sharpness 5.5 refines the cube 4 times (the most levels): 6144 patches, whose samples at
    resolution 1024 (about 6e9) no int numbers, though the cube's own 24 patches' would fit."""
    cube = stitch.primitive("cube")
    with pytest.warns(UserWarning, match="semi-sharp"):
        mesh = stitch.Mesh(cube.vertices, cube.faces, creases=[[0, 1]], crease_sharpness=[5.5])
    with pytest.raises(ValueError, match="6144 patches of the refined mesh"):
        stitch.IncrementalSurface(mesh, "mdc", 1024)
