#include "snapshot_rules.h"

#include <cmath>
#include <set>
#include <string>

#include "case_fields.h"
#include "dem/law_traits.h"
#include "format_number.h"
#include "problem_list.h"
#include "snapshot_packing.h"

namespace dem::io {
namespace {

std::string item(const std::string& path, int index) { return path + '[' + std::to_string(index) + ']'; }

// The range checks of ProblemList (problem_list.h), phrased as a case's
// are, for a snapshot's Problems; a number's finiteness and magnitude the
// structure checks judged already (snapshot_structure_checks.cpp).
class Rules {
 public:
  explicit Rules(Problems& problems) : problems_(problems) {}

  void finite(const std::string&, double) {}
  void positive(const std::string& path, double value) {
    if (!(value > 0)) problems_.add(path, "must be > 0 (got " + format_number(value) + ")");
  }
  void non_negative(const std::string& path, double value) {
    if (!(value >= 0)) problems_.add(path, "must be >= 0 (got " + format_number(value) + ")");
  }
  void within(const std::string& path, double value, const Interval& interval) {
    const bool above = interval.low_open ? value > interval.low : value >= interval.low;
    const bool below = interval.high_open ? value < interval.high : value <= interval.high;
    if (!above || !below) problems_.add(path, "must be in " + interval.text() + " (got " + format_number(value) + ")");
  }
  // An orientation in 3D: a unit quaternion (w, x, y, z). The engine keeps
  // its length within 1e-12 of 1 (motion.cpp), so 1e-6 leaves room for
  // any run and none for a zero or a scaled quaternion.
  bool unit_quaternion(const std::string& path, const double* q) {
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::abs(length - 1.0) <= 1e-6) return true;
    problems_.add(path, "must be a unit quaternion, an orientation (got one of length " + format_number(length) + ")");
    return false;
  }
  Problems& problems() { return problems_; }

 private:
  Problems& problems_;
};

// The schema's values are the engine's (SnapshotConversion.EveryContactLawKeepsItsSchemaValue).
bool is_hertz(proto::SnapshotContactLaw law) { return dem::is_hertz(static_cast<ContactLaw>(law)); }

// The case's rules (case_rules.h) over the snapshot's settings, and the
// checks across fields that case_validation.cpp and
// contact_model_checks.cpp make.
void check_settings(Rules& rules, const proto::Snapshot& m) {
  const proto::SnapshotSettings& s = m.settings();
  const std::set<int> particle_materials(m.particles().material().begin(), m.particles().material().end());
  bool hertz = false;
  for (int i = 0; i < s.contact_models_size(); ++i) {
    const proto::SnapshotContactModel& model = s.contact_models(i);
    const std::string path = item("settings.contact_models", i);
    if (is_hertz(model.law())) {
      hertz = true;
      check_snapshot_fields<HertzDampingDef>(model, path, rules, "hertz_");
    } else {
      check_snapshot_fields<LinearLawDef>(model, path, rules, "linear_");
      if (model.law() == proto::SNAPSHOT_LAW_LINEAR_RESTITUTION) {
        rules.within(path + ".restitution", model.restitution(), kRestitution);
      }
    }
    if (model.has_friction()) rules.non_negative(path + ".friction", model.friction());
    if (model.has_cohesion()) rules.non_negative(path + ".cohesion", model.cohesion());
    check_snapshot_fields<RollingResistanceDef>(model, path, rules, "rolling_");
  }
  for (int i = 0; i < s.materials_size(); ++i) {
    const proto::SnapshotMaterial& material = s.materials(i);
    const std::string path = item("settings.materials", i);
    check_snapshot_fields<MaterialDef>(material, path, rules);
    // 0 passes the rules (a wall's); a particle material's density cannot
    // be, nor, under a Hertz law, its E (Randall 1989, 3.6 and 4.8-4.10; a
    // wall of E = 0 is rigid).
    if (particle_materials.contains(i)) {
      if (material.density() == 0) rules.positive(path + ".density", 0.0);
      if (hertz && material.youngs_modulus() == 0) rules.positive(path + ".youngs_modulus", 0.0);
    }
  }
  check_snapshot_fields<DampingDef>(s.damping(), "settings.damping", rules);
  rules.within("settings.time_step_fraction", s.time_step_fraction(), Interval{0.0, 1.0, true, false});
  rules.non_negative("settings.fixed_time_step", s.fixed_time_step());
  rules.non_negative("settings.contact_tolerance", s.contact_tolerance());
}

// Orientations are unit quaternions in 3D, an ellipsoid's semi-axes > 0
// and a superquadric's b > 0 and n in (1, 10] (shape_checks.cpp).
template <int Dim>
void check_orientations(Rules& rules, const proto::SnapshotParticles& p) {
  constexpr std::size_t kShape = kShapeWidth<Dim>;
  const std::size_t count = static_cast<std::size_t>(p.radius_size());
  std::size_t found = 0;
  for (std::size_t i = 0; i < count && found < 3; ++i) {
    const int index = static_cast<int>(i);
    const double* shape = p.shape().data() + i * kShape;
    bool good = true;
    if constexpr (Dim == 3) {
      good = rules.unit_quaternion(item("particles.rotation", index), p.rotation().data() + i * 4);
      if (shape[0] != 0) {  // an ellipsoid: semi-axes, then its orientation
        for (int axis = 0; axis < 3; ++axis) {
          if (!(shape[axis] > 0)) {
            rules.problems().add(item("particles.shape", index),
                                 "an ellipsoid's semi-axes must be > 0 (got " + format_number(shape[axis]) + ")");
            good = false;
          }
        }
        good = rules.unit_quaternion(item("particles.shape", index) + " (orientation)", shape + 3) && good;
      }
    } else if (shape[0] != 0) {  // a superquadric: a, b, n, angle
      if (!(shape[0] > 0) || !(shape[1] > 0) || !(shape[2] > 1.0 && shape[2] <= 10.0)) {
        rules.problems().add(item("particles.shape", index),
                             "a superquadric's semi-axes must be > 0 and its exponent n in (1, 10] (got a " +
                                 format_number(shape[0]) + ", b " + format_number(shape[1]) + ", n " +
                                 format_number(shape[2]) + ")");
        good = false;
      }
    }
    if (!good) ++found;
  }
}

void check_cycles(Problems& problems, const proto::Snapshot& m) {
  if (m.cycle() > kLargestSnapshotCycle) {
    problems.add("cycle", "is " + std::to_string(m.cycle()) + ", beyond 2^62 (" +
                              std::to_string(kLargestSnapshotCycle) +
                              "): the cycle counter could wrap in the run that continues it");
    return;
  }
  if (m.sorted_cycle() > m.cycle()) {
    problems.add("sorted_cycle", "is " + std::to_string(m.sorted_cycle()) + ", after the snapshot's cycle " +
                                     std::to_string(m.cycle()));
  }
  for (int i = 0; i < m.contacts().formed_cycle_size(); ++i) {
    if (m.contacts().formed_cycle(i) > m.cycle()) {
      problems.add(item("contacts.formed_cycle", i), "is " + std::to_string(m.contacts().formed_cycle(i)) +
                                                         ", after the snapshot's cycle " + std::to_string(m.cycle()));
      break;
    }
  }
}

}  // namespace

template <int Dim>
void check_case_rules(const proto::Snapshot& message, Problems& problems) {
  Rules rules(problems);
  check_settings(rules, message);
  check_orientations<Dim>(rules, message.particles());
  check_cycles(problems, message);
}

template void check_case_rules<2>(const proto::Snapshot&, Problems&);
template void check_case_rules<3>(const proto::Snapshot&, Problems&);

}  // namespace dem::io
