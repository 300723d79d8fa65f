// Everything the service reads from the engine, in a few small functions:
// plate forces (with the normal stress and settlement), contact statistics
// and contact queries, as protocol messages. Written once over the
// dimension; the rest of the service never looks inside a World.
#pragma once

#include <optional>
#include <vector>

#include "dem/analysis/region_measures.h"
#include "dem/protocol/messages.h"
#include "dem/world.h"

namespace dem::service {

// The normalised contact force histogram: bins of this width from f = 0,
// the last one open-ended (docs/DDS.md, ContactStats).
inline constexpr double kHistogramBinWidth = 0.25;
inline constexpr int kHistogramBins = 21;  // [0, 0.25) ... [4.75, 5), [5, inf)

// One wall: its resultant, normal stress = normal force / wall_area (the
// length times the unit depth in 2D, the area in 3D) and settlement = the
// displacement of its reference point since the case was loaded, along the
// wall's normal (towards the particles).
template <int Dim>
protocol::WallForce read_wall(const BasicWorld<Dim>& world, WallId wall);

template <int Dim>
std::vector<protocol::WallForce> read_walls(const BasicWorld<Dim>& world);

// Contact counts, sliding fraction, coordination number (2 C_pp + C_pw) / N,
// mean and maximum normal force, the histogram of f = F / mean(F), kinetic
// energy and out-of-balance ratio.
template <int Dim>
protocol::ContactStats read_contact_stats(const BasicWorld<Dim>& world);

// The measures of the case's regions (output.region; dem/analysis) as the
// telemetry carries them; the server, cycle, time and stamp are the
// caller's to set.
template <int Dim>
protocol::RegionTelemetry read_regions(const BasicWorld<Dim>& world,
                                       const std::vector<analysis::RegionT<Dim>>& regions);

// Filters a contact query can combine; unset ones let everything through.
struct ContactFilter {
  std::optional<WallId> wall;
  std::optional<protocol::Vector3> box_min;  // with box_max: the contact point inside the box
  std::optional<protocol::Vector3> box_max;
  std::optional<double> min_normal_force;  // N: contacts carrying more
  std::optional<ParticleId> particle;      // the contacts of this particle
};

template <int Dim>
// Throws CommandError (not found) when the filter names a particle the
// world does not hold: a stale id is an error, not another particle.
std::vector<protocol::ContactEntry> query_contacts(const BasicWorld<Dim>& world, const ContactFilter& filter);

// A servo's gain and speed cap when a command leaves them to the server.
// Stability needs gain k_n n dt < 1 for n wall contacts of normal stiffness
// k_n over one time step dt (the servo of PFC and Randall 1989, 4.1); the
// gain takes half of that bound with n the most discs that fit along the
// wall, so it stays stable as contacts form. The cap moves the wall at most
// a twentieth of the mean radius per step. Nothing when no contact model
// has a linear stiffness (the Hertz laws' stiffness depends on the overlap).
struct ServoLimits {
  double gain = 0.0;       // m/(N s)
  double max_speed = 0.0;  // m/s
};
template <int Dim>
std::optional<ServoLimits> default_servo_limits(const BasicWorld<Dim>& world, WallId wall,
                                                const std::vector<ContactModelDef>& contact_models);

}  // namespace dem::service
