"""stitch.Surface: tessellation into numpy arrays without copies, exact vectorised evaluation,
continuity analysis, export."""
import threading
import time

import numpy as np
import pytest

import stitch


@pytest.fixture(scope="module")
def holed():
    """The cube with a hole through it (genus 1, one 10-sided face): extraordinary points of
    every kind the method distinguishes."""
    mesh = stitch.primitive("cube")
    mesh.edit("insert-edge 1@1 5@2")
    return mesh


@pytest.mark.parametrize("method", ["mdc", "asc", "cc"])
def test_welded_tessellation_is_closed_with_the_input_genus(holed, method):
    surface = stitch.Surface(holed, method)
    assert surface.method == method
    t = surface.tessellate(4)
    assert t.vertices.dtype == np.float64 and t.vertices.shape[1] == 3
    assert t.quads.dtype == np.int32 and t.quads.shape == (holed.num_patches * 16, 4)
    assert t.normals.shape == t.vertices.shape
    # The attributes only when asked.
    assert t.uvs.shape == (0, 2) and t.patches.shape == (0,) and t.levels.shape == (0,)
    a = surface.tessellate(4, uvs=True, patches=True, levels=True)
    assert np.array_equal(a.vertices, t.vertices) and np.array_equal(a.quads, t.quads)
    assert a.uvs.shape == (len(t.vertices), 2)
    assert a.patches.dtype == np.int32 and a.patches.shape == (len(t.vertices),)
    assert a.levels.shape == (len(t.vertices),)
    assert surface.tessellate(4, patches=True).uvs.shape == (0, 2)
    # Building a stitch.Mesh checks that the quads form a closed oriented manifold.
    assert stitch.Mesh(t.vertices, t.quads).genus == 1
    # Normals are normalised in double precision: unit up to a few ulps.
    np.testing.assert_allclose(np.linalg.norm(t.normals, axis=1), 1.0, atol=1e-12)


def test_unwelded_tessellation_has_every_patch_grid(holed):
    r = 3
    t = stitch.Surface(holed).tessellate(r, welded=False, uvs=True, patches=True)
    assert len(t.vertices) == holed.num_patches * (r + 1) ** 2
    assert len(t.quads) == holed.num_patches * r * r
    assert np.array_equal(np.unique(t.patches), np.arange(holed.num_patches))
    assert t.uvs.min() == 0.0 and t.uvs.max() == 1.0


def test_tessellation_arrays_are_views_of_the_library_buffers(holed):
    t = stitch.Surface(holed).tessellate(2, uvs=True, patches=True, levels=True)
    for name in ["vertices", "normals", "uvs", "patches", "levels", "quads"]:
        a = getattr(t, name)
        assert a.base is t, name  # the buffer the library filled, owned by the Tessellation
        assert not a.flags.owndata and not a.flags.writeable and a.flags.c_contiguous
        assert np.shares_memory(a, getattr(t, name))
    vertices = t.vertices
    del t  # the array keeps its owner alive
    assert np.isfinite(vertices).all()


def test_evaluate_reproduces_the_tessellation(holed):
    surface = stitch.Surface(holed)
    t = surface.tessellate(3, welded=False, uvs=True, patches=True, levels=True)
    e = surface.evaluate(t.patches, t.uvs[:, 0], t.uvs[:, 1])
    # The same evaluation at the same (patch, u, v): equal but for the order of operations,
    # which must not differ by more than round-off on coordinates of size 1.
    np.testing.assert_allclose(e.position, t.vertices, rtol=0, atol=1e-12)
    np.testing.assert_allclose(e.normal, t.normals, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(e.level, t.levels)


def test_evaluate_broadcasts(holed):
    surface = stitch.Surface(holed)
    u = np.linspace(0, 1, 5)[:, None]
    v = np.linspace(0, 1, 7)[None, :]
    e = surface.evaluate(3, u, v)
    assert e.position.shape == (5, 7, 3) and e.level.shape == (5, 7)
    one = surface.evaluate([3], [u[2, 0]], [v[0, 4]])
    np.testing.assert_array_equal(one.position[0], e.position[2, 4])  # same call, same bits


@pytest.mark.parametrize("method", ["mdc", "asc", "cc"])
def test_derivatives_and_normals(holed, method):
    rng = np.random.default_rng(9)
    surface = stitch.Surface(holed, method)
    patches = rng.integers(0, holed.num_patches, 20)
    u, v = rng.uniform(0.1, 0.9, 20), rng.uniform(0.1, 0.9, 20)
    e = surface.evaluate(patches, u, v)
    n = np.cross(e.du, e.dv)
    np.testing.assert_allclose(e.normal, n / np.linalg.norm(n, axis=-1, keepdims=True),
                               atol=1e-12)
    if method == "cc":
        # OpenSubdiv's derivatives of the Gregory patches near extraordinary vertices ignore the
        # rational terms (its default, OPENSUBDIV_GREGORY_EVAL_TRUE_DERIVATIVES off): they differ
        # from the positions' slopes by up to ~10% there, so only the normal is checked.
        return
    h = 1e-5
    du = (surface.evaluate(patches, u + h, v).position -
          surface.evaluate(patches, u - h, v).position) / (2 * h)
    dv = (surface.evaluate(patches, u, v + h).position -
          surface.evaluate(patches, u, v - h).position) / (2 * h)
    # Central differences: truncation h^2 |p'''| ~ 1e-10 plus round-off eps/h ~ 1e-11, on
    # derivatives of size 1 (measured 1e-9 at most); 1e-6 leaves room for the sub-patches of
    # the hierarchy, which meet with C1 continuity only.
    np.testing.assert_allclose(e.du, du, atol=1e-6)
    np.testing.assert_allclose(e.dv, dv, atol=1e-6)


def test_analyze_measures_what_the_paper_claims(examples):
    cube = stitch.read(str(examples / "cube.obj"))
    mdc = stitch.Surface(cube, "mdc").analyze()
    asc = stitch.Surface(cube, "asc").analyze()
    assert set(mdc) == {"method", "touching_extraordinary", "away_from_extraordinary",
                        "max_position_gap_relative", "extraordinary_points",
                        "g1_normal_spread_at_extraordinary_points_deg", "max_jump_by_distance"}
    assert mdc["method"] == "mdc" and mdc["extraordinary_points"] == 8
    # mdc is C1 across the edges leaving extraordinary points, up to round-off (measured
    # ~1e-13 degrees); AS&C kinks there by degrees (measured 7.4).
    assert mdc["touching_extraordinary"]["max_deg"] < 1e-9
    assert asc["touching_extraordinary"]["max_deg"] > 1.0
    assert mdc["g1_normal_spread_at_extraordinary_points_deg"] < 1e-9
    assert mdc["touching_extraordinary"]["samples"] > 0


def perturbed_prism():
    """A pentagonal prism with moved vertices: its pentagons' K-gons are not affinely regular,
    so regularize has something to do (every triangle is regular in that sense)."""
    prism = stitch.primitive("prism", 5)
    noise = np.random.default_rng(5).normal(scale=0.1, size=prism.vertices.shape)
    return stitch.Mesh(prism.vertices + noise, prism.faces)


@pytest.mark.parametrize("kwargs", [dict(kgon_scale=0.5), dict(kgon_rotate=20.0),
                                    dict(regularize=True), dict(kgon_construction="doo-sabin")])
def test_kgon_controls_change_the_surface(holed, kwargs):
    # The K-gon construction differs only on faces made by inserting an edge between two faces.
    mesh = holed if "kgon_construction" in kwargs else perturbed_prism()
    default = stitch.Surface(mesh).tessellate(2).vertices
    again = stitch.Surface(mesh, "mdc", kgon_scale=1.0).tessellate(2).vertices
    np.testing.assert_array_equal(default, again)  # deterministic
    other = stitch.Surface(mesh, **kwargs).tessellate(2).vertices
    assert other.shape == default.shape
    assert np.abs(other - default).max() > 1e-4  # measured >= 1.5e-3


def test_surface_keeps_the_mesh_it_was_built_from():
    mesh = stitch.primitive("cube")
    surface = stitch.Surface(mesh)
    mesh.edit("insert-edge 1@1 5@2")
    assert surface.mesh.genus == 0 and mesh.genus == 1
    assert np.array_equal(surface.patches, np.arange(24))
    assert stitch.Mesh(*(lambda t: (t.vertices, t.quads))(surface.tessellate(2))).genus == 0


@pytest.mark.parametrize("ext", [".obj", ".ply", ".off", ".stl", ".glb"])
def test_export(holed, tmp_path, ext):
    surface = stitch.Surface(holed)
    path = tmp_path / ("surface" + ext)
    surface.export(str(path), resolution=3)
    assert path.stat().st_size > 0
    if ext == ".glb":
        assert path.read_bytes()[:4] == b"glTF"
    elif ext != ".stl":  # STL repeats positions per triangle: nothing to weld on reading
        back = stitch.read(str(path))
        t = surface.tessellate(3)
        assert (back.num_vertices, back.num_faces, back.genus) == (len(t.vertices), len(t.quads), 1)


def test_export_ascii_ply(holed, tmp_path):
    path = tmp_path / "surface.ply"
    stitch.Surface(holed).export(str(path), resolution=2, ascii_ply=True)
    assert path.read_text().startswith("ply\nformat ascii 1.0\n")


def test_export_unwelded_samples(holed, tmp_path):
    path = tmp_path / "samples.ply"
    stitch.Surface(holed).export(str(path), resolution=2, welded=False)
    header = path.read_bytes().split(b"end_header\n")[0].decode()
    assert f"element vertex {holed.num_patches * 9}" in header
    assert "property int patch" in header


def test_heavy_calls_release_the_gil():
    surface = stitch.Surface(stitch.primitive("torus", 60, 60))
    counted = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counted[0] += 1

    worker = threading.Thread(target=count)
    worker.start()
    try:
        time.sleep(0.05)
        before = counted[0]
        surface.tessellate(8)  # about 0.1 s of C++ on two cores
        during = counted[0] - before
    finally:
        stop.set()
        worker.join()
    # Holding the GIL, the call would leave the counter where it was (a handful of increments
    # at the switches around it); released, the counter runs throughout.
    assert during > 1000


def test_a_tube_that_folds_is_unfolded():
    # Prism 30's straight tube folds at resolution 16 with the fitted K-gons (docs/method.md,
    # "Quads split along the shorter diagonal"); the search finds controls for its face and
    # bridge, as stitch smooth does.
    mesh = stitch.primitive("prism", 30)
    mesh.edit("insert-edge 1@1 31@2")
    surface = stitch.Surface(mesh)
    [tube] = surface.unfolded_tubes
    assert tube["face"] == 0 and tube["bridge"] == 90
    assert tube["fitted_folds"] > 0 and tube["unfolded"] and tube["axis_open"]
    setting = (tube["face_scale"], tube["face_rotate"], tube["face_stretch"], tube["bridge_scale"])
    assert setting != (1.0, 0.0, 1.0, 1.0)
    # A setting of the grid: the descent past it (which also moves the face K-gon) not needed.
    assert not tube["descended"] and tube["face_offset"] == (0.0, 0.0, 0.0)
    fitted = stitch.Surface(mesh, unfold_tubes=False)
    assert fitted.unfolded_tubes == []
    assert np.abs(surface.tessellate(2).vertices - fitted.tessellate(2).vertices).max() > 1e-3
    # A tube that is clean already is left alone.
    holed = stitch.primitive("cube")
    holed.edit("insert-edge 1@1 5@2")
    assert stitch.Surface(holed).unfolded_tubes == []
