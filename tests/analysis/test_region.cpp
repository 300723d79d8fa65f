// Regions: what they contain, their size, and the errors that name the
// region and the field that makes no sense.
#include <gtest/gtest.h>

#include <numbers>

#include "dem/analysis/region.h"
#include "dem/error.h"

namespace dem::analysis {
namespace {

std::string error_of(const Region& region) {
  try {
    check_region(region);
  } catch (const DefinitionError& e) {
    return e.what();
  }
  return "";
}

TEST(Region, BoxAndBallContainTheirPoints) {
  Region box{"box", RegionShape::kBox, {0.0, 0.0}, {2.0, 1.0}};
  EXPECT_TRUE(box.contains({1.0, 0.5}));
  EXPECT_TRUE(box.contains({2.0, 1.0}));  // the boundary counts
  EXPECT_FALSE(box.contains({2.1, 0.5}));
  Region ball{"ball", RegionShape::kBall};
  ball.centre = {1.0, 1.0};
  ball.radius = 0.5;
  EXPECT_TRUE(ball.contains({1.3, 1.4}));
  EXPECT_FALSE(ball.contains({1.4, 1.4}));
  EXPECT_DOUBLE_EQ(region_measure(box), 2.0);
  EXPECT_DOUBLE_EQ(region_measure(ball), std::numbers::pi * 0.25);
  Region3 sphere{"sphere", RegionShape::kBall};
  sphere.radius = 2.0;
  EXPECT_DOUBLE_EQ(region_measure(sphere), 4.0 / 3.0 * std::numbers::pi * 8.0);
  EXPECT_TRUE(Region{"all"}.contains({1e9, -1e9}));
}

TEST(Region, BadDefinitionsNameTheRegionAndTheField) {
  EXPECT_EQ(error_of(Region{}), "region: name must not be empty");
  Region box{"core", RegionShape::kBox, {0.0, 0.0}, {1.0, 0.0}};
  EXPECT_EQ(error_of(box), "region \"core\": box.max.y must be greater than box.min.y");
  Region ball{"circle", RegionShape::kBall};
  EXPECT_EQ(error_of(ball), "region \"circle\": ball.radius must be > 0");
  ball.radius = 1.0;
  ball.centre.x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(ball), "region \"circle\": ball.centre must be finite");
  ball.centre.x() = 0.0;
  EXPECT_EQ(error_of(ball), "");
}

}  // namespace
}  // namespace dem::analysis
