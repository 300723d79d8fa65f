// Where the force between two superquadrics, or between one and a wall,
// acts: the centroid of the region they overlap (superquadric.h says why).
// The region is bounded by each body's boundary inside the other (or by
// the body's boundary past the wall's line and the line); its two meeting
// points are found by Newton's method on both functions at once, the arcs
// between them sampled, and the centroid is that of the polygon.
#pragma once

#include <optional>

#include "superquadric.h"

namespace dem {

// The centroid of the overlap of two placed superquadrics whose contact
// (eq. 42) is `contact`, from the radial parameters of its points P_i and
// P_j (which lie inside the overlap); none when it cannot be traced (an
// overlap too deep to be a contact).
std::optional<Vec2> overlap_centroid(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                     const SuperquadricContact& contact, double t_i, double t_j);

// The centroid of a placed superquadric's part past the line through
// `on_line` whose normal `outward` points away from the body's side, from
// its support point (superquadric_line_contact); none when it cannot be
// traced.
std::optional<Vec2> line_overlap_centroid(const PlacedSuperquadric& body, const Vec2& on_line, const Vec2& outward,
                                          const SupportContact& support);

}  // namespace dem
