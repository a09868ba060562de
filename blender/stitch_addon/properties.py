"""The add-on's preference (where the stitch module is) and the settings each object keeps. The
names of methods, boundary rules, K-gon constructions and UV modes come from the module's tables
(stitch.choices()), as the command line's and the modeler's do."""

import bpy

from . import locate


def module_or_none():
    try:
        from .smooth import module

        return module()
    except locate.NotFound:
        return None


# Blender shows garbage for enum items whose strings Python no longer holds: keep them.
_ITEMS = {}


def choice_items(keyword):
    """EnumProperty items for one of stitch.choices()' tables, the library's default first."""

    def items(self, context):
        if keyword not in _ITEMS:
            stitch = module_or_none()
            if stitch is None:  # nothing to choose from until the module is found
                return [("", "(stitch module not found)", "see Preferences > Add-ons > Stitch")]
            _ITEMS[keyword] = [(c["name"], c["name"], c["help"]) for c in stitch.choices()[keyword]]
        return _ITEMS[keyword]

    return items


def settings_changed(settings, context):
    """A live source is smoothed again when a setting changes (and when live is turned on)."""
    from . import smooth

    obj = settings.id_data
    smooth.LIVE.pop(obj.as_pointer(), None)
    if settings.live and settings.source is None:
        smooth.refresh_live(obj)


class StitchSettings(bpy.types.PropertyGroup):
    """Per object: a source's smoothing settings and its smooth object, or a smooth object's
    source. The ranges are the library's: it refuses what is out of them, with its message."""

    method: bpy.props.EnumProperty(
        name="Method",
        items=choice_items("method"),
        description="stitch smooth --method",
        update=settings_changed,
    )
    resolution: bpy.props.IntProperty(
        name="Resolution",
        description="Segments per patch side (each face corner is one bicubic patch)",
        default=8,  # stitch smooth's
        min=1,
        soft_max=32,
        update=settings_changed,
    )
    boundary: bpy.props.EnumProperty(
        name="Boundary",
        items=choice_items("boundary"),
        description="stitch smooth --boundary",
        update=settings_changed,
    )
    kgon_scale: bpy.props.FloatProperty(
        name="K-gon Scale",
        description="Scale every K-gon with K != 4 about its centroid (--kgon-scale)",
        default=1.0,
        soft_min=0.1,
        soft_max=3.0,
        update=settings_changed,
    )
    kgon_rotate: bpy.props.FloatProperty(
        name="K-gon Rotate",
        description="Rotate every K-gon with K != 4 in its plane, degrees (--kgon-rotate)",
        default=0.0,
        soft_min=-180.0,
        soft_max=180.0,
        update=settings_changed,
    )
    regularize: bpy.props.BoolProperty(
        name="Regularize",
        description="Replace every K-gon with K != 4 by its best-fitting affinely regular polygon "
        "(--regularize)",
        update=settings_changed,
    )
    kgon_construction: bpy.props.EnumProperty(
        name="K-gon Construction",
        items=choice_items("kgon_construction"),
        description="stitch smooth --kgon-construction",
        update=settings_changed,
    )
    round_semi_sharp: bpy.props.BoolProperty(
        name="Round Semi-sharp",
        description="mdc and asc: round semi-sharp creases at Sharp From (one patch per corner) "
        "instead of honouring them as OpenSubdiv does by refining the mesh first (--sharp-from)",
        update=settings_changed,
    )
    sharp_from: bpy.props.FloatProperty(
        name="Sharp From",
        description="With Round Semi-sharp: sharpness (crease c is 10 c^2, as Blender gives "
        "OpenSubdiv) from which mdc and asc make an edge or corner infinitely sharp, smaller ones "
        "smooth; cc honours every value (--sharp-from)",
        default=4.0,  # --sharp-from's before semi-sharp tags were honoured by refinement
        soft_min=0.0,
        soft_max=10.0,
        update=settings_changed,
    )
    uv_mode: bpy.props.EnumProperty(
        name="UVs",
        items=choice_items("uv"),
        description="How UV maps are carried onto the surface (--uv)",
        update=settings_changed,
    )
    live: bpy.props.BoolProperty(
        name="Live",
        description="Smooth again whenever the mesh changes; moved vertices update only the "
        "patches they change",
        update=settings_changed,
    )
    target: bpy.props.PointerProperty(type=bpy.types.Object, name="Smooth Object")
    source: bpy.props.PointerProperty(type=bpy.types.Object, name="Source")
    status: bpy.props.StringProperty(name="Status", description="What the last live update did")


class StitchPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_dir: bpy.props.StringProperty(
        name="Module Folder",
        description="The folder holding the compiled stitch module (the build's python/ "
        f"folder). Empty: ${locate.ENVIRONMENT}, or the build the add-on's zip was made from",
        subtype="DIR_PATH",
    )

    def draw(self, context):
        self.layout.prop(self, "module_dir")
        try:
            stitch = locate.load(self.module_dir)
            self.layout.label(
                text=f"stitch {stitch.__version__}: {stitch.__file__}", icon="CHECKMARK"
            )
        except locate.NotFound as e:
            column = self.layout.column()
            for line in str(e).split(". "):
                column.label(text=line, icon="ERROR")
