// LikelihoodFieldModel's endpoint scoring on AVX2: four beams of one
// particle at a time, their cells' distance codes and then log p read by
// two gathers. The arithmetic is the scalar loop's, in the same order and
// rounded step by step (AVX2 only, no FMA to fuse it), so the values are
// the same bit for bit; likelihood_field_model_test compares them.

#include "algorithms/amcl/likelihood_field_lanes.hpp"

#include <stdexcept>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PLAYERKIT_FIELD_LANES_AVX2 1
#endif

namespace playerkit::amcl::field_lanes {

#ifdef PLAYERKIT_FIELD_LANES_AVX2

namespace {

[[gnu::target("avx2")]] void score_fours(const FieldTable& field, const CellPose& pose, const double* hx,
                                         const double* hy, std::size_t count, float* values) {
  const __m256d col = _mm256_set1_pd(pose.col), row = _mm256_set1_pd(pose.row);
  const __m256d cos_r = _mm256_set1_pd(pose.cos_r), sin_r = _mm256_set1_pd(pose.sin_r);
  const __m128i zero = _mm_setzero_si128();
  const __m128i width = _mm_set1_epi32(field.width), height = _mm_set1_epi32(field.height);
  const __m128i low_byte = _mm_set1_epi32(0xFF);
  const __m128i all_ones = _mm_set1_epi32(-1);
  const __m128 outside_value = _mm_set1_ps(field.log_outside);
  const auto* codes = reinterpret_cast<const int*>(field.codes);
  for (std::size_t b = 0; b < count; b += 4) {
    const __m256d x = _mm256_loadu_pd(hx + b), y = _mm256_loadu_pd(hy + b);
    const __m256d at_col = _mm256_sub_pd(_mm256_add_pd(col, _mm256_mul_pd(cos_r, x)), _mm256_mul_pd(sin_r, y));
    const __m256d at_row = _mm256_add_pd(_mm256_add_pd(row, _mm256_mul_pd(sin_r, x)), _mm256_mul_pd(cos_r, y));
    const __m128i cell_col = _mm256_cvttpd_epi32(_mm256_floor_pd(at_col));
    const __m128i cell_row = _mm256_cvttpd_epi32(_mm256_floor_pd(at_row));
    // Off the map: col or row below 0 or at least the size (a huge or NaN
    // coordinate converts to INT_MIN, below 0).
    __m128i outside = _mm_or_si128(_mm_cmplt_epi32(cell_col, zero), _mm_cmplt_epi32(cell_row, zero));
    const __m128i inside_size = _mm_and_si128(_mm_cmpgt_epi32(width, cell_col), _mm_cmpgt_epi32(height, cell_row));
    outside = _mm_or_si128(outside, _mm_andnot_si128(inside_size, all_ones));
    // Cells off the map read cell 0 instead, and take log_outside.
    const __m128i index = _mm_andnot_si128(outside, _mm_add_epi32(_mm_mullo_epi32(cell_row, width), cell_col));
    const __m128i code = _mm_and_si128(_mm_i32gather_epi32(codes, index, 1), low_byte);
    const __m128 value = _mm_i32gather_ps(field.log_by_code, code, 4);
    _mm_storeu_ps(values + b, _mm_blendv_ps(value, outside_value, _mm_castsi128_ps(outside)));
  }
}

}  // namespace

bool available() {
  static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
  return avx2;
}

void endpoint_values(const FieldTable& field, const CellPose& pose, const double* hx, const double* hy,
                     std::size_t count, float* values) {
  score_fours(field, pose, hx, hy, count, values);
}

#else  // not x86-64: the scalar loop only

bool available() { return false; }

void endpoint_values(const FieldTable&, const CellPose&, const double*, const double*, std::size_t, float*) {
  throw std::logic_error("field_lanes::endpoint_values: no vector scoring on this processor");
}

#endif

}  // namespace playerkit::amcl::field_lanes
