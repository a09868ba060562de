"""The sidebar panel (View3D > Sidebar > Stitch): the active object's settings and the buttons."""

import bpy

from . import locate


class STITCH_PT_smooth(bpy.types.Panel):
    bl_label = "Stitch"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stitch"

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def draw(self, context):
        from .operators import source_of
        from .smooth import module

        layout = self.layout
        obj = source_of(context.active_object)
        try:
            module()
        except locate.NotFound:
            layout.label(text="stitch module not found:", icon="ERROR")
            layout.label(text="see Preferences > Add-ons > Stitch")
            return
        settings = obj.stitch
        layout.use_property_split = True
        layout.use_property_decorate = False
        if obj != context.active_object:
            layout.label(text=f"Source: {obj.name}", icon="MESH_DATA")
        for name in ("method", "resolution", "boundary", "uv_mode"):
            layout.prop(settings, name)
        kgons = layout.column(heading="K-gons", align=True)
        for name, text in (
            ("kgon_scale", "Scale"),
            ("kgon_rotate", "Rotate"),
            ("kgon_construction", "Construction"),
        ):
            kgons.prop(settings, name, text=text)
        kgons.prop(settings, "regularize")
        rounding = layout.row()
        rounding.prop(settings, "round_semi_sharp")
        rounding.prop(settings, "sharp_from")
        layout.prop(settings, "live")
        layout.operator("object.stitch_smooth", icon="MOD_SUBSURF")
        if settings.target is not None:
            layout.label(text=f"Smooth object: {settings.target.name}", icon="OUTLINER_OB_MESH")
        if settings.status:
            layout.label(text=settings.status)
        layout.operator("export_scene.stitch_exact", icon="EXPORT")
