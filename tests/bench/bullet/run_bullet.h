/* The Bullet side of the side-by-side benchmark (run_bullet.cpp). */
#ifndef LFEM_BENCH_BULLET_RUN_BULLET_H
#define LFEM_BENCH_BULLET_RUN_BULLET_H

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Runs the scene in Bullet's deformable world; r.ok = 0 (after a message on stderr) when it
 * cannot be built or blows up (a NaN or a node far outside the scene). */
bench_result bench_run_bullet(const bench_scene* scene);

/* "3.24" or the like: the Bullet version the program was built with. */
const char* bench_bullet_version(void);

#ifdef __cplusplus
}
#endif

#endif
