"""The add-on's panel for docs/blender.md, rendered by Blender itself on a virtual display:

    xvfb-run -a -s "-screen 0 1600x900x24" blender --factory-startup --enable-event-simulate \\
        --python blender/screenshot.py -- docs/figures/blender_panel.png

(STITCH_PYTHON_DIR naming the build's python/ folder unless build/python is beside it). A mesh with
a tunnel and a creased rim is smoothed with the add-on; the source is drawn as wires over its
smooth object, the sidebar shows the Stitch tab, and the window is saved cropped to the 3D view.
Blender draws its UI only in a window, hence the display: `-b` has none."""

import pathlib
import sys

import addon_utils
import bpy
import mathutils

OUT = pathlib.Path(sys.argv[sys.argv.index("--") + 1]).resolve()
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
addon_utils.enable("stitch_addon", default_set=True)
from stitch_addon import smooth  # noqa: E402


def view3d():
    return next(a for a in bpy.context.window.screen.areas if a.type == "VIEW_3D")


def click(x, y):
    window = bpy.context.window
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    window.event_simulate(type="LEFTMOUSE", value="PRESS", x=x, y=y)
    window.event_simulate(type="LEFTMOUSE", value="RELEASE", x=x, y=y)


def scene():
    window = bpy.context.window
    window.event_simulate(type="ESC", value="PRESS")  # the splash screen
    window.event_simulate(type="ESC", value="RELEASE")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    # A cube with a tunnel through two dents (docs/python.md), its top rim creased.
    stitch = smooth.module()
    mesh = stitch.primitive("cube")
    mesh.edit("extrude-face 1 -0.4 0.5", "extrude-face 2 -0.4 0.5", "connect-faces 1 2")
    me = bpy.data.meshes.new("tunnel")
    me.from_pydata(mesh.vertices.tolist(), [], mesh.faces)
    for edge in me.edges:
        edge.crease = 1.0 if all(me.vertices[v].co.z > 0.99 for v in edge.vertices) else 0.0
    obj = bpy.data.objects.new("tunnel", me)
    bpy.context.scene.collection.objects.link(obj)
    obj.display_type = "WIRE"
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    area = view3d()
    area.spaces.active.show_region_ui = True
    area.spaces.active.overlay.show_floor = False
    view = area.spaces.active.region_3d
    view.view_perspective = "PERSP"
    view.view_rotation = mathutils.Euler((0.95, 0.0, 0.7)).to_quaternion()  # from above, aslant
    with bpy.context.temp_override(area=area, region=area.regions[-1]):
        bpy.ops.object.stitch_smooth()
        bpy.ops.view3d.view_selected()
    view.view_distance *= 1.5  # room for the sidebar
    obj.stitch.status = ""
    ui = next(r for r in area.regions if r.type == "UI")
    # The sidebar's tabs run down its right edge: Item, Tool, View, then Stitch. Blender 3.4 has
    # no property for the active tab, so it is clicked.
    click(ui.x + ui.width - 12, ui.y + ui.height - 161)


def shot():
    area = view3d()
    full = OUT.with_suffix(".full.png")
    bpy.ops.screen.screenshot(filepath=str(full))
    try:
        from PIL import Image

        image = Image.open(full)
        top = image.height - (area.y + area.height)
        image.crop((area.x, top, area.x + area.width, top + area.height)).convert("RGB").save(
            OUT, optimize=True
        )
        full.unlink()
    except ImportError:  # python3-pil: keep the whole window
        full.rename(OUT)
    print(f"wrote {OUT}")
    bpy.ops.wm.quit_blender()


bpy.app.timers.register(scene, first_interval=1.0)
bpy.app.timers.register(shot, first_interval=4.0)
