// The machine's limits for a roofline (docs/performance.md, "Machine limits"): memory bandwidth
// from STREAM-like kernels (McCalpin's copy and triad on arrays far larger than the last-level
// cache, OpenMP over the threads) and the double-precision FMA peak per instruction set (SSE2, the
// build's default; AVX2 + FMA and AVX-512 through target attributes, each run only when the CPU
// reports it). Benchmark, never a test: best of 5 repeats, printed as CSV.
//   build/bin/machine_probe [--threads N] [--megabytes M]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Bytes moved per element: copy reads b and writes a (16, plus the write-allocate read the
// hardware may add, which STREAM does not count either); triad reads b, c and writes a (24).
double copy_gbs(std::vector<double>& a, const std::vector<double>& b, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.size());
  double best = 1e300;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t i = 0; i < n; ++i) a[i] = b[i];
    best = std::min(best, seconds_since(t0));
  }
  return 16.0 * double(n) / best / 1e9;
}

double triad_gbs(std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                 int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.size());
  const double s = 3.0;
  double best = 1e300;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    best = std::min(best, seconds_since(t0));
  }
  return 24.0 * double(n) / best / 1e9;
}

// FMA throughput: 16 independent accumulator chains of width W hide the FMA latency; each
// iteration does 16 W fused multiply-adds = 32 W flops. The compiler vectorises the inner loops
// for the target of each function (checked: the loop body is 16 vfmadd per iteration).
constexpr int kChains = 16;
constexpr long kIterations = 20'000'000;

volatile double g_start = 1.0, g_x = 0.999999999, g_y = 1e-9;  // opaque: no constant folding

template <int W>
[[gnu::always_inline]] inline double fma_kernel_body() {
  double acc[kChains][W];
  const double start = g_start, x = g_x, y = g_y;
  for (int c = 0; c < kChains; ++c)
    for (int w = 0; w < W; ++w) acc[c][w] = start + 1e-9 * (c * W + w);
  for (long i = 0; i < kIterations; ++i)
    for (int c = 0; c < kChains; ++c)
      for (int w = 0; w < W; ++w) acc[c][w] = acc[c][w] * x + y;
  double sum = 0.0;
  for (int c = 0; c < kChains; ++c)
    for (int w = 0; w < W; ++w) sum += acc[c][w];
  return sum;
}

double fma_sse2() {
  return fma_kernel_body<2>();
}
__attribute__((target("avx2,fma"))) double fma_avx2() {
  return fma_kernel_body<4>();
}
__attribute__((target("avx512f"))) double fma_avx512() {
  return fma_kernel_body<8>();
}

// GFLOP/s on `threads` threads (each runs the kernel; the sum keeps the result alive).
double peak_gflops(double (*kernel)(), int width, int threads) {
  double best = 1e300, sink = 0.0;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads) reduction(+ : sink)
    sink += kernel();
    best = std::min(best, seconds_since(t0));
  }
  if (sink == 42.0) std::puts("");  // never: keeps the kernels from being optimised away
  return 2.0 * kChains * width * double(kIterations) * threads / best / 1e9;
}

}  // namespace

int main(int argc, char** argv) {
  int threads = omp_get_max_threads();
  double megabytes = 800.0;  // per array: far beyond a 32 MB last-level cache
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--megabytes") && i + 1 < argc) {
      megabytes = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: machine_probe [--threads N] [--megabytes M]\n");
      return 1;
    }
  }
  const std::size_t n = static_cast<std::size_t>(megabytes * 1e6 / sizeof(double));
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  std::printf("quantity,threads,value,unit\n");
  for (const int t : {1, threads}) {
    std::printf("stream_copy,%d,%.2f,GB/s\n", t, copy_gbs(a, b, t));
    std::printf("stream_triad,%d,%.2f,GB/s\n", t, triad_gbs(a, b, c, t));
    std::printf("fma_peak_sse2,%d,%.2f,GFLOP/s\n", t, peak_gflops(fma_sse2, 2, t));
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      std::printf("fma_peak_avx2,%d,%.2f,GFLOP/s\n", t, peak_gflops(fma_avx2, 4, t));
    if (__builtin_cpu_supports("avx512f"))
      std::printf("fma_peak_avx512,%d,%.2f,GFLOP/s\n", t, peak_gflops(fma_avx512, 8, t));
    if (t == threads) break;
  }
  return 0;
}
