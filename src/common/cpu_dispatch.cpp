#include "common/cpu_dispatch.h"

#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace lfem {
namespace {

// What the hardware and the operating system allow. GCC's __builtin_cpu_supports knows the
// ISA levels themselves (every feature the compiler may use at that level, and the OS's
// support for the AVX and AVX-512 registers through XGETBV).
CpuLevel detect_cpu_level() {
#if LFEM_CPU_VARIANTS
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v4")) return CpuLevel::x86_64_v4;
    if (__builtin_cpu_supports("x86-64-v3")) return CpuLevel::x86_64_v3;
#endif
    return CpuLevel::baseline;
}

CpuLevel resolve_cpu_level() {
    CpuLevel level = detect_cpu_level();
    CpuLevel cap;
    if (cpu_level_from_name(std::getenv("LFEM_CPU_LEVEL"), cap) && cap < level) level = cap;
    return level;
}

}  // namespace

CpuLevel cpu_level() {
    static const CpuLevel level = resolve_cpu_level();
    return level;
}

const char* cpu_level_name(CpuLevel level) {
    switch (level) {
        case CpuLevel::x86_64_v4: return "x86-64-v4";
        case CpuLevel::x86_64_v3: return "x86-64-v3";
        default: return "baseline";
    }
}

bool cpu_level_from_name(const char* name, CpuLevel& level) {
    if (!name) return false;
    for (CpuLevel l : {CpuLevel::baseline, CpuLevel::x86_64_v3, CpuLevel::x86_64_v4}) {
        if (std::strcmp(name, cpu_level_name(l)) == 0) {
            level = l;
            return true;
        }
    }
    return false;
}

}  // namespace lfem
