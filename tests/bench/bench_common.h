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

/* The active contacts of the last step into *contacts (grown as needed, *capacity its size),
 * their number into *count. Returns 0, or -1 after printing why. */
static inline int bench_contacts(lfem_world* world, lfem_contact** contacts, uint32_t* capacity, uint32_t* count) {
    lfem_status s = lfem_world_query_contacts(world, *contacts, *capacity, count);
    if (s == LFEM_BUFFER_TOO_SMALL) {
        lfem_contact* grown = (lfem_contact*)realloc(*contacts, sizeof(lfem_contact) * 2 * *count);
        if (!grown) return -1;
        *contacts = grown;
        *capacity = 2 * *count;
        s = lfem_world_query_contacts(world, *contacts, *capacity, count);
    }
    if (s != LFEM_OK) {
        fprintf(stderr, "lfem_world_query_contacts failed: %s\n", lfem_last_error());
        return -1;
    }
    return 0;
}

/* Adds a mesh to a body as its tets require: lfem_body_add_quadratic_mesh for 10-node tets,
 * lfem_body_add_mesh otherwise. */
static inline lfem_status bench_add_mesh(lfem_world* world, lfem_body body, const lfem_mesh* mesh) {
    return (lfem_mesh_get_nodes_per_tet(mesh) == 10 ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh)(
        world, body, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh), lfem_mesh_get_tets(mesh),
        lfem_mesh_get_tet_count(mesh));
}

#endif
