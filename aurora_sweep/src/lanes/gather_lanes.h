// Per-lane loads at per-lane indices for the SIMD engine (the history ring,
// the link models' rings). xsimd 8.1 sends the AVX-512 and AVX2 gathers to
// its element-wise generic code (over half the engine's time under perf);
// these overloads issue the gather instructions themselves. Other sets (SSE
// has no gather) take xsimd's.
#pragma once

#include <xsimd/xsimd.hpp>

#include <cstdint>

namespace aurora_sweep {

template <class B, class I>
inline B gatherLanes(const typename B::value_type* base, const I& index) {
  return B::gather(base, index);
}

#if defined(__AVX512F__)
template <>
inline xsimd::batch<float, xsimd::avx512bw> gatherLanes(const float* base,
                                                       const xsimd::batch<int32_t, xsimd::avx512bw>& index) {
  return _mm512_i32gather_ps(index, base, sizeof(float));
}
template <>
inline xsimd::batch<double, xsimd::avx512bw> gatherLanes(const double* base,
                                                        const xsimd::batch<int64_t, xsimd::avx512bw>& index) {
  return _mm512_i64gather_pd(index, base, sizeof(double));
}
template <>
inline xsimd::batch<int32_t, xsimd::avx512bw> gatherLanes(const int32_t* base,
                                                         const xsimd::batch<int32_t, xsimd::avx512bw>& index) {
  return _mm512_i32gather_epi32(index, base, sizeof(int32_t));
}
template <>
inline xsimd::batch<int64_t, xsimd::avx512bw> gatherLanes(const int64_t* base,
                                                         const xsimd::batch<int64_t, xsimd::avx512bw>& index) {
  return _mm512_i64gather_epi64(index, base, sizeof(int64_t));
}
#endif

#if defined(__AVX2__)
using Avx2Arch = xsimd::fma3<xsimd::avx2>;
template <>
inline xsimd::batch<float, Avx2Arch> gatherLanes(const float* base, const xsimd::batch<int32_t, Avx2Arch>& index) {
  return _mm256_i32gather_ps(base, index, sizeof(float));
}
template <>
inline xsimd::batch<double, Avx2Arch> gatherLanes(const double* base, const xsimd::batch<int64_t, Avx2Arch>& index) {
  return _mm256_i64gather_pd(base, index, sizeof(double));
}
template <>
inline xsimd::batch<int32_t, Avx2Arch> gatherLanes(const int32_t* base, const xsimd::batch<int32_t, Avx2Arch>& index) {
  return _mm256_i32gather_epi32(base, index, sizeof(int32_t));
}
template <>
inline xsimd::batch<int64_t, Avx2Arch> gatherLanes(const int64_t* base, const xsimd::batch<int64_t, Avx2Arch>& index) {
  return _mm256_i64gather_epi64(reinterpret_cast<const long long*>(base), index, sizeof(int64_t));
}
#endif

// Products of 64-bit lanes whose values are below 2^32: one 32 x 32 -> 64-bit
// multiply per lane (the Philox rounds of lane_links.h).
template <class U>
inline U mulLow32(const U& a, const U& b) {
  return a * b;
}
#if defined(__AVX512F__)
template <>
inline xsimd::batch<uint64_t, xsimd::avx512bw> mulLow32(const xsimd::batch<uint64_t, xsimd::avx512bw>& a,
                                                       const xsimd::batch<uint64_t, xsimd::avx512bw>& b) {
  return _mm512_mul_epu32(a, b);
}
#endif
#if defined(__AVX2__)
template <>
inline xsimd::batch<uint64_t, Avx2Arch> mulLow32(const xsimd::batch<uint64_t, Avx2Arch>& a,
                                                const xsimd::batch<uint64_t, Avx2Arch>& b) {
  return _mm256_mul_epu32(a, b);
}
#endif
#if defined(__SSE4_2__)
template <>
inline xsimd::batch<uint64_t, xsimd::sse4_2> mulLow32(const xsimd::batch<uint64_t, xsimd::sse4_2>& a,
                                                     const xsimd::batch<uint64_t, xsimd::sse4_2>& b) {
  return _mm_mul_epu32(a, b);
}
#endif

}  // namespace aurora_sweep
