// The geometry of a run of ellipsoid pair rows, for a force pass that takes
// its rows in batches: the geometry of the whole run first, then the law
// row by row. The rows whose bodies may touch (bounding spheres and
// supports, EllipsoidShape::screen) have their searches made several at a
// time across the lanes of a vector (ellipsoid_contacts); each row's
// geometry and search state come out bit for bit as EllipsoidShape::pair
// gives them one row at a time.
#pragma once

#include <algorithm>
#include <cstdint>

#include "contact_geometry.h"

namespace dem {

// Rows k < count, of bodies first[k] and second[k], their searches'
// state search[k] (read, and written as EllipsoidShape::pair writes it),
// into out[k].
template <bool kApartGeometry>
void ellipsoid_pair_geometry(const PassInputs<3>& in, const Slot* first, const std::int32_t* second,
                             ContactSearch* search, int count, ContactGeometry<3>* out) {
  // A chunk's queries and results stay in the core's own cache.
  constexpr int kChunk = 16;
  EllipsoidQuery queries[kChunk];
  EllipsoidContact found[kChunk];
  int row_of[kChunk];
  for (int begin = 0; begin < count; begin += kChunk) {
    const int end = std::min(count, begin + kChunk);
    int searches = 0;
    for (int k = begin; k < end; ++k) {
      if (EllipsoidShape::screen<kApartGeometry>(in, first[k], second[k], search[k], out[k], queries[searches])) {
        row_of[searches++] = k;
      }
    }
    ellipsoid_contacts(queries, found, searches);
    for (int m = 0; m < searches; ++m) {
      const EllipsoidContact& c = found[m];
      const int k = row_of[m];
      search[k] = {c.multiplier_i, c.multiplier_j, true};
      out[k] = EllipsoidShape::geometry(c, queries[m].centre_i, queries[m].centre_j);
    }
  }
}

// Bodies [begin, end)'s frames (the pass's frame_ellipsoids), four at a
// time across the lanes of a vector (ellipsoid_frames): the same bits as
// ellipsoid_frame body by body.
inline void ellipsoid_frames_of(const Particles<3>& p, EllipsoidFrame* frames, std::int64_t begin, std::int64_t end) {
  std::int64_t i = begin;
  for (; i + 4 <= end; i += 4) {
    ellipsoid_frames({p.shape[i].axes, p.shape[i + 1].axes, p.shape[i + 2].axes, p.shape[i + 3].axes},
                     {p.rotation[i], p.rotation[i + 1], p.rotation[i + 2], p.rotation[i + 3]}, frames + i);
  }
  for (; i < end; ++i) frames[i] = ellipsoid_frame(p.shape[i].axes, p.rotation[i]);
}

}  // namespace dem
