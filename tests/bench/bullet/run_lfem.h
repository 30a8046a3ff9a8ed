/* The lfem side of the side-by-side benchmark (run_lfem.c). */
#ifndef LFEM_BENCH_BULLET_RUN_LFEM_H
#define LFEM_BENCH_BULLET_RUN_LFEM_H

#include "lfem.h"
#include "scene.h"

/* Runs the scene in lfem; r.ok = 0 (after a message on stderr) when a call fails. profile is
 * nullable: lfem's per-phase profile of the run. */
bench_result bench_run_lfem(const bench_scene* scene, lfem_profile* profile);

#endif
