// The plate loading analyses (Miyata et al. 2002, 3.2-3.3) on a row of
// five discs of three heights pressed by a plate: the contacts on the plate
// form in a known order, at known stresses.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>

#include "dem/analysis/compression_analysis.h"
#include "dem/io/compression_csv.h"
#include "dem/io/compression_state.h"
#include "dem/programme.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

// Discs of radius 0.1, 0.099, 0.1, 0.098, 0.1 m resting on the floor under
// gravity, k = 1e6 N/m: the plate (1.2 m long) meets the three tallest
// first; 2 mm later, at 3 x 5e5 N/m x 2 mm / 1.2 m = 2.5 kPa, the fourth;
// at 5.8 kPa the last.
WorldDef row_of_discs() {
  WorldDef def;
  def.materials.push_back({"disc", 1000, 0.5, 0});
  ContactModelDef model;
  model.linear = {1e6, 1e6};
  def.contact_models.push_back(model);
  const double radii[] = {0.1, 0.099, 0.1, 0.098, 0.1};
  for (int i = 0; i < 5; ++i) {
    ParticleDef disc;
    // At rest on the floor: pressed into it by their weight.
    const double weight = 1000 * std::numbers::pi * radii[i] * radii[i] * 9.81;
    disc.position = {0.1 + 0.2 * i, radii[i] - weight / 1e6};
    disc.radius = radii[i];
    def.particles.push_back(disc);
  }
  def.walls.push_back(WallDef{"bottom", {0.5, 0.0}, {1.0, 0.0}, -0.6, 0.6, MaterialId{0}, {}});
  def.walls.push_back(WallDef{"top", {0.5, 1.0}, {-1.0, 0.0}, -0.6, 0.6, MaterialId{0}, {}});
  def.gravity = {0.0, -9.81};
  // Local damping stills the discs without touching the contact forces,
  // so the plate's force is the sum of its springs'.
  def.damping.local_alpha = 0.7;
  def.fixed_time_step = 1e-4;
  def.threads = 1;
  return def;
}

dem::analysis::CompressionSettings settings() {
  dem::analysis::CompressionSettings s;
  s.loading_plate = WallId{1};
  s.bottom_plate = WallId{0};
  s.loading_stage = 1;
  s.transition_stress = 2000;
  s.final_stress = 5000;
  s.contacts_at_stress = {500, 8000};
  s.force_distribution = dem::analysis::ForceDistributionSettings{7000, 8500, 4, 0.25, 1.0};
  return s;
}

class CompressionAnalysisTest : public ::testing::Test {
 protected:
  // A first stage of 10 cycles the analyses skip, then the plate placed
  // 1 cm above the discs and lowered at 0.1 m/s, sampled every 10 cycles.
  void run() {
    StageDef rest;
    rest.cycles = 10;
    run_stage(world_, rest, 5, [&](const World& w) { return analysis_.add(w, 0), true; });
    StageDef load;
    load.place_wall = PlaceWallDef{WallId{1}, 0.01};
    load.wall_motions = {{WallId{1}, WallMotion{{0.0, -0.1}, 0.0, {}}}};
    load.cycles = 1700;
    run_stage(world_, load, 10, [&](const World& w) {
      for (const PlateSnapshot* snapshot : analysis_.add(w, 1)) taken_.push_back(snapshot->index);
      return true;
    });
  }

  using PlateSnapshot = dem::analysis::PlateSnapshotT<2>;
  World world_{row_of_discs()};
  dem::analysis::CompressionAnalysis analysis_{settings()};
  std::vector<int> taken_;
};

TEST_F(CompressionAnalysisTest, SamplesThePlatesFromTheLoadingStageOn) {
  run();
  const std::vector<dem::analysis::CompressionSample>& samples = analysis_.samples();
  ASSERT_EQ(samples.size(), 170u);
  EXPECT_EQ(samples.front().stage, 1);
  EXPECT_EQ(samples.front().cycle, 20u);
  EXPECT_NEAR(samples.front().settlement, 0.1 * 10 * 1e-4, 1e-12);
  EXPECT_EQ(samples.front().loading_contacts, 0);
  EXPECT_EQ(samples.front().bottom_contacts, 5);
  EXPECT_EQ(samples.back().loading_contacts, 5);
  // The plate's stress is its force over its length x unit depth.
  const WallMeasure top = world_.wall_measures()[1];
  EXPECT_DOUBLE_EQ(samples.back().stress, top.normal_force / 1.2);
}

TEST_F(CompressionAnalysisTest, ContactsFormInTheirStates) {
  run();
  const dem::analysis::CompressionResults r = analysis_.results(world_);
  ASSERT_TRUE(r.state_cycles.transition && r.state_cycles.final);
  const auto& top = r.load_by_state[0];
  EXPECT_EQ(top[0].contacts, 3);
  EXPECT_EQ(top[1].contacts, 1);
  EXPECT_EQ(top[2].contacts, 1);
  // Miyata Fig. 30: the loads of the three groups add up to the plate's.
  const double load = top[0].load + top[1].load + top[2].load;
  EXPECT_NEAR(load, world_.wall_measures()[1].normal_force, 1e-9 * load);
  EXPECT_GT(top[0].load / load, 0.6);  // the first contacts carry the most
  // The bottom's contacts formed before the loading began.
  EXPECT_EQ(r.load_by_state[1][0].contacts, 5);
  EXPECT_EQ(r.load_by_state[1][1].contacts + r.load_by_state[1][2].contacts, 0);
  // By order of formation (the seed's Fig. 30): of five, ranks 0-1 (10k < 20)
  // initial, 2-3 (10k < 35) transition, 4 final.
  const auto& order = r.load_by_formation[0];
  EXPECT_EQ(order[0].contacts, 2);
  EXPECT_EQ(order[1].contacts, 2);
  EXPECT_EQ(order[2].contacts, 1);
  EXPECT_NEAR(order[0].load + order[1].load + order[2].load, load, 1e-9 * load);
  EXPECT_LE(order[1].last_formed, order[2].first_formed);
}

// Miyata Fig. 30: "the first 40 % of the contact points newly created",
// "between 40 and 70 %" and "between 70 and 100 %", whatever order the
// engine lists them in; ties in the cycle go by particle id.
TEST(LoadByFormationOrder, GroupsTheFirst40TheNext30AndTheLast30Percent) {
  std::vector<dem::analysis::PlateContactT<2>> contacts;
  const std::uint64_t formed[] = {90, 10, 50, 30, 70, 20, 100, 40, 60, 80};
  for (int k = 0; k < 10; ++k) {
    dem::analysis::PlateContactT<2> c;
    c.particle = ParticleId{9 - k};
    c.normal_force = static_cast<double>(formed[k]);  // load = the cycle, to read off the groups
    c.formed_cycle = formed[k];
    contacts.push_back(c);
  }
  const auto groups = dem::analysis::load_by_formation_order<2>(contacts);
  EXPECT_EQ(groups[0].contacts, 4);
  EXPECT_EQ(groups[1].contacts, 3);
  EXPECT_EQ(groups[2].contacts, 3);
  EXPECT_DOUBLE_EQ(groups[0].load, 10 + 20 + 30 + 40);
  EXPECT_DOUBLE_EQ(groups[1].load, 50 + 60 + 70);
  EXPECT_DOUBLE_EQ(groups[2].load, 80 + 90 + 100);
  EXPECT_EQ(groups[0].first_formed, 10u);
  EXPECT_EQ(groups[2].last_formed, 100u);
  // Three contacts formed in one cycle: the lower particle id ranks first.
  std::vector<dem::analysis::PlateContactT<2>> tied(3);
  for (int k = 0; k < 3; ++k) {
    tied[k].particle = ParticleId{2 - k};
    tied[k].formed_cycle = 5;
    tied[k].normal_force = 1.0 + k;
  }
  // Of three, ranks 0 and 1 are initial (10k < 12), rank 2 transition (20 < 21).
  const auto tie_groups = dem::analysis::load_by_formation_order<2>(tied);
  EXPECT_EQ(tie_groups[0].contacts, 2);
  EXPECT_DOUBLE_EQ(tie_groups[0].load, 3.0 + 2.0);  // particles 0 and 1
  EXPECT_EQ(tie_groups[1].contacts, 1);
  EXPECT_DOUBLE_EQ(tie_groups[1].load, 1.0);  // particle 2
  EXPECT_EQ(tie_groups[2].contacts, 0);
}

TEST_F(CompressionAnalysisTest, SnapshotsAtTheirStresses) {
  run();
  const auto& snapshots = analysis_.snapshots();
  // The loading's start (target 0: the unloaded state of Fig. 28), 500 Pa;
  // 7000 to 8500 Pa in four, whose 8000 Pa serves the contacts too.
  ASSERT_EQ(snapshots.size(), 6u);
  EXPECT_EQ(taken_, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(snapshots[0].target_stress, 0);
  EXPECT_EQ(snapshots[0].sample.cycle, analysis_.samples().front().cycle);
  EXPECT_EQ(snapshots[0].loading.size(), 0u);
  EXPECT_EQ(snapshots[0].bottom.size(), 5u);
  EXPECT_EQ(snapshots[1].target_stress, 500);
  EXPECT_GE(snapshots[1].sample.stress, 500);
  EXPECT_EQ(snapshots[1].loading.size(), 3u);
  EXPECT_EQ(snapshots[1].bottom.size(), 5u);
  EXPECT_FALSE(snapshots[1].for_distribution);
  for (std::size_t k = 2; k < snapshots.size(); ++k) {
    EXPECT_GE(snapshots[k].sample.stress, snapshots[k].target_stress);
    EXPECT_EQ(snapshots[k].loading.size(), 5u);
  }
  EXPECT_EQ(std::count_if(snapshots.begin(), snapshots.end(), [](const auto& s) { return s.for_distribution; }), 4);
  std::vector<double> for_contacts;
  for (const PlateSnapshot& s : snapshots)
    if (s.for_contacts) for_contacts.push_back(s.target_stress);
  EXPECT_EQ(for_contacts, (std::vector<double>{0, 500, 8000}));
}

// Without contacts_at_stress there is no whole-assembly moment, and no
// snapshot of the loading's start.
TEST(CompressionAnalysis, NoStartSnapshotWithoutContactsAtStress) {
  World world{row_of_discs()};
  dem::analysis::CompressionSettings s = settings();
  s.contacts_at_stress.clear();
  dem::analysis::CompressionAnalysis analysis{s};
  StageDef load;
  load.place_wall = PlaceWallDef{WallId{1}, 0.01};
  load.wall_motions = {{WallId{1}, WallMotion{{0.0, -0.1}, 0.0, {}}}};
  load.cycles = 1700;
  run_stage(world, load, 10, [&](const World& w) { return analysis.add(w, 1), true; });
  ASSERT_EQ(analysis.snapshots().size(), 4u);
  for (const dem::analysis::PlateSnapshotT<2>& snapshot : analysis.snapshots()) {
    EXPECT_TRUE(snapshot.for_distribution);
    EXPECT_FALSE(snapshot.for_contacts);
  }
}

// A checkpoint keeps the analysis's state as text (dem/io/compression_state.h):
// a fresh analysis restored from it holds the same samples and snapshots,
// bit for bit, and sums up the run the same.
TEST_F(CompressionAnalysisTest, ItsStateComesBackFromACheckpointsText) {
  run();
  const std::string text = dem::io::compression_state_text(analysis_.state());
  dem::analysis::CompressionAnalysis restored{settings()};
  restored.restore(dem::io::compression_state_from_text<2>(text));
  ASSERT_EQ(restored.samples().size(), analysis_.samples().size());
  ASSERT_EQ(restored.snapshots().size(), 6u);
  for (std::size_t i = 0; i < analysis_.samples().size(); ++i) {
    const auto& a = restored.samples()[i];
    const auto& b = analysis_.samples()[i];
    EXPECT_TRUE(a.stage == b.stage && a.cycle == b.cycle && a.time == b.time && a.settlement == b.settlement &&
                a.stress == b.stress && a.loading_contacts == b.loading_contacts &&
                a.bottom_stress == b.bottom_stress && a.bottom_contacts == b.bottom_contacts)
        << "sample " << i;
  }
  for (std::size_t k = 0; k < 6; ++k) {
    const PlateSnapshot& a = restored.snapshots()[k];
    const PlateSnapshot& b = analysis_.snapshots()[k];
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.target_stress, b.target_stress);
    EXPECT_EQ(a.for_distribution, b.for_distribution);
    EXPECT_EQ(a.for_contacts, b.for_contacts);
    ASSERT_EQ(a.loading.size(), b.loading.size());
    for (std::size_t c = 0; c < a.loading.size(); ++c) {
      EXPECT_EQ(a.loading[c].particle, b.loading[c].particle);
      EXPECT_EQ(a.loading[c].point, b.loading[c].point);
      EXPECT_EQ(a.loading[c].normal_force, b.loading[c].normal_force);
      EXPECT_EQ(a.loading[c].shear_force, b.loading[c].shear_force);
      EXPECT_EQ(a.loading[c].formed_cycle, b.loading[c].formed_cycle);
    }
    EXPECT_EQ(a.bottom.size(), b.bottom.size());
  }
  EXPECT_EQ(dem::io::compression_state_text(restored.state()), text);
  EXPECT_EQ(restored.results(world_).states[1].secant_stiffness, analysis_.results(world_).states[1].secant_stiffness);
  // More snapshots than the settings have targets: not this analysis's state.
  dem::analysis::CompressionSettings fewer = settings();
  fewer.contacts_at_stress.clear();
  fewer.force_distribution.reset();
  dem::analysis::CompressionAnalysis other{fewer};
  EXPECT_THROW(other.restore(dem::io::compression_state_from_text<2>(text)), std::runtime_error);
  EXPECT_THROW(dem::io::compression_state_from_text<2>("samples 3\n1 2"), std::runtime_error);
}

TEST_F(CompressionAnalysisTest, ForceDistributionPoolsTheSnapshots) {
  run();
  const dem::analysis::CompressionResults r = analysis_.results(world_);
  ASSERT_TRUE(r.force_distribution);
  for (const dem::analysis::PlateForceDistribution& d : *r.force_distribution) {
    EXPECT_EQ(d.snapshots, 4);
    EXPECT_EQ(d.contacts, 20);
    EXPECT_NEAR(std::accumulate(d.f.begin(), d.f.end(), 0.0) / d.contacts, 1.0, 1e-12);
    int counted = 0;
    for (const dem::analysis::ForceClass& c : d.classes) counted += c.contacts;
    EXPECT_EQ(counted, 20);
  }
  // The three tall discs carry more than the mean, the two short ones less.
  EXPECT_EQ((*r.force_distribution)[0].tail.contacts, 12);
}

TEST_F(CompressionAnalysisTest, WritesTheFilesWithTheirColumns) {
  const std::filesystem::path directory = test::fresh_directory("compression_csv");
  {
    CompressionCsv csv(directory, "top", "bottom");
    run();
    for (const dem::analysis::CompressionSample& s : analysis_.samples()) csv.write_sample(s);
    for (const PlateSnapshot& s : analysis_.snapshots()) csv.write_snapshot(s, {});
    csv.write_results(analysis_.results(world_));
    EXPECT_EQ(csv.files().size(), 10u);
  }
  const auto lines = [&](const std::string& name) {
    std::ifstream in(directory / name);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    return all;
  };
  const auto samples = lines("compression.csv");
  ASSERT_EQ(samples.size(), 171u);
  EXPECT_EQ(samples[0],
            "stage,cycle,time,settlement,stress,loading_contacts,bottom_stress,bottom_contacts,contact_ratio");
  EXPECT_EQ(samples.back().substr(samples.back().rfind(',') + 1), "1");  // 5 contacts on each plate
  // The start (none on the loading plate, five on the bottom), 500 Pa, four more.
  EXPECT_EQ(lines("plate_contacts.csv").size(), 1u + 5 + 3 + 5 + 4 * (5 + 5));
  EXPECT_EQ(lines("plate_contacts.csv")[0],
            "snapshot,target_stress,cycle,stress,plate,particle,x,y,normal_force,shear_force,f,formed_cycle,formed_in,"
            "for_contacts,for_distribution");
  // The start's bottom rows: a for_contacts snapshot, not the distribution's.
  EXPECT_EQ(lines("plate_contacts.csv")[1].substr(lines("plate_contacts.csv")[1].size() - 4), ",1,0");
  EXPECT_EQ(lines("compression_states.csv").size(), 4u);
  EXPECT_EQ(lines("load_by_state.csv").size(), 7u);
  EXPECT_EQ(lines("load_by_formation.csv").size(), 7u);
  EXPECT_EQ(lines("force_tail.csv")[0],
            "plate,snapshots,contacts,mean_force,tail_from,tail_contacts,decay_rate,decay_rate_error,excess_cv,"
            "q_model_decay_rate,mueth_decay_rate");
  EXPECT_EQ(lines("force_distribution.csv")[0],
            "plate,f_low,f_high,contacts,probability_density,load_share,load_density,q_model,mueth");
  EXPECT_EQ(lines("stress_drops.csv").size(), 1u);  // the stress only rises
  std::filesystem::remove_all(directory);
}

// Figs. 27-28 need the whole assembly where the plates' contacts are
// taken: record_compression writes every particle and contact at the
// loading's start and at each contacts_at_stress snapshot, at the same
// moment as plate_contacts.csv (the same plate forces, particle by
// particle), with the columns of particles.csv and contacts.csv.
TEST(CompressionAnalysis, WritesTheWholeAssemblyAtTheContactSnapshots) {
  World world{row_of_discs()};
  dem::analysis::CompressionAnalysis analysis{settings()};
  const std::filesystem::path directory = test::fresh_directory("compression_assembly");
  {
    CompressionCsv csv(directory, "top", "bottom");
    StageDef load;
    load.place_wall = PlaceWallDef{WallId{1}, 0.01};
    load.wall_motions = {{WallId{1}, WallMotion{{0.0, -0.1}, 0.0, {}}}};
    load.cycles = 1700;
    run_stage(world, load, 10, [&](const World& w) { return record_compression(analysis, csv, w, 1), true; });
  }
  const auto particles = test::read_csv(directory / "particles_at_stress.csv");
  const auto contacts = test::read_csv(directory / "contacts_at_stress.csv");
  ASSERT_EQ(particles[0].size(), 4u + 12);
  EXPECT_EQ(particles[0][0] + "," + particles[0][1] + "," + particles[0][2] + "," + particles[0][3] + "," +
                particles[0][4] + "," + particles[0][11] + "," + particles[0][15],
            "snapshot,target_stress,cycle,stress,id,rotation,n");
  EXPECT_EQ(contacts[0][4] + "," + contacts[0][5] + "," + contacts[0][12], "first,second_kind,normal_force");
  // Five discs at each of the three for_contacts snapshots: 0, 500, 8000 Pa.
  ASSERT_EQ(particles.size(), 1u + 3 * 5);
  const std::vector<std::string> snapshots = {"0", "1", "4"};
  for (std::size_t k = 0; k < 3; ++k) {
    const dem::analysis::PlateSnapshotT<2>& snapshot = analysis.snapshots()[std::stoul(snapshots[k])];
    ASSERT_TRUE(snapshot.for_contacts);
    const auto& row = particles[1 + 5 * k];
    EXPECT_EQ(row[0], snapshots[k]);
    EXPECT_EQ(std::stod(row[1]), snapshot.target_stress);
    EXPECT_EQ(std::stoull(row[2]), snapshot.sample.cycle);
    // The top plate's contacts in contacts_at_stress.csv are plate_contacts' at that moment.
    std::vector<std::pair<std::string, std::string>> on_top;
    for (const auto& c : contacts)
      if (c[0] == snapshots[k] && c[5] == "wall" && c[6] == "top") on_top.emplace_back(c[4], c[12]);
    ASSERT_EQ(on_top.size(), snapshot.loading.size()) << "snapshot " << snapshots[k];
    for (std::size_t c = 0; c < on_top.size(); ++c) {
      EXPECT_EQ(std::stoi(on_top[c].first), snapshot.loading[c].particle.value());
      EXPECT_EQ(std::stod(on_top[c].second), snapshot.loading[c].normal_force);
    }
  }
  std::filesystem::remove_all(directory);
}

// In 3D (Miyata 3.3): four ellipsoids resting on a floor, a plate placed
// 5 mm above them and lowered until it carries 1 kPa over its 1.2 m x 1 m.
// The plate's contacts lie on its face, and the files carry z.
TEST(CompressionAnalysis3d, EllipsoidsUnderAPlate) {
  WorldDef3 def;
  def.materials.push_back({"rock", 2600, 0.5, 0, 70e9, 0.2});
  ContactModelDef model;
  model.law = ContactLaw::kHertzLinearTangential;
  model.hertz.restitution = 0.5;
  def.contact_models.push_back(model);
  for (int i = 0; i < 4; ++i) {
    ParticleDef3 p;
    p.position = {0.15 + 0.3 * i, 0.5, 0.05};
    p.shape.axes = {0.1, 0.07, 0.05};
    def.particles.push_back(p);
  }
  WallDef3 bottom;
  bottom.name = "bottom";
  bottom.h2 = 1.2;
  WallDef3 top = bottom;
  top.name = "top";
  top.point = {0.0, 1.0, 0.5};
  top.direction2 = {0.0, -1.0, 0.0};  // the normal, direction x direction2, faces down at the particles
  def.walls = {bottom, top};
  def.gravity = {0.0, 0.0, -9.81};
  def.damping.local_alpha = 0.7;
  def.threads = 1;
  World3 world(def);

  dem::analysis::CompressionSettings s;
  s.loading_plate = WallId{1};
  s.bottom_plate = WallId{0};
  s.loading_stage = 1;
  s.contacts_at_stress = {500};
  dem::analysis::CompressionAnalysis3 analysis(s);
  const std::filesystem::path directory = test::fresh_directory("compression_csv_3d");
  {
    CompressionCsv3 csv(directory, "top", "bottom");
    StageDef3 rest;
    rest.cycles = 2000;
    run_stage(world, rest, 100, [&](const World3& w) { return record_compression(analysis, csv, w, 0), true; });
    StageDef3 load;
    load.place_wall = PlaceWallDef{WallId{1}, 0.005};
    load.wall_motions = {{WallId{1}, WallMotion3{{0.0, 0.0, -0.05}, Vec3::Zero(), {}}}};
    load.cycles = 200000;
    load.until.wall_stress_above = WallThreshold{WallId{1}, 1000};
    run_stage(world, load, 10, [&](const World3& w) { return record_compression(analysis, csv, w, 1), true; });
    record_compression(analysis, csv, world, 1);
    csv.write_results(analysis.results(world));
  }
  ASSERT_FALSE(analysis.samples().empty());
  EXPECT_EQ(analysis.samples().front().stage, 1);
  EXPECT_GE(analysis.samples().back().stress, 1000);
  EXPECT_EQ(analysis.samples().back().loading_contacts, 4);
  EXPECT_EQ(analysis.samples().back().bottom_contacts, 4);
  ASSERT_EQ(analysis.snapshots().size(), 2u);  // the loading's start and 500 Pa
  const double plate_z = world.wall(WallId{1}).point.z();
  for (const dem::analysis::PlateContactT<3>& c : analysis.snapshots()[1].loading)
    EXPECT_NEAR(c.point.z(), plate_z, 1e-3);
  std::ifstream in(directory / "plate_contacts.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "snapshot,target_stress,cycle,stress,plate,particle,x,y,z,normal_force,shear_force,f,formed_cycle,"
            "formed_in,for_contacts,for_distribution");
  // The whole assembly at both: four ellipsoids with their quaternions and
  // semi-axes, and their contacts (none between them, four on each plate at
  // 500 Pa).
  const auto particles = test::read_csv(directory / "particles_at_stress.csv");
  ASSERT_EQ(particles.size(), 1u + 2 * 4);
  ASSERT_EQ(particles[0].size(), 4u + 19);  // the snapshot's four, then particles.csv's
  EXPECT_EQ(particles[0][0] + "," + particles[0][3] + "," + particles[0][4] + "," + particles[0][15],
            "snapshot,stress,id,rotation_w");
  EXPECT_EQ(particles.back()[0], "1");
  EXPECT_EQ(particles.back()[1], "500");
  EXPECT_EQ(std::stoull(particles.back()[2]), analysis.snapshots()[1].sample.cycle);
  EXPECT_EQ(particles.back()[20] + "," + particles.back()[21] + "," + particles.back()[22], "0.1,0.07,0.05");
  const auto contacts = test::read_csv(directory / "contacts_at_stress.csv");
  int on_top = 0;
  for (std::size_t r = 1; r < contacts.size(); ++r) {
    EXPECT_EQ(contacts[r][5], "wall");
    on_top += contacts[r][0] == "1" && contacts[r][6] == "top";
  }
  EXPECT_EQ(on_top, 4);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace dem::io
