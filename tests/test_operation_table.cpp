// The operation table and the typed operations: every front end reads the table, the printer and
// the parser are inverses, and can_apply says exactly what applying does.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

TEST(OperationTable, NamesAreUniqueAndSynopsesStartWithThem) {
  std::set<std::string_view> names;
  for (const OperationInfo& info : operation_table()) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    EXPECT_EQ(info.synopsis.substr(0, info.name.size()), info.name);
    EXPECT_FALSE(info.summary.empty()) << info.name;
    EXPECT_FALSE(info.arguments.empty()) << info.name;
    EXPECT_EQ(find_operation(info.name), &info);
  }
  EXPECT_EQ(names.size(), 15u);
  EXPECT_EQ(find_operation("frobnicate"), nullptr);
  EXPECT_EQ(find_operation(""), nullptr);
}

TEST(OperationTable, OnlyTheRemeshingsRenumber) {
  const HalfedgeMesh cube = test::cube_mesh();
  for (const OperationInfo& info : operation_table()) {
    const bool remeshing = info.synopsis == info.name;  // the four take no arguments
    EXPECT_EQ(info.renumbers, remeshing) << info.name;
  }
  for (const char* line : {"doo-sabin", "vertex-insertion", "catmull-clark", "dual"}) {
    const std::optional<Operation> op = parse_operation(cube, line);
    ASSERT_TRUE(op) << line;
    EXPECT_TRUE(std::holds_alternative<ops::Remesh>(*op));
    EXPECT_EQ(operation_info(*op).name, line);
    EXPECT_TRUE(operation_info(*op).renumbers);
  }
}

TEST(OperationTable, BlankAndCommentLinesParseToNothing) {
  const HalfedgeMesh cube = test::cube_mesh();
  EXPECT_FALSE(parse_operation(cube, ""));
  EXPECT_FALSE(parse_operation(cube, "   \t "));
  EXPECT_FALSE(parse_operation(cube, "# insert-edge 1@1 5@2"));
  const std::optional<Operation> op = parse_operation(cube, "  insert-edge 1@1 5@2  # a hole");
  ASSERT_TRUE(op);
  EXPECT_EQ(format_operation(cube, *op), "insert-edge 1@1 5@2");
}

TEST(OperationTable, ParseErrorsAreUsageErrorsNamingTheOperation) {
  const HalfedgeMesh cube = test::cube_mesh();
  auto message = [&](const char* line) -> std::string {
    try {
      parse_operation(cube, line);
    } catch (const UsageError& e) {
      return e.what();
    }
    return "(no UsageError)";
  };
  EXPECT_NE(message("frobnicate 1").find("unknown operation 'frobnicate'"), std::string::npos);
  EXPECT_NE(message("frobnicate 1").find("insert-edge, delete-edge"), std::string::npos);
  EXPECT_NE(message("insert-edge 1@1").find("insert-edge takes two corners"), std::string::npos);
  EXPECT_NE(message("delete-face 99").find("delete-face: there is no face 99"), std::string::npos);
  EXPECT_NE(message("dual 3").find("dual takes no arguments"), std::string::npos);
}

TEST(OperationTable, RefusalsAreTopologyErrors) {
  HalfedgeMesh cube = test::cube_mesh();
  const HalfedgeMesh before = cube;
  // Both corners at vertex 1: the edge would be a loop.
  EXPECT_THROW(apply_operation(cube, "insert-edge 1@1 1@3"), TopologyError);
  EXPECT_EQ(cube, before);
  const Operation op = *parse_operation(cube, "insert-edge 1@1 1@3");
  const Verdict v = can_apply(cube, op);
  EXPECT_FALSE(v);
  EXPECT_NE(v.refusal().find("the edge would be a loop"), std::string::npos);
}

/// A random typed operation on the mesh's live elements, any of the fifteen, valid or not.
Operation random_typed_operation(const HalfedgeMesh& m, std::mt19937& rng) {
  const auto faces = m.faces().to_vector();
  const auto edges = m.edges().to_vector();
  const auto vertices = m.vertices().to_vector();
  auto pick_face = [&] { return faces[rng() % faces.size()]; };
  auto pick_corner = [&] {
    const auto loop = m.face_loop(pick_face());
    return loop[rng() % loop.size()];
  };
  auto pick_edge = [&] { return edges[rng() % edges.size()]; };
  auto sharpness = [&] { return std::array{0.0, 2.5, 10.0, -1.0}[rng() % 4]; };
  switch (rng() % 15) {
    case 0:
    case 1:
    case 2: {  // the central operator, three times as often
      const Corner a = pick_corner();
      // Half the time a corner on the same face, so faces split as well as merge.
      Corner b = pick_corner();
      if (rng() % 2) {
        const auto loop = m.face_loop(m.face(a));
        b = loop[rng() % loop.size()];
      }
      return ops::InsertEdge{a, b};
    }
    case 3:
      return ops::DeleteEdge{pick_edge()};
    case 4:
      return ops::SubdivideEdge{pick_edge()};
    case 5: {
      const Edge e = pick_edge();
      return ops::CollapseEdge{e, m.origin(HalfedgeMesh::halfedge(e, rng() % 2))};
    }
    case 6:
      return ops::ExtrudeFace{pick_face(), 0.25, rng() % 2 ? 1.0 : 0.5};
    case 7: {
      HandleOptions handle;
      if (rng() % 4) handle.twist = static_cast<int>(rng() % 5) - 2;  // else the least twist
      if (rng() % 3 == 0) handle.segments = 2 + static_cast<int>(rng() % 2);
      if (rng() % 4 == 0) handle.waist = 0.75;
      return ops::ConnectFaces{pick_face(), pick_face(), handle};
    }
    case 8:
      return ops::DeleteFace{pick_face()};
    case 9:
      return ops::OpenFace{pick_face()};
    case 10:
      return ops::FillHole{pick_face()};
    case 11:
      return ops::SetCrease{pick_edge(), sharpness()};
    case 12:
      return ops::SetCorner{vertices[rng() % vertices.size()], sharpness()};
    default:
      return ops::Remesh{static_cast<Remeshing>(rng() % 4)};
  }
}

// The printer and the parser are inverses on every operation, and can_apply answers exactly as
// applying does (counts only: with the full census the result must also read back from a file,
// which no check before the edit promises). Fixed seeds; the mesh grows by the accepted edits.
TEST(OperationTable, PrinterParserAndCanApplyAgreeWithTheOperators) {
  int accepted = 0, refused = 0, remeshed = 0;
  std::array<int, std::variant_size_v<Operation>> seen{};
  for (unsigned seed = 1; seed <= 12; ++seed) {
    std::mt19937 rng(seed);
    HalfedgeMesh m = seed % 3 == 0 ? make_tetrahedron() : test::cube_mesh();
    for (int step = 0; step < 120; ++step) {
      Operation op = random_typed_operation(m, rng);
      // Remeshings grow the mesh fourfold: keep the test fast.
      if (std::holds_alternative<ops::Remesh>(op) && m.num_faces() > 60) continue;
      ++seen[op.index()];
      const std::string line = format_operation(m, op);
      const std::optional<Operation> back = parse_operation(m, line);
      ASSERT_TRUE(back) << line;
      EXPECT_EQ(*back, op) << "seed " << seed << ": " << line;
      EXPECT_EQ(format_operation(m, *back), line);

      const Verdict verdict = can_apply(m, op);
      const HalfedgeMesh before = m;
      bool applied = true;
      std::string why;
      try {
        apply_operation(m, op, Census::counts_only);
      } catch (const TopologyError& e) {
        applied = false;
        why = e.what();
      }
      ASSERT_EQ(verdict.applies(), applied)
          << "seed " << seed << ": " << line << ": can_apply says '" << verdict.refusal()
          << "', applying says '" << why << "'";
      if (applied) {
        ++accepted;
        remeshed += std::holds_alternative<ops::Remesh>(op);
      } else {
        ++refused;
        EXPECT_EQ(m, before) << line;
        EXPECT_EQ(why, verdict.refusal()) << line;
      }
    }
  }
  // The sequence exercises both answers and every operation (counts from these seeds).
  EXPECT_GT(accepted, 300);
  EXPECT_GT(refused, 100);
  EXPECT_GT(remeshed, 0);
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_GT(seen[i], 0) << "alternative " << i;
}

TEST(OperationTable, CornerAndEdgeNamesReadBackOnFacesThatVisitAVertexTwice) {
  // The hole through a cube: the merged face runs along the new edge twice, so vertices 1 and 5
  // each appear on it twice and their corners need the #k form.
  HalfedgeMesh m = test::cube_mesh();
  apply_operation(m, "insert-edge 1@1 5@2");
  int twice = 0;
  for (Face f : m.faces())
    for (Halfedge h : m.face_loop(f)) {
      const std::string name = corner_name(m, h);
      twice += name.find('#') != std::string::npos;
      EXPECT_EQ(parse_corner(m, name), h) << name;
    }
  EXPECT_EQ(twice, 4);
  for (Edge e : m.edges()) {
    const std::string name = edge_name(m, e);
    const size_t blank = name.find(' ');
    EXPECT_EQ(parse_edge(m, name.substr(0, blank), name.substr(blank + 1)), e) << name;
  }
}

}  // namespace
}  // namespace stitch
