// Validation of particle shapes: a superquadric's numbers (Miyata et al.
// 2002, eq. 34), an ellipsoid's (eq. 43), and the engine's rule that a
// case's particles are all round (discs or spheres) or all shaped
// (superquadrics in 2D, ellipsoids in 3D).
#pragma once

#include <optional>
#include <string>

#include "dem/case.pb.h"
#include "problem_list.h"

namespace dem::io {

// a, b > 0 and 1 < n <= 10: the smooth convex shapes Miyata's contact
// detection is written for (section 2.3(1)); the angle finite. In a random
// packing every particle is turned at random, so an angle there is refused.
// Returns whether the shape is sound.
bool check_superquadric(ProblemList& problems, const std::string& path, const proto::Superquadric& shape,
                        bool random_angle);

// Semi-axes > 0 and an orientation that is a finite, non-zero quaternion
// (it is normalised on load). In a random packing every particle takes a
// uniformly random orientation, so one given there is refused. Returns
// whether the shape is sound.
bool check_ellipsoid(ProblemList& problems, const std::string& path, const proto::Ellipsoid& shape,
                     bool random_orientation);

// Notes whether each particle source in turn is shaped and reports the
// first that differs from the first source's.
class ShapeMix {
 public:
  void note(ProblemList& problems, const std::string& path, bool shaped, int dimension);

 private:
  struct First {
    std::string path;
    bool shaped = false;
  };
  std::optional<First> first_;
  bool reported_ = false;
};

}  // namespace dem::io
