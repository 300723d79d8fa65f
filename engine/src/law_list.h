// A list of contact-law types, and what follows from it: the dispatch from
// a law's enum value to its type, and each law's name and traits. A law is
// a type (linear_law.h, restitution_law.h, hertz_laws.h) that carries
//   kLaw            its value of ContactLaw (the number snapshots carry),
//   kName           its name, as cases and messages spell it,
//   kNormalHistory  F_n kept as history (a table column),
//   kMindlin        Mindlin's loading history kept (a table column),
//   kHertz          stiffness from the materials' E and nu (Randall 3.6),
//   kBatchable      branch-free enough for the batched passes,
// and as static functions its parameter resolution (resolve), the checks
// of its model (check_model), its critical time steps (critical_time_step,
// undamped_critical_time_step) and its force law (advance, forces). The engine's list is ContactLaws (law_dispatch.h);
// a new law is its file and an entry there.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <string_view>

#include "dem/definitions.h"
#include "dem/law_traits.h"

namespace dem {

// What a list asks of each law type at once; the functions are asked for
// where they are called.
template <typename Law>
concept LawType = requires {
  { Law::kLaw } -> std::convertible_to<ContactLaw>;
  { Law::kName } -> std::convertible_to<const char*>;
  { Law::kNormalHistory } -> std::convertible_to<bool>;
  { Law::kMindlin } -> std::convertible_to<bool>;
  { Law::kHertz } -> std::convertible_to<bool>;
  { Law::kBatchable } -> std::convertible_to<bool>;
};

template <LawType... Laws>
struct LawList {
  // The list with one more law (a test's own, test_law_list.cpp).
  template <typename Law>
  using With = LawList<Laws..., Law>;
};

template <typename Law>
constexpr ContactLawTraits traits_of() {
  return {Law::kLaw, Law::kName, Law::kNormalHistory, Law::kMindlin, Law::kHertz, Law::kBatchable};
}

// Calls pass.template operator()<Law>() with the type of `law`: one branch
// per pass, none per contact. Returns false for a value no law of the list has.
template <typename List, typename Pass>
struct LawDispatch;

template <typename... Laws, typename Pass>
struct LawDispatch<LawList<Laws...>, Pass> {
  static bool run(ContactLaw law, Pass& pass) {
    return ((law == Laws::kLaw ? (pass.template operator()<Laws>(), true) : false) || ...);
  }
};

template <typename List, typename Pass>
bool with_law_of(ContactLaw law, Pass&& pass) {
  return LawDispatch<List, Pass>::run(law, pass);
}

// The traits of `law`, none for a value no law of the list has.
template <typename List>
std::optional<ContactLawTraits> law_traits_of(ContactLaw law) {
  std::optional<ContactLawTraits> found;
  with_law_of<List>(law, [&]<typename Law>() { found = traits_of<Law>(); });
  return found;
}

// Every law of the list, in list order.
template <typename... Laws>
constexpr std::array<ContactLawTraits, sizeof...(Laws)> every_law(LawList<Laws...>) {
  return {traits_of<Laws>()...};
}

// No two laws of a list share a value or a name (checked where a list is made).
template <typename List>
constexpr bool distinct_laws(List list) {
  const auto laws = every_law(list);
  for (std::size_t i = 0; i < laws.size(); ++i) {
    for (std::size_t j = i + 1; j < laws.size(); ++j) {
      if (laws[i].law == laws[j].law || std::string_view(laws[i].name) == laws[j].name) return false;
    }
  }
  return true;
}

}  // namespace dem
