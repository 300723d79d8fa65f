#include "world_validation.h"

#include <algorithm>
#include <cmath>

#include "dem/error.h"
#include "law_dispatch.h"

namespace dem {

void check(bool ok, const std::string& message) {
  if (!ok) throw DefinitionError(message);
}

std::string quoted(const MaterialDef& m) { return "\"" + m.name + "\""; }

namespace {

void validate_wall(const WallDefT<2>& wall, const std::string& where) {
  check(std::abs(wall.direction.norm() - 1.0) < 1e-9, where + ": direction must be a unit vector");
  check(wall.h2 > wall.h1, where + ": h2 must be greater than h1");
}

void validate_wall(const WallDefT<3>& wall, const std::string& where) {
  check(std::abs(wall.direction.norm() - 1.0) < 1e-9 && std::abs(wall.direction2.norm() - 1.0) < 1e-9,
        where + ": direction and direction2 must be unit vectors");
  check(std::abs(wall.direction.dot(wall.direction2)) < 1e-9,
        where + ": direction2 must be perpendicular to direction");
  check(wall.h2 > wall.h1, where + ": h2 must be greater than h1");
  check(wall.k2 > wall.k1, where + ": k2 must be greater than k1");
  for (std::size_t k = 0; k < wall.triangles.size(); ++k) {
    const auto& t = wall.triangles[k];
    const double scale = std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[0]).squaredNorm(), 1e-300});
    check((t[1] - t[0]).cross(t[2] - t[0]).norm() > 1e-9 * scale && t[0].allFinite() && t[1].allFinite() &&
              t[2].allFinite(),
          where + ": triangle " + std::to_string(k) + " is degenerate (its corners are on one line)");
  }
}

}  // namespace

void check_damping(const DampingDef& d) {
  check(d.contact_beta >= 0.0 && d.global_alpha >= 0.0 && d.global_alpha_rotation.value_or(0.0) >= 0.0,
        "damping: contact_beta and global_alpha must be >= 0");
  check(d.local_alpha >= 0.0 && d.local_alpha < 1.0 && d.local_alpha_rotation.value_or(0.0) >= 0.0 &&
            d.local_alpha_rotation.value_or(0.0) < 1.0,
        "damping: local_alpha must be in [0, 1)");
}

template <int Dim>
void validate_world(const WorldDefT<Dim>& def) {
  const std::size_t materials = def.materials.size();
  check(materials > 0, "world: no materials defined");
  for (std::size_t m = 0; m < materials; ++m) {
    const MaterialDef& mat = def.materials[m];
    const std::string where = "material " + std::to_string(m) + " (" + quoted(mat) + ")";
    check(mat.friction >= 0.0, where + ": friction must be >= 0");
    check(mat.cohesion >= 0.0, where + ": cohesion must be >= 0");
  }
  for (std::size_t k = 0; k < def.contact_models.size(); ++k) {
    const ContactModelDef& model = def.contact_models[k];
    const std::string where = "contact model " + std::to_string(k);
    const bool both_default = model.material_a == kInvalidId && model.material_b == kInvalidId;
    const bool both_valid = model.material_a.valid() && model.material_a.index() < materials &&
                            model.material_b.valid() && model.material_b.index() < materials;
    check(both_default || both_valid, where + ": unknown material id");
    const bool known = with_law(model.law, [&]<typename Law>() { Law::check_model(model, where); });
    check(known, where + ": unknown contact law " + std::to_string(static_cast<int>(model.law)));
    check(model.friction.value_or(0.0) >= 0.0, where + ": friction must be >= 0");
    check(model.cohesion.value_or(0.0) >= 0.0, where + ": cohesion must be >= 0");
    check(model.rolling.friction >= 0.0 && std::isfinite(model.rolling.friction),
          where + ": rolling friction must be >= 0");
    check(model.rolling.damping_ratio >= 0.0 && std::isfinite(model.rolling.damping_ratio),
          where + ": rolling damping ratio must be >= 0");
  }
  check(!def.particles.empty(), "world: no particles defined");
  for (std::size_t i = 0; i < def.particles.size(); ++i) {
    const ParticleDefT<Dim>& p = def.particles[i];
    const std::string where = "particle " + std::to_string(i);
    if constexpr (Dim == 3) {
      const ShapeDefT<3>& shape = p.shape;
      check(shape.ellipsoid() == def.particles[0].shape.ellipsoid(),
            where + ": the particles must be all spheres or all ellipsoids");
      if (shape.ellipsoid()) {
        check((shape.axes.array() > 0.0).all() && shape.axes.allFinite(), where + ": ellipsoid axes must be > 0");
        check(shape.orientation.norm() > 0.0, where + ": ellipsoid orientation must be a rotation");
        continue;  // an ellipsoid's radius comes from its axes
      }
    }
    if constexpr (Dim == 2) {
      const ShapeDefT<2>& shape = p.shape;
      check(shape.superquadric() == def.particles[0].shape.superquadric(),
            where + ": the particles must be all discs or all superquadrics");
      if (shape.superquadric()) {
        check(shape.b > 0.0, where + ": superquadric semi-axis b must be > 0");
        check(shape.n > 1.0 && shape.n <= 10.0, where + ": superquadric exponent n must be in (1, 10]");
        check(def.planar_particle == PlanarParticle::kDisc, where + ": superquadrics have unit thickness, not spheres");
        continue;  // a superquadric's radius comes from its axes
      }
    }
    check(p.radius > 0.0 && std::isfinite(p.radius), where + ": radius must be > 0");
    check(p.material.valid() && p.material.index() < materials, where + ": unknown material id");
    const MaterialDef& mat = def.materials[p.material.index()];
    check(mat.density > 0.0, "material " + to_string(p.material) + " (" + quoted(mat) + "): density must be > 0");
    check(p.position.allFinite() && p.velocity.allFinite(), where + ": position and velocity must be finite");
  }
  for (std::size_t w = 0; w < def.walls.size(); ++w) {
    const WallDefT<Dim>& wall = def.walls[w];
    const std::string where = "wall " + std::to_string(w) + " (\"" + wall.name + "\")";
    validate_wall(wall, where);
    check(wall.material.valid() && wall.material.index() < materials, where + ": unknown material id");
    if (wall.motion.servo) {
      check(wall.motion.servo->gain > 0.0, where + ": servo gain must be > 0");
      check(wall.motion.servo->max_speed > 0.0, where + ": servo max_speed must be > 0");
    }
  }
  for (int d = 0; d < Dim; ++d) {
    if (!def.periodic.axes[d]) continue;
    check(def.periodic.max[d] > def.periodic.min[d], "periodic: max must exceed min along axis " + std::to_string(d));
  }
  check(def.time_step_fraction > 0.0 && def.time_step_fraction <= 1.0, "world: time_step_fraction must be in (0, 1]");
  check(def.fixed_time_step >= 0.0, "world: fixed_time_step must be >= 0");
  check(def.contact_tolerance >= 0.0, "world: contact_tolerance must be >= 0");
  check_damping(def.damping);
  check_body_force(def.gravity, def.centripetal_gravity);
}

template void validate_world(const WorldDefT<2>&);
template void validate_world(const WorldDefT<3>&);

template <int Dim>
void check_periodic_reach(const Periodic<Dim>& periodic, double max_radius, double contact_tolerance) {
  const double reach = 2.0 * max_radius + contact_tolerance;
  for (int d = 0; d < Dim; ++d) {
    check(!periodic.repeats(d) || periodic.length[d] > 2.0 * reach, "periodic: the period along axis " +
                                                                        std::to_string(d) +
                                                                        " must exceed twice the largest diameter plus "
                                                                        "the contact tolerance (" +
                                                                        std::to_string(2.0 * reach) + ")");
  }
}
template void check_periodic_reach(const Periodic<2>&, double, double);
template void check_periodic_reach(const Periodic<3>&, double, double);

template <int Dim>
void check_wall_motion(const WallMotionT<Dim>& motion, WallId wall) {
  if (motion.servo) {
    check(motion.servo->gain > 0.0 && motion.servo->max_speed > 0.0,
          "wall " + to_string(wall) + ": servo gain and max_speed must be > 0");
  }
}
template void check_wall_motion(const WallMotionT<2>&, WallId);
template void check_wall_motion(const WallMotionT<3>&, WallId);

template <int Dim>
void check_body_force(const Vec<Dim>& gravity, const std::optional<CentripetalGravityT<Dim>>& centripetal) {
  check(gravity.allFinite(), "world: gravity must be finite");
  if (!centripetal) return;
  check(centripetal->centre.allFinite(), "centripetal gravity: centre must be finite");
  check(centripetal->acceleration >= 0.0 && std::isfinite(centripetal->acceleration),
        "centripetal gravity: acceleration must be >= 0");
}
template void check_body_force(const Vec2&, const std::optional<CentripetalGravityT<2>>&);
template void check_body_force(const Vec3&, const std::optional<CentripetalGravityT<3>>&);

void check_time_step_fraction(double fraction) {
  check(fraction > 0.0 && fraction <= 1.0, "time_step_fraction must be in (0, 1]");
}

void check_fixed_time_step(double seconds) {
  check(seconds > 0.0 && std::isfinite(seconds), "fixed time step must be a finite number > 0");
}

void check_friction(MaterialId material, std::size_t materials, double friction) {
  check(material.valid() && material.index() < materials, "unknown material id " + to_string(material));
  check(friction >= 0.0 && std::isfinite(friction), "friction must be >= 0");
}

}  // namespace dem
