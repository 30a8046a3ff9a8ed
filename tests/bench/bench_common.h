/* What the benchmarks in tests/bench share: a wall clock, the process's memory figures and the
 * check of every lfem call.
 * Header only (static inline), C99 + POSIX. */
#ifndef LFEM_BENCH_COMMON_H
#define LFEM_BENCH_COMMON_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "lfem.h"

/* Seconds on the monotonic clock: wall time, immune to clock changes. */
static inline double bench_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A field of /proc/self/status in bytes ("VmHWM:" the peak resident set, "VmRSS:" the current
 * one), or -1 when it cannot be read. */
static inline double bench_status_bytes(const char* field) {
    FILE* f = fopen("/proc/self/status", "r");
    char line[256];
    double kb = -1.0;
    if (!f) return -1.0;
    while (fgets(line, sizeof line, f))
        if (strncmp(line, field, strlen(field)) == 0) kb = atof(line + strlen(field));
    fclose(f);
    return kb * 1024.0;
}

/* Every lfem call is checked: on failure, say which call and why, and jump to the function's
 * `fail:` label, which frees what was made and returns -1. */
#define BENCH_TRY(call)                                                          \
    do {                                                                         \
        lfem_status s_ = (call);                                                 \
        if (s_ != LFEM_OK) {                                                     \
            fprintf(stderr, "%s failed: %s\n", #call, lfem_last_error());        \
            goto fail;                                                           \
        }                                                                        \
    } while (0)

#endif
