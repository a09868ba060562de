// The table of K-gon control fields that every front end reads: it covers the whole control,
// and its checks name the field that is out of range.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "stitch/error.hpp"
#include "stitch/kgon/kgon_control.hpp"

namespace stitch {
namespace {

using Kind = KgonControlField::Kind;

/// A value of the field other than its default.
void set_other_than_default(const KgonControlField& f, KgonControl& c) {
  switch (f.kind) {
    case Kind::number:
      c.*f.number = f.name == "rotate" ? 15 : 0.5;
      break;
    case Kind::vector:
      c.*f.vector = Vec3(1, 2, 3);
      break;
    case Kind::flag:
      c.*f.flag = true;
      break;
  }
}

TEST(KgonControlFields, CoverEveryMemberOnceAndNameThemAsFilesDo) {
  // Set through the table, every field of a control written out by hand: a member missing from
  // the table (or listed twice over another's) leaves the two different.
  KgonControl through_table;
  for (const KgonControlField& f : kgon_control_fields()) {
    EXPECT_TRUE(f.is_default(through_table)) << f.name;
    set_other_than_default(f, through_table);
    EXPECT_FALSE(f.is_default(through_table)) << f.name;
    EXPECT_EQ(find_kgon_control_field(f.name), &f);
  }
  const KgonControl by_hand{.scale = 0.5,
                            .rotate_deg = 15,
                            .offset = Vec3(1, 2, 3),
                            .regularize = true,
                            .stretch = 0.5,
                            .stretch_along = Vec3(1, 2, 3)};
  EXPECT_EQ(through_table, by_hand);
  EXPECT_EQ(kgon_control_field_names(),
            "scale, rotate, offset, regularize, stretch, stretch_along");
  EXPECT_EQ(find_kgon_control_field("scael"), nullptr);
}

TEST(KgonControlFields, CheckNamesTheFieldOutOfRange) {
  EXPECT_NO_THROW(check_kgon_control(KgonControl{}));
  struct Bad {
    KgonControl control;
    std::string expected;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Bad& bad : {Bad{{.scale = 0}, "face 2: the scale must be a number from 1e-06"},
                         Bad{{.rotate_deg = 4000}, "face 2: the rotation must be"},
                         Bad{{.offset = Vec3(0, nan, 0)}, "face 2: the offset"},
                         Bad{{.stretch = -1}, "face 2: the stretch must be"},
                         Bad{{.stretch_along = Vec3(1e300, 0, 0)}, "face 2: the stretch direction"},
                         Bad{{.scale = nan}, "face 2: the scale"}}) {
    try {
      check_kgon_control(bad.control, "face 2: ");
      ADD_FAILURE() << "accepted, expected: " << bad.expected;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(bad.expected, 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace stitch
