#include <cstdint>
#include <type_traits>
#include <utility>

#include "contact_fields.h"
#include "world_state.h"

namespace dem {

namespace {

// FNV-1a over the bytes of the state: any bit that differs changes the hash.
class Hasher {
 public:
  void add_bytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= bytes[i];
      hash_ *= 1099511628211ULL;
    }
  }
  template <typename T>
  requires std::is_arithmetic_v<T>
  void add(T value) { add_bytes(&value, sizeof(T)); }
  template <typename Derived>
  void add(const Eigen::MatrixBase<Derived>& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) add(static_cast<double>(v[i]));
  }
  void add(const Quaternion& q) { add(q.coeffs()); }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

// A value the hasher takes (a field of another type cannot be hashed).
template <typename T>
concept Hashable = requires(Hasher h, const T& value) {
  h.add(value);
};

// Each hashed particle field is of such a type (particle_fields.h).
template <int Dim>
constexpr bool hashed_particle_fields_hashable() {
  bool hashable = true;
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto column, auto, auto) {
    using Value = std::remove_cvref_t<decltype(column(std::declval<const Particles<Dim>&>())[0])>;
    if (info.hashed && !Hashable<Value>) hashable = false;
  });
  return hashable;
}
static_assert(hashed_particle_fields_hashable<2>() && hashed_particle_fields_hashable<3>(),
              "a hashed particle field has a type the state hash cannot add");

// Every touching row's key (by particle id), then its hashed fields in the
// order of the field list (dem/snapshot.h), each only where the table keeps
// its column.
template <int Dim>
void add_rows(Hasher& h, const ContactRows<Dim>& rows, const Particles<Dim>& p, bool wall) {
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (!rows.touching(r)) continue;
    h.add(p.id[rows.first[r]].value());
    h.add(wall ? rows.second[r] : p.id[rows.second[r]].value());
    for_each_kept_field<Dim>(rows, r, [&](const ContactFieldInfo& info, auto, const auto& value) {
      if (info.hashed) h.add(value);
    });
  }
}

}  // namespace

template <int Dim>
std::uint64_t hash_state(const WorldState<Dim>& s) {
  Hasher h;
  h.add(s.cycle);
  h.add(s.time);
  const Particles<Dim>& p = s.particles;
  // By id, so the hash names the physical state whatever the storage order;
  // each particle's hashed fields in the order of the field list
  // (particle_fields.h).
  for (const ParticleId id : p.ids) {
    const auto i = static_cast<std::size_t>(p.slot_of(id));
    for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto column, auto, auto) {
      if constexpr (Hashable<std::remove_cvref_t<decltype(column(p)[i])>>) {
        if (info.hashed) h.add(column(p)[i]);
      }
    });
  }
  add_rows(h, s.contacts.pairs, p, false);
  add_rows(h, s.contacts.walls, p, true);
  for (const WallDefT<Dim>& w : s.walls.def) {
    h.add(w.point);
    h.add(w.direction);
    if (w.removed) h.add(w.removed);  // only then, so the hash of a world without removed walls is as it was
  }
  // The fields that move the particles besides the forces, only when set,
  // so the hash of a world without them is as it was.
  if (s.centripetal_gravity) {
    h.add(s.centripetal_gravity->centre);
    h.add(s.centripetal_gravity->acceleration);
  }
  if (s.continuum) {
    h.add(s.continuum->rate);
    h.add(s.continuum->centre);
  }
  return h.value();
}

template std::uint64_t hash_state(const WorldState<2>&);
template std::uint64_t hash_state(const WorldState<3>&);

}  // namespace dem
