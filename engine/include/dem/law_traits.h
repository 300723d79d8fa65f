// What the contact laws are, without their types: each law's name (as
// cases spell it) and traits, from the engine's one list of laws
// (engine/src/law_dispatch.h), for the io layer, the service and tools.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "dem/definitions.h"

namespace dem {

struct ContactLawTraits {
  ContactLaw law;
  const char* name;     // "hertz_mindlin": the case's field and the snapshot's enum value
  bool normal_history;  // keeps F_n as history (BALL's eq. 18, Mindlin's dN)
  bool mindlin;         // keeps Mindlin's loading history (Randall 4.15-4.25)
  bool hertz;           // stiffness from the materials' E and nu (Randall 3.6), Rayleigh's time step
  bool batchable;       // runs in the batched force passes
};

// Every law, in the list's order.
std::span<const ContactLawTraits> contact_laws();
// The traits of `law`; none for a value no law has.
std::optional<ContactLawTraits> contact_law_traits(ContactLaw law);
// The law of that name; none for a name no law has.
std::optional<ContactLaw> contact_law_named(std::string_view name);
// The law's name, "unknown" for a value no law has.
const char* contact_law_name(ContactLaw law);
// Whether the law takes its stiffness from the materials' elastic constants.
bool is_hertz(ContactLaw law);

}  // namespace dem
