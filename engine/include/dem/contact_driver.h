// One contact between two bodies, driven kinematically: each step prescribes
// the normal approach and the tangential displacement, and the contact law
// answers with forces. This is the quasi-static test of Randall (1989) 5.2,
// where kinematically controlled walls impose the relative displacement of
// two spheres, and a way to see any law's force-displacement curve.
#pragma once

#include <memory>

#include "dem/definitions.h"

namespace dem {

struct ContactDriverDef {
  MaterialDef material_a;
  MaterialDef material_b;
  ContactModelDef model;  // material ids are ignored: the pair is (a, b)
  double radius_a = 1.0;  // m
  double radius_b = 1.0;  // m; 0 = b is a flat rigid body (a wall)
  double mass_a = 1.0;    // kg, for dashpots
  double mass_b = 1.0;    // kg; ignored for a wall
};

class ContactDriver {
 public:
  explicit ContactDriver(const ContactDriverDef& def);  // throws DefinitionError on a bad law definition
  ~ContactDriver();
  ContactDriver(ContactDriver&&) noexcept;
  ContactDriver& operator=(ContactDriver&&) noexcept;

  // Moves the bodies together by `approach` (m) and the first body past the
  // second by `tangential` (m) along one tangential axis, over dt seconds.
  void step(double approach, double tangential, double dt);

  double overlap() const;           // m
  double normal_force() const;      // N, elastic part
  double tangential_force() const;  // N, signed along the axis, on the second body
  bool sliding() const;
  double contact_radius() const;  // m, Hertz laws: (R* overlap)^(1/2); 0 otherwise

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dem
