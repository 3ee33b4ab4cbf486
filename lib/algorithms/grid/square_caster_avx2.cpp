// SquareCaster's walk of many rays on AVX2: sixteen walks side by side, as
// four groups of four lanes. The scalar walk (square_caster.cpp) spends
// some sixty instructions on a step; here four steps take about fifty, and
// the four groups' chains of dependent steps overlap (four groups measured
// faster than two or three, and as fast as six or eight).
//
// Each step is the scalar advance() done on four lanes with the same
// operations in the same order: cell numbers are whole numbers held in
// doubles (exact), products and sums are rounded one by one as there (this
// file enables AVX2 only, not FMA, so that nothing fuses them), and the
// floor of the same shifted value. The answers are the scalar walk's bit
// for bit; square_caster_test compares them.
//
// Only the functions marked with the target attribute use AVX2; the rest
// of the program runs on any x86-64, which chooses this walk at run time.

#include "algorithms/grid/square_caster_lanes.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PLAYERKIT_SQUARE_CASTER_AVX2 1
#endif

namespace playerkit::grid::lanes {

#ifdef PLAYERKIT_SQUARE_CASTER_AVX2

namespace {

constexpr int kLanesPerGroup = 4;
constexpr int kGroups = 4;

// A lane with no ray: every step ends at once (length 0) in cell (0, 0).
constexpr LaneStart kIdleLane{0.5, 0.5, 1.0, 0.0, 1.0, kNeverInverse, 0.0,
                              1.0, 0.0,  1.0, 0.0, 0.0, 0.0, 1.0, 0.0};

struct Group {
  __m256d x, y, dx, dy, inverse_x, inverse_y, length;
  __m256d step_x, behind_x, step_y, behind_y;
  __m256d col, row, clearance, along;
};

struct StepEnds {
  int ended;  // lane bits: hit or gone
  int gone;   // lane bits: passed max_range or left the grid
};

[[gnu::target("avx2")]] inline __m256d lane_mask(int lane) {
  const __m256i lanes = _mm256_setr_epi64x(0, 1, 2, 3);
  return _mm256_castsi256_pd(_mm256_cmpeq_epi64(lanes, _mm256_set1_epi64x(lane)));
}

[[gnu::target("avx2")]] inline void put(__m256d& field, double value, __m256d mask) {
  field = _mm256_blendv_pd(field, _mm256_set1_pd(value), mask);
}

[[gnu::target("avx2")]] inline void load_lane(Group& group, int lane, const LaneStart& start) {
  const __m256d mask = lane_mask(lane);
  put(group.x, start.x, mask);
  put(group.y, start.y, mask);
  put(group.dx, start.dx, mask);
  put(group.dy, start.dy, mask);
  put(group.inverse_x, start.inverse_x, mask);
  put(group.inverse_y, start.inverse_y, mask);
  put(group.length, start.length, mask);
  put(group.step_x, start.step_x, mask);
  put(group.behind_x, start.behind_x, mask);
  put(group.step_y, start.step_y, mask);
  put(group.behind_y, start.behind_y, mask);
  put(group.col, start.col, mask);
  put(group.row, start.row, mask);
  put(group.clearance, start.clearance, mask);
  put(group.along, 0.0, mask);
}

// The scalar floor_cell: truncation of the shifted value, which is
// positive, so its floor.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256d floor_cell(__m256d cells_from_corner) {
  const __m256d shift = _mm256_set1_pd(kFloorShift);
  return _mm256_sub_pd(_mm256_floor_pd(_mm256_add_pd(cells_from_corner, shift)), shift);
}

// advance() on four lanes; see it for the why of each line.
[[gnu::target("avx2"), gnu::always_inline]] inline StepEnds step(Group& g, const std::uint8_t* cells, __m256d width,
                                                                 __m256d height) {
  const __m256d zero = _mm256_setzero_pd();
  const __m256d ahead_x = _mm256_add_pd(g.col, _mm256_mul_pd(g.step_x, g.clearance));
  const __m256d ahead_y = _mm256_add_pd(g.row, _mm256_mul_pd(g.step_y, g.clearance));
  const __m256d exit_x = _mm256_mul_pd(_mm256_sub_pd(_mm256_add_pd(ahead_x, g.behind_x), g.x), g.inverse_x);
  const __m256d exit_y = _mm256_mul_pd(_mm256_sub_pd(_mm256_add_pd(ahead_y, g.behind_y), g.y), g.inverse_y);
  const __m256d by_x = _mm256_cmp_pd(exit_x, exit_y, _CMP_LE_OQ);
  __m256d leaves = _mm256_min_pd(exit_y, exit_x);  // std::min(exit_x, exit_y), ties and all
  __m256d cell_x = floor_cell(_mm256_add_pd(g.x, _mm256_mul_pd(leaves, g.dx)));
  __m256d cell_y = floor_cell(_mm256_add_pd(g.y, _mm256_mul_pd(leaves, g.dy)));
  const __m256d stuck = _mm256_cmp_pd(leaves, g.along, _CMP_NGT_UQ);
  if (_mm256_movemask_pd(stuck) != 0) [[unlikely]] {
    const __m256d forward_x = _mm256_cmp_pd(g.step_x, zero, _CMP_GT_OQ);
    const __m256d forward_y = _mm256_cmp_pd(g.step_y, zero, _CMP_GT_OQ);
    const __m256d kept_x = _mm256_blendv_pd(_mm256_min_pd(cell_x, g.col), _mm256_max_pd(cell_x, g.col), forward_x);
    const __m256d kept_y = _mm256_blendv_pd(_mm256_min_pd(cell_y, g.row), _mm256_max_pd(cell_y, g.row), forward_y);
    cell_x = _mm256_blendv_pd(cell_x, kept_x, stuck);
    cell_y = _mm256_blendv_pd(cell_y, kept_y, stuck);
    leaves = _mm256_blendv_pd(leaves, g.along, stuck);
  }
  const __m256d next_col = _mm256_blendv_pd(cell_x, ahead_x, by_x);
  const __m256d next_row = _mm256_blendv_pd(ahead_y, cell_y, by_x);
  __m256d gone = _mm256_cmp_pd(leaves, g.length, _CMP_NLT_UQ);
  gone = _mm256_or_pd(gone, _mm256_cmp_pd(next_col, zero, _CMP_LT_OQ));
  gone = _mm256_or_pd(gone, _mm256_cmp_pd(next_col, width, _CMP_GE_OQ));
  gone = _mm256_or_pd(gone, _mm256_cmp_pd(next_row, zero, _CMP_LT_OQ));
  gone = _mm256_or_pd(gone, _mm256_cmp_pd(next_row, height, _CMP_GE_OQ));
  // A gone lane stays in its cell, so that the read below stays on the
  // grid; its `along` no longer matters (its answer is max_range).
  g.col = _mm256_blendv_pd(next_col, g.col, gone);
  g.row = _mm256_blendv_pd(next_row, g.row, gone);
  g.along = leaves;
  // Whole numbers below 2^31: exact in the double and in the conversion.
  const __m128i index = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(g.row, width), g.col));
  const __m128i read = _mm_i32gather_epi32(reinterpret_cast<const int*>(cells), index, 1);
  g.clearance = _mm256_cvtepi32_pd(_mm_and_si128(read, _mm_set1_epi32(0xFF)));
  const __m256d hit = _mm256_cmp_pd(g.clearance, zero, _CMP_EQ_OQ);
  return {_mm256_movemask_pd(_mm256_or_pd(gone, hit)), _mm256_movemask_pd(gone)};
}

// Walks the started rays sixteen at a time; a lane whose walk ends takes
// the next start. Answers as SquareCaster::scalar_ranges' finish().
[[gnu::target("avx2")]] void walk_all(const LaneMap& map, std::span<const LaneStart> starts,
                                      std::span<const std::size_t> start_ray, std::span<double> ranges) {
  constexpr int kLanes = kLanesPerGroup * kGroups;
  std::array<Group, kGroups> groups{};
  std::array<std::size_t, kLanes> start_of{};  // which start each lane walks
  std::size_t next = 0;
  unsigned active = 0;  // lane bits
  for (int lane = 0; lane < kLanes; ++lane) {
    Group& group = groups[static_cast<std::size_t>(lane / kLanesPerGroup)];
    if (next < starts.size()) {
      load_lane(group, lane % kLanesPerGroup, starts[next]);
      start_of[static_cast<std::size_t>(lane)] = next++;
      active |= 1U << lane;
    } else {
      load_lane(group, lane % kLanesPerGroup, kIdleLane);
    }
  }
  const __m256d width = _mm256_set1_pd(static_cast<double>(map.width));
  const __m256d height = _mm256_set1_pd(static_cast<double>(map.height));
  while (active != 0) {
    unsigned ended = 0, gone = 0;
#pragma GCC unroll 8
    for (int g = 0; g < kGroups; ++g) {
      const StepEnds ends = step(groups[static_cast<std::size_t>(g)], map.cells, width, height);
      ended |= static_cast<unsigned>(ends.ended) << (g * kLanesPerGroup);
      gone |= static_cast<unsigned>(ends.gone) << (g * kLanesPerGroup);
    }
    ended &= active;
    if (ended == 0) continue;
    alignas(32) std::array<double, kLanes> along{};
    for (int g = 0; g < kGroups; ++g) {
      _mm256_store_pd(&along[static_cast<std::size_t>(g * kLanesPerGroup)], groups[static_cast<std::size_t>(g)].along);
    }
    while (ended != 0) {
      const int lane = __builtin_ctz(ended);
      ended &= ended - 1;
      const std::size_t walked = start_of[static_cast<std::size_t>(lane)];
      const double max_range = starts[walked].max_range;
      const bool hit = ((gone >> lane) & 1U) == 0;
      ranges[start_ray[walked]] =
          hit ? std::min(along[static_cast<std::size_t>(lane)] * map.resolution, max_range) : max_range;
      Group& group = groups[static_cast<std::size_t>(lane / kLanesPerGroup)];
      if (next < starts.size()) {
        load_lane(group, lane % kLanesPerGroup, starts[next]);
        start_of[static_cast<std::size_t>(lane)] = next++;
      } else {
        load_lane(group, lane % kLanesPerGroup, kIdleLane);
        active &= ~(1U << lane);
      }
    }
  }
}

}  // namespace

bool available() {
  static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
  return avx2;
}

void walk(const LaneMap& map, std::span<const LaneStart> starts, std::span<const std::size_t> start_ray,
          std::span<double> ranges) {
  walk_all(map, starts, start_ray, ranges);
}

#else  // not x86-64: the scalar walk only

bool available() { return false; }

void walk(const LaneMap&, std::span<const LaneStart>, std::span<const std::size_t>, std::span<double>) {
  throw std::logic_error("square_caster_lanes::walk: no vector walk on this processor");
}

#endif

}  // namespace playerkit::grid::lanes
