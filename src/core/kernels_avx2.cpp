// Kernels for x86-64 CPUs with AVX2 and FMA (compiled with -mavx2 -mfma; kernels.cpp calls them
// only on such a CPU). Intrinsics and raw pointers only: a template from a shared header may be
// instantiated here only with a type of this file's own (kernel_loops.hpp), or the linker could hand
// this file's AVX2 copy of it to the rest of the library.
#include <immintrin.h>

#include "core/kernel_loops.hpp"
#include "core/kernels.hpp"

namespace verve::core {
namespace {

// exp(x) for x <= 0 (Cephes expf): x = n ln2 + r, |r| <= ln2 / 2, e^r by a degree-6 polynomial,
// 2^n put in the exponent bits. Relative error ~1e-7, that of std::exp in float.
__m256 expNonPositive(__m256 x) {
    x = _mm256_max_ps(x, _mm256_set1_ps(-87.0f));  // e^-87 is still a normal float
    const __m256 n = _mm256_round_ps(_mm256_mul_ps(x, _mm256_set1_ps(1.44269504088896341f)),
                                     _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    x = _mm256_fnmadd_ps(n, _mm256_set1_ps(0.693359375f), x);  // ln 2 in two parts, exact first
    x = _mm256_fnmadd_ps(n, _mm256_set1_ps(-2.12194440e-4f), x);
    __m256 y = _mm256_set1_ps(1.9875691500e-4f);
    y = _mm256_fmadd_ps(y, x, _mm256_set1_ps(1.3981999507e-3f));
    y = _mm256_fmadd_ps(y, x, _mm256_set1_ps(8.3334519073e-3f));
    y = _mm256_fmadd_ps(y, x, _mm256_set1_ps(4.1665795894e-2f));
    y = _mm256_fmadd_ps(y, x, _mm256_set1_ps(1.6666665459e-1f));
    y = _mm256_fmadd_ps(y, x, _mm256_set1_ps(5.0000001201e-1f));
    y = _mm256_fmadd_ps(y, _mm256_mul_ps(x, x), x);
    y = _mm256_add_ps(y, _mm256_set1_ps(1.0f));
    const __m256i pow2n = _mm256_slli_epi32(_mm256_add_epi32(_mm256_cvtps_epi32(n), _mm256_set1_epi32(127)), 23);
    return _mm256_mul_ps(y, _mm256_castsi256_ps(pow2n));
}

// For each 8-bit mask, the lane numbers of its set bits first: a left-packing permutation.
struct PackTable {
    std::uint32_t lanes[256][8];
    std::uint8_t count[256];
};
constexpr PackTable makePackTable() {
    PackTable t{};
    for (std::uint32_t mask = 0; mask < 256; ++mask) {
        std::uint32_t n = 0;
        for (std::uint32_t l = 0; l < 8; ++l) {
            if (mask & (1u << l)) t.lanes[mask][n++] = l;
        }
        t.count[mask] = static_cast<std::uint8_t>(n);
    }
    return t;
}
constexpr PackTable kPack = makePackTable();

// The scan over D dimensions, none of them circular, known at compile time (the input's
// broadcasts then stay in registers); D 0: p.dims, any circular. The same operations in the same
// order either way.
template <std::uint32_t D>
std::size_t scanBlocks(const ScanParams& p, const float* centres, const std::uint32_t* features, std::uint32_t firstFeature,
                       std::size_t count, ActiveFeature* out, bool& nearOne) {
    static_assert(kScanLanes == 8, "one block is one AVX register");
    const std::uint32_t dims = D != 0 ? D : p.dims;
    const __m256 cutoff2 = _mm256_set1_ps(p.cutoff2), width2 = _mm256_set1_ps(p.width2);
    const __m256 scale = _mm256_set1_ps(p.negInv2Sigma2);
    const __m256 one = _mm256_set1_ps(1.0f), minusOne = _mm256_set1_ps(-1.0f), two = _mm256_set1_ps(2.0f);
    __m256 point[D != 0 ? D : 1];
    for (std::uint32_t d = 0; d < D; ++d) point[d] = _mm256_set1_ps(p.point[d]);
    std::size_t n = 0;
    int near = 0;
    const float* block = centres;
    for (std::size_t first = 0; first < count; first += kScanLanes) {
        askAhead(p.ahead, kAheadPerBlock);
        __m256 d2 = _mm256_setzero_ps();
        for (std::uint32_t d = 0; d < dims; ++d, block += kScanLanes) {
            __m256 diff = _mm256_sub_ps(D != 0 ? point[d] : _mm256_set1_ps(p.point[d]), _mm256_loadu_ps(block));
            if (D == 0 && p.circular[d]) {  // the shorter way round: -1 and 1 meet
                const __m256 down = _mm256_and_ps(_mm256_cmp_ps(diff, one, _CMP_GT_OQ), two);
                const __m256 up = _mm256_and_ps(_mm256_cmp_ps(diff, minusOne, _CMP_LT_OQ), two);
                diff = _mm256_add_ps(_mm256_sub_ps(diff, down), up);
            }
            d2 = _mm256_fmadd_ps(diff, diff, d2);
        }
        const __m256 activation = expNonPositive(_mm256_mul_ps(d2, scale));
        const std::size_t remaining = count - first;
        const int valid = remaining >= kScanLanes ? 0xff : (1 << remaining) - 1;
        const __m256i laneNumbers = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        const __m256i index =
            features == nullptr
                ? _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(firstFeature + first)), laneNumbers)
            : remaining >= kScanLanes
                ? _mm256_loadu_si256(reinterpret_cast<const __m256i*>(features + first))
                : _mm256_maskload_epi32(reinterpret_cast<const int*>(features + first),
                                        _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(remaining)), laneNumbers));
        const int keep = _mm256_movemask_ps(_mm256_cmp_ps(d2, cutoff2, _CMP_LT_OQ)) & valid;
        near |= _mm256_movemask_ps(_mm256_cmp_ps(d2, width2, _CMP_LT_OQ)) & valid;
        // Left-pack the kept lanes, then interleave (index, activation) pairs: 8 ActiveFeatures.
        const __m256i perm = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kPack.lanes[keep]));
        const __m256 packedIndex = _mm256_castsi256_ps(_mm256_permutevar8x32_epi32(index, perm));
        const __m256 packedActivation = _mm256_permutevar8x32_ps(activation, perm);
        const __m256 lo = _mm256_unpacklo_ps(packedIndex, packedActivation);  // pairs 0 1 | 4 5
        const __m256 hi = _mm256_unpackhi_ps(packedIndex, packedActivation);  // pairs 2 3 | 6 7
        float* dst = reinterpret_cast<float*>(out + n);
        _mm256_storeu_ps(dst, _mm256_permute2f128_ps(lo, hi, 0x20));
        _mm256_storeu_ps(dst + 8, _mm256_permute2f128_ps(lo, hi, 0x31));
        n += kPack.count[keep];
    }
    nearOne |= near != 0;
    return n;
}

std::size_t scan(const ScanParams& p, const float* centres, const std::uint32_t* features, std::uint32_t firstFeature,
                 std::size_t count, ActiveFeature* out, bool& nearOne) {
    bool circular = false;
    for (std::uint32_t d = 0; d < p.dims; ++d) circular |= p.circular[d] != 0;
    if (!circular) {
        switch (p.dims) {
            case 1: return scanBlocks<1>(p, centres, features, firstFeature, count, out, nearOne);
            case 2: return scanBlocks<2>(p, centres, features, firstFeature, count, out, nearOne);
            case 3: return scanBlocks<3>(p, centres, features, firstFeature, count, out, nearOne);
            case 4: return scanBlocks<4>(p, centres, features, firstFeature, count, out, nearOne);
            default: break;
        }
    }
    return scanBlocks<0>(p, centres, features, firstFeature, count, out, nearOne);
}

void boxesWithin(const ScanParams& p, const float* boxes, std::size_t count, float reach2, std::uint8_t* masks) {
    const __m256 zero = _mm256_setzero_ps(), two = _mm256_set1_ps(2.0f), reach = _mm256_set1_ps(reach2);
    for (std::size_t first = 0; first < count; first += kScanLanes, ++masks) {
        __m256 d2 = zero;
        for (std::uint32_t d = 0; d < p.dims; ++d, boxes += 2 * kScanLanes) {
            const __m256 lo = _mm256_loadu_ps(boxes), hi = _mm256_loadu_ps(boxes + kScanLanes);
            const __m256 x = _mm256_set1_ps(p.point[d]);
            auto gap = [&](__m256 at) { return _mm256_max_ps(_mm256_max_ps(_mm256_sub_ps(lo, at), _mm256_sub_ps(at, hi)), zero); };
            __m256 g = gap(x);
            if (p.circular[d]) g = _mm256_min_ps(g, _mm256_min_ps(gap(_mm256_sub_ps(x, two)), gap(_mm256_add_ps(x, two))));
            d2 = _mm256_fmadd_ps(g, g, d2);
        }
        const std::size_t remaining = count - first;
        const int valid = remaining >= kScanLanes ? 0xff : (1 << remaining) - 1;
        *masks = static_cast<std::uint8_t>(_mm256_movemask_ps(_mm256_cmp_ps(d2, reach, _CMP_LE_OQ)) & valid);
    }
}

void rowSums(const float* weights, std::uint32_t stride, const ActiveFeature* phi, std::size_t n,
             std::uint32_t columns, float* sums, PrefetchQueue* ahead) {
    if (columns == 1) {
        // One column (a value): the same four chains as below in scalar registers, with no mask
        // to load through. Lane 0 of the 8-wide sums, bit for bit.
        __m128 acc[4] = {_mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps()};
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4) {
            askAhead(ahead, kAheadPerBlock);
            for (std::size_t j = 0; j < 4; ++j) {
                const __m128 w = _mm_load_ss(weights + std::size_t(phi[i + j].index) * stride);
                acc[j] = _mm_fmadd_ss(w, _mm_set_ss(phi[i + j].activation), acc[j]);
            }
        }
        for (; i < n; ++i) {
            const __m128 w = _mm_load_ss(weights + std::size_t(phi[i].index) * stride);
            acc[0] = _mm_fmadd_ss(w, _mm_set_ss(phi[i].activation), acc[0]);
        }
        _mm_store_ss(sums, _mm_add_ss(_mm_add_ss(acc[0], acc[1]), _mm_add_ss(acc[2], acc[3])));
        return;
    }
    const __m256i laneNumbers = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (std::uint32_t c = 0; c < columns; c += 8) {
        // Up to 8 columns per pass; a masked load never reads past a row's last column.
        const __m256i mask = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(columns - c)), laneNumbers);
        // Four accumulators: an FMA's latency is four adds long.
        __m256 acc[4] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4) {
            askAhead(ahead, kAheadPerBlock);
            for (std::size_t j = 0; j < 4; ++j) {
                const __m256 w = _mm256_maskload_ps(weights + (std::size_t(phi[i + j].index) * stride + c), mask);
                acc[j] = _mm256_fmadd_ps(w, _mm256_set1_ps(phi[i + j].activation), acc[j]);
            }
        }
        for (; i < n; ++i) {
            const __m256 w = _mm256_maskload_ps(weights + (std::size_t(phi[i].index) * stride + c), mask);
            acc[0] = _mm256_fmadd_ps(w, _mm256_set1_ps(phi[i].activation), acc[0]);
        }
        _mm256_maskstore_ps(sums + c, mask, _mm256_add_ps(_mm256_add_ps(acc[0], acc[1]), _mm256_add_ps(acc[2], acc[3])));
    }
}

// w += step * e, then e *= scale, for 4 trace components.
struct Quad4 {
    static void train(float* w, float* e, const float* step, float scale) {
        const __m128 ek = _mm_loadu_ps(e);
        _mm_storeu_ps(w, _mm_fmadd_ps(_mm_loadu_ps(step), ek, _mm_loadu_ps(w)));
        _mm_storeu_ps(e, _mm_mul_ps(ek, _mm_set1_ps(scale)));
    }
    // The same, each weight then within [lo, hi] as std::clamp puts it, min(max(w, lo), hi):
    // max(lo, w) is lo > w ? lo : w, and min(hi, t) is hi < t ? hi : t, as std::max and std::min.
    static void trainClamped(float* w, float* e, const float* step, float scale, const float* lo, const float* hi) {
        const __m128 ek = _mm_loadu_ps(e);
        const __m128 moved = _mm_fmadd_ps(_mm_loadu_ps(step), ek, _mm_loadu_ps(w));
        _mm_storeu_ps(w, _mm_min_ps(_mm_loadu_ps(hi), _mm_max_ps(_mm_loadu_ps(lo), moved)));
        _mm_storeu_ps(e, _mm_mul_ps(ek, _mm_set1_ps(scale)));
    }
};

// For each 4-bit mask, the 32-bit lane numbers that left-pack its 64-bit elements (one
// ActiveFeature each), and how many there are.
struct PairPackTable {
    std::uint32_t lanes[16][8];
    std::uint8_t count[16];
};
constexpr PairPackTable makePairPackTable() {
    PairPackTable t{};
    for (std::uint32_t mask = 0; mask < 16; ++mask) {
        std::uint32_t n = 0;
        for (std::uint32_t p = 0; p < 4; ++p) {
            if (mask & (1u << p)) {
                t.lanes[mask][2 * n] = 2 * p;
                t.lanes[mask][2 * n + 1] = 2 * p + 1;
                ++n;
            }
        }
        t.count[mask] = static_cast<std::uint8_t>(n);
    }
    return t;
}
constexpr PairPackTable kPairPack = makePairPackTable();

// Four features per register ([index, activation] pairs): both tests, one mask per pair, then a
// left-pack. Each store writes 4 features at out + written <= the first of them, so never past
// out[n - 1].
std::size_t strongFeatures(const ActiveFeature* phi, std::size_t n, float threshold, std::uint32_t below, ActiveFeature* out) {
    static_assert(sizeof(ActiveFeature) == 8, "an [index, activation] pair");
    const __m256 atLeast = _mm256_set1_ps(threshold);
    const __m256i sign = _mm256_set1_epi32(INT32_MIN);  // unsigned order as signed: flip the top bit
    const __m256i limit = _mm256_xor_si256(_mm256_set1_epi32(static_cast<int>(below)), sign);
    std::size_t written = 0, i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m256 pairs = _mm256_loadu_ps(reinterpret_cast<const float*>(phi + i));
        const __m256i strong = _mm256_castps_si256(_mm256_cmp_ps(pairs, atLeast, _CMP_GE_OQ));  // odd lanes: activations
        const __m256i inRange = _mm256_cmpgt_epi32(limit, _mm256_xor_si256(_mm256_castps_si256(pairs), sign));  // even: indices
        // A pair's index test moved up to its activation's lane: the pair's sign bit is both tests.
        const __m256i both = _mm256_and_si256(strong, _mm256_slli_epi64(inRange, 32));
        const int mask = _mm256_movemask_pd(_mm256_castsi256_pd(both));
        const __m256i perm = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kPairPack.lanes[mask]));
        _mm256_storeu_ps(reinterpret_cast<float*>(out + written), _mm256_permutevar8x32_ps(pairs, perm));
        written += kPairPack.count[mask];
    }
    return strongFeaturesFrom<Quad4>(phi, i, n, threshold, below, out, written);
}

}  // namespace

const Kernels& avx2KernelTable() {
    static const Kernels k{"avx2+fma", scan, boxesWithin, rowSums, strongFeatures, trainDecay<Quad4>};
    return k;
}

}  // namespace verve::core
