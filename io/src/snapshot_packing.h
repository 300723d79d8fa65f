// How the engine's quantities are packed into the flat arrays of doubles of
// dem.proto.Snapshot (idl/dem/snapshot.proto). Shared by the conversion
// and the contact fields.
#pragma once

#include <google/protobuf/repeated_field.h>

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include "dem/math.h"
#include "dem/snapshot_fields.h"

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

// A quantity Packing knows.
template <typename T>
concept Packable = requires {
  Packing<T>::width;
};

// N items one after the other (a triangle face: its three corners).
template <Packable T, std::size_t N>
struct Packing<std::array<T, N>> {
  static constexpr std::size_t width = N * Packing<T>::width;
  template <typename Out>
  static void put(Out* out, const std::array<T, N>& items) {
    for (const T& item : items) Packing<T>::put(out, item);
  }
  template <typename In>
  static std::array<T, N> get(const In& in, int at) {
    std::array<T, N> items;
    for (std::size_t i = 0; i < N; ++i) items[i] = Packing<T>::get(in, at + static_cast<int>(i * Packing<T>::width));
    return items;
  }
};

// A struct of packable members (a particle's shape): its members in the
// order of its field list (dem/snapshot_fields.h).
template <typename T>
constexpr bool packable_members() {
  return std::apply(
      [](const auto&... field) {
        return (Packable<std::remove_cvref_t<decltype(std::declval<T>().*field.member)>> && ...);
      },
      SnapshotFields<T>::list);
}
template <typename T>
requires(HasSnapshotFields<T>&& packable_members<T>()) struct Packing<T> {
  static constexpr std::size_t width = std::apply(
      [](const auto&... field) {
        return (Packing<std::remove_cvref_t<decltype(std::declval<T>().*field.member)>>::width + ... + 0);
      },
      SnapshotFields<T>::list);
  template <typename Out>
  static void put(Out* out, const T& value) {
    std::apply(
        [&](const auto&... field) {
          (Packing<std::remove_cvref_t<decltype(value.*field.member)>>::put(out, value.*field.member), ...);
        },
        SnapshotFields<T>::list);
  }
  template <typename In>
  static T get(const In& in, int at) {
    T value;
    std::apply(
        [&](const auto&... field) {
          ((value.*field.member = Packing<std::remove_cvref_t<decltype(value.*field.member)>>::get(in, at),
            at += static_cast<int>(Packing<std::remove_cvref_t<decltype(value.*field.member)>>::width)),
           ...);
        },
        SnapshotFields<T>::list);
    return value;
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
constexpr std::size_t kShapeWidth = width<ShapeDefT<Dim>>;
static_assert(kShapeWidth<2> == 4 && kShapeWidth<3> == 7, "a shape's width is part of the snapshot format");

}  // namespace dem::io
