#include "box_control.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dem/error.h"
#include "world_validation.h"

namespace dem {

namespace {

constexpr const char* kAxisNames = "xyz";

template <int Dim>
Vec<Dim> unit(int axis) {
  return Vec<Dim>::Unit(axis);
}

// Each axis's stress from the last force pass: its walls' mean normal
// force over the face the other extents span (2D: times the depth).
template <int Dim>
Vec<Dim> box_stress(const Walls<Dim>& walls, const BoxControlT<Dim>& box, const Vec<Dim>& extent) {
  Vec<Dim> stress = Vec<Dim>::Zero();
  for (int i = 0; i < Dim; ++i) {
    double face = Dim == 2 ? walls.depth : 1.0;
    for (int j = 0; j < Dim; ++j) {
      if (j != i) face *= extent[j];
    }
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    if (face > 0.0)
      stress[i] = 0.5 * (walls.normal_force[a.lower.index()] + walls.normal_force[a.upper.index()]) / face;
  }
  return stress;
}

// The stress each axis is held at now; strain-rate axes 0.
template <int Dim>
Vec<Dim> box_targets(const BoxControlT<Dim>& box, const Vec<Dim>& stress) {
  Vec<Dim> target = Vec<Dim>::Zero();
  double others_sum = 0.0, others_max = -std::numeric_limits<double>::infinity();
  int path_axes = 0;
  for (int i = 0; i < Dim; ++i) {
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    if (a.control == AxisControl::kStress) target[i] = a.stress;
    if (a.control == AxisControl::kStressPath) {
      ++path_axes;
    } else {
      others_sum += stress[i];
      others_max = std::max(others_max, stress[i]);
    }
  }
  if (path_axes == 0) return target;
  double path_target = 0.0;
  if (box.path == StressPath::kConstantMeanStress) {
    path_target = (Dim * box.path_value - others_sum) / path_axes;
  } else if (box.path == StressPath::kStressRatio) {
    path_target = others_max / box.path_value;
  }
  for (int i = 0; i < Dim; ++i) {
    if (box.axes[static_cast<std::size_t>(i)].control == AxisControl::kStressPath) target[i] = path_target;
  }
  return target;
}

}  // namespace

template <int Dim>
Vec<Dim> box_extent(const Walls<Dim>& walls, const BoxControlT<Dim>& box) {
  Vec<Dim> extent;
  for (int i = 0; i < Dim; ++i) {
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    extent[i] = (walls.def[a.upper.index()].point - walls.def[a.lower.index()].point).dot(unit<Dim>(i));
  }
  return extent;
}

template <int Dim>
BoxMeasureT<Dim> measure_box(const Walls<Dim>& walls, const BoxControlT<Dim>& box) {
  BoxMeasureT<Dim> m;
  m.extent = box_extent(walls, box);
  m.stress = box_stress(walls, box, m.extent);
  m.target = box_targets(box, m.stress);
  for (int i = 0; i < Dim; ++i) {
    m.strain[i] =
        box.reference_extent[i] > 0.0 && m.extent[i] > 0.0 ? std::log(box.reference_extent[i] / m.extent[i]) : 0.0;
  }
  m.volumetric_strain = m.strain.sum();
  m.deviator_strain = m.strain.maxCoeff() - m.strain.minCoeff();
  m.mean_stress = m.stress.mean();
  return m;
}

namespace {

// Each axis's walls' speed towards each other for the next step: strain
// rates, and servos on the stresses of the last force pass.
template <int Dim>
Vec<Dim> inward_speeds(const Walls<Dim>& walls, const BoxControlT<Dim>& box, const Vec<Dim>& extent) {
  const Vec<Dim> stress = box_stress(walls, box, extent);
  const Vec<Dim> target = box_targets(box, stress);
  Vec<Dim> inwards;
  for (int i = 0; i < Dim; ++i) {
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    inwards[i] = a.control == AxisControl::kStrainRate
                     ? 0.5 * a.strain_rate * extent[i]
                     : std::clamp(box.gain * (target[i] - stress[i]), -box.max_speed, box.max_speed);
  }
  return inwards;
}

}  // namespace

template <int Dim>
void set_box_velocities(const Walls<Dim>& walls, const BoxControlT<Dim>& box, std::vector<Vec<Dim>>& velocity) {
  const Vec<Dim> inwards = inward_speeds(walls, box, box_extent(walls, box));
  for (int i = 0; i < Dim; ++i) {
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    velocity[a.lower.index()] = inwards[i] * unit<Dim>(i);
    velocity[a.upper.index()] = -inwards[i] * unit<Dim>(i);
  }
}

template <int Dim>
ContinuumFieldT<Dim> box_continuum(const Walls<Dim>& walls, const BoxControlT<Dim>& box) {
  const Vec<Dim> extent = box_extent(walls, box);
  const Vec<Dim> inwards = inward_speeds(walls, box, extent);
  ContinuumFieldT<Dim> field;
  for (int i = 0; i < Dim; ++i) {
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    // The box's walls close at 2 inwards over its extent: the velocity
    // gradient along the axis, extension positive (Randall's e_ii), and
    // the field is still halfway between them, where they both move.
    field.rate[i] = extent[i] > 0.0 ? -2.0 * inwards[i] / extent[i] : 0.0;
    field.centre[i] = 0.5 * (walls.def[a.lower.index()].point[i] + walls.def[a.upper.index()].point[i]);
  }
  return field;
}

template <int Dim>
void check_box_control(const BoxControlT<Dim>& box, const std::vector<WallDefT<Dim>>& walls) {
  std::vector<bool> used(walls.size(), false);
  bool servo = false;
  int path_axes = 0;
  for (int i = 0; i < Dim; ++i) {
    const BoxAxisDef& a = box.axes[static_cast<std::size_t>(i)];
    const std::string axis = std::string("box control: axes[") + std::to_string(i) + "] (" + kAxisNames[i] + ")";
    for (const auto& [field, id, sign] : {std::tuple{".lower", a.lower, 1.0}, std::tuple{".upper", a.upper, -1.0}}) {
      if (const auto missing = missing_wall(walls, id)) throw DefinitionError(axis + field + ": " + *missing);
      const WallDefT<Dim>& wall = walls[id.index()];
      const std::string named = axis + field + ": wall " + to_string(id) + " (\"" + wall.name + "\")";
      check(!used[id.index()], named + " already bounds the box");
      used[id.index()] = true;
      check(!wall.removed, named + " has been removed");
      check((wall_normal(wall) - sign * unit<Dim>(i)).norm() < 1e-6,
            named + " must face " + (sign > 0 ? "+" : "-") + kAxisNames[i] + " (the particles' side)");
    }
    switch (a.control) {
      case AxisControl::kStrainRate:
        check(std::isfinite(a.strain_rate), axis + ".strain_rate: must be finite");
        break;
      case AxisControl::kStress:
        check(std::isfinite(a.stress) && a.stress > 0.0, axis + ".stress: must be > 0 (compression positive)");
        servo = true;
        break;
      case AxisControl::kStressPath:
        ++path_axes;
        servo = true;
        break;
    }
  }
  if (servo) {
    check(box.gain > 0.0 && std::isfinite(box.gain), "box control: gain must be > 0 when an axis is stress-controlled");
    check(box.max_speed > 0.0 && std::isfinite(box.max_speed),
          "box control: max_speed must be > 0 when an axis is stress-controlled");
  }
  if (path_axes > 0) {
    check(box.path != StressPath::kNone, "box control: an axis follows the stress path but no path is set");
    check(path_axes < Dim, "box control: a stress path needs an axis that does not follow it");
  } else {
    check(box.path == StressPath::kNone, "box control: a stress path is set but no axis follows it");
  }
  if (box.path == StressPath::kConstantMeanStress) {
    check(std::isfinite(box.path_value) && box.path_value > 0.0,
          "box control: constant_mean_stress must be > 0 (compression positive)");
  } else if (box.path == StressPath::kStressRatio) {
    check(std::isfinite(box.path_value) && box.path_value >= 1.0,
          "box control: stress_ratio (sigma_1 / sigma_3) must be >= 1");
  }
  check((box.reference_extent.array() >= 0.0).all() && box.reference_extent.allFinite(),
        "box control: reference_extent must be >= 0");
}

template <int Dim>
void check_box_continuum(const BoxControlT<Dim>& box, const PeriodicDefT<Dim>& periodic) {
  check(!box.continuum || !periodic.any(), "box control: continuum is not available with periodic boundaries");
}

template ContinuumFieldT<2> box_continuum(const Walls<2>&, const BoxControlT<2>&);
template ContinuumFieldT<3> box_continuum(const Walls<3>&, const BoxControlT<3>&);
template void check_box_continuum(const BoxControlT<2>&, const PeriodicDefT<2>&);
template void check_box_continuum(const BoxControlT<3>&, const PeriodicDefT<3>&);
template Vec2 box_extent(const Walls<2>&, const BoxControlT<2>&);
template Vec3 box_extent(const Walls<3>&, const BoxControlT<3>&);
template BoxMeasureT<2> measure_box(const Walls<2>&, const BoxControlT<2>&);
template BoxMeasureT<3> measure_box(const Walls<3>&, const BoxControlT<3>&);
template void set_box_velocities(const Walls<2>&, const BoxControlT<2>&, std::vector<Vec2>&);
template void set_box_velocities(const Walls<3>&, const BoxControlT<3>&, std::vector<Vec3>&);
template void check_box_control(const BoxControlT<2>&, const std::vector<WallDefT<2>>&);
template void check_box_control(const BoxControlT<3>&, const std::vector<WallDefT<3>>&);

}  // namespace dem
