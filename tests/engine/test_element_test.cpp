// Element-test control of a box of walls (BoxControlT): strain rates that
// deform the box as asked (Randall 1989, 4.5.2; constant volume, 6.5.2),
// servos and stress paths that hold stresses (4.1), walls taken out (a
// hopper's orifice, 6.2), stages that change friction, damping and time
// step, the errors that name a bad control, and exact restart and thread
// independence with all of it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "model_builders.h"

namespace dem {
namespace {

// 200 discs in a 0.2 m box, four walls: 0 bottom (faces +y), 1 right
// (faces -x), 2 top (faces -y), 3 left (faces +x). No gravity.
WorldDef box_of_discs() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.3, 0.0}};
  ContactModelDef model = testing::linear_model(1e7, 1e7);
  model.law = ContactLaw::kLinearRestitution;
  model.restitution = 0.5;
  def.contact_models = {model};
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {0.2, 0.2};
  packing.sizes = {{0.006, 80}, {0.0045, 120}};
  packing.seed = 3;
  def.particles = generate_random_packing(packing);
  def.walls = {WallDef{"bottom", {0.1, 0.0}, {1, 0}, -0.2, 0.2, MaterialId{0}, {}},
               WallDef{"right", {0.2, 0.1}, {0, 1}, -0.2, 0.2, MaterialId{0}, {}},
               WallDef{"top", {0.1, 0.2}, {-1, 0}, -0.2, 0.2, MaterialId{0}, {}},
               WallDef{"left", {0.0, 0.1}, {0, -1}, -0.2, 0.2, MaterialId{0}, {}}};
  def.damping.local_alpha = 0.5;
  def.threads = 1;
  return def;
}

BoxControl box(AxisControl x, double x_value, AxisControl y, double y_value) {
  BoxControl control;
  control.axes[0] = BoxAxisDef{WallId{3}, WallId{1}, x, x_value, x_value};
  control.axes[1] = BoxAxisDef{WallId{0}, WallId{2}, y, y_value, y_value};
  // A wall moves 5e-6 m/s per Pa of error: about 20 wall contacts of 1e7
  // N/m stiffen the box by some 1e9 Pa/m, so the servo's loop gain per step
  // is 5e-6 x 1e9 x 1.8e-5 s, about 0.1: stable, and quick to compress.
  control.gain = 5e-6;
  control.max_speed = 0.05;
  return control;
}

std::string error_of(const BoxControl& control) {
  World world(box_of_discs());
  try {
    world.set_box_control(control);
  } catch (const DefinitionError& e) {
    return e.what();
  }
  return "";
}

// The boundary strain-rate tensor (Randall 4.5.2) in its principal axes:
// rates e and -e keep the box's area (Randall 6.5.2's constant volume).
TEST(BoxControl, StrainRatesDeformTheBoxAtConstantArea) {
  World world(box_of_discs());
  const double rate = 2.0;  // 1/s
  world.set_box_control(box(AxisControl::kStrainRate, -rate, AxisControl::kStrainRate, rate));
  const double dt = world.time_step();
  const int cycles = 2000;
  world.cycle(cycles);
  const BoxMeasure m = world.box_measure();
  const double t = cycles * dt;
  // Each step shortens y by rate dt and lengthens x as much: (1 -+ rate dt)^n.
  const double y = 0.2 * std::pow(1.0 - rate * dt, cycles), x = 0.2 * std::pow(1.0 + rate * dt, cycles);
  std::printf(
      "after %.4f s at 2/s: extents %.9f x %.9f (expected %.9f x %.9f), area change %.2e, deviator strain "
      "%.6f (2 x rate x t = %.6f)\n",
      t, m.extent.x(), m.extent.y(), x, y, m.extent.prod() / 0.04 - 1.0, m.deviator_strain, 2.0 * rate * t);
  EXPECT_NEAR(m.extent.x(), x, 1e-12);
  EXPECT_NEAR(m.extent.y(), y, 1e-12);
  // Constant area to second order: (1 - (rate dt)^2)^n.
  EXPECT_NEAR(m.extent.prod() / 0.04, std::pow(1.0 - rate * dt * rate * dt, cycles), 1e-12);
  EXPECT_NEAR(m.volumetric_strain, -cycles * std::log(1.0 - rate * rate * dt * dt), 1e-12);
  EXPECT_NEAR(m.deviator_strain, 2.0 * rate * t, 2.0 * rate * t * rate * dt * cycles);
}

// Servos on both axes bring the sample to an isotropic stress, then a
// constant-mean-stress path holds p while the y axis is compressed.
TEST(BoxControl, ServosAndAConstantMeanStressPath) {
  World world(box_of_discs());
  const double p = 2e4;  // Pa (per unit depth: N/m)
  world.set_box_control(box(AxisControl::kStress, p, AxisControl::kStress, p));
  StageDef compress;
  compress.cycles = 200000;
  compress.until.servo_tolerance = 0.01;
  compress.until.out_of_balance_below = 0.05;
  compress.until.min_cycles = 1000;
  compress.until.check_interval = 100;
  ASSERT_TRUE(run_stage(world, compress).condition_met);
  BoxMeasure m = world.box_measure();
  std::printf("isotropic: stresses %.1f, %.1f Pa (target %.0f) after %llu cycles\n", m.stress.x(), m.stress.y(), p,
              static_cast<unsigned long long>(world.cycle_count()));
  EXPECT_NEAR(m.stress.x() / p, 1.0, 0.01);
  EXPECT_NEAR(m.stress.y() / p, 1.0, 0.01);

  // Slowly enough for the servos to follow (a wall retreats at most
  // 5e-6 m/s per Pa; the y walls close at 0.05 x 0.145 / 2 m/s).
  BoxControl path = box(AxisControl::kStressPath, 0.0, AxisControl::kStrainRate, 0.05);
  path.path = StressPath::kConstantMeanStress;
  path.path_value = p;
  StageDef shear;
  shear.box_control = path;
  shear.cycles = 400000;
  shear.until.deviator_strain_above = 0.01;
  shear.until.check_interval = 50;
  double worst = 0.0;
  const StageResult result = run_stage(world, shear, 500, [&](const World& w) {
    const BoxMeasure b = w.box_measure();
    if (b.deviator_strain > 0.002) worst = std::max(worst, std::abs(b.mean_stress / p - 1.0));
    return true;
  });
  ASSERT_TRUE(result.condition_met);
  m = world.box_measure();
  std::printf(
      "constant mean stress path to deviator strain %.4f: sigma_x %.1f, sigma_y %.1f, mean %.1f Pa "
      "(p %.0f; worst %.2f%% off after 0.2%%), x target %.1f\n",
      m.deviator_strain, m.stress.x(), m.stress.y(), m.mean_stress, p, 100.0 * worst, m.target.x());
  EXPECT_GT(m.stress.y(), 1.2 * m.stress.x());  // the compressed axis carries more
  EXPECT_NEAR(m.target.x(), 2.0 * p - m.stress.y(), 1e-9 * p);
  EXPECT_LT(worst, 0.05);
}

TEST(BoxControl, AStressRatioPathHoldsSigma1OverSigma3) {
  World world(box_of_discs());
  world.set_box_control(box(AxisControl::kStress, 1e4, AxisControl::kStress, 1e4));
  StageDef compress;
  compress.cycles = 200000;
  compress.until.servo_tolerance = 0.02;
  compress.until.min_cycles = 1000;
  ASSERT_TRUE(run_stage(world, compress).condition_met);
  BoxControl ratio = box(AxisControl::kStressPath, 0.0, AxisControl::kStrainRate, 0.05);
  ratio.path = StressPath::kStressRatio;
  // Below the sample's strength (at 2, sin phi = 1/3, these discs with
  // tan phi = 0.3 fail and the walls run away).
  ratio.path_value = 1.3;
  world.set_box_control(ratio);
  world.cycle(20000);
  const BoxMeasure m = world.box_measure();
  std::printf("stress ratio path: sigma_y %.1f, sigma_x %.1f Pa, ratio %.4f (1.3)\n", m.stress.y(), m.stress.x(),
              m.stress.y() / m.stress.x());
  EXPECT_NEAR(m.stress.y() / m.stress.x(), 1.3, 0.03);
}

TEST(BoxControl, BadControlsNameTheField) {
  EXPECT_EQ(error_of(box(AxisControl::kStress, -1.0, AxisControl::kStrainRate, 0.0)),
            "box control: axes[0] (x).stress: must be > 0 (compression positive)");
  BoxControl swapped = box(AxisControl::kStrainRate, 0.0, AxisControl::kStrainRate, 0.0);
  std::swap(swapped.axes[1].lower, swapped.axes[1].upper);
  EXPECT_EQ(error_of(swapped), "box control: axes[1] (y).lower: wall 2 (\"top\") must face +y (the particles' side)");
  BoxControl twice = box(AxisControl::kStrainRate, 0.0, AxisControl::kStrainRate, 0.0);
  twice.axes[1].lower = WallId{3};
  EXPECT_EQ(error_of(twice), "box control: axes[1] (y).lower: wall 3 (\"left\") already bounds the box");
  BoxControl no_gain = box(AxisControl::kStress, 1.0, AxisControl::kStrainRate, 0.0);
  no_gain.gain = 0.0;
  EXPECT_EQ(error_of(no_gain), "box control: gain must be > 0 when an axis is stress-controlled");
  EXPECT_EQ(error_of(box(AxisControl::kStressPath, 0.0, AxisControl::kStrainRate, 0.0)),
            "box control: an axis follows the stress path but no path is set");
  BoxControl low_ratio = box(AxisControl::kStressPath, 0.0, AxisControl::kStrainRate, 0.0);
  low_ratio.path = StressPath::kStressRatio;
  low_ratio.path_value = 0.5;
  EXPECT_EQ(error_of(low_ratio), "box control: stress_ratio (sigma_1 / sigma_3) must be >= 1");
  World world(box_of_discs());
  EXPECT_THROW(world.box_measure(), DefinitionError);
}

// A hopper's orifice (Randall 6.2): discs resting on a wall fall once it is
// taken out; it keeps its id, touches nothing and carries nothing.
TEST(RemoveWall, DiscsFallThroughTheOpenedOrifice) {
  WorldDef def = box_of_discs();
  def.gravity = {0.0, -9.81};
  def.walls.push_back(WallDef{"floor", {0.1, 0.0}, {1, 0}, -0.05, 0.05, MaterialId{0}, {}});
  def.walls[0].h1 = -0.2;
  def.walls[0].h2 = -0.05;  // the bottom wall leaves a gap of 0.1 m in the middle, closed by the floor
  World world(def);
  world.cycle(20000);
  ASSERT_GT(world.wall_measures()[4].contacts, 0);
  world.remove_wall(WallId{4});
  EXPECT_TRUE(world.wall(WallId{4}).removed);
  EXPECT_EQ(world.wall_measures()[4].contacts, 0);
  EXPECT_EQ(world.wall_measures()[4].normal_force, 0.0);
  world.cycle(20000);
  int below = 0;
  for (const Vec2& x : world.particles().position) below += x.y() < 0.0 ? 1 : 0;
  std::printf("after opening the orifice: %d of %d discs below the floor's line\n", below, world.particle_count());
  EXPECT_GT(below, 10);
  EXPECT_EQ(world.wall_measures()[4].contacts, 0);
  // A wall bounding a controlled box cannot be taken out.
  World boxed(box_of_discs());
  boxed.set_box_control(box(AxisControl::kStrainRate, 0.0, AxisControl::kStrainRate, 0.0));
  EXPECT_THROW(boxed.remove_wall(WallId{0}), DefinitionError);
}

// 3D: a cube of six walls round 4 x 4 x 4 spheres of radius 12.5 mm that
// just fill it; axes x, y, z by walls (0, 1), (2, 3), (4, 5).
WorldDef3 cube_of_spheres() {
  WorldDef3 def;
  def.materials = {MaterialDef{"sphere", 2500.0, 0.3, 0.0}};
  ContactModelDef model = testing::linear_model(1e5, 1e5);
  model.law = ContactLaw::kLinearRestitution;
  model.restitution = 0.5;
  def.contact_models = {model};
  LatticeDef3 lattice;
  lattice.radius = 0.0125;
  lattice.spacing = 0.025;
  lattice.origin = Vec3::Constant(0.0125);
  lattice.columns = lattice.rows = lattice.layers = 4;
  def.particles = generate_lattice(lattice);
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  auto wall = [](const char* name, const Vec3& point, const Vec3& u, const Vec3& v) {
    WallDef3 w;
    w.name = name;
    w.point = point;
    w.direction = u;
    w.direction2 = v;  // the normal u x v faces the spheres
    w.h1 = w.k1 = -0.1;
    w.h2 = w.k2 = 0.1;
    return w;
  };
  def.walls = {wall("x0", {0.0, 0.05, 0.05}, y, z), wall("x1", {0.1, 0.05, 0.05}, z, y),
               wall("y0", {0.05, 0.0, 0.05}, z, x), wall("y1", {0.05, 0.1, 0.05}, x, z),
               wall("z0", {0.05, 0.05, 0.0}, x, y), wall("z1", {0.05, 0.05, 0.1}, y, x)};
  def.damping.local_alpha = 0.5;
  def.threads = 1;
  return def;
}

// The box control in 3D: strain rates e, -e and 0 keep the cube's volume
// (to second order in e dt); servos on all three axes bring the spheres to
// an isotropic stress, each axis's force over the face the other two
// extents span.
TEST(BoxControl, ACubeOfSixWallsInThreeDimensions) {
  World3 world(cube_of_spheres());
  BoxControl3 control;
  control.axes = {BoxAxisDef{WallId{0}, WallId{1}, AxisControl::kStrainRate, -1.0, 0.0},
                  BoxAxisDef{WallId{2}, WallId{3}, AxisControl::kStrainRate, 1.0, 0.0},
                  BoxAxisDef{WallId{4}, WallId{5}, AxisControl::kStrainRate, 0.0, 0.0}};
  world.set_box_control(control);
  const double dt = world.time_step();
  const int cycles = 100;
  world.cycle(cycles);
  BoxMeasure3 m = world.box_measure();
  EXPECT_NEAR(m.extent.x(), 0.1 * std::pow(1.0 + dt, cycles), 1e-14);
  EXPECT_NEAR(m.extent.y(), 0.1 * std::pow(1.0 - dt, cycles), 1e-14);
  EXPECT_NEAR(m.extent.z(), 0.1, 1e-15);
  EXPECT_NEAR(m.extent.prod() / 1e-3, std::pow(1.0 - dt * dt, cycles), 1e-12);

  World3 pressed(cube_of_spheres());
  const double p = 1e3;  // Pa: 10 N on a face, 0.6 N and 6 um of overlap on each of its 16 contacts
  for (int axis = 0; axis < 3; ++axis) {
    control.axes[axis].control = AxisControl::kStress;
    control.axes[axis].stress = p;
  }
  // About 16 contacts of 1e5 N/m on a face of 0.01 m^2 stiffen an axis by
  // 1.6e8 Pa/m: a gain of 1e-5 m/s per Pa gives a loop gain near 0.1 a step.
  control.gain = 1e-5;
  control.max_speed = 0.05;
  pressed.set_box_control(control);
  StageDef3 compress;
  compress.cycles = 100000;
  compress.until.servo_tolerance = 0.01;
  compress.until.out_of_balance_below = 0.05;
  compress.until.min_cycles = 500;
  compress.until.check_interval = 100;
  ASSERT_TRUE(run_stage(pressed, compress).condition_met);
  m = pressed.box_measure();
  std::printf("3D servos: stresses %.1f, %.1f, %.1f Pa (target %.0f) after %llu cycles, extents %.6f m\n", m.stress.x(),
              m.stress.y(), m.stress.z(), p, static_cast<unsigned long long>(pressed.cycle_count()), m.extent.x());
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(m.stress[axis] / p, 1.0, 0.01) << "axis " << axis;
    const auto& lower = pressed.wall_measures()[static_cast<std::size_t>(2 * axis)];
    EXPECT_NEAR(lower.normal_force / (m.extent[(axis + 1) % 3] * m.extent[(axis + 2) % 3]) / p, 1.0, 0.02);
  }
  EXPECT_NEAR(m.mean_stress / p, 1.0, 0.01);
}

// A stage's start actions (Randall 6.4.3: friction given at 100 kPa; 6.3:
// the step reduced once the bed settles; 6.2: the orifice opened): its
// friction, damping and time step hold from then on, a released box leaves
// its walls where they stand, a removed wall touches nothing.
TEST(Stage, ChangesFrictionDampingAndTimeStepReleasesTheBoxAndRemovesAWall) {
  WorldDef def = box_of_discs();
  def.particles.resize(150);
  def.materials[0].friction = 0.0;
  def.box_control = box(AxisControl::kStress, 1e4, AxisControl::kStress, 1e4);
  def.walls.push_back(WallDef{"spare", {0.1, 0.1}, {1, 0}, -0.01, 0.01, MaterialId{0}, {}});
  World world(def);
  const double step = world.time_step();
  StageDef compress;
  compress.cycles = 2000;
  run_stage(world, compress);
  StageDef next;
  next.release_box_control = true;
  next.remove_walls = {WallId{4}};
  next.damping = DampingDef{0.0, 0.0, std::nullopt, 0.7, std::nullopt};
  next.time_step = TimeStepSetting{0.05, 0.0};
  next.frictions = {{MaterialId{0}, 0.3}};
  next.cycles = 10;
  run_stage(world, next);
  EXPECT_EQ(world.materials()[0].friction, 0.3);
  EXPECT_EQ(world.damping().local_alpha, 0.7);
  EXPECT_NEAR(world.time_step(), 0.05 * world.undamped_critical_time_step(), 1e-15);
  EXPECT_LT(world.time_step(), step);
  EXPECT_FALSE(world.box_control().has_value());
  EXPECT_TRUE(world.wall(WallId{4}).removed);
  EXPECT_EQ(world.wall_measures()[4].contacts, 0);
  StageDef fixed;
  fixed.time_step = TimeStepSetting{0.0, 2e-6};
  fixed.cycles = 1;
  run_stage(world, fixed);
  EXPECT_EQ(world.time_step(), 2e-6);
}

// The box's control, a removed wall and the strain reference travel in the
// snapshot: a restored world continues bit for bit; two threads agree.
TEST(BoxControl, RestartIsExactAndThreadsAgree) {
  WorldDef def = box_of_discs();
  def.particles.resize(150);
  BoxControl control = box(AxisControl::kStressPath, 0.0, AxisControl::kStrainRate, 1.0);
  control.path = StressPath::kConstantMeanStress;
  control.path_value = 1e4;
  def.box_control = control;
  def.walls.push_back(WallDef{"spare", {0.1, 0.1}, {1, 0}, -0.01, 0.01, MaterialId{0}, {}});
  World original(def);
  original.remove_wall(WallId{4});
  def.threads = 2;
  World parallel(def);
  parallel.remove_wall(WallId{4});
  original.cycle(3000);
  parallel.cycle(3000);
  World restored(original.snapshot());
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  ASSERT_TRUE(restored.box_control().has_value());
  EXPECT_EQ(restored.box_control()->reference_extent, original.box_control()->reference_extent);
  EXPECT_TRUE(restored.wall(WallId{4}).removed);
  original.cycle(3000);
  restored.cycle(3000);
  parallel.cycle(3000);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  EXPECT_EQ(parallel.state_hash(), original.state_hash());
  EXPECT_EQ(restored.box_measure().deviator_strain, original.box_measure().deviator_strain);
}

// A stage that sets a box control, resumed from a snapshot taken part-way
// through it (a checkpoint), ends where the uninterrupted stage ends: its
// start actions are not done again (a second set_box_control would move
// the strain reference to the resumed state and the stop condition with it).
TEST(BoxControl, AStageResumedPartWayEndsAsTheWholeStage) {
  WorldDef def = box_of_discs();
  def.particles.resize(150);
  def.walls.push_back(WallDef{"spare", {0.1, 0.1}, {1, 0}, -0.01, 0.01, MaterialId{0}, {}});
  StageDef shear;
  shear.box_control = box(AxisControl::kStrainRate, -0.01, AxisControl::kStrainRate, 0.01);
  shear.remove_walls = {WallId{4}};
  shear.time_step = TimeStepSetting{0.5, 0.0};
  shear.cycles = 20000;
  shear.until.deviator_strain_above = 0.004;
  shear.until.check_interval = 100;
  World whole(def);
  const StageResult all = run_stage(whole, shear);
  ASSERT_TRUE(all.condition_met);

  World first(def);
  std::optional<World::Snapshot> part_way;
  run_stage(first, shear, 1000, [&](const World& w) {
    part_way = w.snapshot();
    return false;
  });
  ASSERT_TRUE(part_way.has_value());
  World resumed(*part_way);
  const std::uint64_t done = resumed.cycle_count();
  const StageResult rest = run_stage(resumed, stage_remainder(shear, done));
  std::printf("whole stage: %llu cycles; resumed after %llu: %llu more, deviator strain %.6f and %.6f\n",
              static_cast<unsigned long long>(all.cycles_run), static_cast<unsigned long long>(done),
              static_cast<unsigned long long>(rest.cycles_run), whole.box_measure().deviator_strain,
              resumed.box_measure().deviator_strain);
  EXPECT_TRUE(rest.condition_met);
  EXPECT_EQ(done + rest.cycles_run, all.cycles_run);
  EXPECT_EQ(resumed.state_hash(), whole.state_hash());
}

}  // namespace
}  // namespace dem
