#include "contact_laws.h"

#include <string>

#include "dem/law_traits.h"
#include "law_dispatch.h"
#include "world_validation.h"

namespace dem {

std::span<const ContactLawTraits> contact_laws() {
  static constexpr auto kLaws = every_law(ContactLaws{});
  return kLaws;
}

std::optional<ContactLawTraits> contact_law_traits(ContactLaw law) { return law_traits_of<ContactLaws>(law); }

std::optional<ContactLaw> contact_law_named(std::string_view name) {
  for (const ContactLawTraits& law : contact_laws()) {
    if (name == law.name) return law.law;
  }
  return std::nullopt;
}

const char* contact_law_name(ContactLaw law) {
  const std::optional<ContactLawTraits> traits = contact_law_traits(law);
  return traits ? traits->name : "unknown";
}

bool is_hertz(ContactLaw law) {
  const std::optional<ContactLawTraits> traits = contact_law_traits(law);
  return traits && traits->hertz;
}

WorldLaws resolve_contact_laws(const std::vector<MaterialDef>& materials, const ContactParamTable& params,
                               std::span<const std::int32_t> particle_materials,
                               std::span<const std::int32_t> wall_materials) {
  const auto count = static_cast<std::int32_t>(materials.size());
  std::vector<bool> particle_material(count, false), wall_material(count, false);
  for (std::int32_t m : particle_materials) particle_material[m] = true;
  for (std::int32_t m : wall_materials) wall_material[m] = true;
  struct Seen {
    bool any = false;
    ContactLaw law = ContactLaw::kLinear;
    std::int32_t a = 0, b = 0;
  };
  Seen pairs, walls;
  auto note = [&](Seen& seen, std::int32_t a, std::int32_t b, const char* kind) {
    const ContactParams& p = params(a, b);
    check(p.defined, "no contact model for materials " + quoted(materials[a]) + " and " + quoted(materials[b]));
    if (!seen.any) {
      seen = {true, p.law, a, b};
      return;
    }
    check(p.law == seen.law, std::string(kind) + " contacts must all use one contact law: materials " +
                                 quoted(materials[seen.a]) + " and " + quoted(materials[seen.b]) + " use " +
                                 contact_law_name(seen.law) + ", " + quoted(materials[a]) + " and " +
                                 quoted(materials[b]) + " use " + contact_law_name(p.law));
  };
  for (std::int32_t a = 0; a < count; ++a) {
    if (!particle_material[a]) continue;
    for (std::int32_t b = 0; b < count; ++b) {
      if (particle_material[b]) note(pairs, a, b, "particle-particle");
      if (wall_material[b]) note(walls, a, b, "particle-wall");
    }
  }
  const WorldLaws laws{pairs.law, walls.law};
  const bool hertz = (pairs.any && is_hertz(pairs.law)) || (walls.any && is_hertz(walls.law));
  if (!hertz) return laws;
  for (std::int32_t m = 0; m < count; ++m) {
    if (!particle_material[m]) continue;
    const MaterialDef& mat = materials[m];
    check(mat.youngs_modulus > 0.0, "material " + quoted(mat) + ": a Hertz law needs youngs_modulus > 0");
    check(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5,
          "material " + quoted(mat) + ": poisson_ratio must be in (-1, 0.5)");
  }
  return laws;
}

}  // namespace dem
