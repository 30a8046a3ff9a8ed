// The CPU dispatch of the kernels (common/cpu_dispatch.h): the level found is the CPU's, each
// level calls its own variant, and the names the tests and users give LFEM_CPU_LEVEL are the
// ones it reads. That the variants give the same bits is checked end to end by ctest
// scene_digest_cpu_levels_agree and tests/platforms.sh.
#include <gtest/gtest.h>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "common/cpu_dispatch.h"

namespace lfem {
namespace {

TEST(CpuDispatch, NamesRoundTrip) {
    for (CpuLevel level : {CpuLevel::baseline, CpuLevel::x86_64_v3, CpuLevel::x86_64_v4}) {
        CpuLevel read = level == CpuLevel::baseline ? CpuLevel::x86_64_v4 : CpuLevel::baseline;
        ASSERT_TRUE(cpu_level_from_name(cpu_level_name(level), read)) << cpu_level_name(level);
        EXPECT_EQ(read, level);
    }
    EXPECT_STREQ(cpu_level_name(CpuLevel::x86_64_v3), "x86-64-v3");  // as documented
}

TEST(CpuDispatch, OtherNamesAreRejected) {
    CpuLevel level = CpuLevel::x86_64_v3;
    for (const char* name : {"", "avx2", "x86-64-v5", "Baseline", "x86-64-v3 "})
        EXPECT_FALSE(cpu_level_from_name(name, level)) << name;
    EXPECT_FALSE(cpu_level_from_name(nullptr, level));
    EXPECT_EQ(level, CpuLevel::x86_64_v3);  // untouched
}

#if LFEM_CPU_VARIANTS && defined(__linux__)
// The level the CPU flags of /proc/cpuinfo allow (the kernel clears the AVX and AVX-512 flags
// when it does not save those registers), as GCC defines the levels.
CpuLevel level_from_proc_cpuinfo() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    std::set<std::string> flags;
    while (std::getline(in, line))
        if (line.rfind("flags", 0) == 0) {
            std::istringstream words(line.substr(line.find(':') + 1));
            for (std::string w; words >> w;) flags.insert(w);
            break;
        }
    const auto all = [&](std::initializer_list<const char*> names) {
        for (const char* n : names)
            if (!flags.count(n)) return false;
        return true;
    };
    // LZCNT ("abm") needs nothing of the OS, and some virtual machines' kernels leave it out of
    // the list though the CPU has it: then it is read from CPUID (leaf 0x80000001, ECX bit 5),
    // as the compiler's runtime reads it.
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (!flags.count("abm") && __get_cpuid(0x80000001u, &eax, &ebx, &ecx, &edx) && (ecx & (1u << 5)))
        flags.insert("abm");
    const bool v2 = all({"cx16", "lahf_lm", "popcnt", "pni", "sse4_1", "sse4_2", "ssse3"});
    const bool v3 = v2 && all({"avx", "avx2", "bmi1", "bmi2", "f16c", "fma", "abm", "movbe", "xsave"});
    const bool v4 = v3 && all({"avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"});
    return v4 ? CpuLevel::x86_64_v4 : v3 ? CpuLevel::x86_64_v3 : CpuLevel::baseline;
}
#endif

TEST(CpuDispatch, LevelIsTheCpus) {
#if LFEM_CPU_VARIANTS && defined(__linux__)
    CpuLevel expected = level_from_proc_cpuinfo(), cap;
    if (cpu_level_from_name(std::getenv("LFEM_CPU_LEVEL"), cap) && cap < expected) expected = cap;
    EXPECT_EQ(cpu_level(), expected) << "detected " << cpu_level_name(cpu_level()) << ", /proc/cpuinfo "
                                     << cpu_level_name(level_from_proc_cpuinfo());
#elif !LFEM_CPU_VARIANTS
    EXPECT_EQ(cpu_level(), CpuLevel::baseline);  // nothing else is compiled
#endif
}

double twice(double x) { return 2.0 * x; }

TEST(CpuDispatch, EachLevelCallsItsVariant) {
    using Variants = CpuVariants<&twice>;
    EXPECT_EQ(cpu_variant<&twice>(CpuLevel::baseline), &Variants::baseline);
#if LFEM_CPU_VARIANTS
    EXPECT_EQ(cpu_variant<&twice>(CpuLevel::x86_64_v3), &Variants::x86_64_v3);
    EXPECT_EQ(cpu_variant<&twice>(CpuLevel::x86_64_v4), &Variants::x86_64_v4);
#else
    EXPECT_EQ(cpu_variant<&twice>(CpuLevel::x86_64_v4), &Variants::baseline);
#endif
    // The variants this CPU runs, run.
    for (CpuLevel level : {CpuLevel::baseline, CpuLevel::x86_64_v3, CpuLevel::x86_64_v4}) {
        if (level <= cpu_level()) {
            EXPECT_EQ(cpu_variant<&twice>(level)(1.5), 3.0) << cpu_level_name(level);
        }
    }
}

}  // namespace
}  // namespace lfem
