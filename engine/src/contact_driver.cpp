#include "dem/contact_driver.h"

#include <cmath>

#include "contact_history.h"
#include "contact_params.h"
#include "dem/error.h"
#include "dem/law_traits.h"
#include "law_dispatch.h"

namespace dem {

// The 2D form of the laws suffices: the motion stays in one plane, with the
// tangential axis t along which F_s is signed (Cundall & Strack, Fig. 3).
struct ContactDriver::State {
  ContactParams params;
  PairProperties pair{};
  ContactHistory<2> history;
  ContactForces<2> forces;
  double overlap = 0.0;
};

ContactDriver::ContactDriver(const ContactDriverDef& def) : state_(std::make_unique<State>()) {
  if (def.radius_a <= 0.0 || def.radius_b < 0.0 || def.mass_a <= 0.0) {
    throw DefinitionError("contact driver: radii and mass must be > 0");
  }
  ContactModelDef model = def.model;
  model.material_a = MaterialId{0};
  model.material_b = MaterialId{1};
  const ContactParamTable table({def.material_a, def.material_b}, {model}, DampingDef{});
  state_->params = table(0, 1);
  const bool wall = def.radius_b == 0.0;
  state_->pair.effective_radius = wall ? def.radius_a : def.radius_a * def.radius_b / (def.radius_a + def.radius_b);
  state_->pair.effective_mass = wall ? def.mass_a : def.mass_a * def.mass_b / (def.mass_a + def.mass_b);
}

ContactDriver::~ContactDriver() = default;
ContactDriver::ContactDriver(ContactDriver&&) noexcept = default;
ContactDriver& ContactDriver::operator=(ContactDriver&&) noexcept = default;

void ContactDriver::step(double approach, double tangential, double dt) {
  State& s = *state_;
  s.overlap += approach;
  if (s.overlap <= 0.0) {
    s.history = ContactHistory<2>{};
    s.forces = ContactForces<2>{};
    return;
  }
  // e along +y from the first body to the second; t = e turned clockwise = +x.
  const ContactKinematics<2> k{s.overlap, approach / dt, tangential / dt, Vec2::UnitY()};
  with_law(s.params.law, [&]<typename Law>() {
    Law::advance(s.history, k, s.pair, s.params, dt);
    s.forces = Law::forces(s.history, k, s.pair, s.params);
  });
}

double ContactDriver::overlap() const { return state_->overlap; }
double ContactDriver::normal_force() const { return state_->forces.normal; }
double ContactDriver::tangential_force() const { return state_->forces.shear; }
bool ContactDriver::sliding() const { return state_->history.sliding; }
double ContactDriver::contact_radius() const {
  const State& s = *state_;
  return is_hertz(s.params.law) && s.overlap > 0.0 ? std::sqrt(s.pair.effective_radius * s.overlap) : 0.0;
}

}  // namespace dem
