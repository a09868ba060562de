"""The operators: Stitch Smooth (the active mesh into its smooth object) and Export Exact Surface
(File > Export: the patches themselves, through stitch's writers). What the library refuses
becomes an error report with its message; its warnings become warning reports."""

import warnings

import bpy
from bpy_extras.io_utils import ExportHelper

from . import locate, properties, smooth


def source_of(obj):
    """The object whose mesh is smoothed: the active one, or the source of a smooth object."""
    return obj.stitch.source or obj


class STITCH_OT_smooth(bpy.types.Operator):
    bl_idname = "object.stitch_smooth"
    bl_label = "Stitch Smooth"
    bl_description = (
        "Smooth the active mesh into a linked object of bicubic patches (stitch); the mesh itself "
        "is kept"
    )
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH"

    def execute(self, context):
        obj = source_of(context.active_object)
        try:
            target, summary, notes = smooth.smooth(obj)
        except (locate.NotFound, ValueError) as e:  # stitch.StitchError is a ValueError
            self.report({"ERROR"}, f"Stitch: {e}")
            return {"CANCELLED"}
        for note in notes:
            self.report({"WARNING"}, f"Stitch: {note}")
        self.report({"INFO"}, summary)
        return {"FINISHED"}


# The exact rows of stitch.output_formats() by first extension, and their enum items (kept alive
# for Blender, see properties._ITEMS).
_ROWS = {}
_FORMATS = []


def exact_formats(self, context):
    if not _FORMATS:
        stitch = properties.module_or_none()
        if stitch is None:
            return [("", "(stitch module not found)", "")]
        for f in stitch.output_formats():
            if f["kind"] == "exact" and f["available"]:
                _ROWS[f["extensions"][0]] = f
                _FORMATS.append(
                    (f["extensions"][0], f"{f['name']} ({', '.join(f['extensions'])})", f["help"])
                )
    return _FORMATS


def takes_faces_and_units(extension):
    """STEP and IGES, the formats written through OpenCASCADE, take faces= and units=."""
    return _ROWS.get(extension, {}).get("needs_cad", False)


class STITCH_OT_export_exact(bpy.types.Operator, ExportHelper):
    bl_idname = "export_scene.stitch_exact"
    bl_label = "Export Exact Surface"
    bl_description = (
        "Write the active mesh's smooth surface itself (STEP, IGES or Bezier JSON patches), not a "
        "tessellation"
    )

    filename_ext = ""  # the format's, see check()
    format: bpy.props.EnumProperty(name="Format", items=exact_formats)
    tolerance: bpy.props.FloatProperty(
        name="Tolerance",
        description="Position tolerance of the cells at extraordinary points, relative to the "
        "model size (stitch smooth --tolerance)",
        default=1e-6,  # stitch smooth's
        soft_min=1e-9,
        soft_max=1e-2,
        precision=8,
    )
    faces: bpy.props.EnumProperty(
        name="Faces",
        items=properties.choice_items("faces"),
        description="STEP and IGES: how patches become faces",
    )
    units: bpy.props.EnumProperty(
        name="Units",
        items=properties.choice_items("units"),
        description="STEP and IGES: declared, not scaled",
    )

    @classmethod
    def poll(cls, context):
        return STITCH_OT_smooth.poll(context)

    def check(self, context):
        """The path with the format's extension, in place of another exact format's."""
        if not self.format:
            return False
        stem = self.filepath
        for extension in sorted(
            {e for row in _ROWS.values() for e in row["extensions"]}, key=len, reverse=True
        ):
            if stem.lower().endswith(extension):  # .bez.json before .json
                stem = stem[: -len(extension)]
                break
        changed = stem + self.format != self.filepath
        self.filepath = stem + self.format
        return changed

    def invoke(self, context, event):
        self.filepath = bpy.path.ensure_ext(
            source_of(context.active_object).name, self.format or ""
        )
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}

    def draw(self, context):
        for name in ("format", "tolerance") + (
            ("faces", "units") if takes_faces_and_units(self.format) else ()
        ):
            self.layout.prop(self, name)

    def execute(self, context):
        obj = source_of(context.active_object)
        self.check(context)
        try:
            stitch = smooth.module()
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                surface = smooth.build_surface(stitch, obj)[0]
                keywords = dict(tolerance=smooth.typed(self.tolerance))
                if takes_faces_and_units(self.format):
                    keywords.update(faces=self.faces, units=self.units)
                report = surface.export(self.filepath, **keywords)
        except (locate.NotFound, ValueError) as e:
            self.report({"ERROR"}, f"Stitch: {e}")
            return {"CANCELLED"}
        for w in caught:
            self.report({"WARNING"}, f"Stitch: {w.message}")
        self.report({"INFO"}, f"{self.filepath}: {report['summary']}")
        return {"FINISHED"}


def export_menu(self, context):
    self.layout.operator(
        STITCH_OT_export_exact.bl_idname, text="Stitch Exact Surface (.step, .igs, .bez.json)"
    )
