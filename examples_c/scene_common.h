/* What the paper's scenes (hammer_table, cup_wall, bar_impact) share: the error check, a wall
 * clock, and where their output files go. Header only (static inline), C99 + POSIX (on
 * Windows, MinGW-w64's clock_gettime and _mkdir). */
#ifndef LFEM_EXAMPLES_SCENE_COMMON_H
#define LFEM_EXAMPLES_SCENE_COMMON_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#ifdef _WIN32
#include <direct.h> /* _mkdir */
#define scene_mkdir(folder) _mkdir(folder)
#else
#define scene_mkdir(folder) mkdir(folder, 0755)
#endif

#include "lfem.h"

/* Every lfem call is checked: on failure, say which call and why, and leave with status 1. */
#define CHECK(call)                                                              \
    do {                                                                         \
        lfem_status s_ = (call);                                                 \
        if (s_ != LFEM_OK) {                                                     \
            fprintf(stderr, "%s failed: %s\n", #call, lfem_last_error());        \
            return 1;                                                            \
        }                                                                        \
    } while (0)

static inline double scene_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Creates the folder that will hold pvd_path (one level, like `mkdir`, not `mkdir -p`), so the
 * default output folder appears on first run. Returns 0, or -1 after printing why. */
static inline int scene_make_output_folder(const char* pvd_path) {
    char folder[1024];
    const char* slash = strrchr(pvd_path, '/');
    if (!slash || slash == pvd_path) return 0; /* the current folder, or the root */
    const size_t n = (size_t)(slash - pvd_path);
    if (n >= sizeof folder) {
        fprintf(stderr, "output path too long: %s\n", pvd_path);
        return -1;
    }
    memcpy(folder, pvd_path, n);
    folder[n] = '\0';
    if (scene_mkdir(folder) != 0 && errno != EEXIST) {
        fprintf(stderr, "cannot create the folder %s: %s\n", folder, strerror(errno));
        return -1;
    }
    return 0;
}

/* The path of a file named name in the folder of pvd_path, into out[size]. */
static inline int scene_sibling_path(const char* pvd_path, const char* name, char* out,
                                     size_t size) {
    const char* slash = strrchr(pvd_path, '/');
    const int folder = slash ? (int)(slash - pvd_path + 1) : 0;
    const int n = snprintf(out, size, "%.*s%s", folder, pvd_path, name);
    if (n < 0 || (size_t)n >= size) {
        fprintf(stderr, "output path too long: %s\n", pvd_path);
        return -1;
    }
    return 0;
}

/* The active contacts of the last step into *contacts (grown with realloc as needed; *capacity
 * is its size), their number into *count. Returns LFEM_OK, or the failing status
 * (LFEM_OUT_OF_MEMORY when the buffer cannot grow). */
static inline lfem_status scene_query_contacts(const lfem_world* world, lfem_contact** contacts,
                                               uint32_t* capacity, uint32_t* count) {
    lfem_status status = lfem_world_query_contacts(world, *contacts, *capacity, count);
    if (status != LFEM_BUFFER_TOO_SMALL) return status;
    lfem_contact* grown = (lfem_contact*)realloc(*contacts, sizeof(lfem_contact) * *count);
    if (!grown) return LFEM_OUT_OF_MEMORY;
    *contacts = grown;
    *capacity = *count;
    return lfem_world_query_contacts(world, *contacts, *capacity, count);
}

#endif
