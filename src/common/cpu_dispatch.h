// CPU dispatch for the hot kernels: a kernel is compiled in the same file for a few
// instruction-set levels, and each loop picks the variant this CPU runs through a plain
// function pointer. No ifunc (ELF only, and run before a sanitizer's runtime is set up), no
// per-target build: the same source builds for Linux, Windows (MinGW) and ARM64, and under the
// sanitizers. The level is found once per process (cpu_level, called by the world's
// constructor), so the choice costs a table look-up per loop.
//
// A kernel joins the dispatch in three steps (src/fem/internal_forces.cpp is the example):
//   1. its body is a function marked LFEM_INLINE, and so are the helpers it calls in
//      its hot loop, so that each variant compiles the whole body for its instruction set;
//   2. its loop calls it through  const auto fn = cpu_variant<&body>(cpu_level());
//   3. its .cpp file is built with -ffp-contract=off (CMakeLists.txt does so for all of src/),
//      so that no variant fuses a*b+c into one rounding: every variant gives the same bits.
#pragma once

namespace lfem {

// The instruction-set levels a kernel is compiled for, in increasing order. x86-64-v3 is
// AVX2 with FMA (Haswell, Zen), x86-64-v4 adds AVX-512 F/BW/CD/DQ/VL (Skylake-X, Zen 4).
// Elsewhere (ARM64: NEON is part of the base instruction set, which the compiler vectorises
// for) and with compilers other than GCC there is only the baseline.
enum class CpuLevel : int { baseline = 0, x86_64_v3 = 1, x86_64_v4 = 2 };

// The best level this CPU (and its operating system, which must save the wide registers) runs,
// detected on the first call and kept for the process; thread-safe. The environment variable
// LFEM_CPU_LEVEL (baseline, x86-64-v3 or x86-64-v4) lowers it, never raises it: the tests use
// it to compare the variants on one machine. An unknown value is ignored.
CpuLevel cpu_level();

// "baseline", "x86-64-v3", "x86-64-v4".
const char* cpu_level_name(CpuLevel level);
// The level of a name as above; false (and level untouched) for any other string or null.
bool cpu_level_from_name(const char* name, CpuLevel& level);

}  // namespace lfem

#if defined(__GNUC__) && !defined(__clang__)
#define LFEM_INLINE __attribute__((always_inline)) inline
#else
#define LFEM_INLINE inline
#endif

// GCC on x86-64, whatever the object format. clang 14 (the fuzz build) lacks the ISA-level
// names of __builtin_cpu_supports; it builds the baseline only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LFEM_CPU_VARIANTS 1
#define LFEM_TARGET_X86_64_V3 __attribute__((target("arch=x86-64-v3")))
#define LFEM_TARGET_X86_64_V4 __attribute__((target("arch=x86-64-v4")))
#else
#define LFEM_CPU_VARIANTS 0
#endif

namespace lfem {

template <auto body>
struct CpuVariants;

// The variants of the kernel function `body`: each is a function of its own, compiled for its
// level, with body's code inlined into it (body and its helpers are LFEM_INLINE).
template <class R, class... Args, R (*body)(Args...)>
struct CpuVariants<body> {
    using Fn = R (*)(Args...);
    static R baseline(Args... args) { return body(args...); }
#if LFEM_CPU_VARIANTS
    LFEM_TARGET_X86_64_V3 static R x86_64_v3(Args... args) { return body(args...); }
    LFEM_TARGET_X86_64_V4 static R x86_64_v4(Args... args) { return body(args...); }
#endif
    static Fn choose(CpuLevel level) {
#if LFEM_CPU_VARIANTS
        if (level == CpuLevel::x86_64_v4) return &x86_64_v4;
        if (level == CpuLevel::x86_64_v3) return &x86_64_v3;
#endif
        (void)level;
        return &baseline;
    }
};

// The variant of `body` to call at `level` (cpu_level() in a library loop).
template <auto body>
typename CpuVariants<body>::Fn cpu_variant(CpuLevel level) {
    return CpuVariants<body>::choose(level);
}

}  // namespace lfem
