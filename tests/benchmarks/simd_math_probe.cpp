// What a vector pow/log gives the Johnson-Cook flow stress (docs/notes/performance_history.md,
// "a vector pow and log"): the roofline found the stress update bound by the latency of one pow
// and one log per radial-return step, so a batched update needs them for W lanes at once.
// Debian's C library ships them (libmvec, glibc >= 2.22: _ZGVdN4vv_pow / _ZGVdN4v_log for AVX2,
// _ZGVeN8vv_pow / _ZGVeN8v_log for AVX-512, the vector-function ABI names). This probe evaluates
//   sigma_y = (A + B eps^n)(1 + C ln(rate))(1 - T*^m)      (Johnson & Cook 1983)
// on 65 536 points with the scalar libm calls and with the 4- and 8-lane library calls (each run
// only when the CPU reports the instruction set), and prints ns per point (best of 5) and the
// largest difference from the scalar result in units of the scalar value's last place (ulp).
// Benchmark, never a test.   build/bin/simd_math_probe
#include <immintrin.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

extern "C" {
__attribute__((target("avx2,fma"))) __m256d _ZGVdN4vv_pow(__m256d, __m256d);
__attribute__((target("avx2,fma"))) __m256d _ZGVdN4v_log(__m256d);
__attribute__((target("avx512f"))) __m512d _ZGVeN8vv_pow(__m512d, __m512d);
__attribute__((target("avx512f"))) __m512d _ZGVeN8v_log(__m512d);
}

namespace {

// 6061-T6, the report's Table 1 set [Pa, -].
constexpr double kA = 324e6, kB = 114e6, kN = 0.42, kC = 0.002, kM = 1.34;

struct Points {
  std::vector<double> eps, rate, t_star, out;
};

void scalar(Points& p) {
  for (std::size_t i = 0; i < p.eps.size(); ++i) {
    p.out[i] = (kA + kB * std::pow(p.eps[i], kN)) * (1.0 + kC * std::log(p.rate[i])) *
               (1.0 - std::pow(p.t_star[i], kM));
  }
}

__attribute__((target("avx2,fma"))) void lanes4(Points& p) {
  const __m256d a = _mm256_set1_pd(kA), b = _mm256_set1_pd(kB), n = _mm256_set1_pd(kN);
  const __m256d c = _mm256_set1_pd(kC), m = _mm256_set1_pd(kM), one = _mm256_set1_pd(1.0);
  for (std::size_t i = 0; i < p.eps.size(); i += 4) {
    const __m256d e = _mm256_loadu_pd(&p.eps[i]);
    const __m256d r = _mm256_loadu_pd(&p.rate[i]);
    const __m256d t = _mm256_loadu_pd(&p.t_star[i]);
    const __m256d hardening = _mm256_fmadd_pd(b, _ZGVdN4vv_pow(e, n), a);
    const __m256d rate_factor = _mm256_fmadd_pd(c, _ZGVdN4v_log(r), one);
    const __m256d thermal = _mm256_sub_pd(one, _ZGVdN4vv_pow(t, m));
    _mm256_storeu_pd(&p.out[i], _mm256_mul_pd(_mm256_mul_pd(hardening, rate_factor), thermal));
  }
}

__attribute__((target("avx512f"))) void lanes8(Points& p) {
  const __m512d a = _mm512_set1_pd(kA), b = _mm512_set1_pd(kB), n = _mm512_set1_pd(kN);
  const __m512d c = _mm512_set1_pd(kC), m = _mm512_set1_pd(kM), one = _mm512_set1_pd(1.0);
  for (std::size_t i = 0; i < p.eps.size(); i += 8) {
    const __m512d e = _mm512_loadu_pd(&p.eps[i]);
    const __m512d r = _mm512_loadu_pd(&p.rate[i]);
    const __m512d t = _mm512_loadu_pd(&p.t_star[i]);
    const __m512d hardening = _mm512_fmadd_pd(b, _ZGVeN8vv_pow(e, n), a);
    const __m512d rate_factor = _mm512_fmadd_pd(c, _ZGVeN8v_log(r), one);
    const __m512d thermal = _mm512_sub_pd(one, _ZGVeN8vv_pow(t, m));
    _mm512_storeu_pd(&p.out[i], _mm512_mul_pd(_mm512_mul_pd(hardening, rate_factor), thermal));
  }
}

template <class Kernel>
double ns_per_point(Points& p, Kernel kernel) {
  double best = 1e300;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int pass = 0; pass < 20; ++pass) kernel(p);
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best / 20.0 / double(p.eps.size()) * 1e9;
}

double worst_ulp(const std::vector<double>& a, const std::vector<double>& reference) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double ulp = std::nextafter(reference[i], INFINITY) - reference[i];
    worst = std::max(worst, std::abs(a[i] - reference[i]) / ulp);
  }
  return worst;
}

}  // namespace

int main() {
  const std::size_t n = 1 << 16;
  Points p;
  p.eps.resize(n);
  p.rate.resize(n);
  p.t_star.resize(n);
  p.out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {  // the ranges of an impact: eps to 2, rates to 1e6 /s
    const double u = (double(i) + 0.5) / double(n);
    p.eps[i] = 1e-4 + 2.0 * u;
    p.rate[i] = std::pow(10.0, 6.0 * std::fmod(7.0 * u, 1.0));
    p.t_star[i] = 0.02 + 0.9 * std::fmod(13.0 * u, 1.0);
  }
  const double t_scalar = ns_per_point(p, scalar);
  const std::vector<double> reference = p.out;
  std::printf("quantity,value,unit\n");
  std::printf("jc_flow_stress_scalar,%.2f,ns/point\n", t_scalar);
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    const double t = ns_per_point(p, lanes4);
    std::printf("jc_flow_stress_avx2_4_lanes,%.2f,ns/point\n", t);
    std::printf("jc_flow_stress_avx2_worst_difference,%.1f,ulp\n", worst_ulp(p.out, reference));
  }
  if (__builtin_cpu_supports("avx512f")) {
    const double t = ns_per_point(p, lanes8);
    std::printf("jc_flow_stress_avx512_8_lanes,%.2f,ns/point\n", t);
    std::printf("jc_flow_stress_avx512_worst_difference,%.1f,ulp\n", worst_ulp(p.out, reference));
  }
  return 0;
}
