"""stitch in Blender: the active mesh smoothed into bicubic Bezier patches (modified de
Casteljau) in a linked object, its creases, UV maps and materials carried over; live updates as
vertices move; the exact surface exported to STEP, IGES or Bezier JSON. A thin layer over the
stitch Python module (docs/python.md); see docs/blender.md."""

bl_info = {
    "name": "Stitch",
    "author": "stitch",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Stitch; File > Export > Stitch Exact Surface",
    "description": "Smooth surfaces of bicubic Bezier patches from polygon meshes (stitch)",
    "category": "Mesh",
}

import bpy

from . import live, operators, panel, properties

CLASSES = (
    properties.StitchSettings,
    properties.StitchPreferences,
    operators.STITCH_OT_smooth,
    operators.STITCH_OT_export_exact,
    panel.STITCH_PT_smooth,
)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Object.stitch = bpy.props.PointerProperty(type=properties.StitchSettings)
    bpy.types.TOPBAR_MT_file_export.append(operators.export_menu)
    live.register()


def unregister():
    live.unregister()
    bpy.types.TOPBAR_MT_file_export.remove(operators.export_menu)
    del bpy.types.Object.stitch
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
