// Every edit stitch accepts gives a mesh that, written to a file, reads back as the same surface:
// connect-faces over every face pair and twist of the five platonic solids, and random sequences
// of operations. Both ways of applying an operation are covered: the command line's (full census,
// which checks the read-back itself) and the modeler's (counts only, which relies on the reader's
// exhaustive search for which edges are twins).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "random_operation.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using stitch::testing::TempFolder;

BuildOptions as_stitch_reads() {
  BuildOptions options;
  options.allow_two_gons = true;  // as `stitch` and the modeler read every file
  return options;
}

/// `back` is `mesh` read back: the same counts and topology.
void expect_same_surface(const HalfedgeMesh& mesh, const HalfedgeMesh& back,
                         const std::string& what) {
  const TopologyStats a = topology_stats(mesh), b = topology_stats(back);
  EXPECT_EQ(b.vertices, a.vertices) << what;
  EXPECT_EQ(b.edges, a.edges) << what;
  EXPECT_EQ(b.faces, a.faces) << what;
  EXPECT_EQ(b.components, a.components) << what;
  EXPECT_EQ(b.genus, a.genus) << what;
  EXPECT_EQ(b.valence_histogram, a.valence_histogram) << what;
  EXPECT_EQ(b.degree_histogram, a.degree_histogram) << what;
}

/// Writes the mesh to an OBJ file and reads it back, expecting the same surface.
void expect_reads_back(const HalfedgeMesh& mesh, const TempFolder& folder,
                       const std::string& what) {
  const std::string path = folder.file("edited.obj");
  write_mesh(path, mesh);
  HalfedgeMesh back;
  const std::string error = test::error_of([&] { back = read_mesh(path, as_stitch_reads()); });
  ASSERT_EQ(error, "") << what;
  expect_same_surface(mesh, back, what);
}

/// The same through the polygon soup a file holds, without the file (thousands of cases: the
/// writer and the parser are covered by the random sequences below).
void expect_soup_reads_back(const HalfedgeMesh& mesh, const std::string& what) {
  HalfedgeMesh back;
  const std::string error =
      test::error_of([&] { back = build_mesh(to_polygon_soup(mesh), as_stitch_reads()); });
  ASSERT_EQ(error, "") << what;
  expect_same_surface(mesh, back, what);
}

/// Applies the line; false (and the mesh unchanged) when it is refused.
bool try_apply(HalfedgeMesh& mesh, const std::string& line, Census census) {
  const HalfedgeMesh before = mesh;
  try {
    apply_operation(mesh, line, census);
    return true;
  } catch (const Error&) {
    EXPECT_EQ(mesh, before) << line << ": a refused operation changed the mesh";
    return false;
  }
}

struct Solid {
  const char* name;
  std::function<HalfedgeMesh()> make;
};

TEST(EditsReadBack, ConnectFacesOverEveryFacePairAndTwistOfThePlatonicSolids) {
  const std::vector<Solid> solids{{"tetrahedron", make_tetrahedron},
                                  {"cube", make_cube},
                                  {"octahedron", make_octahedron},
                                  {"dodecahedron", make_dodecahedron},
                                  {"icosahedron", make_icosahedron}};
  int accepted = 0, tried = 0;
  for (const Solid& solid : solids) {
    const HalfedgeMesh original = solid.make();
    const int faces = original.num_faces();
    const int k = original.degree(Face(0));
    for (int f = 1; f <= faces; ++f)
      for (int g = 1; g <= faces; ++g) {
        if (f == g) continue;
        for (int twist = 0; twist < k; ++twist) {
          const std::string line = fmt::format("connect-faces {} {} {}", f, g, twist);
          const std::string what = fmt::format("{}: {}", solid.name, line);
          HalfedgeMesh modeler = original, cli = original;
          const bool by_modeler = try_apply(modeler, line, Census::counts_only);
          const bool by_cli = try_apply(cli, line, Census::full);
          ++tried;
          // One validation: what one path accepts the other accepts too, with the same result.
          ASSERT_EQ(by_modeler, by_cli) << what;
          if (!by_modeler) continue;
          ++accepted;
          EXPECT_EQ(modeler, cli) << what;
          expect_soup_reads_back(modeler, what);
        }
      }
  }
  // 4*3*3 + 6*5*4 + 8*7*3 + 12*11*5 + 20*19*3 operations; those joining two corners at one
  // vertex are refused (the edge would be a loop), all others accepted.
  EXPECT_EQ(tried, 36 + 120 + 168 + 660 + 1140);
  EXPECT_GT(accepted, tried / 2);
}

/// A random connect-faces line between two faces of equal degree, when there are any.
std::string random_connect(const HalfedgeMesh& m, std::mt19937& rng) {
  const std::vector<Face> faces = m.faces().to_vector();
  const Face f = faces[rng() % faces.size()];
  std::vector<Face> same;
  for (Face g : faces)
    if (g != f && m.degree(g) == m.degree(f)) same.push_back(g);
  if (same.empty()) return "";
  const Face g = same[rng() % same.size()];
  return fmt::format("connect-faces {} {} {}", f.idx + 1, g.idx + 1,
                     static_cast<int>(rng() % 9) - 4);
}

TEST(EditsReadBack, RandomSequencesReadBackAfterEveryAcceptedOperation) {
  TempFolder folder;
  std::mt19937 rng(20260611);
  const std::vector<std::function<HalfedgeMesh()>> starts{
      make_tetrahedron, make_cube, make_octahedron, [] { return make_prism(3); },
      [] { return make_torus(3, 4); }};
  int accepted = 0;
  for (int sequence = 0; sequence < 120; ++sequence) {
    HalfedgeMesh mesh = starts[sequence % starts.size()]();
    for (int step = 0; step < 8; ++step) {
      std::string line = rng() % 3 == 0 ? random_connect(mesh, rng) : "";
      if (line.empty()) line = test::random_operation(mesh, rng);
      const std::string what = fmt::format("sequence {} step {}: {}", sequence, step, line);
      if (!try_apply(mesh, line, Census::counts_only)) continue;
      ++accepted;
      ASSERT_TRUE(find_problems(mesh).empty()) << what;
      expect_reads_back(mesh, folder, what);
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GT(accepted, 400);
}

}  // namespace
}  // namespace stitch
