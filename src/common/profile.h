// Per-phase timing of the step: one steady_clock reading at the start and one at the end of a
// phase, per sub-step, never per element, so profiling costs nothing measurable. The shim
// copies Profile into the public lfem_profile, field by field.
#pragma once

#include <chrono>
#include <cstdint>
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace lfem {

// The wall time spent in a phase and how often it ran.
struct PhaseTime {
    double seconds = 0;
    uint64_t calls = 0;
};

// Where the step spends its time (the phases of lfem_profile, which documents each).
struct Profile {
    uint64_t substeps = 0;
    PhaseTime internal_forces, predictor, kinematic_motion, broad_phase, narrow_phase, shape_queries;
    uint64_t shape_tests = 0, ccd_queries = 0;  // point queries of shapes; of those, by libccd
    PhaseTime normal_solve, friction, global_rotation, commit;
    uint64_t candidate_searches = 0;  // contact's searches for candidate faces
    uint64_t contact_sweeps = 0;      // the slowest group's sweeps per sub-step, summed
    uint64_t constraint_updates = 0;  // one constraint updated in one sweep, summed
};

// Adds the time from construction to destruction to `phase`, and `calls` to its count.
class PhaseTimer {
public:
    // An inactive timer (active = false) reads no clock and adds nothing.
    explicit PhaseTimer(PhaseTime& phase, uint64_t calls = 1, bool active = true)
        : phase_(phase), calls_(calls), stopped_(!active) {
        if (active) start_ = std::chrono::steady_clock::now();
    }
    ~PhaseTimer() { stop(); }
    // Ends the measurement before the end of the scope (once; later calls do nothing).
    void stop() {
        if (stopped_) return;
        stopped_ = true;
        const std::chrono::duration<double> d = std::chrono::steady_clock::now() - start_;
        phase_.seconds += d.count();
        phase_.calls += calls_;
    }
    // The number of calls may be known only at the end (bodies actually processed).
    void set_calls(uint64_t calls) { calls_ = calls; }
    PhaseTimer(const PhaseTimer&) = delete;
    PhaseTimer& operator=(const PhaseTimer&) = delete;

private:
    PhaseTime& phase_;
    uint64_t calls_;
    bool stopped_;
    std::chrono::steady_clock::time_point start_;
};

// Seconds from `from` to now.
inline double seconds_since(std::chrono::steady_clock::time_point from) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

// A count of ticks of a steady counter, for the CPU time each phase took inside a round of the
// pool (share_wall_time below uses only their ratios): the time-stamp counter on x86-64, the
// virtual counter on ARM64, the steady clock elsewhere. A solve reads it twice per contact group
// and sweep, a round twice per body: the steady clock's reading, through the kernel's clock
// page, cost 3 to 4 % of a frame of 32 small cubes on a virtual machine.
inline uint64_t ticks() {
#if defined(__x86_64__) || defined(__i386__)
    return __rdtsc();
#elif defined(__aarch64__)
    uint64_t t;
    asm volatile("mrs %0, cntvct_el0" : "=r"(t));
    return t;
#else
    return uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                        std::chrono::steady_clock::now().time_since_epoch()).count());
#endif
}

// Phases that ran interleaved on several threads (a round of the pool, groups of the contact
// solve): the round's wall time shared out among them by the CPU time each took in it (in any
// unit: ticks). All of it to the first phase when no CPU time was measured.
inline void share_wall_time(double wall, const double* cpu, PhaseTime* const* phases, int n) {
    double total = 0.0;
    for (int k = 0; k < n; ++k) total += cpu[k];
    if (!(total > 0.0)) {
        phases[0]->seconds += wall;
        return;
    }
    for (int k = 0; k < n; ++k) phases[k]->seconds += wall * cpu[k] / total;
}

}  // namespace lfem
