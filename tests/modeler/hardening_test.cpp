// The modeler's script commands refuse numbers outside their documented ranges (issue #10), so
// that nothing non-finite reaches the surface, the view or a saved file; a refused line leaves
// the session as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stitch/mesh/limits.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::modeler {
namespace {

TEST(ModelerHardening, RefusesNumbersOutsideTheirRanges) {
  Session s(make_cube());
  const HalfedgeMesh mesh = s.document.mesh();
  const KgonOptions kgons = s.document.kgon_options();
  for (const std::string line :
       {"move-vertex 1 1e300 0 0", "translate-vertex 1 0 0 1e308", "move-vertex 1 nan 0 0",
        "kgon global scale 1e300", "kgon global scale 0", "kgon global rotate 1e308",
        "kgon global offset 0 0 1e200", "orbit 1e308 0", "zoom 1e6", "extrude-face 1 1e308 1e308",
        "connect-faces 1 3 99999999999999", "primitive torus 100000 100000",
        "primitive prism 2147483647"}) {
    const auto error = run_script(s, {line}, {});
    ASSERT_TRUE(error) << line;
    EXPECT_FALSE(error->message.empty()) << line;
    EXPECT_EQ(s.document.mesh(), mesh) << line;
  }
  EXPECT_EQ(s.document.kgon_options().global, kgons.global);
  EXPECT_TRUE(std::isfinite(s.view.distance));
  EXPECT_TRUE(std::isfinite(s.view.yaw_deg));
}

TEST(ModelerHardening, ManyOrbitsAndZoomsKeepTheViewFinite) {
  Session s(make_cube());
  for (int i = 0; i < 200; ++i) ASSERT_FALSE(run_script(s, {"orbit 3600 3600", "zoom 100"}, {}));
  EXPECT_TRUE(std::isfinite(s.view.distance));
  EXPECT_GT(s.view.distance, 0);
  // The yaw is kept within one turn either way.
  EXPECT_LE(std::abs(s.view.yaw_deg), 180.0);
}

TEST(ModelerHardening, QuotesAtMostSixtyCharactersOfABadNumber) {
  Session s(make_cube());
  const std::string token(100'000, '7');
  const auto error = run_script(s, {"zoom " + token + "x"}, {});
  ASSERT_TRUE(error);
  EXPECT_LT(error->message.size(), 200U) << error->message;
  EXPECT_NE(error->message.find("more characters"), std::string::npos) << error->message;
}

}  // namespace
}  // namespace stitch::modeler
