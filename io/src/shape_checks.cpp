#include "shape_checks.h"

#include <cmath>

#include "case_fields.h"

namespace dem::io {

bool check_superquadric(ProblemList& problems, const std::string& path, const proto::Superquadric& shape,
                        bool random_angle) {
  check_fields<ShapeDefT<2>>(shape, path, problems);  // a, b, n and the angle by their rules (case_rules.h)
  const bool a_ok = !problems.reported(path + ".a");
  const bool b_ok = !problems.reported(path + ".b");
  const bool n_ok = !problems.reported(path + ".n");
  bool angle_ok = !problems.reported(path + ".angle_deg");
  if (angle_ok && random_angle && shape.angle_deg() != 0) {
    problems.add(path + ".angle_deg",
                 "a random packing turns each particle at a random seeded angle; leave angle_deg out");
    angle_ok = false;
  }
  return a_ok && b_ok && n_ok && angle_ok;
}

bool check_ellipsoid(ProblemList& problems, const std::string& path, const proto::Ellipsoid& shape,
                     bool random_orientation) {
  if (!shape.has_semi_axes()) {
    problems.add(path + ".semi_axes", "must be set: semi_axes { x: a1 y: a2 z: a3 } (m, each > 0)");
    return false;
  }
  const proto::Vector& axes = shape.semi_axes();
  const bool x_ok = problems.positive(path + ".semi_axes.x", axes.x());
  const bool y_ok = problems.positive(path + ".semi_axes.y", axes.y());
  const bool z_ok = problems.positive(path + ".semi_axes.z", axes.z());
  if (!shape.has_orientation()) return x_ok && y_ok && z_ok;
  const std::string q_path = path + ".orientation";
  if (random_orientation) {
    problems.add(q_path, "a random packing turns each particle to a uniformly random orientation; leave it out");
    return false;
  }
  const proto::Quaternion& q = shape.orientation();
  bool q_ok = true;
  for (const auto& [name, value] : {std::pair{".w", q.w()}, {".x", q.x()}, {".y", q.y()}, {".z", q.z()}}) {
    q_ok = problems.finite(q_path + name, value) && q_ok;
  }
  if (q_ok && q.w() == 0 && q.x() == 0 && q.y() == 0 && q.z() == 0) {
    problems.add(q_path, "must not be zero (a rotation's quaternion has length 1; leave it out for none)");
    q_ok = false;
  }
  return x_ok && y_ok && z_ok && q_ok;
}

void ShapeMix::note(ProblemList& problems, const std::string& path, bool shaped, int dimension) {
  if (!first_) {
    first_ = First{path, shaped};
    return;
  }
  if (shaped == first_->shaped || reported_) return;
  const bool three = dimension == 3;
  const auto kind = [three](bool s) {
    if (three) return s ? "an ellipsoid" : "a sphere";
    return s ? "a superquadric" : "a disc";
  };
  problems.add(path, std::string("is ") + kind(shaped) + ", but " + first_->path + " is " + kind(first_->shaped) +
                         "; a case's particles are all " +
                         (three ? "spheres or all ellipsoids" : "discs or all superquadrics"));
  reported_ = true;
}

}  // namespace dem::io
