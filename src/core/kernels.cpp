// Chooses the kernels once, by what the CPU running the library supports. The one place that
// knows which instruction sets exist: VERVE_KERNELS_AVX2 is defined by the build when it compiles
// kernels_avx2.cpp (x86-64 with GCC or Clang).
#include "core/kernels.hpp"

namespace verve::core {

#if defined(VERVE_KERNELS_AVX2)
const Kernels& avx2KernelTable();  // kernels_avx2.cpp

const Kernels* avx2Kernels() {
    // Also checks that the OS saves the 256-bit registers (libgcc reads XCR0).
    static const bool supported = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return supported ? &avx2KernelTable() : nullptr;
}
#else
const Kernels* avx2Kernels() { return nullptr; }
#endif

const Kernels& kernels() {
    static const Kernels& best = avx2Kernels() ? *avx2Kernels() : portableKernels();
    return best;
}

}  // namespace verve::core
