// The law of motion in its common case - round particles, no local
// damping, no energy budget - written as loops over the particles' plain
// arrays of doubles, each simple enough for the compiler to run four
// particles at a time. It computes exactly what move_block (motion.cpp)
// computes, in the same order of operations, so the two give the same bits.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "motion.h"

namespace dem {

// The rare turn through a large angle (a fast spin or a long step): cos h
// and sin(h)/h in full.
void large_half_angle(double h2, double& cosine, double& sine_over_h);

// q <- (cos h, a) q, normalised when it drifted from unit length (Cundall &
// Strack eq. 23a in quaternion form; q holds x, y, z, w, as Eigen stores a
// quaternion). The general step (motion.cpp) turns through it too.
[[gnu::always_inline]] inline void turn_by(double* q, double cosine, double ax, double ay, double az) {
  const double qx = q[0], qy = q[1], qz = q[2], qw = q[3];
  const double nw = cosine * qw - (ax * qx + ay * qy + az * qz);
  const double nx = cosine * qx + qw * ax + (ay * qz - az * qy);
  const double ny = cosine * qy + qw * ay + (az * qx - ax * qz);
  const double nz = cosine * qz + qw * az + (ax * qy - ay * qx);
  const double length2 = nw * nw + nx * nx + ny * ny + nz * nz;
  const double rescale = std::abs(length2 - 1.0) > 1e-12 ? 1.0 / std::sqrt(length2) : 1.0;
  q[0] = nx * rescale;
  q[1] = ny * rescale;
  q[2] = nz * rescale;
  q[3] = nw * rescale;
}

// The particles [begin, end) go through in chunks small enough that what
// one loop writes, the next reads from the core's first-level cache: each
// particle's arrays come from memory once a step (at 100k particles the
// law of motion is bound by that traffic). Within a chunk, one loop per
// stride: GCC vectorises a loop over the three-number arrays (position,
// velocity, spin) or over the four-number orientations, not one over both.
template <int Dim>
void move_plain_block(Particles<Dim>& p, const Vec<Dim>& gravity, const Periodic<Dim>& cell, double dt, double keep,
                      double scale, double keep_rotation, double scale_rotation, std::int64_t begin, std::int64_t end,
                      MotionStep& step, HotPlace<Dim>* hot_place = nullptr, HotMotion<Dim>* hot_motion = nullptr) {
  constexpr int D = Dim;
  constexpr int S = Dim == 3 ? 3 : 1;  // components of a spin
  const bool stream = static_cast<std::int64_t>(p.size()) > kPrefetchParticles;
  double* __restrict x = p.position.data()->data();
  double* __restrict v = p.velocity.data()->data();
  const double* __restrict f = p.force.data()->data();
  const double* __restrict mass = p.mass.data();
  const double* __restrict inertia = p.inertia.data();
  const double* __restrict reference = p.reference_position.data()->data();
  double* __restrict w;
  const double* __restrict moment;
  if constexpr (Dim == 3) {
    w = p.angular_velocity.data()->data();
    moment = p.moment.data()->data();
  } else {
    w = p.angular_velocity.data();
    moment = p.moment.data();
  }
  // The cell's bounds; an axis that does not repeat has infinite ones, so
  // the wrap below treats every axis alike (a test of the axis inside the
  // loop kept GCC from vectorising it).
  double g[D], lo[D], hi[D], period[D];
  for (int k = 0; k < D; ++k) {
    g[k] = gravity[k];
    const bool repeats = cell.length[k] > 0.0;
    period[k] = repeats ? cell.length[k] : 0.0;
    lo[k] = repeats ? cell.min[k] : -std::numeric_limits<double>::infinity();
    hi[k] = repeats ? cell.min[k] + cell.length[k] : std::numeric_limits<double>::infinity();
  }
  const bool periodic = cell.any();
  // The largest of non-negative doubles is the largest of their bit
  // patterns read as integers: an integer maximum vectorises, a double one
  // does not without giving up NaN and signed-zero semantics.
  std::int64_t max_travel_bits = 0, max_speed_bits = 0;
  // Chunks of 128 particles while the particles stay in the shared cache
  // between steps; of 16 on larger beds, whose arrays come from memory
  // (plate benchmark, one thread, motion phase against 128: at 10k 32 was
  // 1.105, at 100k 0.557; docs/PERFORMANCE.md, item 14). With the arrays
  // on large pages (large_pages.h), 16 against 32 at 100k: the motion
  // phase 0.78-0.85, the whole 1.018 side by side; 8 and 64 were slower.
  constexpr std::int64_t kChunk = 128, kLargeBedChunk = 16, kLargeBed = 32768;
  const std::int64_t chunk = static_cast<std::int64_t>(p.size()) > kLargeBed ? kLargeBedChunk : kChunk;
  alignas(64) double cosine[kChunk], ax[kChunk], ay[kChunk], az[kChunk], angle2[kChunk];
  for (std::int64_t c0 = begin; c0 < end; c0 += chunk) {
    const std::int64_t n = std::min(chunk, end - c0);
    double* __restrict xc = x + D * c0;
    double* __restrict vc = v + D * c0;
    const double* __restrict fc = f + D * c0;
    const double* __restrict mc = mass + c0;
    // Velocities and positions (Cundall & Strack eqs. 35, 22a), the body
    // force m g added to the force sum; the largest speed.
    for (std::int64_t i = 0; i < n; ++i) {
      const double m = mc[i], dt_m = dt / m;
      double speed2 = 0.0;
      for (int k = 0; k < D; ++k) {
        const double v1 = (vc[D * i + k] * keep + (fc[D * i + k] + m * g[k]) * dt_m) * scale;
        vc[D * i + k] = v1;
        xc[D * i + k] += v1 * dt;
        speed2 += v1 * v1;
      }
      max_speed_bits = std::max(max_speed_bits, std::bit_cast<std::int64_t>(speed2));
    }
    // Across the periodic cell: one period either way; a particle that
    // moved farther, or landed on the edge, is wrapped in full afterwards
    // (the loop itself has no branch, so it runs as vector code; the count
    // of those outside is an integer sum for the same reason).
    if (periodic) {
      std::int64_t outside = 0;
      for (std::int64_t i = 0; i < n; ++i) {
        for (int k = 0; k < D; ++k) {
          double coordinate = xc[D * i + k];
          coordinate =
              coordinate < lo[k] ? coordinate + period[k] : (coordinate >= hi[k] ? coordinate - period[k] : coordinate);
          outside += (coordinate < lo[k]) | (coordinate >= hi[k]);
          xc[D * i + k] = coordinate;
        }
      }
      if (outside > 0) {
        for (std::int64_t i = c0; i < c0 + n; ++i) {
          bool out = false;
          for (int k = 0; k < D; ++k) out = out || xc[D * (i - c0) + k] < lo[k] || xc[D * (i - c0) + k] >= hi[k];
          if (out) cell.wrap(p.position[i]);
        }
      }
    }
    // How far each particle is from where the contact table was built
    // (cell.separation's nearest image, without its branches).
    const double* __restrict rc = reference + D * c0;
    for (std::int64_t i = 0; i < n; ++i) {
      double travel2 = 0.0;
      for (int k = 0; k < D; ++k) {
        double d = xc[D * i + k] - rc[D * i + k];
        d = d > 0.5 * period[k] ? d - period[k] : (d < -0.5 * period[k] ? d + period[k] : d);
        travel2 += d * d;
      }
      max_travel_bits = std::max(max_travel_bits, std::bit_cast<std::int64_t>(travel2));
    }
    double* __restrict wc = w + S * c0;
    const double* __restrict momc = moment + S * c0;
    const double* __restrict ic = inertia + c0;
    if constexpr (Dim == 3) {
      // Spins (eq. 36), and from each new spin the turn through the half
      // angle h = |omega| dt / 2 (eq. 23a; turn() in motion.cpp): cos h and
      // sin(h)/h by their series, the large ones redone in full below.
      std::int64_t chunk_large = 0;
      for (std::int64_t i = 0; i < n; ++i) {
        const double inverse = 1.0 / ic[i];
        double w1[3];
        for (int k = 0; k < 3; ++k) {
          w1[k] = (wc[3 * i + k] * keep_rotation + momc[3 * i + k] * inverse * dt) * scale_rotation;
          wc[3 * i + k] = w1[k];
        }
        const double hx = 0.5 * dt * w1[0], hy = 0.5 * dt * w1[1], hz = 0.5 * dt * w1[2];
        const double h2i = hx * hx + hy * hy + hz * hz;
        constexpr double k2 = 1.0 / 2.0, k12 = 1.0 / 12.0, k30 = 1.0 / 30.0;
        constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0;
        const double sine_over_h = 1.0 - h2i * k6 * (1.0 - h2i * k20 * (1.0 - h2i * k42));
        cosine[i] = 1.0 - h2i * k2 * (1.0 - h2i * k12 * (1.0 - h2i * k30));
        ax[i] = sine_over_h * hx;
        ay[i] = sine_over_h * hy;
        az[i] = sine_over_h * hz;
        angle2[i] = h2i;
        chunk_large += h2i >= 1e-4;
      }
      // Orientations (eq. 23a), four numbers a particle.
      double* __restrict qc = reinterpret_cast<double*>(p.rotation.data() + c0);  // x, y, z, w per particle
      if (chunk_large == 0) {
        for (std::int64_t i = 0; i < n; ++i) turn_by(qc + 4 * i, cosine[i], ax[i], ay[i], az[i]);
      } else {
        for (std::int64_t i = 0; i < n; ++i) {
          if (angle2[i] < 1e-4) {
            turn_by(qc + 4 * i, cosine[i], ax[i], ay[i], az[i]);
          } else {
            const double hx = 0.5 * dt * wc[3 * i], hy = 0.5 * dt * wc[3 * i + 1], hz = 0.5 * dt * wc[3 * i + 2];
            double full_cosine, sine_over_h;
            large_half_angle(angle2[i], full_cosine, sine_over_h);
            turn_by(qc + 4 * i, full_cosine, sine_over_h * hx, sine_over_h * hy, sine_over_h * hz);
          }
        }
      }
    } else {
      double* __restrict angle = p.rotation.data() + c0;
      for (std::int64_t i = 0; i < n; ++i) {
        const double w1 = (wc[i] * keep_rotation + momc[i] * (1.0 / ic[i]) * dt) * scale_rotation;  // eq. 36
        wc[i] = w1;
        angle[i] += w1 * dt;
      }
    }
    // The force pass's side-by-side copies, while the chunk is in the core's
    // cache: streamed to memory on large beds; on small ones they stay in
    // the caches until the pass reads them.
    if (hot_place != nullptr) {
      if (stream) {
        copy_hot_particles<true>(p, hot_place, hot_motion, c0, c0 + n);
      } else {
        copy_hot_particles(p, hot_place, hot_motion, c0, c0 + n);
      }
    }
  }
  if (stream && hot_place != nullptr) finish_streaming();
  step.max_travel = std::sqrt(std::bit_cast<double>(max_travel_bits));
  step.max_speed = std::sqrt(std::bit_cast<double>(max_speed_bits));
}

}  // namespace dem
