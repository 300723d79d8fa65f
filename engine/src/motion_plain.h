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

template <int Dim>
void move_plain_block(Particles<Dim>& p, const Vec<Dim>& gravity, const Periodic<Dim>& cell, double dt, double keep,
                      double scale, double keep_rotation, double scale_rotation, std::int64_t begin, std::int64_t end,
                      MotionStep& step) {
  constexpr int D = Dim;
  constexpr int S = Dim == 3 ? 3 : 1;  // components of a spin
  double* __restrict x = p.position.data()->data();
  double* __restrict v = p.velocity.data()->data();
  const double* __restrict f = p.force.data()->data();
  const double* __restrict mass = p.mass.data();
  const double* __restrict inertia = p.inertia.data();
  double* __restrict w;
  const double* __restrict moment;
  if constexpr (Dim == 3) {
    w = p.angular_velocity.data()->data();
    moment = p.moment.data()->data();
  } else {
    w = p.angular_velocity.data();
    moment = p.moment.data();
  }
  double g[D], lo[D], period[D];
  for (int k = 0; k < D; ++k) {
    g[k] = gravity[k];
    lo[k] = cell.min[k];
    period[k] = cell.length[k];
  }
  // Velocities and positions (Cundall & Strack eqs. 35, 22a), the body
  // force m g added to the force sum.
  for (std::int64_t i = begin; i < end; ++i) {
    const double m = mass[i], dt_m = dt / m;
    for (int k = 0; k < D; ++k) {
      const double v1 = (v[D * i + k] * keep + (f[D * i + k] + m * g[k]) * dt_m) * scale;
      v[D * i + k] = v1;
      x[D * i + k] += v1 * dt;
    }
  }
  // Spins (eq. 36).
  for (std::int64_t i = begin; i < end; ++i) {
    const double inverse = 1.0 / inertia[i];
    for (int k = 0; k < S; ++k) {
      w[S * i + k] = (w[S * i + k] * keep_rotation + moment[S * i + k] * inverse * dt) * scale_rotation;
    }
  }
  // Across the periodic cell: one period either way; a particle that moved
  // farther, or landed on the edge, is wrapped in full afterwards (the loop
  // itself has no branch, so it runs as vector code; the count of those
  // outside is an integer sum for the same reason).
  if (cell.any()) {
    std::int64_t outside = 0;
    for (std::int64_t i = begin; i < end; ++i) {
      for (int k = 0; k < D; ++k) {
        if (!(period[k] > 0.0)) continue;
        double coordinate = x[D * i + k];
        coordinate = coordinate < lo[k] ? coordinate + period[k]
                                        : (coordinate >= lo[k] + period[k] ? coordinate - period[k] : coordinate);
        outside += (coordinate < lo[k]) | (coordinate >= lo[k] + period[k]);
        x[D * i + k] = coordinate;
      }
    }
    if (outside > 0) {
      for (std::int64_t i = begin; i < end; ++i) cell.wrap(p.position[i]);
    }
  }
  // Orientations (eq. 23a): as turn() in motion.cpp; a turn through a large
  // half angle is redone in full afterwards.
  if constexpr (Dim == 3) {
    double* __restrict q = reinterpret_cast<double*>(p.rotation.data());  // x, y, z, w per particle
    // In chunks, two loops: the half-angle turn from the spins (three to a
    // particle), then the product with the orientations (four to a
    // particle); one loop over both strides does not vectorise.
    constexpr std::int64_t kChunk = 256;
    alignas(64) double cosine[kChunk], ax[kChunk], ay[kChunk], az[kChunk], angle2[kChunk];
    std::int64_t large_count = 0;
    for (std::int64_t c0 = begin; c0 < end; c0 += kChunk) {
      const std::int64_t n = std::min(kChunk, end - c0);
      std::int64_t chunk_large = 0;
      const double* __restrict wc = w + 3 * c0;
      for (std::int64_t i = 0; i < n; ++i) {
        const double hx = 0.5 * dt * wc[3 * i], hy = 0.5 * dt * wc[3 * i + 1], hz = 0.5 * dt * wc[3 * i + 2];
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
      double* __restrict qc = q + 4 * c0;
      if (chunk_large == 0) {
        for (std::int64_t i = 0; i < n; ++i) turn_by(qc + 4 * i, cosine[i], ax[i], ay[i], az[i]);
      } else {
        for (std::int64_t i = 0; i < n; ++i) {
          if (angle2[i] < 1e-4) turn_by(qc + 4 * i, cosine[i], ax[i], ay[i], az[i]);  // the large ones below
        }
      }
      large_count += chunk_large;
    }
    if (large_count > 0) {
      for (std::int64_t i = begin; i < end; ++i) {
        const double hx = 0.5 * dt * w[3 * i], hy = 0.5 * dt * w[3 * i + 1], hz = 0.5 * dt * w[3 * i + 2];
        const double h2 = hx * hx + hy * hy + hz * hz;
        if (h2 < 1e-4) continue;
        double full_cosine, sine_over_h;
        large_half_angle(h2, full_cosine, sine_over_h);
        turn_by(q + 4 * i, full_cosine, sine_over_h * hx, sine_over_h * hy, sine_over_h * hz);
      }
    }
  } else {
    for (std::int64_t i = begin; i < end; ++i) p.rotation[i] += w[i] * dt;
  }
  // How far anything moved, and how fast.
  const double* __restrict reference = p.reference_position.data()->data();
  // The largest of non-negative doubles is the largest of their bit
  // patterns read as integers: an integer maximum vectorises, a double one
  // does not without giving up NaN and signed-zero semantics.
  std::int64_t max_travel_bits = 0, max_speed_bits = 0;
  for (std::int64_t i = begin; i < end; ++i) {
    double speed2 = 0.0, travel2 = 0.0;
    for (int k = 0; k < D; ++k) {
      speed2 += v[D * i + k] * v[D * i + k];
      // cell.separation's nearest image, without its branches.
      double d = x[D * i + k] - reference[D * i + k];
      d = d > 0.5 * period[k] ? d - period[k] : (d < -0.5 * period[k] ? d + period[k] : d);
      travel2 += d * d;
    }
    max_speed_bits = std::max(max_speed_bits, std::bit_cast<std::int64_t>(speed2));
    max_travel_bits = std::max(max_travel_bits, std::bit_cast<std::int64_t>(travel2));
  }
  const double max_travel2 = std::bit_cast<double>(max_travel_bits);
  const double max_speed2 = std::bit_cast<double>(max_speed_bits);
  step.max_travel = std::sqrt(max_travel2);
  step.max_speed = std::sqrt(max_speed2);
}

}  // namespace dem
