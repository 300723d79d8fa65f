#include "dem/packing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "dem/error.h"

namespace dem {

std::vector<ParticleDef> generate_lattice(const LatticeDef& def) {
  if (def.radius <= 0.0) throw DefinitionError("lattice: radius must be > 0");
  if (def.columns < 1 || def.rows < 1) throw DefinitionError("lattice: columns and rows must be >= 1");
  if (def.spacing < 2.0 * def.radius) {
    throw DefinitionError("lattice: spacing must be at least twice the radius (particles would overlap)");
  }
  const bool hexagonal = def.arrangement == LatticeArrangement::kHexagonal;
  const double row_pitch = hexagonal ? def.spacing * std::sqrt(3.0) / 2.0 : def.spacing;
  std::vector<ParticleDef> particles;
  particles.reserve(static_cast<std::size_t>(def.columns) * def.rows);
  for (int row = 0; row < def.rows; ++row) {
    const double shift = hexagonal && row % 2 == 1 ? 0.5 * def.spacing : 0.0;
    for (int column = 0; column < def.columns; ++column) {
      ParticleDef p;
      p.position = def.origin + Vec2(column * def.spacing + shift, row * row_pitch);
      p.radius = def.radius;
      p.material = def.material;
      particles.push_back(p);
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

// Occupancy grid with cells of the largest diameter: a new disc can only
// overlap discs in the 3x3 cells around its centre.
class PlacementGrid {
 public:
  PlacementGrid(const Vec2& min, const Vec2& max, double cell)
      : min_(min), cell_(cell),
        columns_(static_cast<int>((max.x() - min.x()) / cell) + 1),
        rows_(static_cast<int>((max.y() - min.y()) / cell) + 1),
        cells_(static_cast<std::size_t>(columns_) * rows_) {}

  bool is_free(const Vec2& x, double r, const std::vector<ParticleDef>& placed) const {
    const int c0 = column(x), r0 = row(x);
    for (int rr = std::max(r0 - 1, 0); rr <= std::min(r0 + 1, rows_ - 1); ++rr) {
      for (int cc = std::max(c0 - 1, 0); cc <= std::min(c0 + 1, columns_ - 1); ++cc) {
        for (int k : cells_[static_cast<std::size_t>(rr) * columns_ + cc]) {
          const double reach = r + placed[k].radius;
          if ((placed[k].position - x).squaredNorm() < reach * reach) return false;
        }
      }
    }
    return true;
  }
  void insert(const Vec2& x, int id) { cells_[static_cast<std::size_t>(row(x)) * columns_ + column(x)].push_back(id); }

 private:
  int column(const Vec2& x) const { return std::clamp(static_cast<int>((x.x() - min_.x()) / cell_), 0, columns_ - 1); }
  int row(const Vec2& x) const { return std::clamp(static_cast<int>((x.y() - min_.y()) / cell_), 0, rows_ - 1); }

  Vec2 min_;
  double cell_;
  int columns_, rows_;
  std::vector<std::vector<int>> cells_;
};

}  // namespace

std::vector<ParticleDef> generate_random_packing(const RandomPackingDef& def) {
  if (!(def.max.x() > def.min.x() && def.max.y() > def.min.y())) {
    throw DefinitionError("random packing: max must exceed min in x and y");
  }
  if (def.sizes.empty()) throw DefinitionError("random packing: no size classes");
  std::vector<SizeClass> sizes = def.sizes;
  double largest = 0.0;
  for (const SizeClass& s : sizes) {
    if (s.radius <= 0.0) throw DefinitionError("random packing: size class radius must be > 0");
    if (s.count < 0) throw DefinitionError("random packing: size class count must be >= 0");
    largest = std::max(largest, s.radius);
  }
  // Largest first: the big discs find room before the box fills up.
  std::stable_sort(sizes.begin(), sizes.end(), [](const SizeClass& a, const SizeClass& b) { return a.radius > b.radius; });

  Random random(def.seed);
  PlacementGrid grid(def.min, def.max, 2.0 * largest);
  std::vector<ParticleDef> placed;
  for (const SizeClass& size : sizes) {
    const Vec2 lo = def.min + Vec2::Constant(size.radius);
    const Vec2 span = (def.max - def.min) - Vec2::Constant(2.0 * size.radius);
    if (span.x() < 0.0 || span.y() < 0.0) {
      throw DefinitionError("random packing: radius " + std::to_string(size.radius) + " does not fit in the box");
    }
    for (int k = 0; k < size.count; ++k) {
      bool done = false;
      for (int attempt = 0; attempt < def.max_attempts && !done; ++attempt) {
        const Vec2 x = lo + Vec2(random.uniform() * span.x(), random.uniform() * span.y());
        if (!grid.is_free(x, size.radius, placed)) continue;
        grid.insert(x, static_cast<int>(placed.size()));
        ParticleDef p;
        p.position = x;
        p.radius = size.radius;
        p.material = def.material;
        placed.push_back(p);
        done = true;
      }
      if (!done) {
        throw DefinitionError("random packing: no free place for particle " + std::to_string(k + 1) + " of " +
                              std::to_string(size.count) + " with radius " + std::to_string(size.radius) +
                              " after " + std::to_string(def.max_attempts) +
                              " attempts; enlarge the box or reduce the count");
      }
    }
  }
  return placed;
}

}  // namespace dem
