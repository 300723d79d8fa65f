// The force-displacement pass over the contact table (Cundall & Strack,
// the force-displacement law) and the force sums it feeds (eqs. 20-21):
// every row is brought up to the particles' current positions and
// velocities and its forces are added into the particles' and walls' sums,
// block by block (contact_blocks.h). The contact law and the particles'
// shape are chosen once per pass, for all particle-particle rows and for all
// particle-wall rows.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "dem/measures.h"
#include "dem/snapshot.h"
#include "step_context.h"

namespace dem {

template <int Dim>
struct WorldState;

// Energy flows of the contacts settled in one pass: the work the dashpots
// took out, the work done on the tangential springs (what they do not give
// back was lost to sliding and micro-slip), and the work of moving walls.
struct ContactEnergy {
  double damping = 0.0;
  double tangential_work = 0.0;
  double wall_work = 0.0;
  ContactEnergy& operator+=(const ContactEnergy& o) {
    damping += o.damping;
    tangential_work += o.tangential_work;
    wall_work += o.wall_work;
    return *this;
  }
};

// The force pass: advances every row's history over the step that brought
// the particles where they are, and sets the force and moment sums of every
// particle and wall. The energy flows are zero unless the step books them.
template <int Dim>
ContactEnergy advance_contacts(WorldState<Dim>& state, const StepContext& step);

// The same sums from the histories as they stand, without advancing them:
// after an edit (particles removed, a wall placed) changed which contacts
// act but not where the particles are.
template <int Dim>
void evaluate_contacts(WorldState<Dim>& state);

// A touching row as the last pass left it: its record, and the force and
// moments the pass applied (force on the first particle).
template <int Dim>
struct RowReport {
  bool wall = false;  // a particle-wall row
  std::size_t row = 0;
  ContactRecordT<Dim> record;
  ShearForce<Dim> shear_damping = zero_shear<Dim>();  // D_s as the law holds it (a vector in 3D)
  Vec<Dim> force = Vec<Dim>::Zero();
  Spin<Dim> moment_first = Space<Dim>::zero_spin();
  Spin<Dim> moment_second = Space<Dim>::zero_spin();
};

// Calls visit(report) for every touching row: pair rows, then wall rows,
// each in table order.
template <int Dim>
void visit_touching_rows(const WorldState<Dim>& state, const std::function<void(const RowReport<Dim>&)>& visit);

// Calls visit(record) for every touching contact as the last pass left it.
template <int Dim>
void visit_touching_contacts(const WorldState<Dim>& state,
                             const std::function<void(const ContactRecordT<Dim>&)>& visit);

// Every touching contact as the last pass left it, by particle id.
template <int Dim>
std::vector<ContactRecordT<Dim>> report_contacts(const WorldState<Dim>& state);

// The touching contacts of one wall, in the same order.
template <int Dim>
std::vector<ContactRecordT<Dim>> report_wall_contacts(const WorldState<Dim>& state, WallId wall);

// The touching contact between two particles, if any.
template <int Dim>
std::optional<ContactRecordT<Dim>> report_pair_contact(const WorldState<Dim>& state, ParticleId a, ParticleId b);

}  // namespace dem
