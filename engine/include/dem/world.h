// The public face of the engine: build a World from a WorldDef, cycle it,
// steer its walls, and read what it measures. No files, no networking.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dem/definitions.h"
#include "dem/measures.h"
#include "dem/profile.h"
#include "dem/snapshot.h"

namespace dem {

struct WorldState;  // engine/src: particles, walls, contacts

// Read-only views of the particles' state arrays (structure of arrays,
// indexed by ParticleId). Valid until the next call that changes the World.
struct ParticleView {
  std::span<const Vec2> position;
  std::span<const Vec2> velocity;          // at the last half step, m/s
  std::span<const double> angular_velocity;
  std::span<const double> rotation;        // accumulated angle, rad
  std::span<const double> radius;
  std::span<const double> mass;
};

class World {
 public:
  // Throws DefinitionError naming the offending item if the definition is invalid.
  explicit World(const WorldDef& def);
  // Restores a saved state; throws DefinitionError if the snapshot is
  // inconsistent (ids out of range, sizes that do not match).
  explicit World(const WorldSnapshot& snapshot);
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Runs n calculation cycles (Cundall & Strack, The calculation cycle).
  void cycle(std::uint64_t n = 1);

  std::uint64_t cycle_count() const;
  double time() const;       // s
  double time_step() const;  // s
  double critical_time_step() const;  // s, the estimate 2 sqrt(m/k)

  int particle_count() const;
  int wall_count() const;
  ParticleView particles() const;

  // Walls, by dense id; find_wall returns kInvalidId for an unknown name.
  WallId find_wall(std::string_view name) const;
  const WallDef& wall(WallId id) const;  // current geometry and motion
  void set_wall_motion(WallId id, const WallMotion& motion);

  std::vector<WallMeasure> wall_measures() const;
  AssemblyMeasures assembly_measures() const;
  std::vector<ContactRecord> contacts() const;  // touching contacts only
  // The touching contact between two particles, if any.
  std::optional<ContactRecord> contact_between(ParticleId a, ParticleId b) const;

  DampingDef damping() const;
  void set_damping(const DampingDef& damping);
  Vec2 gravity() const;
  void set_gravity(const Vec2& gravity);

  // Time spent in each phase of the cycle since the world was built.
  const StepProfile& profile() const;

  int threads() const;
  void set_threads(int threads);  // 0 = all cores; results do not depend on it

  // Everything needed to continue this run exactly (see snapshot.h).
  WorldSnapshot snapshot() const;

  // The time step as a fraction of the critical step (0, 1]; recomputes the step.
  void set_time_step_fraction(double fraction);
  // Friction coefficient tan(phi) of a material; recomputes the pair table
  // (contact models that set their own friction keep it).
  void set_friction(MaterialId material, double friction);
  const std::vector<MaterialDef>& materials() const;

  // 64-bit hash of the complete dynamic state (positions, velocities,
  // rotations, contact history, walls), bit for bit.
  std::uint64_t state_hash() const;

 private:
  std::unique_ptr<WorldState> state_;
};

}  // namespace dem
