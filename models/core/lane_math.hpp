// exp, log, log1p, expm1 and pow written with IEEE basic operations only (+, -, *, /, compares
// and bit moves), branch-free, and inlined, for one double or a vector of kLaneWidth doubles
// (GCC's vector extension, which the compiler lowers to SSE2, AVX2 or AVX-512 instructions, the
// widest the CPU has: models/plasticity/johnson_cook_return_batch.cpp). One template serves both,
// so the flow-stress laws have one source for the one-point update and the batched one. Why not the
// C library: std::pow and std::log are calls the vectoriser cannot see through, and the vector
// library (glibc's libmvec) has a separate kernel per instruction set, so a run's bits would depend
// on the CPU. These give the same bits for one lane or eight, on every x86-64 CPU, provided the
// including file is compiled without floating-point contraction (-ffp-contract=off, the ISO mode
// default of GCC; set explicitly for the batch kernels).
//
// Accuracy (tests/models/core/lane_math_test.cpp, against the C library over 1e6 arguments):
// exp and log within 2 ulp, log1p and expm1 within 4 ulp, pow(x, y) = exp(y log x) within
// (2 + |y ln x|) ulp: 1e-14 relative for a plastic strain of 1e-12 to the power 0.3.
// Method: Cody & Waite range reduction with a split ln 2 (Cody & Waite 1980, Software Manual for
// the Elementary Functions, ch. 6 and 5); exp(r) for |r| <= ln2/2 by its Taylor series to r^13;
// log(m) for m in [sqrt(1/2), sqrt(2)) as 2 atanh(s), s = (m - 1)/(m + 1), to s^23; log1p by a
// rounding correction of log, expm1 from exp's own reduction.
// Domain: exp for every double (0 below -745.2, +inf above 709.8, NaN in, NaN out); log for x > 0
// including subnormals (log 0 = -inf, log of a negative or NaN is NaN, log +inf = +inf); pow for
// x > 0 (pow(0, y > 0) = 0).
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

// A Vec passed by value would change the calling convention between instruction sets (GCC's
// -Wpsabi note); every function here is inlined into its caller, so none is ever called.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact::lane {

#define IMPACT_LANE_INLINE [[gnu::always_inline]] inline

/// A kernel on vectors, compiled once per instruction set and chosen when the program loads (an
/// ifunc) with GCC on x86-64; every template it calls must be always_inline, so that each copy is
/// vectorised for its set. Clang (the fuzz build) gets one generic copy of its two-lane vectors.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define IMPACT_LANE_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define IMPACT_LANE_CLONES
#endif

/// Doubles per vector: eight fill an AVX-512 register (two AVX2, four SSE2 registers). Clang
/// refuses a vector wider than the baseline's registers as a by-value argument even between
/// inlined functions, so its builds (the fuzz targets) use two lanes: a lane's bits do not depend
/// on the width.
#if defined(__clang__)
inline constexpr int kLaneWidth = 2;
#else
inline constexpr int kLaneWidth = 8;
#endif
/// A vector type's alignment follows the instruction set of the file that declares it (16 bytes
/// without AVX), while the AVX-512 copy of a kernel loads it with 64-byte aligned instructions:
/// every struct that holds vectors is declared alignas(kLaneBytes), and its vector members are
/// whole multiples of that size.
inline constexpr int kLaneBytes = kLaneWidth * int(sizeof(double));
using Vec = double __attribute__((vector_size(kLaneBytes)));
using IntVec = std::int64_t __attribute__((vector_size(kLaneBytes)));

/// The integer of a lane's width, and the type of a comparison: bool for a double, a vector of
/// 0 / -1 for a Vec (a ? b : c then selects per lane).
template <class V>
using IntOf = std::conditional_t<std::is_same_v<V, double>, std::int64_t, IntVec>;
template <class V>
using MaskOf = decltype(std::declval<V>() < std::declval<V>());

template <class V>
IMPACT_LANE_INLINE V splat(double x) {
  if constexpr (std::is_same_v<V, double>)
    return x;
  else
    return V{} + x;
}

/// The bits of x as a value of type To of the same size: std::bit_cast for a double, the vector
/// extension's cast for a vector (which reinterprets; UBSan misreads std::bit_cast of a vector).
template <class To, class From>
IMPACT_LANE_INLINE To bits_as(From x) {
  if constexpr (std::is_arithmetic_v<From>)
    return std::bit_cast<To>(x);
  else
    return (To)x;
}

/// m ? a : b per lane, with the arms broadcast.
template <class V>
IMPACT_LANE_INLINE V select(MaskOf<V> m, V a, V b) {
  return m ? a : b;
}
template <class V>
requires(!std::is_same_v<V, double>) IMPACT_LANE_INLINE V select(MaskOf<V> m, double a, V b) {
  return m ? splat<V>(a) : b;
}
template <class V>
requires(!std::is_same_v<V, double>) IMPACT_LANE_INLINE V select(MaskOf<V> m, V a, double b) {
  return m ? a : splat<V>(b);
}

/// Lane k of a value (a double has one lane, k = 0).
template <class V>
IMPACT_LANE_INLINE auto get(const V& v, int k) {
  if constexpr (std::is_arithmetic_v<V>)
    return v;
  else
    return v[k];
}
template <class V, class T>
IMPACT_LANE_INLINE void set(V& v, int k, T x) {
  if constexpr (std::is_arithmetic_v<V>)
    v = x;
  else
    v[k] = x;
}

/// A mask as a stored flag: nonzero where set (1 for a double's bool, -1 in a vector's lane).
template <class V>
IMPACT_LANE_INLINE IntOf<V> flag(MaskOf<V> m) {
  if constexpr (std::is_same_v<V, double>)
    return m ? 1 : 0;
  else
    return m;
}

/// Whether any lane's mask is set.
template <class M>
IMPACT_LANE_INLINE bool any(M m) {
  if constexpr (std::is_arithmetic_v<M>) {  // one lane: a bool, or an int from bool & bool
    return m != 0;
  } else {
    std::int64_t r = 0;
    for (int k = 0; k < kLaneWidth; ++k) r |= m[k];
    return r != 0;
  }
}

template <class V>
IMPACT_LANE_INLINE V abs(V x) {
  return bits_as<V>(bits_as<IntOf<V>>(x) & 0x7fffffffffffffffLL);
}

template <class V>
IMPACT_LANE_INLINE V sqrt(V x) {
  if constexpr (std::is_same_v<V, double>) {
    return __builtin_sqrt(x);
  } else {
    V r;
    for (int k = 0; k < kLaneWidth; ++k) r[k] = __builtin_sqrt(x[k]);
    return r;
  }
}

namespace detail {
constexpr double kShift = 0x1.8p52;  // t + kShift rounds t to an integer held in the low bits
constexpr double kLn2Hi = 0x1.62e42fee00000p-1;  // ln 2 to 32 bits: n * kLn2Hi exact for |n| < 2^21
constexpr double kLn2Lo = 0x1.a39ef35793c76p-33;
constexpr double kLog2e = 0x1.71547652b82fep0;
constexpr double kSqrt2 = 0x1.6a09e667f3bcdp0;

/// (e^r - 1) / r for |r| <= ln2 / 2: its Taylor series to r^12 / 13!, by Estrin's scheme (a
/// shallow tree instead of Horner's chain of 13 dependent steps: the one-lane path is bound by
/// that latency).
template <class V>
IMPACT_LANE_INLINE V expm1_series(V r) {
  const V r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const V a0 = 1.0 + r * (1.0 / 2.0), a1 = 1.0 / 6.0 + r * (1.0 / 24.0);
  const V a2 = 1.0 / 120.0 + r * (1.0 / 720.0), a3 = 1.0 / 5040.0 + r * (1.0 / 40320.0);
  const V a4 = 1.0 / 362880.0 + r * (1.0 / 3628800.0);
  const V a5 = 1.0 / 39916800.0 + r * (1.0 / 479001600.0);
  const V b0 = a0 + r2 * a1, b1 = a2 + r2 * a3, b2 = a4 + r2 * a5;
  return (b0 + r4 * b1) + r8 * (b2 + r4 * (1.0 / 6227020800.0));
}

/// 2^k for an integer-valued k in [-1022, 1023], from its bits.
template <class V>
IMPACT_LANE_INLINE V two_to(V k) {
  using I = IntOf<V>;
  const I bits = bits_as<I>(V(k + kShift)) - std::bit_cast<std::int64_t>(kShift);
  return bits_as<V>(I((bits + 1023) << 52));
}

/// e^x = 2^n (1 + q) with 2^n = a b split in two factors (n spans [-1075, 1024], beyond one
/// exponent field; the products round into the subnormals or overflow to +inf as the true value
/// does). NaN is the caller's to pass through.
template <class V>
struct ExpParts {
  V q, a, b;
};
template <class V>
IMPACT_LANE_INLINE ExpParts<V> exp_parts(V x) {
  V xc = select<V>(x < -745.2, -745.2, x);
  xc = select<V>(xc > 709.8, 709.8, xc);
  const V n = (xc * kLog2e + kShift) - kShift;  // nearest integer to x / ln 2
  const V r = (xc - n * kLn2Hi) - n * kLn2Lo;   // |r| <= ln2 / 2 (plus round-off)
  const V half = (n * 0.5 + kShift) - kShift;
  return {r * expm1_series(r), two_to(half), two_to(V(n - half))};
}
}  // namespace detail

template <class V>
IMPACT_LANE_INLINE V exp(V x) {
  const detail::ExpParts<V> e = detail::exp_parts(x);
  const V result = ((1.0 + e.q) * e.a) * e.b;
  return select<V>(x != x, x, result);
}

/// e^x - 1, accurate for small x: 2^n q + (2^n - 1) with exp's reduction, where q = e^r - 1 keeps
/// every digit and 2^n - 1 is exact for the n that matter.
template <class V>
IMPACT_LANE_INLINE V expm1(V x) {
  const detail::ExpParts<V> e = detail::exp_parts(x);
  const V result = (e.q * e.a) * e.b + (e.a * e.b - 1.0);
  return select<V>(x != x, x, result);
}

template <class V>
IMPACT_LANE_INLINE V log(V x) {
  using namespace detail;
  using I = IntOf<V>;
  const MaskOf<V> subnormal = x < 0x1p-1022;
  const V xs = select<V>(subnormal, x * 0x1p54, x);
  const I bits = bits_as<I>(xs);
  // Exponent field as a double, without an integer-to-double conversion (not a vector
  // instruction before AVX-512): the field's bits placed under 2^52.
  const V biased = bits_as<V>(I((bits >> 52) | std::bit_cast<std::int64_t>(0x1p52))) - 0x1p52;
  V m = bits_as<V>(I((bits & 0x000fffffffffffffLL) | 0x3ff0000000000000LL));
  V e = biased - select<V>(subnormal, 1023.0 + 54.0, splat<V>(1023.0));
  const MaskOf<V> upper = m > kSqrt2;  // m in [sqrt(1/2), sqrt(2))
  m = select<V>(upper, m * 0.5, m);
  e = select<V>(upper, e + 1.0, e);
  const V s = (m - 1.0) / (m + 1.0);
  const V t = s * s, t2 = t * t, t4 = t2 * t2, t8 = t4 * t4;
  // atanh(s) / s = sum s^(2k) / (2k + 1), k = 0..11, by Estrin's scheme in t = s^2.
  const V a0 = 1.0 / 3.0 + t * (1.0 / 5.0), a1 = 1.0 / 7.0 + t * (1.0 / 9.0);
  const V a2 = 1.0 / 11.0 + t * (1.0 / 13.0), a3 = 1.0 / 15.0 + t * (1.0 / 17.0);
  const V a4 = 1.0 / 19.0 + t * (1.0 / 21.0);
  const V b0 = a0 + t2 * a1, b1 = a2 + t2 * a3;
  const V p = (b0 + t4 * b1) + t8 * (a4 + t2 * (1.0 / 23.0));
  const V log_m = 2.0 * s + 2.0 * s * t * p;
  const V result = e * kLn2Hi + (e * kLn2Lo + log_m);
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const V finite_or_inf = select<V>(x == inf, inf, result);
  const V non_negative = select<V>(x == 0.0, -inf, finite_or_inf);
  return select<V>(x >= 0.0, non_negative, splat<V>(nan));
}

/// log(1 + x) for x > -1, accurate for small x: log(u) of u = 1 + x rounded, plus the first-order
/// correction (x - (u - 1)) / u for the rounding of u (Goldberg 1991, "What every computer
/// scientist should know about floating-point arithmetic", ACM Comput. Surv. 23:5, theorem 4).
template <class V>
IMPACT_LANE_INLINE V log1p(V x) {
  const V u = 1.0 + x;
  const V result = log(u) + (x - (u - 1.0)) / u;
  return select<V>(u == std::numeric_limits<double>::infinity(), u, result);
}

/// x^y = exp(y log x) for x > 0 (x = 0 gives exp(-inf y)).
template <class V>
IMPACT_LANE_INLINE V pow(V x, double y) {
  return exp(V(y * log(x)));
}

#undef IMPACT_LANE_INLINE

}  // namespace impact::lane

#pragma GCC diagnostic pop
