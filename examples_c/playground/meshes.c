/* meshes: see meshes.h. */
#include "meshes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pg_math.h"

void pg_mesh_destroy(pg_mesh* mesh) {
    free(mesh->vertices);
    free(mesh->triangles);
    memset(mesh, 0, sizeof *mesh);
}

static int mesh_alloc(pg_mesh* mesh, uint32_t vertex_count, uint32_t triangle_count) {
    mesh->vertices = (float*)calloc((size_t)vertex_count * 6, sizeof(float));
    mesh->triangles = (uint32_t*)calloc((size_t)triangle_count * 3, sizeof(uint32_t));
    mesh->vertex_count = vertex_count;
    mesh->triangle_count = 0;
    if (mesh->vertices && mesh->triangles) return 0;
    pg_mesh_destroy(mesh);
    return -1;
}

static void put_vertex(pg_mesh* mesh, uint32_t i, const double normal[3], const double p[3]) {
    float* v = mesh->vertices + 6 * (size_t)i;
    for (int k = 0; k < 3; ++k) v[k] = (float)normal[k], v[3 + k] = (float)p[k];
}

static void put_triangle(pg_mesh* mesh, uint32_t a, uint32_t b, uint32_t c) {
    uint32_t* t = mesh->triangles + 3 * (size_t)mesh->triangle_count++;
    t[0] = a, t[1] = b, t[2] = c;
}

/* Rounds a point of the box [0, size] onto the box shrunk by radius and swept by a sphere of
 * radius: flat faces stay where they are, edges and corners become quarter cylinders and
 * eighth spheres. */
static void round_point(const double size[3], double radius, double p[3]) {
    double q[3], d[3];
    for (int k = 0; k < 3; ++k) q[k] = fmin(fmax(p[k], radius), size[k] - radius);
    v3_sub(p, q, d);
    const double n = v3_length(d);
    if (n > 0) v3_add_scaled(q, radius / n, d, p);
}

int pg_rounded_box(const double size[3], double radius, uint32_t cells, double** positions,
                   uint32_t** triangles, uint32_t* vertex_count, uint32_t* triangle_count) {
    const uint32_t n = cells, side = n + 1;
    /* Grid points of the box's surface are numbered once through their integer coordinates
     * in [0, n]^3, so the faces share their edge and corner vertices (smooth normals across). */
    int32_t* index = (int32_t*)malloc(sizeof(int32_t) * side * side * side);
    double* p = (double*)malloc(sizeof(double) * 3 * 6 * side * side);
    uint32_t* t = (uint32_t*)malloc(sizeof(uint32_t) * 3 * 12 * n * n);
    if (!index || !p || !t) {
        free(index), free(p), free(t);
        return -1;
    }
    for (uint32_t i = 0; i < side * side * side; ++i) index[i] = -1;
    uint32_t nv = 0, nt = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int high = 0; high < 2; ++high) {
            const int b = (axis + 1) % 3, c = (axis + 2) % 3;
            uint32_t ids[2][2];
            for (uint32_t u = 0; u < n; ++u)
                for (uint32_t v = 0; v < n; ++v) {
                    for (uint32_t du = 0; du < 2; ++du)
                        for (uint32_t dv = 0; dv < 2; ++dv) {
                            uint32_t g[3];
                            g[axis] = high ? n : 0, g[b] = u + du, g[c] = v + dv;
                            const uint32_t key = (g[0] * side + g[1]) * side + g[2];
                            if (index[key] < 0) {
                                for (int k = 0; k < 3; ++k) p[3 * nv + k] = size[k] * g[k] / n;
                                round_point(size, radius, p + 3 * nv);
                                index[key] = (int32_t)nv++;
                            }
                            ids[du][dv] = (uint32_t)index[key];
                        }
                    /* e_b x e_c = e_axis: (u, v) -> (u+1, v) -> (u+1, v+1) turns
                     * counter-clockwise seen from +axis, the outside of the high face. */
                    const uint32_t q[4] = {ids[0][0], ids[1][0], ids[1][1], ids[0][1]};
                    const uint32_t order[2][6] = {{0, 1, 2, 0, 2, 3}, {0, 2, 1, 0, 3, 2}};
                    for (int k = 0; k < 6; ++k) t[3 * nt + k] = q[order[high ? 0 : 1][k]];
                    nt += 2;
                }
        }
    free(index);
    *positions = p;
    *triangles = t;
    *vertex_count = nv;
    *triangle_count = nt;
    return 0;
}

int pg_mesh_box(pg_mesh* mesh, const double half_extents[3]) {
    if (mesh_alloc(mesh, 24, 12) != 0) return -1;
    uint32_t nv = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int high = 0; high < 2; ++high) {
            const int b = (axis + 1) % 3, c = (axis + 2) % 3;
            const double s = high ? 1 : -1;
            double normal[3] = {0, 0, 0};
            normal[axis] = s;
            const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int k = 0; k < 4; ++k) {
                double p[3];
                p[axis] = s * half_extents[axis];
                p[b] = corners[k][0] * half_extents[b];
                p[c] = corners[k][1] * half_extents[c];
                put_vertex(mesh, nv + (uint32_t)k, normal, p);
            }
            if (high) put_triangle(mesh, nv, nv + 1, nv + 2), put_triangle(mesh, nv, nv + 2, nv + 3);
            else put_triangle(mesh, nv, nv + 2, nv + 1), put_triangle(mesh, nv, nv + 3, nv + 2);
            nv += 4;
        }
    return 0;
}

int pg_mesh_capsule(pg_mesh* mesh, double radius, double half_length, uint32_t segments) {
    /* Latitude rings from the bottom pole to the top one; the equator is doubled (once for
     * each hemisphere, half_length apart) so that the cylinder between them is drawn. */
    const uint32_t half_rings = segments / 4 + 1, rings = 2 * half_rings, around = segments + 1;
    if (mesh_alloc(mesh, rings * around, 2 * (rings - 1) * segments) != 0) return -1;
    for (uint32_t r = 0; r < rings; ++r) {
        const int top = r >= half_rings;
        const uint32_t k = top ? r - half_rings : r;
        const double lat = (top ? 0 : -0.5 * PG_PI) + 0.5 * PG_PI * k / (half_rings - 1);
        for (uint32_t s = 0; s < around; ++s) {
            const double lon = 2 * PG_PI * s / segments;
            const double n[3] = {cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat)};
            const double p[3] = {radius * n[0], radius * n[1],
                                 radius * n[2] + (top ? half_length : -half_length)};
            put_vertex(mesh, r * around + s, n, p);
        }
    }
    for (uint32_t r = 0; r + 1 < rings; ++r)
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t a = r * around + s, b = a + 1, c = a + around, d = c + 1;
            put_triangle(mesh, a, b, d);
            put_triangle(mesh, a, d, c);
        }
    return 0;
}

int pg_mesh_sphere(pg_mesh* mesh, double radius, uint32_t segments) {
    return pg_mesh_capsule(mesh, radius, 0, segments);
}

int pg_mesh_grid(pg_mesh* mesh, double half_x, double half_y, uint32_t cells, int parity) {
    const uint32_t side = cells + 1;
    if (mesh_alloc(mesh, side * side, 2 * cells * cells) != 0) return -1;
    const double up[3] = {0, 0, 1};
    for (uint32_t j = 0; j < side; ++j)
        for (uint32_t i = 0; i < side; ++i) {
            const double p[3] = {-half_x + 2 * half_x * i / cells, -half_y + 2 * half_y * j / cells, 0};
            put_vertex(mesh, j * side + i, up, p);
        }
    for (uint32_t j = 0; j < cells; ++j)
        for (uint32_t i = 0; i < cells; ++i) {
            if (parity != 2 && (int)((i + j) % 2) != parity) continue;
            const uint32_t a = j * side + i;
            put_triangle(mesh, a, a + 1, a + side + 1);
            put_triangle(mesh, a, a + side + 1, a + side);
        }
    return 0;
}

void pg_mesh_transform(pg_mesh* mesh, const double rotation[4], const double offset[3]) {
    for (uint32_t i = 0; i < mesh->vertex_count; ++i) {
        float* v = mesh->vertices + 6 * (size_t)i;
        double n[3] = {v[0], v[1], v[2]}, p[3] = {v[3], v[4], v[5]}, rn[3], rp[3];
        quat_rotate(rotation, n, rn);
        quat_rotate(rotation, p, rp);
        for (int k = 0; k < 3; ++k) v[k] = (float)rn[k], v[3 + k] = (float)(rp[k] + offset[k]);
    }
}
