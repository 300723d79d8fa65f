#include "dem/packing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "dem/error.h"
#include "superquadric.h"

namespace dem {

template <int Dim>
std::vector<ParticleDefT<Dim>> generate_lattice(const LatticeDefT<Dim>& def) {
  if (def.radius <= 0.0) throw DefinitionError("lattice: radius must be > 0");
  const int layers = Dim == 3 ? def.layers : 1;
  if (def.columns < 1 || def.rows < 1 || layers < 1) {
    throw DefinitionError("lattice: columns, rows and layers must be >= 1");
  }
  if (def.spacing < 2.0 * def.radius) {
    throw DefinitionError("lattice: spacing must be at least twice the radius (particles would overlap)");
  }
  const bool hexagonal = def.arrangement == LatticeArrangement::kHexagonal;
  // Hexagonal: rows sqrt(3)/2 apart, every other row shifted by half a
  // spacing; in 3D layers sqrt(2/3) apart, every other layer shifted by half
  // a spacing along both axes, so no two particles are closer than spacing.
  const double row_pitch = hexagonal ? def.spacing * std::sqrt(3.0) / 2.0 : def.spacing;
  const double layer_pitch = hexagonal ? def.spacing * std::sqrt(2.0 / 3.0) : def.spacing;
  std::vector<ParticleDefT<Dim>> particles;
  particles.reserve(static_cast<std::size_t>(def.columns) * def.rows * layers);
  for (int layer = 0; layer < layers; ++layer) {
    const double layer_shift = hexagonal && layer % 2 == 1 ? 0.5 * def.spacing : 0.0;
    for (int row = 0; row < def.rows; ++row) {
      const double row_shift = hexagonal && row % 2 == 1 ? 0.5 * def.spacing : 0.0;
      for (int column = 0; column < def.columns; ++column) {
        ParticleDefT<Dim> p;
        Vec<Dim> offset = Vec<Dim>::Zero();
        offset[0] = column * def.spacing + row_shift + layer_shift;
        offset[1] = row * row_pitch + (hexagonal && layer % 2 == 1 ? row_pitch / 3.0 : 0.0);
        if constexpr (Dim == 3) offset[2] = layer * layer_pitch;
        p.position = def.origin + offset;
        p.radius = def.radius;
        p.material = def.material;
        particles.push_back(p);
      }
    }
  }
  return particles;
}

namespace {

// SplitMix64: a small, portable generator, so a seed gives the same packing
// on every platform and library version.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform() {  // in [0, 1)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

// Occupancy grid with cells of the largest diameter: a new particle can only
// overlap particles in the 3^Dim cells around its centre.
template <int Dim>
class PlacementGrid {
 public:
  PlacementGrid(const Vec<Dim>& min, const Vec<Dim>& max, double cell) : min_(min), cell_(cell) {
    std::size_t total = 1;
    for (int d = 0; d < Dim; ++d) {
      counts_[d] = static_cast<int>((max[d] - min[d]) / cell) + 1;
      total *= static_cast<std::size_t>(counts_[d]);
    }
    cells_.resize(total);
  }

  bool is_free(const Vec<Dim>& x, double r, const std::vector<ParticleDefT<Dim>>& placed) const {
    const auto home = cell_of(x);
    constexpr int kNeighbourCells = Dim == 2 ? 9 : 27;
    for (int k = 0; k < kNeighbourCells; ++k) {
      std::array<int, Dim> cell;
      bool inside = true;
      for (int d = 0, code = k; d < Dim; ++d, code /= 3) {
        cell[d] = home[d] + code % 3 - 1;
        inside = inside && cell[d] >= 0 && cell[d] < counts_[d];
      }
      if (!inside) continue;
      for (int j : cells_[index(cell)]) {
        const double reach = r + placed[j].radius;
        if ((placed[j].position - x).squaredNorm() < reach * reach) return false;
      }
    }
    return true;
  }
  void insert(const Vec<Dim>& x, int id) { cells_[index(cell_of(x))].push_back(id); }

 private:
  std::array<int, Dim> cell_of(const Vec<Dim>& x) const {
    std::array<int, Dim> c;
    for (int d = 0; d < Dim; ++d) c[d] = std::clamp(static_cast<int>((x[d] - min_[d]) / cell_), 0, counts_[d] - 1);
    return c;
  }
  std::size_t index(const std::array<int, Dim>& c) const {
    std::size_t i = 0;
    for (int d = Dim - 1; d >= 0; --d) i = i * static_cast<std::size_t>(counts_[d]) + static_cast<std::size_t>(c[d]);
    return i;
  }

  Vec<Dim> min_;
  double cell_;
  std::array<int, Dim> counts_{};
  std::vector<std::vector<int>> cells_;
};

// A rotation drawn uniformly over all orientations (Shoemake 1992,
// "Uniform random rotations", Graphics Gems III).
Quaternion uniform_rotation(Random& random) {
  const double u1 = random.uniform(), u2 = 2.0 * std::numbers::pi * random.uniform(),
               u3 = 2.0 * std::numbers::pi * random.uniform();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return Quaternion(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
}

}  // namespace

template <int Dim>
std::vector<ParticleDefT<Dim>> generate_random_packing(const RandomPackingDefT<Dim>& def) {
  if (!(def.max.array() > def.min.array()).all()) {
    throw DefinitionError("random packing: max must exceed min along every axis");
  }
  if (def.sizes.empty()) throw DefinitionError("random packing: no size classes");
  std::vector<SizeClassT<Dim>> sizes = def.sizes;
  double largest = 0.0;
  for (SizeClassT<Dim>& s : sizes) {
    if constexpr (Dim == 2) {
      if (s.shape.superquadric()) s.radius = superquadric_bounding_radius({s.shape.a, s.shape.b, s.shape.n});
    } else {
      if (s.shape.ellipsoid()) s.radius = s.shape.axes.maxCoeff();
    }
    if (s.radius <= 0.0) throw DefinitionError("random packing: size class radius must be > 0");
    if (s.count < 0) throw DefinitionError("random packing: size class count must be >= 0");
    largest = std::max(largest, s.radius);
  }
  // Largest first: the big particles find room before the box fills up.
  std::stable_sort(sizes.begin(), sizes.end(),
                   [](const SizeClassT<Dim>& a, const SizeClassT<Dim>& b) { return a.radius > b.radius; });

  Random random(def.seed);
  PlacementGrid<Dim> grid(def.min, def.max, 2.0 * largest);
  std::vector<ParticleDefT<Dim>> placed;
  // Attempts between two questions to def.stopped: a few microseconds' work.
  constexpr std::uint64_t kStopPoll = 4096;
  std::uint64_t attempts = 0;
  for (const SizeClassT<Dim>& size : sizes) {
    const Vec<Dim> lo = def.min + Vec<Dim>::Constant(size.radius);
    const Vec<Dim> span = (def.max - def.min) - Vec<Dim>::Constant(2.0 * size.radius);
    if ((span.array() < 0.0).any()) {
      throw DefinitionError("random packing: radius " + std::to_string(size.radius) + " does not fit in the box");
    }
    bool full = false;
    for (int k = 0; k < size.count && !full; ++k) {
      bool done = false;
      for (int attempt = 0; attempt < def.max_attempts && !done; ++attempt) {
        if (++attempts % kStopPoll == 0 && def.stopped && def.stopped()) {
          throw DefinitionError("random packing: stopped after placing " + std::to_string(placed.size()) +
                                " particles");
        }
        Vec<Dim> x = lo;
        for (int d = 0; d < Dim; ++d) x[d] += random.uniform() * span[d];
        if (!grid.is_free(x, size.radius, placed)) continue;
        grid.insert(x, static_cast<int>(placed.size()));
        ParticleDefT<Dim> p;
        p.position = x;
        p.radius = size.radius;
        p.material = def.material;
        p.shape = size.shape;
        if constexpr (Dim == 2) {
          if (p.shape.superquadric()) p.shape.angle = 2.0 * std::numbers::pi * random.uniform();
        } else {
          if (p.shape.ellipsoid()) p.shape.orientation = uniform_rotation(random);
        }
        placed.push_back(p);
        done = true;
      }
      if (!done && def.next_size_when_full) {
        full = true;  // Randall 4.4: on with the next smaller size
      } else if (!done) {
        throw DefinitionError("random packing: no free place for particle " + std::to_string(k + 1) + " of " +
                              std::to_string(size.count) + " with radius " + std::to_string(size.radius) + " after " +
                              std::to_string(def.max_attempts) + " attempts; enlarge the box or reduce the count");
      }
    }
  }
  return placed;
}

template std::vector<ParticleDefT<2>> generate_lattice(const LatticeDefT<2>&);
template std::vector<ParticleDefT<3>> generate_lattice(const LatticeDefT<3>&);
template std::vector<ParticleDefT<2>> generate_random_packing(const RandomPackingDefT<2>&);
template std::vector<ParticleDefT<3>> generate_random_packing(const RandomPackingDefT<3>&);

}  // namespace dem
