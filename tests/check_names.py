"""One table per concept: no extension, method name or shading-mode name is written as a string
literal outside the table that defines it (issue #36). Run by ctest as names.written_once.

Usage: check_names.py SOURCE_DIR
Prints each literal found elsewhere with its place and exits 1 when there is any.
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
SCANNED = ["src", "apps", "python", "include"]

EXTENSION = re.compile(
    r"\.(obj|ply|off|stl|glb|gltf|bin|step|stp|igs|iges|json|png|stitch)\b", re.IGNORECASE)
METHOD = re.compile(r"\b(mdc|asc|cc)\b")
# A shading mode as a name: the whole literal, or after --mode (the words also describe
# pictures in help texts: "zebra stripes", which is not a name).
# ("patches" and "levels" are also JSON keys and attribute names, so only the rarer words count
# as a whole literal.)
MODE_NAMES = {"shaded", "zebra", "isophote", "checker"}
MODE_OPTION = re.compile(r"--mode (shaded|zebra|isophote|levels|patches|checker)\b")

# The tables themselves, and the few places that dispatch on them.
TABLES = {
    "extension": {
        "include/stitch/mesh/formats.hpp",  # the mesh readers' and writers' extensions
        "src/mesh/io.cpp",  # ... and the one lookup from extension to MeshFileFormat
        "src/mesh/io_gltf.cpp",  # a .gltf's buffer in the .bin beside it
        "src/output/output.cpp",  # the output formats
        "include/stitch/project/project_file.hpp",  # project files
        "src/cad/include/stitch/cad/cad.hpp",  # the CAD files read_cad reads
        "src/cad/cad.cpp",
        "src/render/include/stitch/render/image.hpp",  # the one image format
    },
    "method": {"src/eval/surface.cpp"},
    "mode": {"src/render/renderer.cpp", "src/modeler/project.cpp"},
}

LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')


def literals(path):
    """(line number, text) of every string literal outside comments."""
    in_block = False
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        code = line
        if in_block:
            end = code.find("*/")
            if end < 0:
                continue
            code, in_block = code[end + 2:], False
        code = re.sub(r"/\*.*?\*/", "", code)
        if "/*" in code:
            code, in_block = code[: code.index("/*")], True
        # A // outside a literal starts a comment.
        out, i, quoted = "", 0, False
        while i < len(code):
            c = code[i]
            if c == '"' and (i == 0 or code[i - 1] != "\\"):
                quoted = not quoted
            if not quoted and code.startswith("//", i):
                break
            out += c
            i += 1
        if out.lstrip().startswith("#include"):
            continue
        for m in LITERAL.finditer(out):
            yield number, m.group(1)


found = []
for top in SCANNED:
    for path in sorted((root / top).rglob("*")):
        if path.suffix not in {".cpp", ".hpp", ".h"}:
            continue
        rel = path.relative_to(root).as_posix()
        for number, text in literals(path):
            kinds = []
            if EXTENSION.search(text) and rel not in TABLES["extension"]:
                kinds.append("extension")
            if METHOD.search(text) and rel not in TABLES["method"]:
                kinds.append("method name")
            if (text in MODE_NAMES or MODE_OPTION.search(text)) and rel not in TABLES["mode"]:
                kinds.append("shading-mode name")
            for kind in kinds:
                found.append(f"{rel}:{number}: {kind} in \"{text}\"")

if found:
    print("Names written outside their tables (use the table: choices.hpp, output_formats(), "
          "kMeshReadExtensions, ...):")
    print("\n".join(found))
    sys.exit(1)
print("every extension, method and shading-mode name comes from its table")
