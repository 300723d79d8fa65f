#include "contact_model_checks.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "case_fields.h"
#include "case_laws.h"
#include "dem/law_traits.h"
#include "field_path.h"

namespace dem::io {
namespace {

// A pair of material indices in the order a contact model's key uses.
std::pair<int, int> unordered_pair(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

bool is_hertz(const proto::ContactModel& model) {
  const std::optional<ContactLaw> law = case_law(model).law;
  return law && dem::is_hertz(*law);
}

// The law's field name, as a case spells it ("hertz_mindlin").
std::string law_name(const proto::ContactModel& model) {
  const auto* field = model.GetDescriptor()->FindFieldByNumber(model.law_case());
  return field != nullptr ? field->name() : std::string("no law");
}

// The engine's laws by name: "linear, ... or hertz_linear_tangential".
std::string law_names() {
  const auto laws = contact_laws();
  std::string names;
  for (std::size_t k = 0; k < laws.size(); ++k) {
    if (k > 0) names += k + 1 == laws.size() ? " or " : ", ";
    names += laws[k].name;
  }
  return names;
}

class ContactModelChecker {
 public:
  ContactModelChecker(const proto::Case& c, const MaterialUses& uses, ProblemList& problems)
      : case_(c), uses_(uses), problems_(problems) {}

  void run() {
    // Unordered material pairs (by index) to the model that covers them;
    // {-1, -1} is the default model.
    std::map<std::pair<int, int>, int> covered;
    for (int i = 0; i < case_.contact_model_size(); ++i) {
      const proto::ContactModel& model = case_.contact_model(i);
      const std::string path = indexed("contact_model", i);
      const int named = model.materials_size();
      if (named > 2) {
        problems_.add(path + ".materials", "names " + std::to_string(named) +
                                               " materials; name none (the default law), one (a material with itself) "
                                               "or two (a mixed pair)");
      }
      std::vector<int> ids;
      for (int j = 0; j < named; ++j) {
        ids.push_back(find_material(problems_, uses_.materials, indexed(path + ".materials", j), model.materials(j)));
      }
      check_law(path, model);
      // Restitution, friction, cohesion and rolling resistance by their rules (case_rules.h).
      check_fields<ContactModelDef>(model, path, problems_);

      if (named > 2 || std::ranges::count(ids, -1) > 0) continue;
      const std::pair<int, int> pair = named == 0   ? std::pair{-1, -1}
                                       : named == 1 ? std::pair{ids[0], ids[0]}
                                                    : unordered_pair(ids[0], ids[1]);
      const auto [first, inserted] = covered.emplace(pair, i);
      if (inserted) continue;
      if (named == 0) {
        problems_.add(path, "is a second default model (one naming no materials); " +
                                indexed("contact_model", first->second) + " is the first");
      } else {
        problems_.add(path + ".materials", "a second contact model for " + in_quotes(model.materials(0)) + " and " +
                                               in_quotes(model.materials(named - 1)) + "; " +
                                               indexed("contact_model", first->second) + " already covers the pair");
      }
    }
    const TouchingPairs touching = touching_pairs();
    if (!covered.contains({-1, -1})) check_pairs_covered(covered, touching);
    const bool pairs_hertz = check_one_law(covered, touching.particle_particle, "particle-particle");
    const bool walls_hertz = check_one_law(covered, touching.particle_wall, "particle-wall");
    if (pairs_hertz || walls_hertz) check_elastic_constants(touching.particle_ids);
  }

  // Each law's parameters by the type of their message (case_laws.h); the
  // restitution law's e is the model's own (case_rules.h).
  void check_law(const std::string& path, const proto::ContactModel& model) {
    const CaseLaw law = case_law(model);
    if (law.field == nullptr) {
      problems_.add(
          path, "has no law; set one of " + law_names() + ", as linear { normal_stiffness: ... shear_stiffness: ... }");
      return;
    }
    const std::string where = path + "." + law.field->name();
    if (!law.law) problems_.add(where, "is no contact law of this engine");
    if (dynamic_cast<const proto::LinearLaw*>(law.parameters) != nullptr ||
        dynamic_cast<const proto::LinearRestitutionLaw*>(law.parameters) != nullptr) {
      check_fields<LinearLawDef>(*law.parameters, where, problems_);  // both linear laws' stiffnesses
    } else if (dynamic_cast<const proto::HertzLaw*>(law.parameters) != nullptr) {
      check_fields<HertzDampingDef>(*law.parameters, where, problems_);
    }
  }

  // Pairs of material indices that can touch: particle with particle
  // (including the same material) and particle with wall. Walls never touch
  // each other.
  struct TouchingPairs {
    std::set<int> particle_ids;
    std::set<std::pair<int, int>> particle_particle;
    std::set<std::pair<int, int>> particle_wall;
  };

  TouchingPairs touching_pairs() const {
    TouchingPairs touching;
    std::set<int> wall_ids;
    for (const auto& name : uses_.particles) {
      if (const auto found = uses_.materials.find(name); found != uses_.materials.end()) {
        touching.particle_ids.insert(found->second);
      }
    }
    for (const auto& name : uses_.walls) {
      if (const auto found = uses_.materials.find(name); found != uses_.materials.end()) wall_ids.insert(found->second);
    }
    for (const int a : touching.particle_ids) {
      for (const int b : touching.particle_ids) touching.particle_particle.insert(unordered_pair(a, b));
      for (const int w : wall_ids) touching.particle_wall.insert(unordered_pair(a, w));
    }
    return touching;
  }

  // The contact model that serves a pair of materials, or -1 for none.
  static int model_for(const std::map<std::pair<int, int>, int>& covered, std::pair<int, int> pair) {
    if (const auto found = covered.find(pair); found != covered.end()) return found->second;
    if (const auto found = covered.find({-1, -1}); found != covered.end()) return found->second;
    return -1;
  }

  std::string pair_text(std::pair<int, int> pair) const {
    const std::string& a = case_.material(pair.first).name();
    const std::string& b = case_.material(pair.second).name();
    return pair.first == pair.second ? in_quotes(a) + " with itself" : in_quotes(a) + " and " + in_quotes(b);
  }

  // The engine chooses the law once per force pass, not per contact (see
  // ../shared/design/STYLE.md, point 4): one law for every pair of a kind.
  // Returns whether that law is a Hertz law.
  bool check_one_law(const std::map<std::pair<int, int>, int>& covered, const std::set<std::pair<int, int>>& pairs,
                     std::string_view kind) {
    int first_model = -1;
    std::pair<int, int> first_pair;
    std::set<int> reported;
    for (const auto& pair : pairs) {
      const int model = model_for(covered, pair);
      if (model < 0 || case_.contact_model(model).law_case() == proto::ContactModel::LAW_NOT_SET) continue;
      if (first_model < 0) {
        first_model = model;
        first_pair = pair;
        continue;
      }
      const proto::ContactModel& first = case_.contact_model(first_model);
      const proto::ContactModel& here = case_.contact_model(model);
      if (here.law_case() == first.law_case() || !reported.insert(model).second) continue;
      problems_.add(indexed("contact_model", model),
                    "uses " + law_name(here) + " for " + pair_text(pair) + ", but " +
                        indexed("contact_model", first_model) + " uses " + law_name(first) + " for " +
                        pair_text(first_pair) + "; one law must serve every " + std::string(kind) +
                        " contact (particle-particle and particle-wall laws may differ)");
    }
    return first_model >= 0 && is_hertz(case_.contact_model(first_model));
  }

  // The Hertz laws take their stiffness from the particles' elastic
  // constants (Randall 1989, 3.6 and 4.8-4.10); a wall material with E = 0
  // is rigid, so only particle materials must set E.
  void check_elastic_constants(const std::set<int>& particle_ids) {
    for (const int id : particle_ids) {
      const proto::Material& material = case_.material(id);
      if (material.youngs_modulus() == 0) {
        problems_.add(indexed("material", id) + ".youngs_modulus",
                      "must be > 0 for a material particles are made of, as a Hertz law serves its contacts (got 0)");
      }
    }
  }

  // Without a default model, every pair of materials that can touch needs its own.
  void check_pairs_covered(const std::map<std::pair<int, int>, int>& covered, const TouchingPairs& touching) {
    std::set<std::pair<int, int>> pairs = touching.particle_particle;
    pairs.insert(touching.particle_wall.begin(), touching.particle_wall.end());
    for (const auto& [a, b] : pairs) {
      if (covered.contains({a, b})) continue;
      const std::string& name_a = case_.material(a).name();
      const std::string& name_b = case_.material(b).name();
      problems_.add("contact_model", "no contact model for " +
                                         (a == b ? "material " + in_quotes(name_a) + " with itself"
                                                 : "materials " + in_quotes(name_a) + " and " + in_quotes(name_b)) +
                                         ", which can touch; add one naming " + (a == b ? "it" : "both") +
                                         ", or a default model naming no materials");
    }
  }

 private:
  const proto::Case& case_;
  const MaterialUses& uses_;
  ProblemList& problems_;
};

}  // namespace

void check_contact_models(const proto::Case& c, const MaterialUses& uses, ProblemList& problems) {
  ContactModelChecker(c, uses, problems).run();
}

}  // namespace dem::io
