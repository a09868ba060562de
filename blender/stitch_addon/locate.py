"""Finding the compiled `stitch` module: it is built for one Python (Debian's 3.11, the one
Debian's Blender runs), outside Blender, so the add-on looks for it in a few folders and says
which ones it tried when it finds none."""

import glob
import importlib.util
import os
import pathlib
import sys

import bpy

ENVIRONMENT = "STITCH_PYTHON_DIR"
HERE = pathlib.Path(__file__).resolve().parent
# Written by scripts/blender-addon-zip.sh: the build's python/ folder on the machine that made the
# zip, so an add-on installed from it finds that build without a preference.
BUILD_DIR_FILE = HERE / "build_dir.txt"


class NotFound(Exception):
    """The module is not where the add-on looked, or does not import there."""


def candidates(preference=""):
    """(folder, where the folder came from) in the order they are tried."""
    found = []
    if preference:
        # Relative to the .blend file ("//...") as Blender's paths are.
        found.append((pathlib.Path(bpy.path.abspath(preference)), "the add-on's preference"))
    if os.environ.get(ENVIRONMENT):
        found.append((pathlib.Path(os.environ[ENVIRONMENT]), f"${ENVIRONMENT}"))
    if BUILD_DIR_FILE.exists():
        found.append(
            (pathlib.Path(BUILD_DIR_FILE.read_text().strip()), "the build the zip came from")
        )
    # Run from the source tree (blender/stitch_addon): the default build folder beside it.
    found.append((HERE.parent.parent / "build" / "python", "the source tree's build/"))
    return found


def load(preference=""):
    """The imported module, or NotFound saying where it was looked for and how to get it."""
    if "stitch" in sys.modules:
        # A compiled module cannot be unloaded: a changed preference takes effect after a restart.
        return sys.modules["stitch"]
    tried = []
    for folder, origin in candidates(preference):
        files = sorted(
            glob.glob(str(folder / "stitch*.so")) + glob.glob(str(folder / "stitch*.pyd"))
        )
        if not files:
            tried.append(f"{folder} ({origin}): no stitch module")
            continue
        spec = importlib.util.spec_from_file_location("stitch", files[0])
        module = importlib.util.module_from_spec(spec)
        try:
            spec.loader.exec_module(module)
        except ImportError as e:  # built for another Python, or a library it needs is missing
            tried.append(f"{files[0]} ({origin}): {e}")
            continue
        sys.modules["stitch"] = module
        return module
    raise NotFound(
        "the stitch Python module was not found. Build it (cmake --build build --target "
        f"stitch_python) for Python {sys.version_info.major}.{sys.version_info.minor} and give its "
        f"folder in Preferences > Add-ons > Stitch, or in ${ENVIRONMENT}. Tried: "
        + "; ".join(tried)
    )
