// The service's parts that need no DDS: what it reads from the engine, the
// running command's conditions, the telemetry schedule, the lifecycle, and
// the simulation's argument checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/service/case_programme.h"
#include "dem/service/command_error.h"
#include "dem/service/engine_readout.h"
#include "dem/service/lifecycle.h"
#include "dem/service/simulation.h"
#include "dem/service/telemetry_schedule.h"
#include "dem/service/world_steering.h"
#include "dem/service/world_view.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::CommandKind;
using protocol::ReplyStatus;
using protocol::ServerState;

// The nine-disc case compressed for 40 cycles (Cundall & Strack Fig. 5).
World compressed_nine_discs() {
  io::CaseDefinition definition = io::convert_case(io::load_case_file(case_file("nine_disc_damped")).message);
  definition.world.threads = 1;
  World world(definition.world);
  for (const auto& [wall, motion] : definition.stages.front().wall_motions) world.set_wall_motion(wall, motion);
  world.cycle(40);
  return world;
}

ReplyStatus status_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const service::CommandError& error) {
    return error.status();
  }
  return ReplyStatus::kOk;
}

TEST(EngineReadout, PlateStressIsNormalForceOverLengthTimesUnitDepth) {
  const World world = compressed_nine_discs();
  const auto walls = service::read_walls(world);
  const auto measures = world.wall_measures();
  ASSERT_EQ(walls.size(), 4u);
  for (std::size_t i = 0; i < walls.size(); ++i) {
    EXPECT_EQ(walls[i].name, world.wall(WallId::from_index(i)).name);
    EXPECT_EQ(walls[i].area, 400.0);  // h2 - h1 = 200 - (-200), depth 1
    EXPECT_EQ(walls[i].normal_force, measures[i].normal_force);
    EXPECT_EQ(walls[i].normal_stress, measures[i].normal_force / 400.0);
    EXPECT_EQ(walls[i].force.x, measures[i].force.x());
    EXPECT_EQ(walls[i].moment.z, measures[i].moment);
    EXPECT_EQ(walls[i].contacts, measures[i].contacts);
  }
  // Every wall moved 12 per unit time for 40 cycles of 0.01 towards the discs.
  for (const auto& wall : walls) EXPECT_NEAR(wall.settlement, 12.0 * 0.4, 1e-9) << wall.name;
  EXPECT_NEAR(walls[2].displacement.y, -12.0 * 0.4, 1e-9);  // the top wall went down
  EXPECT_GT(walls[2].normal_stress, 0.0);
}

TEST(EngineReadout, ContactStatisticsFollowTheirDefinitions) {
  const World world = compressed_nine_discs();
  const auto stats = service::read_contact_stats(world);
  const auto contacts = world.contacts();
  ASSERT_FALSE(contacts.empty());
  int wall_contacts = 0;
  int sliding = 0;
  double sum = 0.0;
  for (const auto& c : contacts) {
    wall_contacts += c.second_wall != kInvalidId;
    sliding += c.sliding;
    sum += c.normal_force;
  }
  EXPECT_EQ(stats.contacts, static_cast<int>(contacts.size()));
  EXPECT_EQ(stats.wall_contacts, wall_contacts);
  EXPECT_EQ(stats.sliding_contacts, sliding);
  EXPECT_DOUBLE_EQ(stats.mean_normal_force, sum / static_cast<double>(contacts.size()));
  // The square array: 12 disc-disc contacts and 12 disc-wall contacts over 9 discs.
  EXPECT_EQ(stats.contacts - stats.wall_contacts, 12);
  EXPECT_EQ(stats.wall_contacts, 12);
  EXPECT_DOUBLE_EQ(stats.coordination_number, (2.0 * 12 + 12) / 9.0);
  std::uint32_t counted = 0;
  for (const auto n : stats.histogram) counted += n;
  EXPECT_EQ(counted, contacts.size());
  EXPECT_EQ(stats.histogram.size(), static_cast<std::size_t>(service::kHistogramBins));
  EXPECT_EQ(stats.kinetic_energy, world.assembly_measures().kinetic_energy);
}

TEST(EngineReadout, ContactQueriesCombineTheirFilters) {
  const World world = compressed_nine_discs();
  const auto all = service::query_contacts(world, {});
  EXPECT_EQ(all.size(), world.contacts().size());
  service::ContactFilter on_top;
  on_top.wall = world.find_wall("top");
  const auto top = service::query_contacts(world, on_top);
  EXPECT_EQ(top.size(), 3u);
  for (const auto& c : top) EXPECT_EQ(c.second_wall, on_top.wall->value());
  service::ContactFilter box;
  box.box_min = protocol::Vector3{0.0, 0.0, 0.0};
  box.box_max = protocol::Vector3{110.0, 110.0, 0.0};  // around disc 0 (50, 50)
  for (const auto& c : service::query_contacts(world, box)) {
    EXPECT_LE(c.point.x, 110.0);
    EXPECT_LE(c.point.y, 110.0);
  }
  service::ContactFilter strong = on_top;
  strong.min_normal_force = 1e300;
  EXPECT_TRUE(service::query_contacts(world, strong).empty());
}

// The wire's ContactEntry is the engine's record field for field
// (service/src/contact_entry.h): every value arrives, 2D vectors with z = 0,
// and the wire has no field the record lacks.
TEST(EngineReadout, AContactEntryIsTheRecordFieldForField) {
  const World world = compressed_nine_discs();
  const std::vector<ContactRecord> records = world.contacts();
  const auto entries = service::query_contacts(world, {});
  ASSERT_EQ(entries.size(), records.size());
  ASSERT_GT(records.size(), 3u);
  const auto same = [](const protocol::Vector3& wire, const Vec2& v) {
    return wire.x == v.x() && wire.y == v.y() && wire.z == 0.0;
  };
  bool walls = false, moving = false;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const ContactRecord& r = records[i];
    const protocol::ContactEntry& e = entries[i];
    EXPECT_EQ(e.first, r.first.value());
    EXPECT_EQ(e.second_particle, r.second_particle.value());
    EXPECT_EQ(e.second_wall, r.second_wall.value());
    EXPECT_TRUE(same(e.point, r.point));
    EXPECT_TRUE(same(e.normal, r.normal));
    EXPECT_EQ(e.overlap, r.overlap);
    EXPECT_EQ(e.normal_force, r.normal_force);
    EXPECT_EQ(e.shear_force, r.shear_force);
    EXPECT_TRUE(same(e.tangential_force, r.tangential_force));
    EXPECT_EQ(e.normal_damping, r.normal_damping);
    EXPECT_EQ(e.shear_damping, r.shear_damping);
    EXPECT_EQ(e.sliding, r.sliding);
    EXPECT_EQ(e.formed_cycle, r.formed_cycle);
    EXPECT_TRUE(same(e.force, r.force));
    walls = walls || r.second_wall != kInvalidId;
    moving = moving || (r.tangential_force.norm() > 0.0 && r.force.norm() > 0.0);
  }
  EXPECT_TRUE(walls);   // both kinds of second body were compared
  EXPECT_TRUE(moving);  // and the vectors held something other than their defaults
  EXPECT_EQ(std::tuple_size_v<decltype(protocol::Fields<protocol::ContactEntry>::list)>, 14u)
      << "a ContactEntry field this test does not compare";
}

TEST(EngineReadout, ServoDefaultsKeepTheServoStable) {
  const World world = compressed_nine_discs();
  const WallId top = world.find_wall("top");
  std::vector<ContactModelDef> models(1);
  models[0].linear.normal_stiffness = 1.35e9;
  const auto limits = service::default_servo_limits(world, top, models);
  ASSERT_TRUE(limits);
  // At most 400 / (2 * 50) = 4 discs along the wall: gain k_n n dt = 0.5.
  EXPECT_DOUBLE_EQ(limits->gain * 1.35e9 * 4.0 * world.time_step(), 0.5);
  EXPECT_DOUBLE_EQ(limits->max_speed * world.time_step(), 0.05 * 50.0);
  models[0].law = ContactLaw::kHertzMindlin;
  EXPECT_FALSE(service::default_servo_limits(world, top, models));
}

// A run_until command's stage: a programme of one stage of its own
// (CaseProgramme::one_stage), stepped as the runner steps every run.
struct CommandStage {
  CommandStage(service::WorldSession& world, std::uint64_t cycles, const StopConditions& until)
      : programme(service::CaseProgramme::one_stage(world.dimension(), cycles, until)),
        stepper(programme.begin_stage(0, world)) {}
  // Steps to the stage's end as the runner does, a stop at a time.
  void run_to_end() {
    do {
      stepper.cycle(stepper.cycles_to_next_stop());
    } while (!stepper.check());
  }
  service::CaseProgramme programme;
  service::StageStepper stepper;
};

// run_until's conditions are the engine's stop rule (dem/programme.h):
// stress reached from below, all conditions at once, at the checks.
TEST(CommandStage, ReachesAStressFromBelowAtItsChecks) {
  const auto session = std::make_unique<service::WorldSession>(compressed_nine_discs());
  service::WorldSession& world = *session;
  const WallId top = service::find_wall(world, "top");
  const double stress = service::read_wall(world, top).normal_stress;
  ASSERT_GT(stress, 0.0);
  StopConditions loading;  // the top wall presses down: its stress rises
  loading.wall_stress_above = WallThreshold{top, 1.5 * stress};
  loading.check_interval = 5;
  service::set_wall_velocity(world, top, {0.0, -2.0, 0.0}, {});
  CommandStage run(world, 100000, loading);
  EXPECT_EQ(run.stepper.cycles_to_next_stop(), 5u);
  run.run_to_end();
  const StageResult& result = run.stepper.result();
  std::printf("stress %.4g Pa -> %.4g Pa (target %.4g) after %llu cycles\n", stress,
              service::read_wall(world, top).normal_stress, 1.5 * stress,
              static_cast<unsigned long long>(result.cycles_run));
  EXPECT_TRUE(result.condition_met);
  EXPECT_GE(service::read_wall(world, top).normal_stress, 1.5 * stress);
  const std::string reached = service::conditions_reached(run.programme.stage_until(0), world);
  EXPECT_NE(reached.find("the stress on top reached"), std::string::npos) << reached;
  EXPECT_EQ(result.cycles_run % 5, 0u);
}

// The direction is the condition's, not inferred from the start: a stress
// target below the stress now holds at the first check.
TEST(CommandStage, ATargetAlreadyPassedEndsAtTheFirstCheck) {
  const auto session = std::make_unique<service::WorldSession>(compressed_nine_discs());
  service::WorldSession& world = *session;
  const WallId top = service::find_wall(world, "top");
  StopConditions until;
  until.wall_stress_above = WallThreshold{top, 0.5 * service::read_wall(world, top).normal_stress};
  until.check_interval = 5;
  CommandStage run(world, 1000, until);
  run.stepper.cycle(5);
  EXPECT_TRUE(run.stepper.check());
  EXPECT_TRUE(run.stepper.result().condition_met);
  EXPECT_EQ(run.stepper.result().cycles_run, 5u);
}

// All conditions at once: a stress that holds does not end the run while
// the kinetic energy is not below its (unreachable) bound; what holds is
// said of each condition.
TEST(CommandStage, EndsOnlyWhenEveryConditionHolds) {
  const auto session = std::make_unique<service::WorldSession>(compressed_nine_discs());
  service::WorldSession& world = *session;
  const WallId top = service::find_wall(world, "top");
  StopConditions until;
  until.wall_stress_above = WallThreshold{top, 0.5 * service::read_wall(world, top).normal_stress};
  until.kinetic_energy_below = 0.0;  // never: the energy is not negative
  until.check_interval = 5;
  CommandStage run(world, 20, until);
  run.run_to_end();
  EXPECT_FALSE(run.stepper.result().condition_met);
  EXPECT_EQ(run.stepper.result().cycles_run, 20u);
  const std::string said = service::conditions_reached(until, world);
  EXPECT_NE(said.find("the stress on top reached "), std::string::npos) << said;
  EXPECT_NE(said.find(" and the kinetic energy fell to "), std::string::npos) << said;
}

TEST(CommandStage, StopsAtItsCapWithoutConditions) {
  const auto world = std::make_unique<service::WorldSession>(compressed_nine_discs());
  CommandStage run(*world, 25, {});
  EXPECT_EQ(run.stepper.cycles_to_next_stop(), 25u);
  run.stepper.cycle(20);
  EXPECT_FALSE(run.stepper.check());
  EXPECT_EQ(run.stepper.cycles_to_next_stop(), 5u);
  EXPECT_EQ(world->cycle_count(), 60u);  // 40 before, 20 by the run
  run.stepper.cycle(5);
  EXPECT_TRUE(run.stepper.check());
  EXPECT_FALSE(run.stepper.result().condition_met);
}

TEST(TelemetrySchedule, CountsCyclesAndSimulatedTime) {
  service::TelemetrySchedule cycles(10, 0.0);
  cycles.published(0, 0.0);
  EXPECT_EQ(cycles.cycles_until_due(3, 0.0, 1.0), 7u);
  EXPECT_FALSE(cycles.due(9, 0.0));
  EXPECT_TRUE(cycles.due(10, 0.0));
  service::TelemetrySchedule time(0, 0.5);
  time.published(0, 0.0);
  EXPECT_EQ(time.cycles_until_due(0, 0.0, 0.1), 5u);
  double t = 0.0;
  for (int i = 0; i < 5; ++i) t += 0.1;  // 0.49999999999999994: due up to rounding
  EXPECT_TRUE(time.due(5, t));
  service::TelemetrySchedule off(0, 0.0);
  EXPECT_FALSE(off.due(1000000, 1e9));
  EXPECT_EQ(off.cycles_until_due(0, 0.0, 1.0), std::numeric_limits<std::uint64_t>::max());
}

TEST(Lifecycle, EachStateAcceptsItsCommands) {
  EXPECT_FALSE(service::refusal(ServerState::kIdle, CommandKind::kLoadCase));
  EXPECT_FALSE(service::refusal(ServerState::kIdle, CommandKind::kGetState));
  EXPECT_TRUE(service::refusal(ServerState::kIdle, CommandKind::kCycle));
  EXPECT_TRUE(service::refusal(ServerState::kIdle, CommandKind::kQueryContacts));
  EXPECT_FALSE(service::refusal(ServerState::kLoaded, CommandKind::kSetParameter));
  EXPECT_FALSE(service::refusal(ServerState::kRunning, CommandKind::kSetWallVelocity));
  EXPECT_FALSE(service::refusal(ServerState::kRunning, CommandKind::kSaveSnapshot));
  EXPECT_FALSE(service::refusal(ServerState::kRunning, CommandKind::kStop));
  EXPECT_TRUE(service::refusal(ServerState::kRunning, CommandKind::kCycle));
  EXPECT_TRUE(service::refusal(ServerState::kRunning, CommandKind::kRunProgramme));
  EXPECT_FALSE(service::refusal(ServerState::kLoaded, CommandKind::kRunProgramme));
  EXPECT_TRUE(service::refusal(ServerState::kRunning, CommandKind::kLoadCase));
  EXPECT_TRUE(service::refusal(ServerState::kRunning, CommandKind::kSetParameter));
  EXPECT_FALSE(service::refusal(ServerState::kError, CommandKind::kLoadSnapshot));
  EXPECT_TRUE(service::refusal(ServerState::kError, CommandKind::kCycle));
  EXPECT_FALSE(service::refusal(ServerState::kShutdown, CommandKind::kShutdown));
}

TEST(Lifecycle, RunningRefusesAnotherRunAndTheReloads) {
  const auto reason = service::refusal(ServerState::kRunning, CommandKind::kRunUntil);
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("already running"), std::string::npos) << *reason;
  EXPECT_NE(service::refusal(ServerState::kRunning, CommandKind::kLoadSnapshot)->find("stop it first"),
            std::string::npos);
  EXPECT_TRUE(service::refusal(ServerState::kShutdown, CommandKind::kLoadCase));
}

// The named transitions: a load from idle, a run that ends, one that fails
// and a reload out of error, then the shutdown.
TEST(Lifecycle, TakesItsTransitionsAndRefusesTheOthers) {
  using service::Transition;
  service::Lifecycle lifecycle;
  EXPECT_EQ(lifecycle.state(), ServerState::kIdle);
  EXPECT_THROW(lifecycle.take(Transition::kStartRun), std::logic_error);  // nothing to run
  EXPECT_EQ(lifecycle.state(), ServerState::kIdle);
  lifecycle.take(Transition::kInstall);
  EXPECT_EQ(lifecycle.state(), ServerState::kLoaded);
  EXPECT_THROW(lifecycle.take(Transition::kEndRun), std::logic_error);
  lifecycle.take(Transition::kStartRun);
  EXPECT_TRUE(lifecycle.running());
  EXPECT_TRUE(lifecycle.refusal(CommandKind::kCycle));
  EXPECT_THROW(lifecycle.take(Transition::kInstall), std::logic_error);  // no reload under a run
  EXPECT_THROW(lifecycle.take(Transition::kStartRun), std::logic_error);
  lifecycle.take(Transition::kEndRun);
  EXPECT_EQ(lifecycle.state(), ServerState::kLoaded);
  lifecycle.take(Transition::kStartRun);
  lifecycle.take(Transition::kFailRun);
  EXPECT_EQ(lifecycle.state(), ServerState::kError);
  EXPECT_THROW(lifecycle.take(Transition::kStartRun), std::logic_error);
  lifecycle.take(Transition::kInstall);
  EXPECT_EQ(lifecycle.state(), ServerState::kLoaded);
  lifecycle.take(Transition::kShutDown);
  EXPECT_EQ(lifecycle.state(), ServerState::kShutdown);
  EXPECT_THROW(lifecycle.take(Transition::kInstall), std::logic_error);
  EXPECT_THROW(lifecycle.take(Transition::kShutDown), std::logic_error);
}

// Every state's accepted commands are what its transitions allow: a state
// that cannot start a run refuses the runs, one that cannot install refuses the loads.
TEST(Lifecycle, TheRefusalsFollowTheTransitions) {
  using service::Transition;
  for (const ServerState state :
       {ServerState::kIdle, ServerState::kLoaded, ServerState::kRunning, ServerState::kError, ServerState::kShutdown}) {
    const bool can_run = service::next_state(state, Transition::kStartRun).has_value();
    const bool can_load = service::next_state(state, Transition::kInstall).has_value();
    for (const CommandKind run : {CommandKind::kCycle, CommandKind::kRunUntil, CommandKind::kRunProgramme}) {
      EXPECT_EQ(!service::refusal(state, run), can_run)
          << protocol::to_string(state) << " " << protocol::to_string(run);
    }
    for (const CommandKind load : {CommandKind::kLoadCase, CommandKind::kLoadSnapshot}) {
      EXPECT_EQ(!service::refusal(state, load), can_load)
          << protocol::to_string(state) << " " << protocol::to_string(load);
    }
  }
}

TEST(Simulation, ChecksArgumentsAndChangesNothingWhenTheyAreWrong) {
  service::Simulation simulation(1);
  protocol::LoadCaseArgs args;
  args.text = read_text(case_file("nine_disc_damped"));
  simulation.install(simulation.prepare_case(args));
  service::WorldSession& world = simulation.world();
  const std::uint64_t hash = world.state_hash();
  EXPECT_EQ(status_of([&] { simulation.set_wall_velocity({"roof", -1, {{}, {}}}); }), ReplyStatus::kNotFound);
  EXPECT_EQ(status_of([&] { simulation.set_wall_velocity({"", 7, {{}, {}}}); }), ReplyStatus::kNotFound);
  EXPECT_EQ(status_of([&] { simulation.set_wall_velocity({"top", -1, {{0, 0, 1}, {}}}); }), ReplyStatus::kBadRequest);
  EXPECT_EQ(status_of([&] { simulation.set_wall_velocity({"top", -1, {{NAN, 0, 0}, {}}}); }), ReplyStatus::kBadRequest);
  EXPECT_EQ(status_of([&] { simulation.set_wall_servo({"top", -1, 1e6, -1.0, 0.0}); }), ReplyStatus::kBadRequest);
  EXPECT_EQ(status_of([&] { simulation.set_parameter({"contact_damping", "", -1.0, {}}); }), ReplyStatus::kBadRequest);
  EXPECT_EQ(status_of([&] {
              simulation.set_parameter({"time_step_fraction", "", 1.5, {}});
            }),
            ReplyStatus::kBadRequest);
  EXPECT_EQ(status_of([&] { simulation.set_parameter({"friction", "sand", 0.3, {}}); }), ReplyStatus::kNotFound);
  EXPECT_EQ(status_of([&] {
              simulation.set_parameter({"gravity", "", 0.0, {0, -9.81, 1}});
            }),
            ReplyStatus::kBadRequest);
  EXPECT_EQ(status_of([&] { simulation.set_parameter({"viscosity", "", 1.0, {}}); }), ReplyStatus::kNotFound);
  EXPECT_EQ(world.state_hash(), hash);
  EXPECT_EQ(service::damping(world).contact_beta, 0.01);
  EXPECT_EQ(status_of([&] { simulation.set_parameter({"global_damping", "", 3.0, {}}); }), ReplyStatus::kOk);
  EXPECT_EQ(service::damping(world).global_alpha, 3.0);
  EXPECT_EQ(status_of([&] { simulation.set_wall_servo({"top", -1, 1e6, 0.0, 0.0}); }), ReplyStatus::kOk);
  // The servo holds the top wall at 1e6 Pa over its 400 length: it moves in
  // until it does (2000 cycles, a one-stage programme as a cycle command runs).
  auto run = service::CaseProgramme::one_stage(world.dimension(), 2000, {}).begin_stage(0, world);
  run.cycle(run.cycles_to_next_stop());
  EXPECT_TRUE(run.check());
  EXPECT_EQ(world.cycle_count(), 2000u);
  EXPECT_GT(service::read_wall(world, service::find_wall(world, "top")).normal_stress, 0.5e6);
}

}  // namespace
}  // namespace dem::test
