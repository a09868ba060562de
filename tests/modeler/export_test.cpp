// The modeler writes through the library's table of output formats (write_surface): every
// format, the exact ones included, and the table's own refusals.
#include <gtest/gtest.h>

#include <filesystem>

#include "printed_lines.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/output/output.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"
// OCCT's headers after stitch's: OCCT defines a macro Handle (stitch/cad/cad.hpp).
#if STITCH_MODELER_TESTS_CAD
#include "stitch/cad/cad.hpp"
#endif

namespace stitch::modeler {
namespace {

namespace fs = std::filesystem;

constexpr bool kWithCad = STITCH_MODELER_TESTS_CAD;

TEST(ModelerExport, ScriptsWriteEveryFormatOfTheTable) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  ASSERT_FALSE(run_script(s, {"resolution 3"}, {}));
  for (const OutputFormat& f : output_formats()) {
    const std::string path = dir.file("surface" + std::string(f.extensions[0]));
    SCOPED_TRACE(path);
    Printed printed;
    if (f.needs_cad && !kWithCad) {
      const auto error = run_script(s, {"export " + path}, printed.hooks());
      ASSERT_TRUE(error);
      EXPECT_NE(error->message.find("without OpenCASCADE"), std::string::npos) << error->message;
      continue;
    }
    const ScriptResult r = run_script_line(s, "export " + path, printed.hooks());
    EXPECT_TRUE(fs::exists(path));
    EXPECT_EQ(r.message.rfind("exported " + path + " (", 0), 0u) << r.message;
    EXPECT_NE(r.message.find("method mdc"), std::string::npos) << r.message;
    if (f.kind == OutputKind::tessellated) {
      EXPECT_NE(r.message.find("resolution 3"), std::string::npos) << r.message;
    } else {
      // The writer's notes (the patch set's depth and deviation) reach the script's output.
      ASSERT_FALSE(printed.lines.empty());
      EXPECT_NE(printed.lines[0].find("Bezier patches"), std::string::npos) << printed.lines[0];
    }
  }
  EXPECT_FALSE(s.document.modified());  // an export is no edit
}

TEST(ModelerExport, ExactFilesReadBack) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  const std::string bezier = dir.file("cube.bez.json");
  ASSERT_FALSE(run_script(s, {"method asc", "export " + bezier}, {}));
  const PatchSet patches = read_bezier_json(bezier);
  EXPECT_EQ(patches.method, Method::asc);
  EXPECT_GE(patches.patches.size(), static_cast<size_t>(s.document.mesh().num_halfedges()));
  if (!kWithCad) GTEST_SKIP() << "built without OpenCASCADE";
#if STITCH_MODELER_TESTS_CAD
  // One B-spline face per quad of the cube (the default packing), as the summary says.
  for (const char* extension : {".step", ".igs"}) {
    const std::string path = dir.file(std::string("cube") + extension);
    SCOPED_TRACE(path);
    const ScriptResult r = run_script_line(s, "export " + path, {});
    EXPECT_NE(r.message.find("(6 B-spline faces (quads)"), std::string::npos) << r.message;
    EXPECT_EQ(cad::read_face_names(path).size(), 6u);
  }
#endif
}

TEST(ModelerExport, RefusalsAreTheTables) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  // An extension no row has: the library's message, which lists the table's extensions.
  const std::string unknown = dir.file("surface.xyz");
  std::string expected;
  try {
    output_format(unknown);
  } catch (const UsageError& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  auto error = run_script(s, {"export " + unknown}, {});
  ASSERT_TRUE(error);
  EXPECT_EQ(error->message, expected);
  EXPECT_NE(error->message.find(output_extensions()), std::string::npos) << error->message;
  EXPECT_FALSE(fs::exists(unknown));

  // The Catmull-Clark surface has no exact form: every exact format refuses it.
  ASSERT_FALSE(run_script(s, {"method cc"}, {}));
  for (const OutputFormat& f : output_formats()) {
    if (f.kind != OutputKind::exact) continue;
    const std::string path = dir.file("cc" + std::string(f.extensions[0]));
    error = run_script(s, {"export " + path}, {});
    ASSERT_TRUE(error) << path;
    EXPECT_NE(error->message.find(f.needs_cad && !kWithCad ? "without OpenCASCADE"
                                                           : "not a set of Bezier patches"),
              std::string::npos)
        << error->message;
    EXPECT_FALSE(fs::exists(path));
  }

  // `export` alone: its usage names every format.
  error = run_script(s, {"export"}, {});
  ASSERT_TRUE(error);
  EXPECT_NE(error->message.find(output_extensions()), std::string::npos) << error->message;
}

}  // namespace
}  // namespace stitch::modeler
