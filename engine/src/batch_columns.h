// Columns of a batch gathered from arrays of 3-vectors: for eight packed
// rows, the three components of each row's vector side by side, as the
// force pass's law loop reads them (contact_batch.h). One element at a
// time this is three loads and three stores a row; with AVX-512 the eight
// vectors are loaded whole (a 3-lane masked load reads nothing past the
// vector) and transposed in registers: 8 loads, 11 shuffles and 3 stores.
// Only data moves, so the columns hold the same bits either way.
#pragma once

#include <cstdint>

#include "dem/math.h"
#include "inline.h"

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#endif

namespace dem {

// Packed row j of a batch's three columns as a spin or a shear history: a
// 3-vector in 3D, the first column's double in 2D (the two have one type
// per dimension). The batched passes' law loops read and write their rows
// through these (contact_batch.h, wall_batch.h).
template <int Dim, int N>
DEM_INLINE Spin<Dim> column_entry(const double (&columns)[3][N], int j) {
  if constexpr (Dim == 3) {
    return Vec3(columns[0][j], columns[1][j], columns[2][j]);
  } else {
    return columns[0][j];
  }
}
template <int Dim, int N>
DEM_INLINE void set_column_entry(double (&columns)[3][N], int j, const Spin<Dim>& value) {
  if constexpr (Dim == 3) {
    for (int k = 0; k < 3; ++k) columns[k][j] = value[k];
  } else {
    columns[0][j] = value;
  }
}

// out_x[j], out_y[j], out_z[j] = the three doubles at base + kStride *
// slot[j], for j in [0, count): a column of 3-vectors (kStride 3) or of
// records that begin with one (the pass's side-by-side copies). With
// kLanes 4 (records of four doubles or more), out_w[j] = the fourth: the
// side-by-side copies hold a radius or a mass there (contact_blocks.h),
// which so comes with the vector at the cost of one shuffle and one store.
template <int kStride, int kLanes = 3>
void gather_columns(const double* base, const std::int32_t* slot, int count, double* out_x, double* out_y,
                    double* out_z, double* out_w = nullptr) {
  static_assert(kLanes == 3 || (kLanes == 4 && kStride >= 4));
  int j = 0;
#if defined(__AVX512F__) && defined(__AVX512VL__)
  // Lanes of two 4-wide halves [x0 y0 z0 w0 x1 y1 z1 w1] (w zero with three
  // lanes): first the x and y of four rows, then their z and w.
  const __m512i xy = _mm512_setr_epi64(0, 4, 8, 12, 1, 5, 9, 13);
  const __m512i zw = _mm512_setr_epi64(2, 6, 10, 14, 3, 7, 11, 15);
  const __m512i low = _mm512_setr_epi64(0, 1, 2, 3, 8, 9, 10, 11);
  const __m512i high = _mm512_setr_epi64(4, 5, 6, 7, 12, 13, 14, 15);
  constexpr __mmask8 kRead = kLanes == 4 ? 0xf : 0x7;  // a 3-lane masked load reads nothing past the vector
  auto pair = [&](int a) {
    const __m256d first = _mm256_maskz_loadu_pd(kRead, base + kStride * static_cast<std::int64_t>(slot[a]));
    const __m256d second = _mm256_maskz_loadu_pd(kRead, base + kStride * static_cast<std::int64_t>(slot[a + 1]));
    // (The masked insert: the plain one's undefined upper half trips GCC
    // 12's maybe-uninitialized warning.)
    return _mm512_maskz_insertf64x4(0xff, _mm512_castpd256_pd512(first), second, 1);
  };
  for (; j + 8 <= count; j += 8) {
    const __m512d r01 = pair(j), r23 = pair(j + 2), r45 = pair(j + 4), r67 = pair(j + 6);
    const __m512d xy03 = _mm512_permutex2var_pd(r01, xy, r23);  // x0 x1 x2 x3 y0 y1 y2 y3
    const __m512d zw03 = _mm512_permutex2var_pd(r01, zw, r23);  // z0 z1 z2 z3 w0 w1 w2 w3
    const __m512d xy47 = _mm512_permutex2var_pd(r45, xy, r67);
    const __m512d zw47 = _mm512_permutex2var_pd(r45, zw, r67);
    _mm512_storeu_pd(out_x + j, _mm512_permutex2var_pd(xy03, low, xy47));
    _mm512_storeu_pd(out_y + j, _mm512_permutex2var_pd(xy03, high, xy47));
    _mm512_storeu_pd(out_z + j, _mm512_permutex2var_pd(zw03, low, zw47));
    if constexpr (kLanes == 4) _mm512_storeu_pd(out_w + j, _mm512_permutex2var_pd(zw03, high, zw47));
  }
#endif
  for (; j < count; ++j) {
    const double* v = base + kStride * static_cast<std::int64_t>(slot[j]);
    out_x[j] = v[0];
    out_y[j] = v[1];
    out_z[j] = v[2];
    if constexpr (kLanes == 4) out_w[j] = v[3];
  }
}

}  // namespace dem
