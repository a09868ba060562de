"""What a front end holding its mesh in arrays (the Blender add-on) gives and gets: crease and
corner tags and per-corner texture coordinates into stitch.Mesh, the same surface as the file
with the same tags and UVs; texture coordinates and source faces per sample and per patch; the
names of stitch.choices()."""
import re

import numpy as np
import pytest

import stitch
from meshes import CUBE_FACES, CUBE_VERTICES


def file_uvs(path):
    """A file's per-corner texture coordinates, one row per corner of its faces in order."""
    vt, rows = [], []
    for line in path.read_text().splitlines():
        words = line.split()
        if words and words[0] == "vt":
            vt.append([float(w) for w in words[1:3]])
        elif words and words[0] == "f":
            rows.extend(vt[int(w.split("/")[1]) - 1] for w in words[1:])
    return np.array(rows)


def test_tags_given_as_arrays_make_the_surface_of_the_file_with_them(examples):
    read = stitch.read(str(examples / "cube_creased.obj"))
    creases = [[4, 5], [5, 6], [6, 7], [7, 4]]  # the file's `t crease` lines, 0-based as there
    given = stitch.Mesh(CUBE_VERTICES, CUBE_FACES, creases=creases)  # sharpness 10 by default
    assert given.topology()["crease_edges"] == read.topology()["crease_edges"] == 4
    for method in ["mdc", "cc"]:
        a = stitch.Surface(read, method).tessellate(4).vertices
        b = stitch.Surface(given, method).tessellate(4).vertices
        assert np.array_equal(a, b)
    corner = stitch.Mesh(CUBE_VERTICES, CUBE_FACES, corner_sharpness=[10, 0, 0, 0, 0, 0, 0, 0])
    assert corner.topology()["corner_vertices"] == 1
    np.testing.assert_allclose(stitch.Surface(corner).tessellate(2).vertices[0], CUBE_VERTICES[0])


def test_semi_sharp_tags_warn_as_a_file_does():
    with pytest.warns(UserWarning, match=r"1 edge has finite sharpness \(semi-sharp\)"):
        stitch.Mesh(CUBE_VERTICES, CUBE_FACES, creases=[[0, 1]], crease_sharpness=[2.5])


def test_semi_sharp_tags_are_honoured_by_refinement_unless_sharp_from_rounds_them(tmp_path):
    """Sharpness 2.5 on one edge: three levels of refinement, 4^3 patches per corner, the
    patches numbered on refined_mesh; sharp_from= rounds as before (one patch per corner)."""
    with pytest.warns(UserWarning, match="semi-sharp"):
        mesh = stitch.Mesh(CUBE_VERTICES, CUBE_FACES, creases=[[0, 1]], crease_sharpness=[2.5])
    surface = stitch.Surface(mesh)
    assert surface.refinement["levels"] == 3
    assert surface.refinement["patches"] == 24 * 4**3 == len(surface.patches)
    refined = surface.refined_mesh
    assert refined is not None and len(refined.faces) == 6 * 4**3
    assert surface.tessellate(1, welded=False, patches=True).patches.max() < 4 * len(refined.faces)
    name = surface.corner_name(int(surface.patches[-1]))
    assert surface.patch(name) == surface.patches[-1]
    assert surface.export(str(tmp_path / "s.bez.json"))["faces"] >= 24 * 4**3
    rounded = stitch.Surface(mesh, sharp_from=4)
    assert rounded.refinement["levels"] == 0 and rounded.refined_mesh is None
    assert len(rounded.patches) == 24


def test_tags_are_checked_like_a_files():
    with pytest.raises(stitch.InputError, match="names edge"):
        stitch.Mesh(CUBE_VERTICES, CUBE_FACES, creases=[[0, 6]])  # a diagonal, not an edge
    with pytest.raises(stitch.InputError, match="sharpness -1"):
        stitch.Mesh(CUBE_VERTICES, CUBE_FACES, creases=[[0, 1]], crease_sharpness=[-1])
    with pytest.raises(ValueError, match="crease_sharpness must have shape"):
        stitch.Mesh(CUBE_VERTICES, CUBE_FACES, creases=[[0, 1]], crease_sharpness=[1, 2])
    with pytest.raises(ValueError, match="needs creases"):
        stitch.Mesh(CUBE_VERTICES, CUBE_FACES, crease_sharpness=[1])
    with pytest.raises(ValueError, match="corner_sharpness must have shape"):
        stitch.Mesh(CUBE_VERTICES, CUBE_FACES, corner_sharpness=[1])


def test_per_corner_uvs_make_the_file_with_them(examples, tmp_path):
    """Corners at one vertex with equal UVs are joined, others make a seam: the cube's UV layout
    as its file gives it, so both write the same OBJ."""
    path = examples / "cube_uv.obj"
    uvs = file_uvs(path)
    given = stitch.Mesh(CUBE_VERTICES, CUBE_FACES, uvs=uvs)
    assert given.has_uvs
    stitch.Surface(stitch.read(str(path))).export(str(tmp_path / "read.obj"), resolution=3)
    stitch.Surface(given).export(str(tmp_path / "given.obj"), resolution=3)
    assert (tmp_path / "read.obj").read_bytes() == (tmp_path / "given.obj").read_bytes()


def test_texcoords_are_the_written_ones_per_sample(examples, tmp_path):
    surface = stitch.Surface(stitch.read(str(examples / "cube_uv.obj")))
    n = 3
    texcoords = surface.texcoords(n)
    corners = surface.tessellate(n, welded=False)
    assert texcoords.shape == (len(corners.vertices), 2)
    # The OBJ's `f v/vt/vn` corners, quad after quad, are the unwelded samples of the same quads.
    surface.export(str(tmp_path / "out.obj"), resolution=n)
    vt = np.array(
        [
            [float(w) for w in line.split()[1:3]]
            for line in (tmp_path / "out.obj").read_text().splitlines()
            if line.startswith("vt ")
        ]
    )
    faces = [
        line for line in (tmp_path / "out.obj").read_text().splitlines() if line.startswith("f ")
    ]
    written = vt[[int(c.split("/")[1]) - 1 for f in faces for c in f.split()[1:]]]
    assert np.array_equal(written, texcoords[corners.quads.ravel()])
    linear = surface.texcoords(n, uv="linear")
    assert not np.array_equal(linear, texcoords)
    # Another UV map of the same mesh: the map of a mesh built with it.
    other = 2 * file_uvs(examples / "cube_uv.obj")
    built = stitch.Surface(stitch.Mesh(CUBE_VERTICES, CUBE_FACES, uvs=other)).texcoords(n)
    assert np.array_equal(surface.texcoords(n, uvs=other), built)


def test_another_uv_map_of_a_refined_surface_is_refined_with_it(examples):
    """Refined for a semi-sharp crease, the patches are the refined mesh's corners: another UV
    map is refined as the mesh's own, so it gives what a mesh built with that map gives."""
    uvs = file_uvs(examples / "cube_uv.obj")
    tags = {"creases": [[0, 1]], "crease_sharpness": [1.5]}
    with pytest.warns(UserWarning, match="semi-sharp"):
        mesh = stitch.Mesh(CUBE_VERTICES, CUBE_FACES, uvs=uvs, **tags)
        other = stitch.Mesh(CUBE_VERTICES, CUBE_FACES, uvs=2 * uvs + 1, **tags)
    surface = stitch.Surface(mesh)
    assert len(surface.patches) == 24 * 16  # refined two levels
    n = 3
    assert np.array_equal(surface.texcoords(n, uvs=uvs), surface.texcoords(n))
    assert np.array_equal(surface.texcoords(n, uvs=2 * uvs + 1), stitch.Surface(other).texcoords(n))
    assert not np.array_equal(surface.texcoords(n, uvs=2 * uvs + 1), surface.texcoords(n))


def test_texcoords_refusals():
    surface = stitch.Surface(stitch.primitive("cube"))
    with pytest.raises(ValueError, match="no texture coordinates"):
        surface.texcoords(2)
    with pytest.raises(ValueError, match=re.escape("uvs must have shape (24, 2)")):
        surface.texcoords(2, uvs=np.zeros((23, 2)))
    with pytest.raises(stitch.UsageError, match="unknown"):
        surface.texcoords(2, uv="cubic", uvs=np.zeros((24, 2)))


def test_welded_and_unwelded_quads_are_the_same_quads_patch_after_patch():
    mesh = stitch.primitive("cube")
    mesh.edit("insert-edge 1@1 5@2")
    surface = stitch.Surface(mesh)
    n = 3
    welded, corners = surface.tessellate(n), surface.tessellate(n, welded=False, patches=True)
    assert np.abs(welded.vertices[welded.quads] - corners.vertices[corners.quads]).max() < 1e-12
    # Quad q lies on patch q // n^2, of face patch_faces[q // n^2].
    first = corners.quads[:, 0]
    assert np.array_equal(corners.patches[first], np.repeat(surface.patches, n * n))
    for k, patch in enumerate(surface.patches):
        face = surface.patch_faces[k]
        name = surface.corner_name(patch)
        assert int(re.match(r"\d+@(\d+)", name).group(1)) == face + 1


def test_choices_are_the_names_the_keywords_take():
    choices = stitch.choices()
    mesh = stitch.primitive("cube")
    assert stitch.Surface(mesh).method == choices["method"][0]["name"]  # the default first
    for method in choices["method"]:
        assert stitch.Surface(mesh, method["name"]).method == method["name"] and method["help"]
    for boundary in choices["boundary"]:
        stitch.Surface(mesh, boundary=boundary["name"])
    for construction in choices["kgon_construction"]:
        stitch.Surface(mesh, kgon_construction=construction["name"])
    assert [c["name"] for c in choices["uv"]][0] == "smooth"
    assert {c["name"] for c in choices["faces"]} >= {"quads", "corners"}
