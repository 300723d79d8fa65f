#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/csv_writers.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

using test::read_csv;
using test::Row;

double number(const std::string& field) {
  double value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  EXPECT_TRUE(error == std::errc{} && end == field.data() + field.size()) << field;
  return value;
}

// Two overlapping discs resting on a floor, a third apart from both, cycled
// once so the contacts carry forces.
class CsvWriters : public ::testing::Test {
 protected:
  CsvWriters() : world_(make_world()) { world_.cycle(1); }
  ~CsvWriters() override { std::filesystem::remove_all(directory_); }

  static WorldDef make_world() {
    WorldDef def;
    def.materials.push_back({"disc", 1000, 0.5, 0});
    def.contact_models.push_back({});
    def.particles.push_back({Vec2(0.0, 0.0099), 0.01, MaterialId{0}, Vec2(0.1 / 3, 0), 0.5});
    def.particles.push_back({Vec2(0.0199, 0.0099), 0.01, MaterialId{0}, Vec2::Zero(), 0});
    def.particles.push_back({Vec2(0.1, 0.05), 0.01, MaterialId{0}, Vec2::Zero(), 0});
    WallDef floor;
    floor.name = "floor";
    floor.point = Vec2(-0.05, 0);
    floor.h2 = 0.2;
    def.walls.push_back(floor);
    def.fixed_time_step = 1e-6;
    def.energy_budget = true;
    return def;
  }

  std::filesystem::path directory_ =
      test::fresh_directory(::testing::UnitTest::GetInstance()->current_test_info()->name());
  World world_;
};

TEST_F(CsvWriters, WallsAreLongFormat) {
  WallsCsv walls(directory_ / "nested" / "out");
  walls.write(world_);
  world_.cycle(1);
  walls.write(world_);
  const auto rows = read_csv(directory_ / "nested" / "out" / "walls.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (Row{"cycle", "time", "wall", "fx", "fy", "moment", "normal_force", "contacts", "eccentricity",
                          "x", "y", "dx", "dy", "normal_stress", "settlement"}));
  EXPECT_EQ((Row{rows[1][0], rows[1][1], rows[1][2]}), (Row{"1", "1e-06", "floor"}));
  const WallMeasure measure = world_.wall_measures()[0];
  const Row& row = rows[2];
  EXPECT_EQ(row[0], "2");
  EXPECT_EQ(number(row[3]), measure.force.x());
  EXPECT_EQ(number(row[4]), measure.force.y());
  EXPECT_EQ(number(row[5]), measure.moment);
  EXPECT_EQ(number(row[6]), measure.normal_force);
  EXPECT_EQ(row[7], "2");
  EXPECT_EQ(number(row[8]), measure.eccentricity);
  EXPECT_EQ(number(row[9]), measure.point.x());
  EXPECT_EQ(number(row[12]), measure.displacement.y());
  EXPECT_EQ(number(row[13]), measure.normal_force / world_.wall_area(WallId{0}));
  EXPECT_EQ(number(row[14]), world_.wall_settlement(WallId{0}));
  EXPECT_GT(measure.normal_force, 0);
}

TEST_F(CsvWriters, AssemblyLeavesTheEnergyColumnsEmptyWithoutABudget) {
  WorldDef def = make_world();
  def.energy_budget = false;
  World world(def);
  world.cycle(1);
  AssemblyCsv assembly(directory_);
  assembly.write(world);
  const auto rows = read_csv(directory_ / "assembly.csv");
  ASSERT_EQ(rows.size(), 2u);
  ASSERT_EQ(rows[1].size(), 23u);
  EXPECT_EQ(number(rows[1][2]), world.assembly_measures().kinetic_energy);
  // The quasi-static measures are written with or without a budget.
  EXPECT_EQ(number(rows[1][8]), world.assembly_measures().elastic_energy);
  for (std::size_t column = 15; column < 23; ++column) EXPECT_EQ(rows[1][column], "") << rows[0][column];
}

TEST_F(CsvWriters, AssemblyRoundTripsEveryDigit) {
  AssemblyCsv assembly(directory_);
  assembly.write(world_);
  const auto rows = read_csv(directory_ / "assembly.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (Row{"cycle",
                          "time",
                          "kinetic_energy",
                          "out_of_balance",
                          "max_contact_force",
                          "contacts",
                          "sliding_contacts",
                          "time_step_ratio",
                          "elastic_energy",
                          "kinetic_to_elastic",
                          "unbalanced_force",
                          "sliding_fraction",
                          "mean_stress",
                          "deformation_rate",
                          "inertial_number",
                          "gravity_work",
                          "wall_work",
                          "strain_energy",
                          "contact_damping",
                          "friction",
                          "global_damping",
                          "local_damping",
                          "energy_residual"}));
  const AssemblyMeasures measures = world_.assembly_measures();
  EXPECT_EQ(number(rows[1][1]), world_.time());
  EXPECT_EQ(number(rows[1][2]), measures.kinetic_energy);
  EXPECT_EQ(number(rows[1][3]), measures.out_of_balance);
  EXPECT_EQ(number(rows[1][4]), measures.max_contact_force);
  EXPECT_EQ(rows[1][5], std::to_string(measures.contacts));
  EXPECT_EQ(rows[1][5], "3");
  EXPECT_EQ(number(rows[1][8]), measures.elastic_energy);
  EXPECT_EQ(number(rows[1][9]), measures.kinetic_to_elastic);
  EXPECT_EQ(number(rows[1][10]), measures.unbalanced_force);
  EXPECT_EQ(number(rows[1][11]), measures.sliding_fraction);
  EXPECT_EQ(number(rows[1][12]), measures.mean_stress);
  EXPECT_EQ(number(rows[1][13]), measures.deformation_rate);
  EXPECT_EQ(number(rows[1][14]), measures.inertial_number);
  EXPECT_EQ(number(rows[1][15]), measures.energy.gravity_work);
  EXPECT_EQ(number(rows[1][18]), measures.energy.contact_damping);
  EXPECT_EQ(number(rows[1][22]), measures.energy.residual());
}

TEST_F(CsvWriters, ProbesReportTouchingAndApartPairs) {
  ProbesCsv probes(directory_, {{"pair", ParticleId{0}, ParticleId{1}}, {"apart", ParticleId{0}, ParticleId{2}}});
  probes.write(world_);
  const auto rows = read_csv(directory_ / "probes.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (Row{"cycle", "time", "probe", "normal_force", "shear_force", "touching"}));
  const ContactRecord contact = *world_.contact_between(ParticleId{0}, ParticleId{1});
  EXPECT_EQ(rows[1][2], "pair");
  EXPECT_EQ(number(rows[1][3]), contact.normal_force);
  EXPECT_EQ(number(rows[1][4]), contact.shear_force);
  EXPECT_EQ(rows[1][5], "1");
  EXPECT_EQ(rows[2], (Row{"1", "1e-06", "apart", "0", "0", "0"}));
}

TEST_F(CsvWriters, ContactsNameTheSecondBody) {
  write_contacts_csv(directory_, world_);
  std::ifstream in(directory_ / "contacts.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0],
            "first,second_kind,second,x,y,nx,ny,overlap,normal_force,shear_force,tangential_x,tangential_y,"
            "normal_damping,shear_damping,sliding,formed_cycle,force_x,force_y");
  EXPECT_THAT(lines, ::testing::Contains(::testing::StartsWith("0,particle,1,")));
  EXPECT_THAT(lines, ::testing::Contains(::testing::StartsWith("0,wall,floor,")));
  EXPECT_THAT(lines, ::testing::Contains(::testing::StartsWith("1,wall,floor,")));
}

TEST_F(CsvWriters, ParticlesRoundTrip) {
  write_particles_csv(directory_, world_);
  const auto rows = read_csv(directory_ / "particles.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0],
            (Row{"id", "x", "y", "radius", "vx", "vy", "angular_velocity", "rotation", "material", "a", "b", "n"}));
  const ParticleView particles = world_.particles();
  for (int id = 0; id < 3; ++id) {
    const Row& row = rows[id + 1];
    EXPECT_EQ(row[0], std::to_string(id));
    EXPECT_EQ(number(row[1]), particles.position[ParticleId::from_index(id)].x());
    EXPECT_EQ(number(row[2]), particles.position[ParticleId::from_index(id)].y());
    EXPECT_EQ(number(row[3]), particles.radius[ParticleId::from_index(id)]);
    EXPECT_EQ(number(row[4]), particles.velocity[ParticleId::from_index(id)].x());
    EXPECT_EQ(number(row[5]), particles.velocity[ParticleId::from_index(id)].y());
    EXPECT_EQ(number(row[6]), particles.angular_velocity[ParticleId::from_index(id)]);
    EXPECT_EQ(number(row[7]), particles.rotation[ParticleId::from_index(id)]);
    // Discs: material, and the shape a = b = R, n = 2.
    EXPECT_EQ(row[8], "disc");
    EXPECT_EQ(number(row[9]), particles.radius[ParticleId::from_index(id)]);
    EXPECT_EQ(number(row[10]), particles.radius[ParticleId::from_index(id)]);
    EXPECT_EQ(number(row[11]), 2.0);
  }
}

// Superquadrics keep their semi-axes and exponent; ellipsoids their three semi-axes.
TEST(CsvWritersShapes, SuperquadricsAndEllipsoidsKeepTheirShapes) {
  const auto directory = test::fresh_directory("particles_shapes");
  const LoadedCase superquadrics = load_case_file(std::filesystem::path(DEM_IO_TEST_DATA) / "superquadrics.case.txtpb");
  World world(convert_case(superquadrics.message).world);
  write_particles_csv(directory / "2d", world);
  const auto rows = read_csv(directory / "2d" / "particles.csv");
  ASSERT_EQ(rows.size(), 1u + 22u);
  EXPECT_EQ((Row{rows[1][8], rows[1][9], rows[1][10], rows[1][11]}), (Row{"rock", "0.05", "0.025", "4"}));
  EXPECT_EQ((Row{rows[2][9], rows[2][10], rows[2][11]}), (Row{"0.03", "0.04", "2.5"}));
  EXPECT_EQ((Row{rows[3][9], rows[3][10], rows[3][11]}), (Row{"0.04", "0.02", "4"}));
  EXPECT_EQ(number(rows[1][7]), world.particles().rotation[ParticleId{0}]);  // the angle, 90 degrees

  const LoadedCase ellipsoids = load_case_file(std::filesystem::path(DEM_IO_TEST_DATA) / "ellipsoids.case.txtpb");
  World3 world3(convert_case<3>(ellipsoids.message).world);
  write_particles_csv(directory / "3d", world3);
  const auto rows3 = read_csv(directory / "3d" / "particles.csv");
  ASSERT_EQ(rows3.size(), 1u + 13u);
  EXPECT_EQ((Row{rows3[1][15], rows3[1][16], rows3[1][17], rows3[1][18]}), (Row{"rock", "0.1", "0.07", "0.05"}));
  EXPECT_EQ((Row{rows3[2][16], rows3[2][17], rows3[2][18]}), (Row{"0.08", "0.06", "0.04"}));
}

TEST_F(CsvWriters, AnUnwritableDirectoryIsNamed) {
  // A file where the directory should be: root can write anywhere, so
  // permissions would not make this fail.
  std::filesystem::create_directories(directory_);
  const auto blocker = directory_ / "taken";
  std::ofstream(blocker) << "a file\n";
  try {
    AssemblyCsv assembly(blocker / "out");
    FAIL() << "wrote under a file";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), HasSubstr("cannot create the output directory " + (blocker / "out").string()));
  }
}

TEST_F(CsvWriters, AnUnwritableFileIsNamed) {
  std::filesystem::create_directories(directory_ / "particles.csv");
  try {
    write_particles_csv(directory_, world_);
    FAIL() << "wrote over a directory";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), HasSubstr("cannot write " + (directory_ / "particles.csv").string()));
  }
}

// The 3D counterpart: two overlapping spheres resting on a floor rectangle,
// a third apart from both, cycled once.
class CsvWriters3d : public ::testing::Test {
 protected:
  CsvWriters3d() : world_(make_world()) { world_.cycle(1); }
  ~CsvWriters3d() override { std::filesystem::remove_all(directory_); }

  static WorldDef3 make_world() {
    WorldDef3 def;
    def.materials.push_back({"sphere", 1000, 0.5, 0});
    def.contact_models.push_back({});
    def.particles.push_back({Vec3(0.0, 0.0, 0.0099), 0.01, MaterialId{0}, Vec3(0.1 / 3, 0, 0), Vec3(0, 0, 0.5)});
    def.particles.push_back({Vec3(0.0199, 0.0, 0.0099), 0.01, MaterialId{0}, Vec3::Zero(), Vec3::Zero()});
    def.particles.push_back({Vec3(0.1, 0.05, 0.05), 0.01, MaterialId{0}, Vec3::Zero(), Vec3::Zero()});
    WallDef3 floor;
    floor.name = "floor";
    floor.point = Vec3(-0.05, -0.05, 0);
    floor.h2 = 0.2;
    floor.k2 = 0.1;
    def.walls.push_back(floor);
    def.fixed_time_step = 1e-6;
    return def;
  }

  std::filesystem::path directory_ =
      test::fresh_directory(std::string("3d_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  World3 world_;
};

TEST_F(CsvWriters3d, WallsHaveThreeComponentsAndTwoEccentricities) {
  WallsCsv3 walls(directory_);
  walls.write(world_);
  const auto rows = read_csv(directory_ / "walls.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (Row{"cycle",
                          "time",
                          "wall",
                          "fx",
                          "fy",
                          "fz",
                          "moment_x",
                          "moment_y",
                          "moment_z",
                          "normal_force",
                          "contacts",
                          "eccentricity_u",
                          "eccentricity_v",
                          "x",
                          "y",
                          "z",
                          "dx",
                          "dy",
                          "dz",
                          "normal_stress",
                          "settlement"}));
  const WallMeasure3 measure = world_.wall_measures()[0];
  const Row& row = rows[1];
  EXPECT_EQ(row[2], "floor");
  EXPECT_EQ(number(row[5]), measure.force.z());
  EXPECT_EQ(number(row[6]), measure.moment.x());
  EXPECT_EQ(number(row[8]), measure.moment.z());
  EXPECT_EQ(number(row[9]), measure.normal_force);
  EXPECT_EQ(row[10], "2");
  EXPECT_EQ(number(row[11]), measure.eccentricity.x());
  EXPECT_EQ(number(row[12]), measure.eccentricity.y());
  EXPECT_EQ(number(row[13]), -0.05);
  EXPECT_EQ(number(row[18]), measure.displacement.z());
  EXPECT_EQ(number(row[19]), measure.normal_force / world_.wall_area(WallId{0}));
  EXPECT_EQ(number(row[20]), world_.wall_settlement(WallId{0}));
  EXPECT_GT(measure.normal_force, 0);
}

TEST_F(CsvWriters3d, AssemblyAndProbesKeepTheir2dColumns) {
  AssemblyCsv assembly(directory_);
  assembly.write(world_);
  ProbesCsv probes(directory_, {{"pair", ParticleId{0}, ParticleId{1}}});
  probes.write(world_);
  const auto assembly_rows = read_csv(directory_ / "assembly.csv");
  ASSERT_EQ(assembly_rows.size(), 2u);
  EXPECT_EQ(number(assembly_rows[1][2]), world_.assembly_measures().kinetic_energy);
  const auto probe_rows = read_csv(directory_ / "probes.csv");
  ASSERT_EQ(probe_rows.size(), 2u);
  EXPECT_EQ(number(probe_rows[1][3]), world_.contact_between(ParticleId{0}, ParticleId{1})->normal_force);
  EXPECT_EQ(probe_rows[1][5], "1");
}

TEST_F(CsvWriters3d, ContactsHaveAPointANormalAndTheTangentialForce) {
  write_contacts_csv(directory_, world_);
  const auto rows = read_csv(directory_ / "contacts.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], (Row{"first",
                          "second_kind",
                          "second",
                          "x",
                          "y",
                          "z",
                          "nx",
                          "ny",
                          "nz",
                          "overlap",
                          "normal_force",
                          "shear_force",
                          "tangential_x",
                          "tangential_y",
                          "tangential_z",
                          "normal_damping",
                          "shear_damping",
                          "sliding",
                          "formed_cycle",
                          "force_x",
                          "force_y",
                          "force_z"}));
  for (const ContactRecord3& contact : world_.contacts()) {
    const auto row = std::find_if(rows.begin() + 1, rows.end(), [&](const Row& r) {
      return r[0] == std::to_string(contact.first.value()) &&
             r[1] == (contact.second_wall != kInvalidId ? "wall" : "particle");
    });
    ASSERT_NE(row, rows.end());
    EXPECT_EQ(number((*row)[5]), contact.point.z());
    EXPECT_EQ(number((*row)[8]), contact.normal.z());
    EXPECT_EQ(number((*row)[10]), contact.normal_force);
    EXPECT_EQ(number((*row)[12]), contact.tangential_force.x());
    EXPECT_EQ(number((*row)[14]), contact.tangential_force.z());
    EXPECT_EQ(number((*row)[15]), contact.normal_damping);
    EXPECT_EQ((*row)[17], contact.sliding ? "1" : "0");
    EXPECT_EQ((*row)[18], std::to_string(contact.formed_cycle));
    EXPECT_EQ(number((*row)[19]), contact.force.x());
    EXPECT_EQ(number((*row)[21]), contact.force.z());
  }
  EXPECT_EQ(rows[3][2], "floor");
}

TEST_F(CsvWriters3d, ParticlesHaveVectorsAndQuaternions) {
  world_.cycle(10);
  write_particles_csv(directory_, world_);
  const auto rows = read_csv(directory_ / "particles.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], (Row{"id", "x", "y", "z", "radius", "vx", "vy", "vz", "angular_velocity_x", "angular_velocity_y",
                          "angular_velocity_z", "rotation_w", "rotation_x", "rotation_y", "rotation_z", "material",
                          "a1", "a2", "a3"}));
  const ParticleViewT<3> particles = world_.particles();
  for (int id = 0; id < 3; ++id) {
    const Row& row = rows[id + 1];
    EXPECT_EQ(number(row[3]), particles.position[ParticleId::from_index(id)].z());
    EXPECT_EQ(number(row[4]), particles.radius[ParticleId::from_index(id)]);
    EXPECT_EQ(number(row[7]), particles.velocity[ParticleId::from_index(id)].z());
    EXPECT_EQ(number(row[10]), particles.angular_velocity[ParticleId::from_index(id)].z());
    EXPECT_EQ(number(row[11]), particles.rotation[ParticleId::from_index(id)].w());
    EXPECT_EQ(number(row[14]), particles.rotation[ParticleId::from_index(id)].z());
    EXPECT_EQ(row[15], "sphere");
    EXPECT_EQ(number(row[18]), particles.radius[ParticleId::from_index(id)]);
  }
  EXPECT_NE(number(rows[1][14]), 0);  // the first sphere spins about z
}

std::string field(const auto& value) {
  std::string line;
  append_field(line, value);
  return line;
}

TEST(CsvFields, FormatsAsDocumented) {
  EXPECT_EQ(field(0.1), "0.1");
  EXPECT_EQ(field(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(field(1e-300), "1e-300");
  EXPECT_EQ(field(true), "1");
  EXPECT_EQ(field(-7), "-7");
  EXPECT_EQ(field(std::uint64_t{18446744073709551615u}), "18446744073709551615");
  EXPECT_EQ(field(std::string("floor")), "floor");
  EXPECT_EQ(field("floor, north"), "\"floor, north\"");
  EXPECT_EQ(field("say \"hi\""), "\"say \"\"hi\"\"\"");
}

}  // namespace
}  // namespace dem::io
