#include <cstdint>
#include <type_traits>

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
  void add(T value) {
    add_bytes(&value, sizeof(T));
  }
  template <typename Derived>
  void add(const Eigen::MatrixBase<Derived>& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) add(static_cast<double>(v[i]));
  }
  void add(const Quaternion& q) { add(q.coeffs()); }
  template <typename T>
  void add_all(const std::vector<T>& values) {
    for (const T& v : values) add(v);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

template <int Dim>
void add_contact(Hasher& h, const ContactState<Dim>& s, const ContactForce<Dim>& f) {
  h.add(s.normal_force);
  h.add(s.shear);
  h.add(f.force);
  h.add(s.mindlin.t_star);
  h.add(s.mindlin.t_star2);
  h.add(s.mindlin.lag);
}

}  // namespace

template <int Dim>
std::uint64_t hash_state(const WorldState<Dim>& s) {
  Hasher h;
  h.add(s.cycle);
  h.add(s.time);
  h.add_all(s.particles.position);
  h.add_all(s.particles.velocity);
  h.add_all(s.particles.angular_velocity);
  h.add_all(s.particles.rotation);
  const ContactTable<Dim>& t = s.contacts;
  for (std::size_t k = 0; k < t.pairs.size(); ++k) {
    if (!t.pairs[k].state.touching) continue;
    h.add(t.pairs[k].first);
    h.add(t.pairs[k].second);
    add_contact(h, t.pairs[k].state, t.pair_forces[k]);
  }
  for (std::size_t k = 0; k < t.walls.size(); ++k) {
    if (!t.walls[k].state.touching) continue;
    h.add(t.walls[k].particle);
    h.add(t.walls[k].wall);
    add_contact(h, t.walls[k].state, t.wall_forces[k]);
  }
  for (const WallDefT<Dim>& w : s.walls.def) {
    h.add(w.point);
    h.add(w.direction);
  }
  return h.value();
}

template std::uint64_t hash_state(const WorldState<2>&);
template std::uint64_t hash_state(const WorldState<3>&);

}  // namespace dem
