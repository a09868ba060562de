"""Between Blender meshes and stitch: what a source mesh gives stitch (positions, faces, creases,
UV maps, materials), and the smooth object's mesh filled from a tessellation. Arrays only, through
foreach_get/foreach_set, so a mesh of 10k faces converts in milliseconds."""

import numpy as np


def crease_to_sharpness(crease):
    """Blender's crease (0..1) as OpenSubdiv's sharpness, the way Blender's own subdivision gives
    it to OpenSubdiv (BKE_subdiv_crease_to_sharpness_f, 10 c^2): 1 is infinitely sharp (10),
    0.5 is 2.5."""
    c = np.clip(crease, 0.0, 1.0)
    return 10.0 * c * c


def _read(collection, name, count, dtype, width=1):
    values = np.empty(count * width, dtype)
    collection.foreach_get(name, values)
    return values.reshape(count, width) if width > 1 else values


def _edge_creases(me):
    attribute = me.attributes.get("crease_edge")  # Blender 4.0 and later
    if attribute is not None:
        return _read(attribute.data, "value", len(me.edges), np.float32)
    return _read(me.edges, "crease", len(me.edges), np.float32)  # 3.x


def _vertex_creases(me):
    attribute = me.attributes.get("crease_vert")  # Blender 4.0 and later
    if attribute is not None:
        return _read(attribute.data, "value", len(me.vertices), np.float32)
    if len(me.vertex_creases):  # 3.x: a layer that exists once a vertex crease was set
        return _read(me.vertex_creases[0].data, "value", len(me.vertices), np.float32)
    return np.zeros(len(me.vertices), np.float32)


class Source:
    """A snapshot of a Blender mesh as stitch takes it. Vertices no face uses (loose vertices and
    edges) are left out, so stitch vertex i is Blender vertex used[i]; faces and their corners
    keep Blender's order, so stitch face f is polygon f and per-corner arrays follow the loops."""

    def __init__(self, me):
        nv, nl, nf = len(me.vertices), len(me.loops), len(me.polygons)
        self.positions = _read(me.vertices, "co", nv, np.float32, 3)
        loop_start = _read(me.polygons, "loop_start", nf, np.int32)
        loop_total = _read(me.polygons, "loop_total", nf, np.int32)
        # Polygons normally use the loops in order; where they do not, put them in that order.
        order = np.repeat(loop_start - np.cumsum(loop_total) + loop_total, loop_total)
        order += np.arange(nl, dtype=np.int32)
        self.loop_vertex = _read(me.loops, "vertex_index", nl, np.int32)[order]
        self.loop_total = loop_total
        loop_edge = _read(me.loops, "edge_index", nl, np.int32)
        self.material = _read(me.polygons, "material_index", nf, np.int32)
        self.used = np.unique(self.loop_vertex)
        self.remap = np.full(nv, -1, np.int32)
        self.remap[self.used] = np.arange(len(self.used), dtype=np.int32)

        edges = _read(me.edges, "vertices", len(me.edges), np.int32, 2)
        creases = _edge_creases(me)
        on_faces = np.zeros(len(me.edges), bool)
        on_faces[loop_edge] = True  # a loose edge is not part of the surface
        tagged = np.flatnonzero((creases > 0) & on_faces)
        self.creases = self.remap[edges[tagged]]
        self.crease_sharpness = crease_to_sharpness(creases[tagged].astype(np.float64))
        self.corner_sharpness = crease_to_sharpness(
            _vertex_creases(me)[self.used].astype(np.float64)
        )

        # Every UV map, per corner; the active one first, the one stitch.Mesh keeps.
        layers = list(me.uv_layers)
        active = me.uv_layers.active
        if active is not None:
            layers.sort(key=lambda layer: layer.name != active.name)
        self.uv_maps = [
            (layer.name, _read(layer.data, "uv", nl, np.float32, 2)[order]) for layer in layers
        ]

    def faces(self):
        """The face loops in stitch's vertex numbers: one array when all faces have one degree."""
        corners = self.remap[self.loop_vertex]
        if not len(self.loop_total):
            return []
        if np.all(self.loop_total == self.loop_total[0]):
            return corners.reshape(len(self.loop_total), int(self.loop_total[0]))
        return np.split(corners, np.cumsum(self.loop_total)[:-1])

    def stitch_positions(self):
        return self.positions[self.used].astype(np.float64)

    def mesh(self, stitch):
        """The stitch.Mesh, with creases, corners and the active UV map (refusals raise
        stitch.StitchError with the library's message)."""
        return stitch.Mesh(
            self.stitch_positions(),
            self.faces(),
            uvs=self.uv_maps[0][1].astype(np.float64) if self.uv_maps else None,
            creases=self.creases if len(self.creases) else None,
            crease_sharpness=self.crease_sharpness if len(self.creases) else None,
            corner_sharpness=self.corner_sharpness if np.any(self.corner_sharpness) else None,
        )

    def same_except_positions(self, other):
        """Whether only vertex positions differ, so the live surface can update them alone."""
        return (
            np.array_equal(self.loop_vertex, other.loop_vertex)
            and np.array_equal(self.loop_total, other.loop_total)
            and len(self.positions) == len(other.positions)
            and np.array_equal(self.creases, other.creases)
            and np.array_equal(self.crease_sharpness, other.crease_sharpness)
            and np.array_equal(self.corner_sharpness, other.corner_sharpness)
            and np.array_equal(self.material, other.material)
            and len(self.uv_maps) == len(other.uv_maps)
            and all(
                a[0] == b[0] and np.array_equal(a[1], b[1])
                for a, b in zip(self.uv_maps, other.uv_maps)
            )
        )


# Where the patches' own normals at a shared sample differ by more than this, the surface has an
# edge there (a crease, a corner's cone, AS&C's kinks); elsewhere they agree to round-off.
KINK_RADIANS = np.radians(0.01)


def fill_mesh(me, vertices, quads, corner_normals, face_materials, uv_maps):
    """Replaces the geometry of `me` with a smooth-shaded quad mesh: (n, 3) vertices, (m, 4)
    quads, (m, 4, 3) the surface's normals at each quad's corners (each patch its own), (m,)
    material indices and (name, (4m, 2) per-corner UVs) maps."""
    nq = len(quads)
    me.clear_geometry()
    me.vertices.add(len(vertices))
    me.vertices.foreach_set("co", np.ascontiguousarray(vertices, np.float32).ravel())
    me.loops.add(4 * nq)
    me.loops.foreach_set("vertex_index", np.ascontiguousarray(quads, np.int32).ravel())
    me.polygons.add(nq)
    me.polygons.foreach_set("loop_start", np.arange(0, 4 * nq, 4, dtype=np.int32))
    me.polygons.foreach_set("loop_total", np.full(nq, 4, np.int32))
    me.polygons.foreach_set("material_index", np.ascontiguousarray(face_materials, np.int32))
    me.polygons.foreach_set("use_smooth", np.ones(nq, bool))
    me.update(calc_edges=True)
    for name, uvs in uv_maps:
        layer = me.uv_layers.new(name=name, do_init=False)
        layer.data.foreach_set("uv", np.ascontiguousarray(uvs, np.float32).ravel())
    if uv_maps:
        me.uv_layers.active_index = 0
    mark_sharp_edges(me, quads, corner_normals)


def mark_sharp_edges(me, quads, corner_normals):
    """Marks the edges where the surface is not smooth (its patches' normals differ at either
    end), so Blender's shading splits its normals there and nowhere else. Blender computes the
    normals from the tessellation, which costs a fraction of setting the exact ones as custom
    normals and follows live updates by itself. A surface without such edges is shaded plainly."""
    quads = np.asarray(quads, np.int64)
    ends = np.roll(quads, -1, axis=1)  # quad side k runs from corner k to corner k + 1
    at_start = corner_normals
    at_end = np.roll(corner_normals, -1, axis=1)
    key = (np.minimum(quads, ends) * len(me.vertices) + np.maximum(quads, ends)).ravel()
    order = np.argsort(key, kind="stable")
    key = key[order]
    # The two sides of an inner edge are neighbours in that order: i runs a -> b, j runs b -> a.
    pair = np.flatnonzero(key[:-1] == key[1:])
    i, j = order[pair], order[pair + 1]
    at_start, at_end = at_start.reshape(-1, 3), at_end.reshape(-1, 3)
    agree = np.minimum(
        np.einsum("ij,ij->i", at_start[i], at_end[j]), np.einsum("ij,ij->i", at_end[i], at_start[j])
    )
    sharp_keys = key[pair[agree < np.cos(KINK_RADIANS)]]
    if hasattr(me, "use_auto_smooth"):  # Blender before 4.1 splits normals at sharp edges only so
        me.use_auto_smooth = len(sharp_keys) > 0
        me.auto_smooth_angle = np.pi
    if not len(sharp_keys):
        return
    edges = np.empty(2 * len(me.edges), np.int32)
    me.edges.foreach_get("vertices", edges)
    edges = edges.reshape(-1, 2).astype(np.int64)
    edge_keys = edges.min(axis=1) * len(me.vertices) + edges.max(axis=1)
    me.edges.foreach_set("use_edge_sharp", np.isin(edge_keys, sharp_keys))
