"""Live mode: after every depsgraph update, a source object with "live" on whose geometry changed
(in edit mode too) is smoothed again, incrementally when only its vertices moved."""

import bpy
from bpy.app.handlers import persistent

from . import smooth

# Writing the smooth object's mesh tags the depsgraph again; that update is ours, not the user's.
_updating = False


@persistent
def on_depsgraph_update(scene, depsgraph):
    global _updating
    if _updating:
        return
    changed = set()
    for update in depsgraph.updates:
        if not update.is_updated_geometry:
            continue
        original = update.id.original
        if isinstance(original, bpy.types.Object):
            changed.add(original)
        elif isinstance(original, bpy.types.Mesh):  # an edit of shared data reaches every user
            changed.update(o for o in scene.objects if o.data == original)
    _updating = True
    try:
        for obj in changed:
            if obj.type == "MESH" and obj.stitch.live and obj.stitch.source is None:
                smooth.refresh_live(obj)
    finally:
        _updating = False


def register():
    bpy.app.handlers.depsgraph_update_post.append(on_depsgraph_update)


def unregister():
    if on_depsgraph_update in bpy.app.handlers.depsgraph_update_post:
        bpy.app.handlers.depsgraph_update_post.remove(on_depsgraph_update)
    smooth.LIVE.clear()
