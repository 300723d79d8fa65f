// The measures of a region on arrangements whose answers are known by hand:
// a square packing of discs under known contact forces (the stress tensor,
// its tangential part, the fabric, porosity, coordination), rattlers, and a
// real World whose packing is pressed by walls.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <type_traits>

#include "dem/analysis/region_measures.h"
#include "dem/world.h"

namespace dem::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

// k x k discs of radius R at spacing 2R, touching, with walls around them.
// Every horizontal contact (between discs, and with the side walls) presses
// with F_x and carries a tangential force T; every vertical one presses with
// F_y and carries T, turned so that each disc's moments balance: the stress
// is [[F_x, -T], [-T, F_y]] / (2R) per unit depth.
struct Lattice {
  int k = 4;
  double radius = 0.5, fx = 3.0, fy = 1.0, t = 0.0;
};

// A contact of particle a with particle b (or a wall, b = -1) along the
// unit normal e (from a to the other), with the force on a.
template <int Dim>
void add_contact(AssemblySampleT<Dim>& s, int a, int b, const std::type_identity_t<Vec<Dim>>& e,
                 const std::type_identity_t<Vec<Dim>>& force_on_a, double radius, int wall) {
  ContactRecordT<Dim> c;
  c.first = ParticleId{a};
  if (b >= 0) {
    c.second_particle = ParticleId{b};
  } else {
    c.second_wall = WallId{wall};
  }
  c.normal = e;
  c.point = s.position[static_cast<std::size_t>(a)] + radius * e;
  c.force = force_on_a;
  c.normal_force = -force_on_a.dot(e);
  c.tangential_force = force_on_a - force_on_a.dot(e) * e;
  if constexpr (Dim == 2) {
    c.shear_force = force_on_a.dot(Vec2(e.y(), -e.x()));  // along t = e turned clockwise; F_s acts against t (Fig. 3)
  } else {
    c.shear_force = c.tangential_force.norm();
  }
  s.contacts.push_back(c);
}

AssemblySample lattice(const Lattice& l) {
  AssemblySample s;
  const double r = l.radius;
  auto id = [&](int i, int j) { return j * l.k + i; };
  for (int j = 0; j < l.k; ++j) {
    for (int i = 0; i < l.k; ++i) {
      s.position.push_back({r + 2.0 * r * i, r + 2.0 * r * j});
      s.radius.push_back(r);
      s.rotation.push_back(0.1 * i);
    }
  }
  const Vec2 ex = Vec2::UnitX(), ey = Vec2::UnitY();
  for (int j = 0; j < l.k; ++j) {
    for (int i = 0; i < l.k; ++i) {
      // The right-hand neighbour or wall: force (-F_x, T) on this disc.
      add_contact(s, id(i, j), i + 1 < l.k ? id(i + 1, j) : -1, ex, {-l.fx, l.t}, r, 1);
      // The one above: force (T, -F_y).
      add_contact(s, id(i, j), j + 1 < l.k ? id(i, j + 1) : -1, ey, {l.t, -l.fy}, r, 2);
      // The walls on the left and below push back the same.
      if (i == 0) add_contact(s, id(i, j), -1, -ex, {l.fx, -l.t}, r, 3);
      if (j == 0) add_contact(s, id(i, j), -1, -ey, {-l.t, l.fy}, r, 0);
    }
  }
  return s;
}

TEST(RegionMeasures, SquarePackingUnderKnownForcesGivesTheBoundaryTractions) {
  const Lattice l;
  const AssemblySample s = lattice(l);
  const double side = 2.0 * l.radius * l.k;
  for (const Region& region : {Region{"all"}, Region{"box", RegionShape::kBox, {0.0, 0.0}, {side, side}}}) {
    const RegionMeasures m = measure_region(s, region);
    // Cundall & Strack's discs of unit thickness: sigma = F / (2R) per unit depth.
    EXPECT_NEAR(m.stress(0, 0), l.fx / (2.0 * l.radius), 1e-12) << region.name;
    EXPECT_NEAR(m.stress(1, 1), l.fy / (2.0 * l.radius), 1e-12);
    EXPECT_NEAR(m.stress(0, 1), 0.0, 1e-12);
    EXPECT_NEAR(m.porosity, 1.0 - kPi / 4.0, 1e-12);
    EXPECT_NEAR(m.void_ratio, m.porosity / (1.0 - m.porosity), 1e-12);
    EXPECT_EQ(m.particles, 16);
    EXPECT_EQ(m.rattlers, 0);
    EXPECT_NEAR(m.coordination, 4.0, 1e-12);  // walls count
    EXPECT_NEAR(m.mechanical_coordination, 4.0, 1e-12);
    EXPECT_NEAR(m.principal_stress.values[0], 3.0, 1e-12);
    EXPECT_NEAR(m.principal_stress.values[1], 1.0, 1e-12);
    EXPECT_NEAR(m.principal_stress.angle, 0.0, 1e-12);
    EXPECT_NEAR(m.mean_stress, 2.0, 1e-12);
    EXPECT_NEAR(m.sin_phi, 0.5, 1e-12);  // (3 - 1) / (3 + 1)
    EXPECT_NEAR(m.tangential_share, 0.0, 1e-12);
    // Randall 4.48: as many horizontal as vertical contacts; weighted to
    // the normal force, 3 : 1.
    EXPECT_EQ(m.particle_contacts, 24);
    EXPECT_NEAR(m.fabric.tensor(0, 0), 0.5, 1e-12);
    EXPECT_NEAR(m.fabric.anisotropy, 0.0, 1e-12);
    EXPECT_NEAR(m.weighted_fabric.tensor(0, 0), 0.75, 1e-12);
    EXPECT_NEAR(m.weighted_fabric.principal.values[0] - m.weighted_fabric.principal.values[1], 0.5, 1e-12);
    EXPECT_NEAR(m.fabric_trace, 2.0 * 24 * l.radius / (side * side), 1e-12);  // (4.46)
    EXPECT_NEAR(m.max_normal_force, 3.0, 1e-12);
    EXPECT_NEAR(m.mean_rotation, 0.15, 1e-12);  // 0, 0.1, 0.2, 0.3 in each row
  }
}

TEST(RegionMeasures, TangentialForcesCarryTheirShareOfTheDeviator) {
  Lattice l;
  l.fx = 2.0;
  l.fy = 2.0;
  l.t = 0.5;
  AssemblySample s = lattice(l);
  const RegionMeasures m = measure_region(s, Region{"all"});
  // [[2, -0.5], [-0.5, 2]]: principal 2.5 and 1.5 at -45 degrees, and the
  // whole deviator is the tangential forces' (equal normal stresses).
  EXPECT_NEAR(m.stress(0, 1), -0.5, 1e-12);
  EXPECT_NEAR(m.stress(1, 0), -0.5, 1e-12);
  EXPECT_NEAR(m.principal_stress.values[0], 2.5, 1e-12);
  EXPECT_NEAR(m.principal_stress.values[1], 1.5, 1e-12);
  EXPECT_NEAR(m.principal_stress.angle, -kPi / 4.0, 1e-12);
  EXPECT_NEAR(m.tangential_share, 1.0, 1e-12);
  EXPECT_NEAR(m.tangential_stress(0, 0), 0.0, 1e-12);
  // Unequal normal stresses a, b: the share is 4 tau^2 / ((a - b)^2 + 4 tau^2).
  l.fx = 3.0;
  l.fy = 1.0;
  s = lattice(l);
  const RegionMeasures m2 = measure_region(s, Region{"all"});
  const double a = 3.0, b = 1.0, tau = 0.5;
  EXPECT_NEAR(m2.tangential_share, 4.0 * tau * tau / ((a - b) * (a - b) + 4.0 * tau * tau), 1e-12);
}

TEST(RegionMeasures, AMeasurementCircleInsideAPackingReadsItsStress) {
  Lattice l;
  l.k = 40;
  const AssemblySample s = lattice(l);
  Region circle{"circle", RegionShape::kBall};
  circle.centre = {20.0, 20.0};
  circle.radius = 12.0;
  const RegionMeasures m = measure_region(s, circle);
  // The discs whose centres lie inside stand for the circle's area times
  // its solid fraction: near F / (2R), off by the discs cut by its edge.
  std::printf(
      "measurement circle of radius 12 in a square packing: sigma_xx %.5f (3), sigma_yy %.5f (1), "
      "porosity %.5f (%.5f), %d discs\n",
      m.stress(0, 0), m.stress(1, 1), m.porosity, 1.0 - kPi / 4.0, m.particles);
  EXPECT_NEAR(m.stress(0, 0), 3.0, 0.03);
  EXPECT_NEAR(m.stress(1, 1), 1.0, 0.01);
  EXPECT_NEAR(m.porosity, 1.0 - kPi / 4.0, 0.005);
  EXPECT_EQ(m.rattlers, 0);
}

TEST(RegionMeasures, RattlersAreThoseLeftWithFewerThanTwoContacts) {
  // A chain 0-1-2-3 with 0 and 3 also on walls, and a disc 4 touching only
  // disc 5, which touches 4 and 2: 4 is a rattler (one contact), and then
  // so is 5 (one contact left); 0-3 are not. Disc 6 touches nothing.
  AssemblySample s;
  for (int i = 0; i < 7; ++i) {
    s.position.push_back({static_cast<double>(i), 0.0});
    s.radius.push_back(0.5);
  }
  const Vec2 e = Vec2::UnitX();
  add_contact(s, 0, -1, -e, {0.1, 0.0}, 0.5, 0);
  add_contact(s, 0, 1, e, {-0.1, 0.0}, 0.5, 0);
  add_contact(s, 1, 2, e, {-0.1, 0.0}, 0.5, 0);
  add_contact(s, 2, 3, e, {-0.1, 0.0}, 0.5, 0);
  add_contact(s, 3, -1, e, {-0.1, 0.0}, 0.5, 1);
  add_contact(s, 4, 5, e, {-0.1, 0.0}, 0.5, 0);
  add_contact(s, 2, 5, Vec2::UnitY(), {0.0, -0.1}, 0.5, 0);
  const std::vector<bool> rattlers = find_rattlers(s);
  EXPECT_EQ(rattlers, (std::vector<bool>{false, false, false, false, true, true, true}));
  const RegionMeasures m = measure_region(s, Region{"all"});
  EXPECT_EQ(m.rattlers, 3);
  // Contacts per disc: 2, 2, 3, 2, 1, 2, 0 -> 12 / 7; without rattlers 2 each.
  EXPECT_NEAR(m.coordination, 12.0 / 7.0, 1e-12);
  EXPECT_NEAR(m.mechanical_coordination, 2.0, 1e-12);
}

TEST(RegionMeasures, SlidingContactsAreCountedAmongTheParticleContacts) {
  // The 4 x 4 lattice's 24 particle-particle contacts, 6 of them at the
  // Coulomb limit, and two wall contacts marked sliding too: those are left
  // out (a wall contact's friction is the wall's).
  AssemblySample s = lattice(Lattice{});
  int marked = 0, walls = 0;
  for (ContactRecord& c : s.contacts) {
    if (c.second_particle != kInvalidId && marked < 6) {
      c.sliding = true;
      ++marked;
    } else if (c.second_particle == kInvalidId && walls < 2) {
      c.sliding = true;
      ++walls;
    }
  }
  const RegionMeasures m = measure_region(s, Region{"all"});
  EXPECT_EQ(m.particle_contacts, 24);
  EXPECT_EQ(m.contacts, 40);  // and 16 with the four walls
  EXPECT_EQ(m.sliding_contacts, 6);
  EXPECT_NEAR(m.sliding_fraction, 0.25, 1e-12);
}

// 3D: k^3 spheres of radius R in a simple cubic packing, every contact
// along x pressing with F_x, along y with F_y, along z with F_z (walls
// around): each sphere's cell (2R)^3 carries 2 R F per axis, so
// sigma_ii = F_i / (4 R^2); porosity 1 - pi/6; fabric diag(1/3).
TEST(RegionMeasures, CubicPackingOfSpheresGivesTheBoundaryTractions) {
  constexpr int k = 3;
  constexpr double r = 0.5;
  const Vec3 force{6.0, 3.0, 1.0};
  AssemblySample3 s;
  auto id = [&](int i, int j, int l) { return (l * k + j) * k + i; };
  for (int l = 0; l < k; ++l) {
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < k; ++i) {
        s.position.push_back({r + 2.0 * r * i, r + 2.0 * r * j, r + 2.0 * r * l});
        s.radius.push_back(r);
        s.rotation.push_back(0.0);
      }
    }
  }
  for (int l = 0; l < k; ++l) {
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < k; ++i) {
        const int a = id(i, j, l);
        const int index[3] = {i, j, l};
        for (int axis = 0; axis < 3; ++axis) {
          const Vec3 e = Vec3::Unit(axis);
          int next[3] = {i, j, l};
          ++next[axis];
          add_contact(s, a, index[axis] + 1 < k ? id(next[0], next[1], next[2]) : -1, e, Vec3(-force[axis] * e), r,
                      2 * axis + 1);
          if (index[axis] == 0) add_contact(s, a, -1, Vec3(-e), Vec3(force[axis] * e), r, 2 * axis);
        }
      }
    }
  }
  const double side = 2.0 * r * k;
  const Region3 box{"box", RegionShape::kBox, Vec3::Zero(), Vec3::Constant(side)};
  for (const Region3& region : {Region3{"all"}, box}) {
    const RegionMeasures3 m = measure_region(s, region);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(m.stress(axis, axis), force[axis] / (4.0 * r * r), 1e-12) << region.name << " axis " << axis;
      EXPECT_NEAR(m.stress(axis, (axis + 1) % 3), 0.0, 1e-12);
      EXPECT_NEAR(m.fabric.tensor(axis, axis), 1.0 / 3.0, 1e-12);
      EXPECT_NEAR(m.weighted_fabric.tensor(axis, axis), force[axis] / force.sum(), 1e-12);
    }
    EXPECT_NEAR(m.principal_stress.values[0], 6.0, 1e-12);
    EXPECT_NEAR(m.principal_stress.values[2], 1.0, 1e-12);
    EXPECT_NEAR(std::abs(m.principal_stress.directions.col(0).x()), 1.0, 1e-12);  // the major axis is x
    EXPECT_NEAR(m.mean_stress, 10.0 / 3.0, 1e-12);
    EXPECT_NEAR(m.sin_phi, 5.0 / 7.0, 1e-12);  // (6 - 1) / (6 + 1)
    EXPECT_NEAR(m.porosity, 1.0 - kPi / 6.0, 1e-12);
    EXPECT_NEAR(m.coordination, 6.0, 1e-12);
    EXPECT_EQ(m.particle_contacts, 3 * k * k * (k - 1));
    EXPECT_NEAR(m.fabric.anisotropy, 0.0, 1e-12);
  }
}

// A World: 3 x 3 discs of radius 1 in a square packing pressed by four
// walls, each contact overlapping by delta, so with the linear
// spring-dashpot's F = k delta (Miyata eq. 13) the sample carries
// k delta / (2 - delta) per unit depth both ways at the first instant.
TEST(RegionMeasures, WorldPressedByWallsCarriesTheirStress) {
  const double delta = 1e-7, k = 1e6;
  WorldDef def;
  def.materials.push_back({"disc", 1000, 0.5, 0});
  ContactModelDef model;
  model.law = ContactLaw::kLinearRestitution;
  model.linear = {k, k};
  model.restitution = 0.5;
  def.contact_models.push_back(model);
  const double spacing = 2.0 - delta;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) def.particles.push_back(ParticleDef{{1.0 + spacing * i, 1.0 + spacing * j}, 1.0});
  }
  const double low = 1.0 - (1.0 - delta), high = 1.0 + 2.0 * spacing + (1.0 - delta);
  const double middle = 0.5 * (low + high);
  def.walls.push_back(WallDef{"bottom", {middle, low}, {1.0, 0.0}, -5.0, 5.0, MaterialId{0}, {}});
  def.walls.push_back(WallDef{"right", {high, middle}, {0.0, 1.0}, -5.0, 5.0, MaterialId{0}, {}});
  def.walls.push_back(WallDef{"top", {middle, high}, {-1.0, 0.0}, -5.0, 5.0, MaterialId{0}, {}});
  def.walls.push_back(WallDef{"left", {low, middle}, {0.0, -1.0}, -5.0, 5.0, MaterialId{0}, {}});
  def.fixed_time_step = 1e-5;
  def.threads = 1;
  const World world(def);
  const AssemblySample s = sample(world);
  ASSERT_EQ(s.contacts.size(), 24u);
  // The cells of the packing tile this box exactly.
  const Region cells{"cells",
                     RegionShape::kBox,
                     {1.0 - 0.5 * spacing, 1.0 - 0.5 * spacing},
                     {1.0 + 2.5 * spacing, 1.0 + 2.5 * spacing}};
  const RegionMeasures m = measure_region(s, cells);
  const double expected = k * delta / spacing;
  std::printf("pressed packing: sigma_xx %.9e, sigma_yy %.9e, expected %.9e\n", m.stress(0, 0), m.stress(1, 1),
              expected);
  // The discs overlap their neighbours by delta: the solid they clip to the
  // box counts those slivers twice, an error of order delta / R.
  EXPECT_NEAR(m.stress(0, 0) / expected, 1.0, 1e-6);
  EXPECT_NEAR(m.stress(1, 1) / expected, 1.0, 1e-6);
  EXPECT_NEAR(m.stress(0, 1) / expected, 0.0, 1e-9);
  // The side wall carries three contacts of k delta over the sample's side.
  const auto walls = world.wall_measures();
  EXPECT_NEAR(walls[1].normal_force, 3.0 * k * delta,
              1e-8 * k * delta);  // overlaps of 1e-7 on positions of 1: round-off 1e-9
  EXPECT_NEAR(m.stress(0, 0) * 3.0 * spacing / walls[1].normal_force, 1.0, 1e-6);
  EXPECT_NEAR(m.coordination, 4.0, 1e-12);
}

}  // namespace
}  // namespace dem::analysis
