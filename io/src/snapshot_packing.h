// How the engine's quantities are packed into the flat arrays of doubles of
// dem.proto.Snapshot (idl/dem/snapshot.proto). Shared by the conversion
// and the contact fields.
#pragma once

#include <google/protobuf/repeated_field.h>

#include <cstddef>

#include "dem/math.h"

namespace dem::io {

using Doubles = google::protobuf::RepeatedField<double>;

// How each quantity is packed into a flat array of doubles
// (idl/dem/snapshot.proto): a scalar (2D spin, angle, shear), a 2-vector
// (2D vector, 3D eccentricity), a 3-vector, a quaternion as w, x, y, z.
template <typename T>
struct Packing;
template <>
struct Packing<double> {
  static constexpr std::size_t width = 1;
  template <typename Out>
  static void put(Out* out, double v) {
    out->Add(v);
  }
  template <typename In>
  static double get(const In& in, int at) {
    return in.Get(at);
  }
};
template <>
struct Packing<Vec2> {
  static constexpr std::size_t width = 2;
  template <typename Out>
  static void put(Out* out, const Vec2& v) {
    out->Add(v.x());
    out->Add(v.y());
  }
  template <typename In>
  static Vec2 get(const In& in, int at) {
    return {in.Get(at), in.Get(at + 1)};
  }
};
template <>
struct Packing<Vec3> {
  static constexpr std::size_t width = 3;
  template <typename Out>
  static void put(Out* out, const Vec3& v) {
    out->Add(v.x());
    out->Add(v.y());
    out->Add(v.z());
  }
  template <typename In>
  static Vec3 get(const In& in, int at) {
    return {in.Get(at), in.Get(at + 1), in.Get(at + 2)};
  }
};
template <>
struct Packing<Quaternion> {
  static constexpr std::size_t width = 4;
  template <typename Out>
  static void put(Out* out, const Quaternion& q) {
    out->Add(q.w());
    out->Add(q.x());
    out->Add(q.y());
    out->Add(q.z());
  }
  template <typename In>
  static Quaternion get(const In& in, int at) {
    return Quaternion(in.Get(at), in.Get(at + 1), in.Get(at + 2), in.Get(at + 3));
  }
};

template <typename T, typename Out>
void put(Out* out, const T& value) {
  Packing<T>::put(out, value);
}
// The index-th item of a packed array of T.
template <typename T, typename In>
T get(const In& in, int index) {
  return Packing<T>::get(in, index * static_cast<int>(Packing<T>::width));
}
template <typename T>
constexpr std::size_t width = Packing<T>::width;

// A particle's shape: a 2D superquadric's a, b, n, angle; a 3D ellipsoid's
// semi-axes and orientation.
template <int Dim>
constexpr std::size_t kShapeWidth = Dim == 2 ? 4 : 7;

}  // namespace dem::io
