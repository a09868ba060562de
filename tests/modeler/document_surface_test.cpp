// The Document's changes drive stitch::IncrementalSurface exactly: every edit, undo and redo
// (vertex moves, K-gon controls, topology operations, remeshings) is checked against a surface
// built from scratch. The surface itself is tested with the core alone in
// tests/test_incremental_surface.cpp; this checks the Changes the Document reports.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "incremental_check.hpp"
#include "stitch/modeler/document.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::modeler {
namespace {

void check_update(IncrementalSurface& live, const Document& doc, const Change& change) {
  test::check_update(live, doc.mesh(), doc.kgon_options(), change);
}

TEST(ModelerDocumentSurface, EditsUndoAndRedoKeepTheSurfaceExact) {
  for (Method method : {Method::mdc, Method::asc}) {
    SCOPED_TRACE(to_string(method));
    Document doc(make_cube());
    IncrementalSurface live;
    live.rebuild(doc.mesh(), doc.kgon_options(), method, 2);
    check_update(live, doc, doc.move_vertices({Vertex(2)}, {Vec3(1.2, 1.1, -1.0)}));
    KgonControl k;
    k.scale = 0.7;
    k.rotate_deg = 12;
    check_update(live, doc, doc.set_kgon_control({KgonKind::face, 1}, k));
    check_update(live, doc, doc.set_kgon_control({KgonKind::vertex, 3}, k));
    k.regularize = true;
    check_update(live, doc, doc.set_kgon_control({}, k));  // the global control
    int applied = 0;
    for (const std::string op : {"insert-edge 1@1 5@2", "open-face 2", "subdivide-edge 3 4",
                                 "extrude-face 3 0.4", "crease 1 2 10", "delete-face 4"}) {
      SCOPED_TRACE(op);
      Change c;
      try {
        c = doc.apply_operation(op);
      } catch (const Error&) {
        continue;  // refused: nothing changed
      }
      ++applied;
      check_update(live, doc, c);
    }
    EXPECT_GE(applied, 5);
    int undone = 0;
    while (doc.can_undo()) {
      check_update(live, doc, doc.undo());
      ++undone;
    }
    EXPECT_TRUE(doc.mesh() == make_cube());
    for (int i = 0; i < undone; ++i) check_update(live, doc, doc.redo());
    while (doc.can_undo()) check_update(live, doc, doc.undo());
    // A remeshing (refused with the crease and the hole: so on the cube again) renumbers
    // everything: whole, rebuilt in full, both ways.
    for (int step = 0; step < 2; ++step) {
      const Change c = step == 0 ? doc.apply_operation("catmull-clark") : doc.undo();
      EXPECT_TRUE(c.whole);
      EXPECT_TRUE(live.update(doc.mesh(), doc.kgon_options(), c).full);
      test::expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
    }
  }
}

}  // namespace
}  // namespace stitch::modeler
