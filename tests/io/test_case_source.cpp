#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dem/io/case_loader.h"
#include "dem/io/case_source.h"
#include "dem/io/case_validation.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

constexpr const char* kText = R"(material { name: "disc" }
wall {
  name: "floor"
  h1: 2
}
stage { wall { wall: "lid" } }
)";

TEST(CaseSource, PointsAtTheFieldsLine) {
  const LoadedCase loaded = parse_case_text(kText, "case.txtpb");
  EXPECT_EQ(describe_problem(loaded.source, "wall[0].h1", "bad"), "case.txtpb:4:3: wall[0].h1: bad");
  EXPECT_EQ(describe_problem(loaded.source, "stage[0].wall[0].wall", "bad"),
            "case.txtpb:6:16: stage[0].wall[0].wall: bad");
}

TEST(CaseSource, AFieldLeftOutPointsAtItsMessage) {
  const LoadedCase loaded = parse_case_text(kText, "case.txtpb");
  EXPECT_EQ(describe_problem(loaded.source, "wall[0].h2", "bad"), "case.txtpb:2:1: wall[0].h2: bad");
  EXPECT_EQ(describe_problem(loaded.source, "wall[0].point.x", "bad"), "case.txtpb:2:1: wall[0].point.x: bad");
}

TEST(CaseSource, UnknownPlacesGiveTheNameAlone) {
  const LoadedCase loaded = parse_case_text(kText, "case.txtpb");
  EXPECT_EQ(describe_problem(loaded.source, "particles", "none"), "case.txtpb: particles: none");
  EXPECT_EQ(describe_problem(loaded.source, "wall[5].h2", "bad"), "case.txtpb: wall[5].h2: bad");
  EXPECT_EQ(describe_problem(loaded.source, "no_such_field[0]", "bad"), "case.txtpb: no_such_field[0]: bad");
  EXPECT_EQ(describe_problem(loaded.source, "wall.h2", "bad"), "case.txtpb: wall.h2: bad");
}

TEST(CaseSource, WithoutLocationsOrName) {
  EXPECT_EQ(describe_problem({.name = "request 3"}, "wall[0].h2", "bad"), "request 3: wall[0].h2: bad");
  EXPECT_EQ(describe_problem({}, "wall[0].h2", "bad"), "wall[0].h2: bad");
}

TEST(CaseSource, ValidationMessagesCarryTheLine) {
  const LoadedCase loaded = parse_case_text(kText, "case.txtpb");
  try {
    validate_case(loaded.message, loaded.source);
    FAIL() << "the case validated";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb:6:16: stage[0].wall[0].wall: unknown wall \"lid\""));
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb:2:1: wall[0].h2: must be greater than h1 (0 <= 2)"));
  }
}

}  // namespace
}  // namespace dem::io
