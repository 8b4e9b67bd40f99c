// How long the core's divide and square-root unit takes per instruction, for one double and
// for two (docs/benchmarks.md, "what did not help"): four independent chains, so the figure
// is the unit's throughput rather than one chain's latency. A multiply row gives the scale.
#include <benchmark/benchmark.h>

#if defined(__SSE2__) && defined(__GNUC__)
#include <emmintrin.h>

namespace {

template <class Op>
void fourChains(benchmark::State& state, Op op) {
  __m128d a = _mm_set1_pd(2.0), b = _mm_set1_pd(3.0), c = _mm_set1_pd(5.0), d = _mm_set1_pd(7.0);
  for (auto _ : state) {
    a = op(a);
    b = op(b);
    c = op(c);
    d = op(d);
    // Keeps the chains alive in their registers (DoNotOptimize would pass them through memory).
    asm volatile("" : "+x"(a), "+x"(b), "+x"(c), "+x"(d));
  }
  benchmark::DoNotOptimize(_mm_add_pd(_mm_add_pd(a, b), _mm_add_pd(c, d)));
  state.SetItemsProcessed(4 * state.iterations());  // instructions
}

const __m128d kNearOne = _mm_set1_pd(1.0000001);  // keeps the chains' values finite and normal

void BM_SqrtOneDouble(benchmark::State& s) { fourChains(s, [](__m128d x) { return _mm_sqrt_sd(x, x); }); }
void BM_SqrtTwoDoubles(benchmark::State& s) { fourChains(s, [](__m128d x) { return _mm_sqrt_pd(x); }); }
void BM_DivideOneDouble(benchmark::State& s) { fourChains(s, [](__m128d x) { return _mm_div_sd(x, kNearOne); }); }
void BM_DivideTwoDoubles(benchmark::State& s) { fourChains(s, [](__m128d x) { return _mm_div_pd(x, kNearOne); }); }
void BM_MultiplyTwoDoubles(benchmark::State& s) { fourChains(s, [](__m128d x) { return _mm_mul_pd(x, kNearOne); }); }

}  // namespace

BENCHMARK(BM_SqrtOneDouble);
BENCHMARK(BM_SqrtTwoDoubles);
BENCHMARK(BM_DivideOneDouble);
BENCHMARK(BM_DivideTwoDoubles);
BENCHMARK(BM_MultiplyTwoDoubles);
#endif

BENCHMARK_MAIN();
