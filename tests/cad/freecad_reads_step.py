"""A real CAD client reads stitch's STEP: FreeCAD (Debian's freecad-python3) imports the files
`stitch smooth` writes and its Part workbench finds a valid shape with the faces, shells and, for
a closed mesh, the solid and volume that stitch reported.

Usage: freecad_reads_step.py STITCH_CLI EXAMPLES_DIR SHAPES_DIR WORK_DIR
Exits 77 (CTest's skip) with a message when FreeCAD cannot be imported.
"""
import os
import re
import subprocess
import sys

sys.path.append("/usr/lib/freecad-python3/lib")
try:
    import FreeCAD  # noqa: F401  (loads the application that Part needs)
    import Part
except ImportError as error:
    print(f"SKIP: FreeCAD's Python module is not installed ({error}); "
          "scripts/install-deps.sh installs freecad-python3")
    sys.exit(77)

cli, examples, shapes, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)

# (mesh, faces stitch must write, closed): a quad is one face and a K-sided face K faces.
CASES = [
    (os.path.join(examples, "cube.obj"), 6, True),
    (os.path.join(examples, "cube_hole.obj"), 14, True),
    # A chess piece with infinitely sharp creases and an open bottom.
    (os.path.join(shapes, "catmark_rook.obj"), None, False),
    # Boundaries, triangles, pentagons.
    (os.path.join(shapes, "catmark_nonquads.obj"), None, False),
]

failures = []
for mesh, faces, closed in CASES:
    name = os.path.splitext(os.path.basename(mesh))[0]
    out = os.path.join(work, name + ".step")
    run = subprocess.run([cli, "smooth", mesh, "-o", out, "-q"], capture_output=True, text=True)
    if run.returncode != 0:
        failures.append(f"{name}: stitch smooth failed: {run.stderr}")
        continue
    summary = run.stdout
    reported_faces = int(re.search(r"\((\d+) B-spline faces", summary).group(1))
    reported_shells = int(re.search(r"(\d+) shell", summary).group(1))
    volume = re.search(r"volume ([0-9.eE+-]+)", summary)

    shape = Part.Shape()
    shape.read(out)
    checks = [
        ("valid", shape.isValid(), True),
        ("faces", len(shape.Faces), reported_faces),
        ("shells", len(shape.Shells), reported_shells),
        ("solids", len(shape.Solids), 1 if closed else 0),
    ]
    if faces is not None:
        checks.append(("faces as the issue counts them", len(shape.Faces), faces))
    for what, got, expected in checks:
        if got != expected:
            failures.append(f"{name}: {what}: FreeCAD {got}, expected {expected}")
    if closed:
        # stitch integrates the patches' polynomials exactly; FreeCAD's Shape.Volume is OCCT's
        # fixed Gauss rule, measured 4e-4 off on faces with many knot spans (the cube's packed
        # faces), so the two agree to 1e-3.
        exact = float(volume.group(1))
        if abs(shape.Volume - exact) > 1e-3 * exact:
            failures.append(f"{name}: volume: FreeCAD {shape.Volume}, stitch {exact}")
    print(f"{name}: FreeCAD reads {len(shape.Faces)} faces, {len(shape.Shells)} shell(s), "
          f"{len(shape.Solids)} solid(s), valid {shape.isValid()}, volume {shape.Volume:.6g}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
