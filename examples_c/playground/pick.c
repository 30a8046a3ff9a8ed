/* pick: see pick.h.
 * TEMPORARY until lfem_world_cast_ray is on this branch: a ray against the bodies' boundary
 * triangles (the temporary skins), one by one. */
#include "pick.h"

#include <stdint.h>

#include "pg_math.h"

static int ray_triangle(const double o[3], const double d[3], const float* a, const float* b,
                        const float* c, double* t) {
    double e1[3], e2[3], p[3], s[3], q[3];
    for (int k = 0; k < 3; ++k) e1[k] = b[k] - a[k], e2[k] = c[k] - a[k], s[k] = o[k] - a[k];
    v3_cross(d, e2, p);
    const double det = v3_dot(e1, p);
    if (det > -1e-14 && det < 1e-14) return 0;
    const double u = v3_dot(s, p) / det;
    if (u < 0 || u > 1) return 0;
    v3_cross(s, e1, q);
    const double v = v3_dot(d, q) / det;
    if (v < 0 || u + v > 1) return 0;
    *t = v3_dot(e2, q) / det;
    return *t >= 0;
}

int pg_pick(pg_room* room, const double origin[3], const double direction[3], pg_hit* hit) {
    int found = 0;
    for (int i = 0; i < room->body_count; ++i) {
        const pg_mesh* m = &room->bodies[i].skin;
        for (uint32_t t = 0; t < m->triangle_count; ++t) {
            const uint32_t* tri = m->triangles + 3 * t;
            double dist;
            if (!ray_triangle(origin, direction, m->vertices + 6 * tri[0] + 3, m->vertices + 6 * tri[1] + 3,
                              m->vertices + 6 * tri[2] + 3, &dist))
                continue;
            if (found && dist >= hit->distance) continue;
            found = 1;
            hit->body = room->bodies[i].body;
            hit->triangle = t;
            hit->distance = dist;
            v3_add_scaled(origin, dist, direction, hit->point);
        }
    }
    return found;
}
