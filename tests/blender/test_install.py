"""The add-on as a user installs it, inside Blender:

    BLENDER_USER_SCRIPTS=DIR blender -b --factory-startup --python-exit-code 1 \\
        --python test_install.py -- BUILD_DIR WORK_DIR

scripts/blender-addon-zip.sh packs it, Preferences > Add-ons > Install (addon_install) puts it in
DIR/addons, and the installed add-on finds the module of the build the zip was made from, with
no preference and no $STITCH_PYTHON_DIR."""

import os
import pathlib
import subprocess
import sys

import addon_utils
import bpy

BUILD, WORK = (pathlib.Path(p) for p in sys.argv[sys.argv.index("--") + 1 :])
ROOT = pathlib.Path(__file__).resolve().parents[2]
WORK.mkdir(parents=True, exist_ok=True)
assert "STITCH_PYTHON_DIR" not in os.environ
addons = pathlib.Path(bpy.utils.user_resource("SCRIPTS", path="addons"))
assert str(addons).startswith(os.environ["BLENDER_USER_SCRIPTS"]), addons  # not the user's own

zip_path = WORK / "stitch_addon.zip"
subprocess.run(
    [str(ROOT / "scripts" / "blender-addon-zip.sh"), str(BUILD), str(zip_path)], check=True
)
assert bpy.ops.preferences.addon_install(filepath=str(zip_path), overwrite=True) == {"FINISHED"}
assert (addons / "stitch_addon" / "__init__.py").exists()
addon_utils.enable("stitch_addon", default_set=True)
assert bpy.context.preferences.addons["stitch_addon"].preferences.module_dir == ""

cube = bpy.data.objects["Cube"]  # the factory scene's
bpy.context.view_layer.objects.active = cube
cube.stitch.resolution = 2
assert bpy.ops.object.stitch_smooth() == {"FINISHED"}
assert len(cube.stitch.target.data.vertices) == 98, len(cube.stitch.target.data.vertices)
stitch = sys.modules["stitch"]
assert pathlib.Path(stitch.__file__).parent == BUILD / "python", stitch.__file__
addon_utils.disable("stitch_addon")
print(f"installed from {zip_path.name} into {addons}; the module from {stitch.__file__}")
