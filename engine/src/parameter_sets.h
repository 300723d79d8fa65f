// How the rows of a contact table find their parameters in the batched
// force passes (contact_batch.h, wall_batch.h). A table's rows resolve to
// the sets of the material pairs they join, and a bed has few distinct
// ones: one when the particles share a material (or copies of one) and
// the walls another, a handful for a few particle materials. The law loop
// runs a vector of rows at once, so how it reads a row's set decides its
// speed:
//   kOne   every row has the same set: its fields are constants, broadcast
//          once (the one-material speed);
//   kFew   up to kFewSets sets: each field is chosen among them by the
//          row's set number, a few blends of constants per vector;
//   kMany  any number: each field is read from the row's set, a load per
//          lane (a gather).
// (docs/PERFORMANCE.md, "Material mixes", has the rates of each.)
#pragma once

#include <cstdint>
#include <vector>

#include "contact_params.h"
#include "inline.h"

namespace dem {

enum class SetChoice { kOne, kFew, kMany };
inline constexpr int kFewSets = 4;

// The distinct parameter sets of one table's rows and the set of each
// pair of materials (entry a * materials + b; pairs no row joins: 0).
struct RowSets {
  std::vector<ContactParams> sets;
  std::vector<std::int32_t> set_of;

  SetChoice choice() const {
    if (sets.size() <= 1) return SetChoice::kOne;
    return sets.size() <= static_cast<std::size_t>(kFewSets) ? SetChoice::kFew : SetChoice::kMany;
  }
};

// The sets of the rows joining a material of `first` to one of `second`:
// equal sets (two materials with the same properties) count once, so a
// copy of a material takes the same path and gives the same bits.
RowSets row_sets(const ContactParamTable& table, const std::vector<std::int32_t>& first,
                 const std::vector<std::int32_t>& second);

// kFew: the sets as the law loop holds them, the last repeated to fill kFewSets.
struct FewSets {
  ContactParams set[kFewSets];
};
FewSets few_sets(const RowSets& sets);

// Set s of `few`, every field chosen lane by lane as selects (which a
// vector loop turns into blends of its registers) rather than read from
// few.set[s] (which it would have to gather). Lists every field of
// ContactParams: the laws read what they need of the result.
DEM_INLINE ContactParams choose_set(const FewSets& few, double s) {
  static_assert(kFewSets == 4);
  static_assert(sizeof(ContactParams) == 16 * sizeof(double), "a new field of ContactParams belongs here too");
  // The four values read first, whatever s: a value read under a
  // condition would keep the branch and the loop from vectorising.
  const auto pick = [&](double ContactParams::*field) {
    const double v0 = few.set[0].*field, v1 = few.set[1].*field, v2 = few.set[2].*field, v3 = few.set[3].*field;
    const double low = s == 0.0 ? v0 : v1;
    const double high = s == 2.0 ? v2 : v3;
    return s < 2.0 ? low : high;
  };
  ContactParams p = few.set[0];  // (its law and flag are every set's)
  p.friction = pick(&ContactParams::friction);
  p.cohesion = pick(&ContactParams::cohesion);
  p.normal_stiffness = pick(&ContactParams::normal_stiffness);
  p.shear_stiffness = pick(&ContactParams::shear_stiffness);
  p.normal_viscosity = pick(&ContactParams::normal_viscosity);
  p.shear_viscosity = pick(&ContactParams::shear_viscosity);
  p.restitution_viscosity = pick(&ContactParams::restitution_viscosity);
  p.contact_modulus = pick(&ContactParams::contact_modulus);
  p.shear_modulus = pick(&ContactParams::shear_modulus);
  p.damping_ratio = pick(&ContactParams::damping_ratio);
  p.tangential_damping_ratio = pick(&ContactParams::tangential_damping_ratio);
  p.normal_dashpot = pick(&ContactParams::normal_dashpot);
  p.tangential_dashpot = pick(&ContactParams::tangential_dashpot);
  p.rolling_friction = pick(&ContactParams::rolling_friction);
  p.rolling_damping_ratio = pick(&ContactParams::rolling_damping_ratio);
  return p;
}

// What the law loop of a batched pass holds of a table's sets (kChoice),
// and set number s of a row as it reads it (a double: see contact_batch.h).
template <SetChoice kChoice>
class LoopSets {
 public:
  explicit LoopSets(const RowSets& sets) {
    if constexpr (kChoice == SetChoice::kOne) {
      if (!sets.sets.empty()) one_ = sets.sets.front();  // (a table without rows has no set)
    }
    if constexpr (kChoice == SetChoice::kFew) few_ = few_sets(sets);
    if constexpr (kChoice == SetChoice::kMany) many_ = sets.sets.data();
  }
  DEM_INLINE const ContactParams& operator[](double) const requires(kChoice == SetChoice::kOne) { return one_; }
  DEM_INLINE ContactParams operator[](double s) const requires(kChoice == SetChoice::kFew) {
    return choose_set(few_, s);
  }
  DEM_INLINE const ContactParams& operator[](double s) const requires(kChoice == SetChoice::kMany) {
    return many_[static_cast<std::int32_t>(s)];
  }

 private:
  // Copies, not references: their fields become loop invariants in
  // registers. Read through a reference, the stores of the batch could
  // alias them, and a field read under a condition (a dashpot off while
  // sliding) becomes a masked load that stops the law loop from vectorising.
  ContactParams one_;
  FewSets few_;
  const ContactParams* many_ = nullptr;
};

}  // namespace dem
