#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <string>

#include "dem/io/case_validation.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

TEST(CaseValidation, TheValidCaseHasNoProblems) {
  EXPECT_EQ(test::problem_text(test::valid_case()), "");
  EXPECT_NO_THROW(validate_case(test::valid_case()));
}

TEST(CaseValidation, ReportsEveryProblemAtOnce) {
  proto::Case c = test::valid_case();
  c.mutable_wall(2)->set_h2(0);
  c.mutable_material(0)->set_friction(-1);
  c.mutable_stage(2)->mutable_wall(0)->set_wall("lid");
  try {
    validate_case(c, {.name = "case.txtpb"});
    FAIL() << "the case validated";
  } catch (const CaseError& error) {
    ASSERT_EQ(error.problems().size(), 3u);
    EXPECT_EQ(std::string(error.what()),
              "case.txtpb: material[0].friction: must be >= 0 (got -1)\n"
              "case.txtpb: wall[2].h2: must be greater than h1 (0 <= 0)\n"
              "case.txtpb: stage[2].wall[0].wall: unknown wall \"lid\" "
              "(the case defines \"bottom\", \"left\", \"right\", \"top\")");
  }
}

// Every pair within the contact tolerance gets a contact-table row: it is
// held to the largest particle the sources give, a shape's by its larger
// semi-axis, and only once every source's size passed its own checks.
TEST(CaseValidation, TheContactToleranceIsHeldToTheLargestParticle) {
  proto::Case c = load_case_file(test::data_path("superquadrics.case.txtpb")).message;
  c.mutable_particles(0)->mutable_particle()->mutable_superquadric()->set_a(0.01);
  c.mutable_particles(2)->mutable_random_packing()->mutable_size(0)->mutable_superquadric()->set_b(0.045);
  c.mutable_numerics()->set_contact_tolerance(0.09);
  EXPECT_EQ(test::problem_text(c), "");
  c.mutable_numerics()->set_contact_tolerance(0.091);
  EXPECT_EQ(test::problem_text(c),
            "numerics.contact_tolerance: must be at most the largest particle's diameter (0.09 m), got 0.091 m; leave "
            "it out for a tenth of the mean radius\n");
  // A size that failed its own check does not count: the others' largest does.
  c.mutable_particles(2)->mutable_random_packing()->mutable_size(0)->mutable_superquadric()->set_n(20);
  EXPECT_THAT(test::problem_text(c), HasSubstr("numerics.contact_tolerance: must be at most the largest particle's "
                                               "diameter (0.08 m), got 0.091 m"));
}

// One plausible mistake: a change to the valid case and a piece of the message
// that must name the field.
struct Mistake {
  std::string name;
  std::function<void(proto::Case&)> make;
  std::string expected;
};

std::ostream& operator<<(std::ostream& out, const Mistake& mistake) { return out << mistake.name; }

class CaseMistake : public ::testing::TestWithParam<Mistake> {};

TEST_P(CaseMistake, IsReportedWithItsField) {
  proto::Case c = test::valid_case();
  GetParam().make(c);
  EXPECT_THAT(test::problem_text(c), HasSubstr(GetParam().expected));
  EXPECT_THROW(validate_case(c), CaseError);
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

proto::Lattice& lattice(proto::Case& c) { return *c.mutable_particles(0)->mutable_lattice(); }
proto::Particle& disc(proto::Case& c) { return *c.mutable_particles(1)->mutable_particle(); }
proto::RandomPacking& packing(proto::Case& c) { return *c.mutable_particles(2)->mutable_random_packing(); }
proto::Until& until(proto::Case& c, int stage) { return *c.mutable_stage(stage)->mutable_until(); }
proto::WallMotion& command(proto::Case& c) { return *c.mutable_stage(1)->mutable_wall(0)->mutable_motion(); }
proto::Superquadric& shape(proto::Case& c) {
  disc(c).clear_radius();
  auto& s = *disc(c).mutable_superquadric();
  s.set_a(0.01);
  s.set_b(0.005);
  s.set_n(4);
  return s;
}
proto::Superquadric& packed_shape(proto::Case& c) {
  packing(c).mutable_size(0)->clear_radius();
  auto& s = *packing(c).mutable_size(0)->mutable_superquadric();
  s.set_a(0.005);
  s.set_b(0.0025);
  s.set_n(4);
  return s;
}
proto::CompressionOutput& compression(proto::Case& c) {
  auto& out = *c.mutable_output()->mutable_compression();
  out.set_loading_plate("top");
  out.set_bottom_plate("bottom");
  return out;
}
proto::MeasurementRegion& region(proto::Case& c) {
  auto& r = *c.mutable_output()->add_region();
  r.set_name("core");
  return r;
}
// A biaxial box of the four walls: x by strain rate, y held at 1 kPa.
proto::BoxControl& box_control(proto::Case& c) {
  if (c.has_box_control()) return *c.mutable_box_control();
  auto& box = *c.mutable_box_control();
  auto* x = box.add_axis();
  x->set_lower_wall("left");
  x->set_upper_wall("right");
  x->set_strain_rate(0.01);
  auto* y = box.add_axis();
  y->set_lower_wall("bottom");
  y->set_upper_wall("top");
  y->set_stress(1e3);
  box.set_gain(1e-6);
  box.set_max_speed(0.01);
  return box;
}
proto::ParticleFile& new_particle_file(proto::Case& c) {
  auto& file = *c.add_particles()->mutable_csv_file();
  file.set_path("more.csv");
  file.set_material("disc");
  return file;
}

const Mistake kMistakes[] = {
    // Materials
    {"MaterialWithoutName", [](auto& c) { c.mutable_material(2)->clear_name(); },
     "material[2].name: must not be empty"},
    {"DuplicateMaterial", [](auto& c) { c.mutable_material(1)->set_name("disc"); },
     "material[1].name: duplicate material name \"disc\" (material[0] has it too)"},
    {"NegativeDensity", [](auto& c) { c.mutable_material(1)->set_density(-1); },
     "material[1].density: must be >= 0 (got -1)"},
    {"ParticleMaterialWithoutDensity", [](auto& c) { c.mutable_material(0)->clear_density(); },
     "material[0].density: must be > 0 for a material particles are made of (got 0)"},
    {"NegativeFriction", [](auto& c) { c.mutable_material(0)->set_friction(-0.5); },
     "material[0].friction: must be >= 0 (got -0.5)"},
    {"NegativeCohesion", [](auto& c) { c.mutable_material(2)->set_cohesion(-3); },
     "material[2].cohesion: must be >= 0 (got -3)"},
    {"InfiniteDensity", [](auto& c) { c.mutable_material(0)->set_density(kInfinity); },
     "material[0].density: must be a finite number (got inf)"},
    {"NaNFriction", [](auto& c) { c.mutable_material(0)->set_friction(std::nan("")); },
     "material[0].friction: must be a finite number (got nan)"},
    {"NegativeYoungsModulus", [](auto& c) { c.mutable_material(0)->set_youngs_modulus(-1); },
     "material[0].youngs_modulus: must be >= 0 (got -1)"},
    {"PoissonRatioHalf", [](auto& c) { c.mutable_material(2)->set_poisson_ratio(0.5); },
     "material[2].poisson_ratio: must be in (-1, 0.5) (got 0.5)"},
    {"PoissonRatioMinusOne", [](auto& c) { c.mutable_material(1)->set_poisson_ratio(-1); },
     "material[1].poisson_ratio: must be in (-1, 0.5) (got -1)"},

    // Contact models
    {"ZeroNormalStiffness", [](auto& c) { c.mutable_contact_model(0)->mutable_linear()->set_normal_stiffness(0); },
     "contact_model[0].linear.normal_stiffness: must be > 0 (got 0)"},
    {"NegativeShearStiffness", [](auto& c) { c.mutable_contact_model(1)->mutable_linear()->set_shear_stiffness(-1); },
     "contact_model[1].linear.shear_stiffness: must be >= 0 (got -1)"},
    {"ContactModelWithoutLaw", [](auto& c) { c.mutable_contact_model(2)->clear_linear(); },
     "contact_model[2]: has no law; set one of linear, linear_restitution, hertz_mindlin or hertz_linear_tangential, "
     "as linear { normal_stiffness: ... shear_stiffness: ... }"},
    {"RestitutionLawZeroStiffness",
     [](auto& c) { c.mutable_contact_model(0)->mutable_linear_restitution()->set_restitution(0.5); },
     "contact_model[0].linear_restitution.normal_stiffness: must be > 0 (got 0)"},
    {"RestitutionLawNegativeShearStiffness",
     [](auto& c) { c.mutable_contact_model(0)->mutable_linear_restitution()->set_shear_stiffness(-1); },
     "contact_model[0].linear_restitution.shear_stiffness: must be >= 0 (got -1)"},
    {"RestitutionLawWithoutRestitution",
     [](auto& c) { c.mutable_contact_model(0)->mutable_linear_restitution()->set_normal_stiffness(1e6); },
     "contact_model[0].linear_restitution.restitution: must be in (0, 1] (got 0)"},
    {"HertzNegativeDampingRatio",
     [](auto& c) { c.mutable_contact_model(0)->mutable_hertz_mindlin()->set_damping_ratio(-0.1); },
     "contact_model[0].hertz_mindlin.damping_ratio: must be >= 0 (got -0.1)"},
    {"HertzRestitutionAboveOne",
     [](auto& c) { c.mutable_contact_model(0)->mutable_hertz_linear_tangential()->set_restitution(1.5); },
     "contact_model[0].hertz_linear_tangential.restitution: must be in (0, 1] (got 1.5)"},
    {"HertzWithoutYoungsModulus",
     [](auto& c) {
       for (auto& model : *c.mutable_contact_model()) model.mutable_hertz_mindlin();
     },
     "material[0].youngs_modulus: must be > 0 for a material particles are made of, as a Hertz law serves its "
     "contacts (got 0)"},
    {"TwoLawsForParticles", [](auto& c) { c.mutable_contact_model(0)->mutable_hertz_mindlin(); },
     "contact_model[2]: uses linear for \"disc\" and \"glass\", but contact_model[0] uses hertz_mindlin for "
     "\"disc\" with itself; one law must serve every particle-particle contact"},
    {"TwoLawsForWalls",
     [](auto& c) {
       auto& law = *c.mutable_contact_model(1)->mutable_linear_restitution();
       law.set_normal_stiffness(2e6);
       law.set_restitution(0.5);
     },
     "contact_model[2]: uses linear for \"steel\" and \"glass\", but contact_model[1] uses linear_restitution for "
     "\"disc\" and \"steel\"; one law must serve every particle-wall contact"},
    {"ContactModelUnknownMaterial", [](auto& c) { c.mutable_contact_model(1)->set_materials(1, "iron"); },
     "contact_model[1].materials[1]: unknown material \"iron\" (the case defines \"disc\", \"glass\", \"steel\")"},
    {"ContactModelThreeMaterials", [](auto& c) { c.mutable_contact_model(1)->add_materials("glass"); },
     "contact_model[1].materials: names 3 materials"},
    {"ContactModelNegativeFriction", [](auto& c) { c.mutable_contact_model(1)->set_friction(-0.1); },
     "contact_model[1].friction: must be >= 0 (got -0.1)"},
    {"ContactModelNegativeCohesion", [](auto& c) { c.mutable_contact_model(0)->set_cohesion(-2); },
     "contact_model[0].cohesion: must be >= 0 (got -2)"},
    {"DuplicatePairReversed",
     [](auto& c) {
       c.mutable_contact_model(0)->set_materials(0, "steel");
       c.mutable_contact_model(0)->add_materials("disc");
     },
     "contact_model[1].materials: a second contact model for \"disc\" and \"steel\"; contact_model[0] already "
     "covers the pair"},
    {"SecondDefaultModel", [](auto& c) { c.mutable_contact_model(0)->clear_materials(); },
     "contact_model[2]: is a second default model (one naming no materials); contact_model[0] is the first"},
    {"UncoveredMixedPair", [](auto& c) { c.mutable_contact_model()->RemoveLast(); },
     "contact_model: no contact model for materials \"disc\" and \"glass\", which can touch"},
    {"UncoveredSelfPair", [](auto& c) { c.mutable_contact_model()->RemoveLast(); },
     "contact_model: no contact model for material \"glass\" with itself"},
    {"UncoveredParticleWallPair", [](auto& c) { c.mutable_contact_model()->RemoveLast(); },
     "contact_model: no contact model for materials \"steel\" and \"glass\""},

    // Particles
    {"NoParticles", [](auto& c) { c.clear_particles(); }, "particles: the case defines no particles"},
    {"DimensionFour", [](auto& c) { c.set_dimension(4); }, "dimension: must be 2 or 3 (got 4); leave it out for 2"},
    {"UnknownPlanarParticle", [](auto& c) { c.set_planar_particle(static_cast<proto::Case::PlanarParticle>(7)); },
     "planar_particle: must be DISC or SPHERE (got 7)"},
    {"EmptySource", [](auto& c) { c.mutable_particles(1)->Clear(); },
     "particles[1]: is empty; set particle, lattice, random_packing or csv_file"},
    {"ParticleNegativeRadius", [](auto& c) { disc(c).set_radius(-0.01); },
     "particles[1].particle.radius: must be > 0 (got -0.01)"},
    {"ParticleZeroRadius", [](auto& c) { disc(c).clear_radius(); },
     "particles[1].particle.radius: must be > 0 (got 0)"},
    {"ParticleWithoutMaterial", [](auto& c) { disc(c).clear_material(); },
     "particles[1].particle.material: must name a material"},
    {"ParticleInfiniteVelocity", [](auto& c) { disc(c).mutable_velocity()->set_y(-kInfinity); },
     "particles[1].particle.velocity.y: must be a finite number (got -inf)"},
    {"ParticleZIn2d", [](auto& c) { disc(c).mutable_position()->set_z(0.01); },
     "particles[1].particle.position.z: must be 0 in a 2D case (got 0.01); set dimension: 3 for a 3D case"},
    {"ParticleSpinVectorIn2d", [](auto& c) { disc(c).mutable_angular_velocity_3d()->set_x(1); },
     "particles[1].particle.angular_velocity_3d: is for 3D cases only (this case is 2D); set dimension: 3 for a 3D "
     "case"},
    {"LatticeLayersIn2d", [](auto& c) { lattice(c).set_layers(2); },
     "particles[0].lattice.layers: is for 3D cases only (this case is 2D)"},
    {"PackingZIn2d", [](auto& c) { packing(c).mutable_max()->set_z(0.1); },
     "particles[2].random_packing.max.z: must be 0 in a 2D case (got 0.1)"},
    {"ParticleFileWithoutPath", [](auto& c) { new_particle_file(c).clear_path(); },
     "particles[3].csv_file.path: must name a CSV file of particles (lines of x,y,r), relative to the case file's "
     "directory"},
    {"ParticleFileUnknownMaterial", [](auto& c) { new_particle_file(c).set_material("sand"); },
     "particles[3].csv_file.material: unknown material \"sand\""},
    {"ParticleFileOffsetZIn2d", [](auto& c) { new_particle_file(c).mutable_offset()->set_z(1); },
     "particles[3].csv_file.offset.z: must be 0 in a 2D case (got 1)"},
    {"LatticeUnknownMaterial", [](auto& c) { lattice(c).set_material("sand"); },
     "particles[0].lattice.material: unknown material \"sand\""},
    {"LatticeNegativeRadius", [](auto& c) { lattice(c).set_radius(-1); },
     "particles[0].lattice.radius: must be > 0 (got -1)"},
    {"LatticeNoColumns", [](auto& c) { lattice(c).clear_columns(); }, "particles[0].lattice.columns: must be > 0"},
    {"LatticeNoRows", [](auto& c) { lattice(c).set_rows(0); }, "particles[0].lattice.rows: must be > 0"},
    {"LatticeOverlapping", [](auto& c) { lattice(c).set_spacing(0.015); },
     "particles[0].lattice.spacing: must be at least 2 * radius (0.02) so neighbours do not overlap (got 0.015)"},
    {"LatticeNegativeSpacing", [](auto& c) { lattice(c).set_spacing(-0.03); },
     "particles[0].lattice.spacing: must be >= 0 (got -0.03)"},
    {"PackingBoxInsideOut", [](auto& c) { packing(c).mutable_max()->set_y(0.05); },
     "particles[2].random_packing.max: must lie above and to the right of min (min (0, 0.07), max (0.1, 0.05))"},
    {"PackingNoSizes", [](auto& c) { packing(c).clear_size(); },
     "particles[2].random_packing.size: lists no size classes"},
    {"PackingZeroCount", [](auto& c) { packing(c).mutable_size(0)->clear_count(); },
     "particles[2].random_packing.size[0].count: must be > 0"},
    {"PackingNegativeRadius", [](auto& c) { packing(c).mutable_size(0)->set_radius(-0.005); },
     "particles[2].random_packing.size[0].radius: must be > 0 (got -0.005)"},
    {"PackingDiscTooBig", [](auto& c) { packing(c).mutable_size(0)->set_radius(0.02); },
     "particles[2].random_packing.size[0].radius: discs of radius 0.02 do not fit in the box (0.1 x "},
    {"PackingTooManyAttempts", [](auto& c) { packing(c).set_max_attempts(3'000'000'000u); },
     "particles[2].random_packing.max_attempts: must be at most 10000000 (got 3000000000)"},
    {"SuperquadricWithoutA", [](auto& c) { shape(c).clear_a(); },
     "particles[1].particle.superquadric.a: must be > 0 (got 0)"},
    {"SuperquadricNegativeB", [](auto& c) { shape(c).set_b(-0.005); },
     "particles[1].particle.superquadric.b: must be > 0 (got -0.005)"},
    {"SuperquadricExponentOne", [](auto& c) { shape(c).set_n(1); },
     "particles[1].particle.superquadric.n: must be in (1, 10] (got 1)"},
    {"SuperquadricExponentAboveTen", [](auto& c) { shape(c).set_n(10.5); },
     "particles[1].particle.superquadric.n: must be in (1, 10] (got 10.5)"},
    {"SuperquadricInfiniteAngle", [](auto& c) { shape(c).set_angle_deg(kInfinity); },
     "particles[1].particle.superquadric.angle_deg: must be a finite number (got inf)"},
    {"SuperquadricWithRadius",
     [](auto& c) {
       shape(c);
       disc(c).set_radius(0.01);
     },
     "particles[1].particle.radius: is set by the shape (its bounding radius); leave it out"},
    {"SuperquadricAmongDiscs", [](auto& c) { shape(c); },
     "particles[1].particle: is a superquadric, but particles[0].lattice is a disc; a case's particles are all "
     "discs or all superquadrics"},
    {"SuperquadricSpheres",
     [](auto& c) {
       shape(c);
       c.set_planar_particle(proto::Case::SPHERE);
     },
     "particles[1].particle.superquadric: superquadrics have unit thickness; leave planar_particle out (DISC)"},
    {"PackedSuperquadricWithAngle", [](auto& c) { packed_shape(c).set_angle_deg(30); },
     "particles[2].random_packing.size[0].superquadric.angle_deg: a random packing turns each particle at a "
     "random seeded angle; leave angle_deg out"},
    {"PackedSuperquadricWithRadius",
     [](auto& c) {
       packed_shape(c);
       packing(c).mutable_size(0)->set_radius(0.005);
     },
     "particles[2].random_packing.size[0].radius: is set by the shape (its bounding radius); leave it out"},
    {"PackedSuperquadricTooBig", [](auto& c) { packed_shape(c).set_a(0.02); },
     "particles[2].random_packing.size[0].superquadric: superquadrics with a semi-axis of 0.02 do not fit in the "
     "box (0.1 x 0.03)"},
    {"PackedSuperquadricZeroExponent", [](auto& c) { packed_shape(c).clear_n(); },
     "particles[2].random_packing.size[0].superquadric.n: must be in (1, 10] (got 0)"},
    {"TooManyParticles",
     [](auto& c) {
       lattice(c).set_columns(100'000);
       lattice(c).set_rows(100'000);
     },
     "particles: define 10000000005 particles, more than the particle budget of"},

    // Walls
    {"WallEndsWhereItStarts", [](auto& c) { c.mutable_wall(2)->set_h2(0); },
     "wall[2].h2: must be greater than h1 (0 <= 0)"},
    {"WallBackwards", [](auto& c) { c.mutable_wall(0)->set_h1(0.5); },
     "wall[0].h2: must be greater than h1 (0.1 <= 0.5)"},
    {"WallWithoutName", [](auto& c) { c.mutable_wall(1)->clear_name(); }, "wall[1].name: must not be empty"},
    {"DuplicateWall", [](auto& c) { c.mutable_wall(3)->set_name("top"); },
     "wall[3].name: duplicate wall name \"top\" (wall[2] has it too)"},
    {"WallZeroDirection", [](auto& c) { c.mutable_wall(2)->mutable_direction()->Clear(); },
     "wall[2].direction: must not be zero-length"},
    {"WallWithoutOrientation", [](auto& c) { c.mutable_wall(0)->clear_angle_deg(); },
     "wall[0]: has no orientation; set direction"},
    {"WallInfiniteAngle", [](auto& c) { c.mutable_wall(1)->set_angle_deg(kInfinity); },
     "wall[1].angle_deg: must be a finite number (got inf)"},
    {"WallDirection2In2d", [](auto& c) { c.mutable_wall(0)->mutable_direction2()->set_y(1); },
     "wall[0].direction2: is for 3D cases only (this case is 2D)"},
    {"WallK2In2d", [](auto& c) { c.mutable_wall(0)->set_k2(1); }, "wall[0].k2: is for 3D cases only"},
    {"WallDirectionZIn2d", [](auto& c) { c.mutable_wall(2)->mutable_direction()->set_z(1); },
     "wall[2].direction.z: must be 0 in a 2D case (got 1)"},
    {"WallUnknownMaterial", [](auto& c) { c.mutable_wall(1)->set_material("iron"); },
     "wall[1].material: unknown material \"iron\""},
    {"WallServoWithoutGain", [](auto& c) { c.mutable_wall(2)->mutable_motion()->mutable_servo()->set_max_speed(1); },
     "wall[2].motion.servo.gain: must be > 0 (got 0)"},
    {"WallServoNegativeSpeed",
     [](auto& c) {
       c.mutable_wall(2)->mutable_motion()->mutable_servo()->set_gain(1e-3);
       c.mutable_wall(2)->mutable_motion()->mutable_servo()->set_max_speed(-1);
     },
     "wall[2].motion.servo.max_speed: must be > 0 (got -1)"},
    {"WallServoAndVelocity",
     [](auto& c) {
       auto& motion = *c.mutable_wall(2)->mutable_motion();
       motion.mutable_servo()->set_gain(1e-3);
       motion.mutable_servo()->set_max_speed(1);
       motion.mutable_velocity()->set_y(-1);
     },
     "wall[2].motion: sets both servo and velocity/angular_velocity"},

    // Damping, time step, gravity, numerics
    {"NegativeContactDamping", [](auto& c) { c.mutable_damping()->set_contact_beta(-1e-5); },
     "damping.contact_beta: must be >= 0 (got -1e-05)"},
    {"NegativeGlobalDamping", [](auto& c) { c.mutable_damping()->set_global_alpha(-2); },
     "damping.global_alpha: must be >= 0 (got -2)"},
    {"PeriodicWithoutAxis", [](auto& c) { c.mutable_periodic()->mutable_max()->set_x(1); },
     "periodic: names no periodic axis; set x, y or z to true"},
    {"PeriodicEmptyCell",
     [](auto& c) {
       c.mutable_periodic()->set_x(true);
       c.mutable_periodic()->mutable_min()->set_x(0.1);
     },
     "periodic.max.x: must exceed periodic.min.x (0 <= 0.1)"},
    {"PeriodicZIn2d", [](auto& c) { c.mutable_periodic()->set_z(true); },
     "periodic.z: is for 3D cases only (this case is 2D); set dimension: 3 for a 3D case"},
    {"NegativeRotationalDamping", [](auto& c) { c.mutable_damping()->set_global_alpha_rotation(-1); },
     "damping.global_alpha_rotation: must be >= 0 (got -1)"},
    {"LocalDampingOfOne", [](auto& c) { c.mutable_damping()->set_local_alpha(1.0); },
     "damping.local_alpha: must be in [0, 1) (got 1)"},
    {"NegativeLocalRotationalDamping", [](auto& c) { c.mutable_damping()->set_local_alpha_rotation(-0.1); },
     "damping.local_alpha_rotation: must be in [0, 1) (got -0.1)"},
    {"TimeStepFractionAboveOne", [](auto& c) { c.mutable_time_step()->set_fraction(1.5); },
     "time_step.fraction: must be in (0, 1] (got 1.5)"},
    {"NegativeTimeStepFraction", [](auto& c) { c.mutable_time_step()->set_fraction(-0.1); },
     "time_step.fraction: must be in (0, 1] (got -0.1)"},
    {"NegativeFixedTimeStep", [](auto& c) { c.mutable_time_step()->set_fixed(-1e-6); },
     "time_step.fixed: must be >= 0 (got -1e-06)"},
    {"NaNGravity", [](auto& c) { c.mutable_gravity()->set_x(std::nan("")); },
     "gravity.x: must be a finite number (got nan)"},
    {"GravityZIn2d", [](auto& c) { c.mutable_gravity()->set_z(-9.81); },
     "gravity.z: must be 0 in a 2D case (got -9.81); set dimension: 3 for a 3D case"},
    {"NegativeContactTolerance", [](auto& c) { c.mutable_numerics()->set_contact_tolerance(-0.001); },
     "numerics.contact_tolerance: must be >= 0 (got -0.001)"},
    {"ContactToleranceBeyondTheLargestDiameter", [](auto& c) { c.mutable_numerics()->set_contact_tolerance(0.5); },
     "numerics.contact_tolerance: must be at most the largest particle's diameter (0.02 m), got 0.5 m; leave it out "
     "for a tenth of the mean radius"},
    {"TooManyThreads", [](auto& c) { c.mutable_numerics()->set_threads(3'000'000'000u); },
     "numerics.threads: asks for 3000000000 threads; this machine gives the process"},
    {"HundredThousandThreads", [](auto& c) { c.mutable_numerics()->set_threads(100'000); },
     "numerics.threads: asks for 100000 threads"},

    // Numbers double arithmetic cannot carry through the force laws
    {"SubnormalDensity", [](auto& c) { c.mutable_material(0)->set_density(4.9e-324); },
     "material[0].density: must be at least 1e-30 (got 5e-324): numbers this small underflow"},
    {"HugeStiffness", [](auto& c) { c.mutable_contact_model(0)->mutable_linear()->set_normal_stiffness(1e308); },
     "contact_model[0].linear.normal_stiffness: must be at most 1e+30 in magnitude (got 1e+308)"},
    {"HugePosition", [](auto& c) { disc(c).mutable_position()->set_x(-1e31); },
     "particles[1].particle.position.x: must be at most 1e+30 in magnitude (got -1e+31)"},
    {"TinyRadius", [](auto& c) { disc(c).set_radius(1e-40); },
     "particles[1].particle.radius: must be at least 1e-30 (got 1e-40)"},

    // Particle counts and packings the machine cannot hold
    {"LatticeCountOverflowing64Bits",
     [](auto& c) {
       c.set_dimension(3);
       lattice(c).set_columns(4'000'000'000u);
       lattice(c).set_rows(4'000'000'000u);
       lattice(c).set_layers(4'000'000'000u);
     },
     "particles: define more than 2^64 particles, more than the particle budget"},
    {"PackingGridTooLarge", [](auto& c) { packing(c).mutable_max()->set_x(1e12); },
     "particles[2].random_packing.max: the box is"},
    {"PackingCannotFit", [](auto& c) { packing(c).mutable_size(0)->set_count(1'000'000); },
     "particles[2].random_packing.size: the particles' area"},

    // Stages
    {"StageUnknownWall", [](auto& c) { c.mutable_stage(1)->mutable_wall(0)->set_wall("lid"); },
     "stage[1].wall[0].wall: unknown wall \"lid\" (the case defines \"bottom\", \"left\", \"right\", \"top\")"},
    {"StageCommandWithoutWall", [](auto& c) { c.mutable_stage(2)->mutable_wall(0)->clear_wall(); },
     "stage[2].wall[0].wall: must name a wall"},
    {"StageCommandsAWallTwice", [](auto& c) { c.mutable_stage(2)->add_wall()->set_wall("top"); },
     "stage[2].wall[1].wall: wall \"top\" is already commanded by stage[2].wall[0]"},
    {"StageServoWithoutGain", [](auto& c) { command(c).mutable_servo()->clear_gain(); },
     "stage[1].wall[0].motion.servo.gain: must be > 0 (got 0)"},
    {"StageServoZeroSpeed", [](auto& c) { command(c).mutable_servo()->set_max_speed(0); },
     "stage[1].wall[0].motion.servo.max_speed: must be > 0 (got 0)"},
    {"StageServoInfiniteTarget", [](auto& c) { command(c).mutable_servo()->set_target_force(kInfinity); },
     "stage[1].wall[0].motion.servo.target_force: must be a finite number (got inf)"},
    {"StageSpinVectorIn2d",
     [](auto& c) { c.mutable_stage(2)->mutable_wall(0)->mutable_motion()->mutable_angular_velocity_3d()->set_z(1); },
     "stage[2].wall[0].motion.angular_velocity_3d: is for 3D cases only"},
    {"StageWithoutCycles", [](auto& c) { c.mutable_stage(2)->clear_cycles(); }, "stage[2].cycles: must be > 0"},
    {"StageNegativeDamping", [](auto& c) { c.mutable_stage(1)->mutable_damping()->set_global_alpha(-1); },
     "stage[1].damping.global_alpha: must be >= 0 (got -1)"},
    {"StageTimeStepWithoutValue", [](auto& c) { c.mutable_stage(1)->mutable_time_step(); },
     "stage[1].time_step: set fraction (of the critical step) or fixed (s)"},
    {"StageTimeStepFractionTooLarge", [](auto& c) { c.mutable_stage(1)->mutable_time_step()->set_fraction(1.5); },
     "stage[1].time_step.fraction: must be in (0, 1] (got 1.5)"},
    {"StageFrictionOfUnknownMaterial",
     [](auto& c) {
       auto* friction = c.mutable_stage(0)->add_friction();
       friction->set_material("granite");
       friction->set_friction(0.1);
     },
     "stage[0].friction[0].material: unknown material \"granite\""},
    {"StageNegativeFriction",
     [](auto& c) {
       auto* friction = c.mutable_stage(0)->add_friction();
       friction->set_material(c.material(0).name());
       friction->set_friction(-0.2);
     },
     "stage[0].friction[0].friction: must be >= 0 (got -0.2)"},
    {"UntilWithoutCondition", [](auto& c) { until(c, 0).clear_kinetic_energy_below(); },
     "stage[0].until: sets no stop condition"},
    {"UntilNegativeKineticEnergy", [](auto& c) { until(c, 0).set_kinetic_energy_below(-1); },
     "stage[0].until.kinetic_energy_below: must be > 0 (got -1)"},
    {"UntilZeroOutOfBalance", [](auto& c) { until(c, 0).set_out_of_balance_below(0); },
     "stage[0].until.out_of_balance_below: must be > 0 (got 0)"},
    {"UntilServoToleranceWithoutServo", [](auto& c) { until(c, 0).set_servo_tolerance(0.01); },
     "stage[0].until.servo_tolerance: no wall is servo-controlled during this stage"},
    {"UntilServoToleranceAfterServoStopped", [](auto& c) { until(c, 2).set_servo_tolerance(0.01); },
     "stage[2].until.servo_tolerance: no wall is servo-controlled during this stage"},
    {"UntilStressOfUnknownWall",
     [](auto& c) { until(c, 0).mutable_wall_stress_above()->set_wall("lid"); },
     "stage[0].until.wall_stress_above.wall: unknown wall \"lid\" (the case defines \"bottom\", \"left\", "
     "\"right\", \"top\")"},
    {"UntilSettlementWithoutWall", [](auto& c) { until(c, 0).mutable_wall_settlement_above()->set_value(0.01); },
     "stage[0].until.wall_settlement_above.wall: must name a wall"},
    {"UntilInfiniteStress",
     [](auto& c) {
       until(c, 0).mutable_wall_stress_above()->set_wall("top");
       until(c, 0).mutable_wall_stress_above()->set_value(kInfinity);
     },
     "stage[0].until.wall_stress_above.value: must be a finite number (got inf)"},
    {"TrimRoughWithoutWavelength",
     [](auto& c) {
       c.mutable_stage(1)->mutable_trim()->set_height(0.05);
       c.mutable_stage(1)->mutable_trim()->set_amplitude(0.01);
     },
     "stage[1].trim.wavelength: must be > 0 for a rough surface (amplitude 0.01; got 0)"},
    {"TrimNegativeAmplitude", [](auto& c) { c.mutable_stage(1)->mutable_trim()->set_amplitude(-0.01); },
     "stage[1].trim.amplitude: must be >= 0 (got -0.01)"},
    {"TrimNegativeWavelength", [](auto& c) { c.mutable_stage(1)->mutable_trim()->set_wavelength(-1); },
     "stage[1].trim.wavelength: must be >= 0 (got -1)"},
    {"TrimNaNHeight", [](auto& c) { c.mutable_stage(1)->mutable_trim()->set_height(std::nan("")); },
     "stage[1].trim.height: must be a finite number (got nan)"},
    {"PlaceUnknownWall", [](auto& c) { c.mutable_stage(2)->mutable_place_wall()->set_wall("lid"); },
     "stage[2].place_wall.wall: unknown wall \"lid\""},
    {"PlaceWithNegativeClearance",
     [](auto& c) {
       c.mutable_stage(2)->mutable_place_wall()->set_wall("top");
       c.mutable_stage(2)->mutable_place_wall()->set_clearance(-0.001);
     },
     "stage[2].place_wall.clearance: must be >= 0 (got -0.001)"},
    {"UntilMinCyclesBeyondCap", [](auto& c) { until(c, 0).set_min_cycles(500); },
     "stage[0].until.min_cycles: must not exceed the stage's cycles (500 > 400)"},

    // Output
    {"ProbeUnknownParticle", [](auto& c) { c.mutable_output()->mutable_probe(0)->set_second(99); },
     "output.probe[0].second: no particle with id 99 (the case defines 14 particles, ids 0 to 13)"},
    {"ProbeFirstUnknown", [](auto& c) { c.mutable_output()->mutable_probe(1)->set_first(14); },
     "output.probe[1].first: no particle with id 14"},
    {"ProbeSameParticle", [](auto& c) { c.mutable_output()->mutable_probe(1)->set_second(4); },
     "output.probe[1].second: must differ from first (both are 4)"},
    {"ProbeWithoutName", [](auto& c) { c.mutable_output()->mutable_probe(0)->clear_name(); },
     "output.probe[0].name: must not be empty"},
    {"CompressionUnknownPlate", [](auto& c) { compression(c).set_loading_plate("lid"); },
     "output.compression.loading_plate: unknown wall \"lid\""},
    {"CompressionWithoutBottom", [](auto& c) { compression(c).clear_bottom_plate(); },
     "output.compression.bottom_plate: must name a wall"},
    {"CompressionSamePlates", [](auto& c) { compression(c).set_bottom_plate("top"); },
     "output.compression.bottom_plate: must differ from loading_plate (both are \"top\")"},
    {"CompressionStatesOutOfOrder", [](auto& c) { compression(c).set_transition_stress(300e3); },
     "output.compression.final_stress: must exceed transition_stress (250000 <= 3e+05; 0 stands for the "
     "defaults, 50000 and 250000)"},
    {"CompressionNegativeTransition", [](auto& c) { compression(c).set_transition_stress(-1); },
     "output.compression.transition_stress: must be >= 0 (got -1)"},
    {"CompressionSnapshotAtZero",
     [](auto& c) {
       compression(c).add_contacts_at_stress(50e3);
       compression(c).add_contacts_at_stress(0);
     },
     "output.compression.contacts_at_stress[1]: must be > 0 (got 0)"},
    {"ForceDistributionEmptyWindow",
     [](auto& c) {
       auto& d = *compression(c).mutable_force_distribution();
       d.set_stress_from(600e3);
       d.set_stress_to(400e3);
     },
     "output.compression.force_distribution.stress_to: must exceed stress_from (4e+05 <= 6e+05)"},
    {"ForceDistributionWithoutWindow", [](auto& c) { compression(c).mutable_force_distribution(); },
     "output.compression.force_distribution.stress_from: must be > 0 (got 0)"},
    {"ForceDistributionOneSnapshot",
     [](auto& c) {
       auto& d = *compression(c).mutable_force_distribution();
       d.set_stress_from(400e3);
       d.set_stress_to(600e3);
       d.set_snapshots(1);
     },
     "output.compression.force_distribution.snapshots: must be at least 2"},
    {"ForceDistributionNegativeWidth",
     [](auto& c) { compression(c).mutable_force_distribution()->set_bin_width(-0.25); },
     "output.compression.force_distribution.bin_width: must be >= 0 (got -0.25)"},
    {"StressDropFractionOfOne", [](auto& c) { compression(c).set_stress_drop_fraction(1); },
     "output.compression.stress_drop_fraction: must be in [0, 1) (got 1); leave it out for 0.02"},
    {"DuplicateProbe", [](auto& c) { c.mutable_output()->mutable_probe(1)->set_name("corner"); },
     "output.probe[1].name: duplicate probe name \"corner\" (output.probe[0] has it too)"},
    // Rolling resistance
    {"NegativeRollingFriction", [](auto& c) { c.mutable_contact_model(0)->mutable_rolling()->set_friction(-0.1); },
     "contact_model[0].rolling.friction: must be >= 0 (got -0.1)"},
    {"NegativeRollingDamping", [](auto& c) { c.mutable_contact_model(0)->mutable_rolling()->set_damping_ratio(-1); },
     "contact_model[0].rolling.damping_ratio: must be >= 0 (got -1)"},
    // Measurement regions
    {"RegionWithoutShape", [](auto& c) { region(c); },
     "output.region[0]: has no shape; set whole: true, box { min ... max ... } or ball { centre ... radius ... }"},
    {"RegionWithoutName", [](auto& c) { region(c).clear_name(); },
     "output.region[0].name: must not be empty (it labels the region's rows in regions.csv)"},
    {"DuplicateRegion",
     [](auto& c) {
       region(c).set_whole(true);
       region(c).set_whole(true);
     },
     "output.region[1].name: duplicate region name \"core\" (output.region[0] has it too)"},
    {"FlatBoxRegion",
     [](auto& c) {
       auto& box = *region(c).mutable_box();
       box.mutable_max()->set_x(0.1);
       box.mutable_max()->set_y(-0.1);
     },
     "output.region[0].box.max.y: must be greater than box.min.y (-0.1 <= 0)"},
    {"BallWithoutRadius", [](auto& c) { region(c).mutable_ball()->mutable_centre()->set_x(0.05); },
     "output.region[0].ball.radius: must be > 0 (got 0)"},
    {"BallIn3d", [](auto& c) { region(c).mutable_ball()->mutable_centre()->set_z(0.05); },
     "output.region[0].ball.centre.z: must be 0 in a 2D case"},
    // Box control
    {"BoxWithOneAxis", [](auto& c) { box_control(c).mutable_axis()->RemoveLast(); },
     "box_control.axis: must list 2 axes (x then y) in a 2D case (got 1)"},
    {"BoxUnknownWall", [](auto& c) { box_control(c).mutable_axis(1)->set_upper_wall("lid"); },
     "box_control.axis[1].upper_wall: unknown wall \"lid\""},
    {"BoxSameWallTwice", [](auto& c) { box_control(c).mutable_axis(0)->set_upper_wall("left"); },
     "box_control.axis[0].upper_wall: must differ from lower_wall (both are \"left\")"},
    {"BoxAxisWithoutControl", [](auto& c) { box_control(c).mutable_axis(0)->clear_strain_rate(); },
     "box_control.axis[0]: says nothing of what drives it; set strain_rate (1/s), stress (Pa) or stress_path: true"},
    {"BoxNegativeStress", [](auto& c) { box_control(c).mutable_axis(1)->set_stress(-5); },
     "box_control.axis[1].stress: must be > 0 (got -5)"},
    {"BoxServoWithoutGain", [](auto& c) { box_control(c).clear_gain(); },
     "box_control.gain: must be > 0 (got 0)"},
    {"BoxPathWithoutPath", [](auto& c) { box_control(c).mutable_axis(1)->set_stress_path(true); },
     "box_control: an axis follows the stress path, but no path is set; set constant_mean_stress or stress_ratio"},
    {"BoxPathWithoutAxis", [](auto& c) { box_control(c).set_constant_mean_stress(1e3); },
     "box_control: sets a stress path, but no axis follows it; set stress_path: true on an axis"},
    {"BoxRatioBelowOne",
     [](auto& c) {
       box_control(c).mutable_axis(1)->set_stress_path(true);
       box_control(c).set_stress_ratio(0.5);
     },
     "box_control.stress_ratio: must be >= 1 (sigma_1 / sigma_3; got 0.5)"},
    {"StageBoxSetAndReleased",
     [](auto& c) {
       c.mutable_stage(1)->mutable_box_control()->CopyFrom(box_control(c));
       c.mutable_stage(1)->set_release_box_control(true);
     },
     "stage[1].release_box_control: a stage sets box_control or releases it, not both"},
    {"DeviatorStrainWithoutBox", [](auto& c) { until(c, 0).set_deviator_strain_above(0.01); },
     "stage[0].until.deviator_strain_above: no box control is set during this stage (box_control)"},
    {"RemoveUnknownWall", [](auto& c) { c.mutable_stage(1)->add_remove_wall("orifice"); },
     "stage[1].remove_wall[0]: unknown wall \"orifice\""},

    // Randall's preparation (1989, 4.4-4.5.2, 6.4.2)
    {"BoxContinuumInAPeriodicCell",
     [](auto& c) {
       box_control(c).set_continuum(true);
       c.mutable_periodic()->set_x(true);
       c.mutable_periodic()->mutable_max()->set_x(1);
     },
     "box_control.continuum: a continuum field carries the particles across a deforming box; a periodic cell does "
     "not deform (leave periodic out or continuum false)"},
    {"NegativeCentripetalGravity", [](auto& c) { c.mutable_centripetal_gravity()->set_acceleration(-1); },
     "centripetal_gravity.acceleration: must be >= 0 (got -1)"},
    {"CentripetalCentreNotFinite",
     [](auto& c) { c.mutable_centripetal_gravity()->mutable_centre()->set_x(kInfinity); },
     "centripetal_gravity.centre.x: must be a finite number (got inf)"},
    {"StageBodyForceNegative",
     [](auto& c) { c.mutable_stage(1)->mutable_body_force()->mutable_centripetal()->set_acceleration(-2); },
     "stage[1].body_force.centripetal.acceleration: must be >= 0 (got -2)"},
    {"StageGravityNotFinite",
     [](auto& c) { c.mutable_stage(1)->mutable_body_force()->mutable_gravity()->set_y(kInfinity); },
     "stage[1].body_force.gravity.y: must be a finite number (got inf)"},
    {"UntilOutOfBalanceInAnUnknownRegion",
     [](auto& c) {
       region(c).set_whole(true);
       until(c, 0).mutable_region_out_of_balance_below()->set_region("centre");
       until(c, 0).mutable_region_out_of_balance_below()->set_value(0.1);
     },
     "stage[0].until.region_out_of_balance_below.region: names no output.region (\"core\"; got \"centre\")"},
    {"UntilOutOfBalanceInARegionWithoutValue",
     [](auto& c) {
       region(c).set_whole(true);
       until(c, 0).mutable_region_out_of_balance_below()->set_region("core");
     },
     "stage[0].until.region_out_of_balance_below.value: must be > 0 (got 0)"},
};

INSTANTIATE_TEST_SUITE_P(CaseValidation, CaseMistake, ::testing::ValuesIn(kMistakes),
                         [](const auto& test) { return test.param.name; });

// The same, starting from the valid 3D case.
class CaseMistake3d : public ::testing::TestWithParam<Mistake> {};

TEST_P(CaseMistake3d, IsReportedWithItsField) {
  proto::Case c = test::valid_3d_case().message;
  GetParam().make(c);
  EXPECT_THAT(test::problem_text(c), HasSubstr(GetParam().expected));
  EXPECT_THROW(validate_case(c), CaseError);
}

proto::Particle& sphere(proto::Case& c) { return *c.mutable_particles(0)->mutable_particle(); }

// Gives a particle or a size class an ellipsoid's semi-axes.
template <typename Source>
proto::Ellipsoid& ellipsoid(Source& source, double a1, double a2, double a3) {
  proto::Vector& axes = *source.mutable_ellipsoid()->mutable_semi_axes();
  axes.set_x(a1);
  axes.set_y(a2);
  axes.set_z(a3);
  return *source.mutable_ellipsoid();
}

void set(proto::Vector& v, const std::array<double, 3>& xyz) {
  v.set_x(xyz[0]);
  v.set_y(xyz[1]);
  v.set_z(xyz[2]);
}

void face(proto::Wall& wall, const std::array<double, 3>& i, const std::array<double, 3>& j,
          const std::array<double, 3>& k) {
  proto::Triangle& t = *wall.add_face();
  set(*t.mutable_i(), i);
  set(*t.mutable_j(), j);
  set(*t.mutable_k(), k);
}

const Mistake kMistakes3d[] = {
    {"PlanarSphereIn3d", [](auto& c) { c.set_planar_particle(proto::Case::SPHERE); },
     "planar_particle: is for 2D cases only (this case is 3D); 3D particles are spheres"},
    {"ScalarSpinIn3d", [](auto& c) { sphere(c).set_angular_velocity(1); },
     "particles[0].particle.angular_velocity: is for 2D cases only (this case is 3D); set angular_velocity_3d { x: "
     "... y: ... z: ... }"},
    {"NaNSpinVector", [](auto& c) { sphere(c).mutable_angular_velocity_3d()->set_z(std::nan("")); },
     "particles[0].particle.angular_velocity_3d.z: must be a finite number (got nan)"},
    {"InfiniteZ", [](auto& c) { sphere(c).mutable_position()->set_z(kInfinity); },
     "particles[0].particle.position.z: must be a finite number (got inf)"},
    {"PackingFlatBox", [](auto& c) { c.mutable_particles(2)->mutable_random_packing()->mutable_max()->set_z(0.006); },
     "particles[2].random_packing.max: must exceed min along x, y and z (min (0, 0, 0.006), max (0.01, 0.01, "
     "0.006))"},
    {"PackingSphereTooBig",
     [](auto& c) { c.mutable_particles(2)->mutable_random_packing()->mutable_size(0)->set_radius(0.003); },
     "particles[2].random_packing.size[0].radius: spheres of radius 0.003 do not fit in the box (0.01 x 0.01 x "},
    {"AngleDegIn3d", [](auto& c) { c.mutable_wall(0)->set_angle_deg(0); },
     "wall[0].angle_deg: is for 2D cases only (this case is 3D); set direction { x: ... y: ... z: ... } and "
     "direction2"},
    {"WallWithoutOrientation3d", [](auto& c) { c.mutable_wall(0)->clear_direction(); },
     "wall[0]: has no orientation; set direction { x: ... y: ... z: ... } and direction2"},
    {"WallWithoutDirection2", [](auto& c) { c.mutable_wall(3)->clear_direction2(); },
     "wall[3].direction2: must be set for a 3D wall"},
    {"WallZeroDirection2", [](auto& c) { c.mutable_wall(3)->mutable_direction2()->Clear(); },
     "wall[3].direction2: must not be zero-length"},
    {"WallSidesNotPerpendicular", [](auto& c) { c.mutable_wall(0)->mutable_direction2()->set_x(1); },
     "wall[0].direction2: must be perpendicular to direction (they are 45 degrees apart)"},
    {"WallK2BelowK1", [](auto& c) { c.mutable_wall(1)->set_k2(0); }, "wall[1].k2: must be greater than k1 (0 <= 0)"},
    {"WallInfiniteK1", [](auto& c) { c.mutable_wall(1)->set_k1(-kInfinity); },
     "wall[1].k1: must be a finite number (got -inf)"},
    {"StageScalarSpinIn3d",
     [](auto& c) { c.mutable_stage(1)->mutable_wall(0)->mutable_motion()->set_angular_velocity(1); },
     "stage[1].wall[0].motion.angular_velocity: is for 2D cases only (this case is 3D)"},
    {"ServoAndSpinVector",
     [](auto& c) {
       auto& motion = *c.mutable_wall(5)->mutable_motion();
       motion.mutable_servo()->set_gain(1e-3);
       motion.mutable_servo()->set_max_speed(1);
       motion.mutable_angular_velocity_3d()->set_x(1);
     },
     "wall[5].motion: sets both servo and velocity/angular_velocity"},
    {"HertzParticleWithoutYoungsModulus", [](auto& c) { c.mutable_material(1)->clear_youngs_modulus(); },
     "material[1].youngs_modulus: must be > 0 for a material particles are made of, as a Hertz law serves its "
     "contacts (got 0)"},
    {"LinearWallLawAmongHertz",
     [](auto& c) {
       auto& law = *c.mutable_contact_model(2)->mutable_linear();
       law.set_normal_stiffness(1e6);
     },
     "contact_model[2]: uses linear for \"glass\" and \"wall\", but contact_model[1] uses hertz_mindlin for "
     "\"steel\" and \"wall\"; one law must serve every particle-wall contact (particle-particle and particle-wall "
     "laws may differ)"},
    {"SuperquadricIn3d",
     [](auto& c) {
       sphere(c).clear_radius();
       auto& s = *sphere(c).mutable_superquadric();
       s.set_a(0.002);
       s.set_b(0.001);
       s.set_n(4);
     },
     "particles[0].particle.superquadric: is for 2D cases only (this case is 3D); 3D particles are spheres or "
     "ellipsoids (set ellipsoid)"},
    {"EllipsoidWithRadius", [](auto& c) { ellipsoid(sphere(c), 0.002, 0.0015, 0.001); },
     "particles[0].particle.radius: is set by the shape (its bounding radius); leave it out"},
    {"EllipsoidWithoutSemiAxes", [](auto& c) { sphere(c).clear_radius(), sphere(c).mutable_ellipsoid(); },
     "particles[0].particle.ellipsoid.semi_axes: must be set"},
    {"EllipsoidFlatAxis",
     [](auto& c) {
       sphere(c).clear_radius();
       ellipsoid(sphere(c), 0.002, 0.0015, 0);
     },
     "particles[0].particle.ellipsoid.semi_axes.z: must be > 0 (got 0)"},
    {"EllipsoidZeroQuaternion",
     [](auto& c) {
       sphere(c).clear_radius();
       ellipsoid(sphere(c), 0.002, 0.0015, 0.001).mutable_orientation();
     },
     "particles[0].particle.ellipsoid.orientation: must not be zero"},
    {"EllipsoidAmongSpheres",
     [](auto& c) {
       sphere(c).clear_radius();
       ellipsoid(sphere(c), 0.002, 0.0015, 0.001);
     },
     "particles[1].lattice: is a sphere, but particles[0].particle is an ellipsoid; a case's particles are all "
     "spheres or all ellipsoids"},
    {"PackedEllipsoidWithOrientation",
     [](auto& c) {
       auto& size = *c.mutable_particles(2)->mutable_random_packing()->mutable_size(0);
       size.clear_radius();
       ellipsoid(size, 0.001, 0.0008, 0.0005).mutable_orientation()->set_w(1);
     },
     "particles[2].random_packing.size[0].ellipsoid.orientation: a random packing turns each particle to a "
     "uniformly random orientation; leave it out"},
    {"PackedEllipsoidTooLong",
     [](auto& c) {
       auto& size = *c.mutable_particles(2)->mutable_random_packing()->mutable_size(0);
       size.clear_radius();
       ellipsoid(size, 0.003, 0.0008, 0.0005);
     },
     "particles[2].random_packing.size[0].ellipsoid: ellipsoids with a semi-axis of 0.003 do not fit in the box "
     "(0.01 x 0.01 x 0.004)"},
    {"FaceOnALine",
     [](auto& c) {
       auto& w = *c.mutable_wall(0);
       w.clear_h1(), w.clear_h2(), w.clear_k1(), w.clear_k2();
       face(w, {0, 0, 0}, {0.01, 0, 0}, {0.01, 0.01, 0});
       face(w, {0, 0, 0}, {0.005, 0.005, 0}, {0.01, 0.01, 0});
     },
     "wall[0].face[1]: is degenerate: its corners i, j, k lie on one line (or coincide)"},
    {"FacesWithExtent",
     [](auto& c) {
       face(*c.mutable_wall(0), {0, 0, 0}, {0.01, 0, 0}, {0.01, 0.01, 0});
     },
     "wall[0].h2: must be left out for a wall of faces"},
    {"FacesAcrossTheFrame",
     [](auto& c) {
       auto& w = *c.mutable_wall(0);
       w.clear_h1(), w.clear_h2(), w.clear_k1(), w.clear_k2();
       face(w, {0, 0, 0}, {0, 0, 0.01}, {0, 0.01, 0.01});
     },
     "wall[0].face: span nothing along direction or direction2"},
    {"ParticleFileWithoutPath3d", [](auto& c) { c.mutable_particles(3)->mutable_csv_file()->clear_path(); },
     "particles[3].csv_file.path: must name a CSV file of particles (lines of x,y,z,r)"},
};

INSTANTIATE_TEST_SUITE_P(CaseValidation, CaseMistake3d, ::testing::ValuesIn(kMistakes3d),
                         [](const auto& test) { return test.param.name; });

TEST(CaseValidation, EllipsoidsAndFacesHaveNoProblems) {
  EXPECT_EQ(test::problem_text(load_case_file(test::data_path("ellipsoids.case.txtpb")).message), "");
}

TEST(CaseValidation, AnEllipsoidIn2dIsRefused) {
  proto::Case c = load_case_file(test::data_path("superquadrics.case.txtpb")).message;
  proto::Particle& p = *c.mutable_particles(0)->mutable_particle();
  p.clear_superquadric();
  ellipsoid(p, 0.05, 0.03, 0.02);
  EXPECT_THAT(test::problem_text(c), HasSubstr("particles[0].particle.ellipsoid: is for 3D cases only (this case is "
                                               "2D); set dimension: 3, or superquadric for a 2D shape"));
}

TEST(CaseValidation, FacesIn2dAreRefused) {
  proto::Case c = test::valid_case();
  face(*c.mutable_wall(0), {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  EXPECT_THAT(test::problem_text(c), HasSubstr("wall[0].face: is for 3D cases only (this case is 2D)"));
}

TEST(CaseValidation, TheValid3dCaseHasNoProblems) { EXPECT_EQ(test::problem_text(test::valid_3d_case().message), ""); }

TEST(CaseValidation, ARigidWallMaterialNeedsNoYoungsModulus) {
  const proto::Case c = test::valid_3d_case().message;
  ASSERT_EQ(c.material(2).youngs_modulus(), 0);  // "wall" is only used by walls
  EXPECT_EQ(test::problem_text(c), "");
}

TEST(CaseValidation, SidesPerpendicularToAFewDigitsAreAccepted) {
  proto::Case c = test::valid_3d_case().message;
  c.mutable_wall(0)->mutable_direction2()->set_x(1e-7);
  EXPECT_EQ(test::problem_text(c), "");
}

// Particle files are read at conversion: until then their size is unknown,
// so probe ids beyond the other sources are not refused here.
TEST(CaseValidation, ProbeIdsBeyondAParticleFileWaitForConversion) {
  proto::Case c = test::valid_3d_case().message;
  c.mutable_output()->mutable_probe(0)->set_second(20);
  EXPECT_EQ(test::problem_text(c), "");
}

TEST(CaseValidation, AWallOnlyMaterialNeedsNoDensity) {
  proto::Case c = test::valid_case();
  ASSERT_EQ(c.material(1).density(), 0);  // "steel" is only used by walls
  EXPECT_EQ(test::problem_text(c), "");
}

TEST(CaseValidation, ADefaultModelCoversEveryPair) {
  proto::Case c = test::valid_case();
  c.mutable_contact_model()->DeleteSubrange(0, 2);
  EXPECT_EQ(test::problem_text(c), "");
}

}  // namespace
}  // namespace dem::io
