"""Smoothing a source object into its linked smooth object, once (stitch.Surface, as `stitch
smooth` builds it) or live (stitch.IncrementalSurface, which re-evaluates only the patches a moved
vertex changes)."""

import time
import warnings

import bpy
import numpy as np

from . import convert, locate


def module():
    """The stitch module, from the folder the add-on's preference names (or the defaults)."""
    addon = bpy.context.preferences.addons.get(__package__)
    return locate.load(addon.preferences.module_dir if addon else "")


def typed(value):
    """A float setting as the user typed it: Blender keeps floats in 32 bits, and the shortest
    decimal that is that float is the number typed (1e-6, not 9.99999997e-7), so the surface is
    the one `stitch smooth` gives for the same options."""
    return float(repr(np.float32(value)))


def surface_keywords(settings):
    """The stitch.Surface / IncrementalSurface keywords the object's settings give."""
    return dict(
        kgon_scale=typed(settings.kgon_scale),
        kgon_rotate=typed(settings.kgon_rotate),
        regularize=settings.regularize,
        kgon_construction=settings.kgon_construction,
        boundary=settings.boundary,
        # None: semi-sharp creases honoured by refinement, as `stitch smooth` without the option.
        sharp_from=typed(settings.sharp_from) if settings.round_semi_sharp else None,
    )


def read_source(obj):
    if obj.mode != "EDIT":
        return convert.Source(obj.data)
    # The edit-mode mesh reaches obj.data only when written back, and even then Blender shows no
    # UV data of a mesh in edit mode: read a copy (to_mesh of an original object: no modifiers).
    obj.update_from_editmode()
    try:
        return convert.Source(obj.to_mesh())
    finally:
        obj.to_mesh_clear()


def build_surface(stitch, obj):
    """The exact surface of a source object with its settings, and the snapshot it was built
    from."""
    source = read_source(obj)
    settings = obj.stitch
    return (
        stitch.Surface(source.mesh(stitch), settings.method, **surface_keywords(settings)),
        source,
    )


def target_of(obj):
    """The smooth object linked to `obj`, made (parented to it, in its collections) if need be."""
    target = obj.stitch.target
    if target is None:
        me = bpy.data.meshes.new(f"{obj.name} smooth")
        target = bpy.data.objects.new(f"{obj.name} smooth", me)
        obj.stitch.target = target
        target.stitch.source = obj
    if not target.users_collection:  # new, or deleted from the scene since
        for collection in obj.users_collection:
            collection.objects.link(target)
    target.parent = obj  # follows the source's transform
    return target


def copy_materials(obj, target):
    """The source's material slots, so material_index means the same on both."""
    me = target.data
    me.materials.clear()
    for material in obj.data.materials:
        me.materials.append(material)
    for slot, own in zip(obj.material_slots, target.material_slots):
        if slot.link == "OBJECT":
            own.link = "OBJECT"
            own.material = slot.material


def smooth(obj):
    """Builds the smooth surface of `obj` into its linked object. Returns (target, summary line,
    warnings of the library). stitch.StitchError (a ValueError) for what the library refuses."""
    stitch = module()
    settings = obj.stitch
    n = settings.resolution
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        surface, source = build_surface(stitch, obj)
        welded = surface.tessellate(n)
        # Same quads, same order: the unwelded samples carry what differs between the patches at
        # a shared sample (normals across a crease, UVs across a seam).
        corners = surface.tessellate(n, welded=False)
        loop_samples = corners.quads.ravel()
        uv_maps = []
        for i, (name, uvs) in enumerate(source.uv_maps):
            texcoords = surface.texcoords(n, uv=settings.uv_mode, uvs=None if i == 0 else uvs)
            uv_maps.append((name, texcoords[loop_samples]))
        LIVE.pop(obj.as_pointer(), None)
        if settings.live:  # ready before the first change, so that one is incremental already
            LIVE[obj.as_pointer()] = LiveSurface(stitch, obj, source, welded.quads)
    face_materials = source.material[np.repeat(surface.patch_faces, n * n)]
    target = target_of(obj)
    copy_materials(obj, target)  # first: clearing a mesh's materials resets its faces' indices
    convert.fill_mesh(
        target.data,
        welded.vertices,
        welded.quads,
        corners.normals[corners.quads],
        face_materials,
        uv_maps,
    )
    summary = (
        f"{target.name}: {len(welded.vertices)} vertices, {len(welded.quads)} quads, "
        f"{len(surface.patches)} bicubic patches, method {surface.method}, resolution {n}"
    )
    return target, summary, [str(w.message) for w in caught]


class LiveSurface:
    """A source's surface kept up to date as its vertices move (IncrementalSurface), mapped onto
    the smooth object's mesh: each vertex of that mesh reads one sample of the incremental
    tessellation, whose patch h holds the (n + 1)^2 rows from h (n + 1)^2."""

    def __init__(self, stitch, obj, source, quads):
        settings = obj.stitch
        n = self.resolution = settings.resolution
        self.source = source
        self.surface = stitch.IncrementalSurface(
            source.mesh(stitch), settings.method, n, **surface_keywords(settings)
        )
        samples = self.surface.tessellation
        per = (n + 1) ** 2
        # The patches in order (half-edges with a patch): welded quad q is cell q % n^2 of patch
        # q // n^2 (Surface.tessellate), which is quad h n^2 + q % n^2 of the incremental one.
        patches = np.flatnonzero(samples.patches[::per] >= 0)
        q = np.arange(len(quads))
        corners = samples.quads[np.repeat(patches, n * n) * n * n + q % (n * n)]
        self.vertex_rows = np.empty(quads.max() + 1, np.int64)
        self.vertex_rows[quads.ravel()] = corners.ravel()
        self.vertex_patches = (self.vertex_rows // per).astype(np.int32)
        self.per = per
        self.positions = samples.vertices[self.vertex_rows].astype(np.float32)
        self.recomputed = 0  # patches the last update evaluated again
        # What the last update took: from reading the source to the mesh written, and stitch's part.
        self.seconds = self.stitch_seconds = 0.0

    def update(self, source, me):
        """New positions of the source's vertices into the smooth mesh `me`: only the samples of
        the patches the surface evaluated again are copied."""
        positions = source.stitch_positions()
        start = time.perf_counter()
        self.recomputed = self.surface.update_positions(positions)
        self.stitch_seconds = time.perf_counter() - start
        self.source = source
        if self.recomputed:
            samples = self.surface.tessellation
            hit = np.zeros(len(samples.patches) // self.per, bool)
            hit[self.surface.recomputed] = True
            moved = hit[self.vertex_patches]
            self.positions[moved] = samples.vertices[self.vertex_rows[moved]]
            me.vertices.foreach_set("co", self.positions.ravel())
            me.update()  # Blender's normals follow; the sharp edges stay where they were


# Live surfaces by source object (as_pointer: valid for the session; a stale entry fails the
# topology check and is rebuilt).
LIVE = {}


def refresh_live(obj):
    """After a change of a live source: positions only, through its LiveSurface; anything else
    (topology, creases, UVs, materials, or no live surface yet), a full smooth. Errors go to the
    object's status line, since a handler has nobody to report to."""
    try:
        start = time.perf_counter()
        source = read_source(obj)
        live = LIVE.get(obj.as_pointer())
        target = obj.stitch.target
        if (
            live is not None
            and target is not None
            and len(target.data.vertices) == len(live.positions)  # not undone to another one
            and live.source.same_except_positions(source)
        ):
            live.update(source, target.data)
            live.seconds = time.perf_counter() - start
            status = f"live: {live.recomputed} patches updated in {live.seconds * 1000:.1f} ms"
        else:
            status = "live: " + smooth(obj)[1]
    except Exception as e:  # a handler has no caller to raise to: the panel shows it
        status = f"live: {e}"
    if obj.stitch.status != status:
        obj.stitch.status = status
