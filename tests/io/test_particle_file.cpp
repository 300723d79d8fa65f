#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dem/io/particle_file.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

template <int Dim>
std::vector<std::string> problems(const std::string& text) {
  try {
    parse_particle_text<Dim>(text, "beads.csv");
  } catch (const CaseError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "parsed without an error:\n" << text;
  return {};
}

TEST(ParticleFile, ReadsA3dFileWithCommentsAndAHeader) {
  const auto particles = read_particle_file<3>(test::data_path("spheres_3d.csv"));
  ASSERT_EQ(particles.size(), 3u);
  EXPECT_EQ(particles[0].position, Vec3(0.002, 0.002, 0.001));
  EXPECT_EQ(particles[1].position, Vec3(0.002, 0.006, 0.001));  // spaces after the commas
  EXPECT_EQ(particles[2].radius, 0.0009);                       // after a blank line
  EXPECT_EQ(particles[2].material, MaterialId{0});
  EXPECT_EQ(particles[2].velocity, Vec3::Zero());
}

TEST(ParticleFile, ReadsA2dFileWithoutAHeader) {
  const auto particles = read_particle_file<2>(test::data_path("discs_2d.csv"));
  ASSERT_EQ(particles.size(), 2u);
  EXPECT_EQ(particles[1].position, Vec2(0.08, 0.05));
  EXPECT_EQ(particles[1].radius, 0.01);
}

TEST(ParticleFile, KeepsEveryDigitAndReadsWindowsLineEnds) {
  const auto particles = parse_particle_text<2>("x,y,r\r\n0.1,-2.5e-3,0.30000000000000004\r\n", "beads.csv");
  ASSERT_EQ(particles.size(), 1u);
  EXPECT_EQ(particles[0].position, Vec2(0.1, -2.5e-3));
  EXPECT_EQ(particles[0].radius, 0.30000000000000004);
}

TEST(ParticleFile, AMissingFileIsNamed) {
  const auto path = test::data_path("no_such.csv");
  try {
    read_particle_file<3>(path);
    FAIL() << "a missing file was read";
  } catch (const CaseError& error) {
    EXPECT_EQ(std::string(error.what()), path.string() + ": cannot read the particle file: No such file or directory");
  }
}

TEST(ParticleFile, ADirectoryIsNamed) { EXPECT_THROW(read_particle_file<3>(test::data_path("")), CaseError); }

TEST(ParticleFile, MalformedLinesAreNamedWithTheirNumbers) {
  EXPECT_THAT(problems<3>("# beads\nx,y,z,r\n1,2,3,0.5\n1,2,0.5\n1,2,3,abc\n1,2,3\n"),
              ElementsAre("beads.csv:4: expected 4 values (x,y,z,r), got 3 (x,y,r is a 2D row; the case is 3D)",
                          "beads.csv:5: column 4 (r): \"abc\" is not a number",
                          "beads.csv:6: expected 4 values (x,y,z,r), got 3 (x,y,r is a 2D row; the case is 3D)"));
  EXPECT_THAT(problems<2>("1,2,3,4,5\n"), ElementsAre("beads.csv:1: expected 3 values (x,y,r), got 5"));
  EXPECT_THAT(problems<2>("1,,0.5\n"), ElementsAre("beads.csv:1: column 2 (y): \"\" is not a number"));
  EXPECT_THAT(problems<2>("1,2 3,0.5\n"), ElementsAre("beads.csv:1: column 2 (y): \"2 3\" is not a number"));
  EXPECT_THAT(problems<2>("1,inf,0.5\n"), ElementsAre("beads.csv:1: column 2 (y): must be a finite number (got inf)"));
  EXPECT_THAT(problems<3>("1,2,3,0\n"), ElementsAre("beads.csv:1: column 4 (r): the radius must be > 0 (got 0)"));
}

TEST(ParticleFile, TheHeaderMustMatchTheDimension) {
  EXPECT_THAT(problems<2>("x,y,z,r\n1,2,3,0.5\n"),
              ElementsAre(HasSubstr("beads.csv:1: the header x,y,z,r is that of a 3D file; the case is 2D (columns "
                                    "x,y,r)"),
                          HasSubstr("beads.csv:2: expected 3 values (x,y,r), got 4")));
  EXPECT_THAT(problems<3>("# first a comment\nradius,x,y,z\n1,2,3,0.5\n"),
              ElementsAre("beads.csv:2: the header names the columns radius,x,y,z; expected x,y,z,r (the case is 3D)"));
  // A second header is a row like any other.
  EXPECT_THAT(problems<2>("x,y,r\nx,y,r\n"), ElementsAre(HasSubstr("beads.csv:2: column 1 (x): \"x\" is not a number"),
                                                         HasSubstr("column 2 (y)"), HasSubstr("column 3 (r)")));
}

TEST(ParticleFile, AFileWithoutParticlesIsRefused) {
  EXPECT_THAT(problems<3>("# only comments\nx,y,z,r\n\n"),
              ElementsAre("beads.csv: holds no particles (expected lines of x,y,z,r)"));
}

TEST(ParticleFile, AFileWrongThroughoutShowsTheFirstTenLines) {
  std::string text;
  for (int i = 0; i < 25; ++i) text += "1,2,0.5\n";
  const auto list = problems<3>(text);
  ASSERT_EQ(list.size(), 11u);
  EXPECT_THAT(list[9], HasSubstr("beads.csv:10: expected 4 values"));
  EXPECT_EQ(list[10], "beads.csv: 15 more malformed lines not listed");
}

}  // namespace
}  // namespace dem::io
