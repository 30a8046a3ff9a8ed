/* grab: see grab.h. */
#include "grab.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pg_math.h"

/* A hand's width: the grip holds the boundary nodes within this of the point hit (and always
 * the hit triangle's three). Three nodes alone tear a patch out of a soft body when it is
 * swung; a hand-sized patch carries it. */
static const double kGripRadius = 0.12;

/* The nodes to hold, into nodes[] (room for every node of the body); returns how many, or -1. */
static int grip_nodes(const lfem_world* world, lfem_body body, uint32_t triangle, const double hit[3],
                      uint32_t* nodes) {
    uint32_t node_count = 0, triangle_count = 0;
    PG_TRY(lfem_body_get_node_count(world, body, &node_count));
    PG_TRY(lfem_body_get_boundary_triangle_count(world, body, &triangle_count));
    double* x = (double*)malloc(sizeof(double) * 3 * node_count);
    uint32_t* tris = (uint32_t*)malloc(sizeof(uint32_t) * 3 * triangle_count);
    unsigned char* taken = (unsigned char*)calloc(node_count, 1);
    int n = -1;
    if (x && tris && taken && triangle < triangle_count &&
        lfem_body_get_positions(world, body, x, node_count) == LFEM_OK &&
        lfem_body_get_boundary_triangles(world, body, tris, triangle_count) == LFEM_OK) {
        double reach = kGripRadius;
        for (int k = 0; k < 3; ++k) {
            double d[3];
            v3_sub(x + 3 * tris[3 * triangle + k], hit, d);
            reach = fmax(reach, v3_length(d));
        }
        n = 0;
        for (uint32_t i = 0; i < 3 * triangle_count; ++i) {
            const uint32_t v = tris[i];
            double d[3];
            v3_sub(x + 3 * v, hit, d);
            if (!taken[v] && v3_length(d) <= reach) taken[v] = 1, nodes[n++] = v;
        }
    } else {
        fprintf(stderr, "playground: could not read the grabbed body: %s\n", lfem_last_error());
    }
    free(x), free(tris), free(taken);
    return n;
}

int pg_grab_begin(pg_grab* grab, pg_room* room, const double origin[3], const double direction[3],
                  const double forward[3]) {
    lfem_ray_hit hit;
    int found = 0;
    const lfem_query_filter sees = {PG_PICKABLE, PG_PICKABLE}; /* bodies and furniture, not walls */
    PG_TRY(lfem_world_cast_ray(room->world, origin, direction, HUGE_VAL, sees, &hit, &found));
    if (!found || hit.triangle == UINT32_MAX) return 0; /* nothing, or a shape: a wall, the floor */
    const pg_body* pb = pg_room_find(room, hit.body);
    if (!pb) return 0;
    if (!pb->deformable) { /* the crate: kinematic while held, moved at the hand's velocity */
        PG_TRY(lfem_body_set_type(room->world, hit.body, LFEM_BODY_KINEMATIC));
        const double still[3] = {0, 0, 0};
        PG_TRY(lfem_body_set_kinematic_velocity(room->world, hit.body, still, still));
        grab->active = grab->rigid = 1;
        grab->body = hit.body;
        grab->node_count = 0;
        memcpy(grab->point, hit.point, sizeof grab->point);
        v3_set(grab->last_move, 0, 0, 0);
        memcpy(grab->plane_normal, forward, sizeof grab->plane_normal);
        return 1;
    }
    uint32_t node_count = 0;
    PG_TRY(lfem_body_get_node_count(room->world, hit.body, &node_count));
    uint32_t* nodes = (uint32_t*)malloc(sizeof(uint32_t) * node_count);
    const int held = nodes ? grip_nodes(room->world, hit.body, hit.triangle, hit.point, nodes) : -1;
    lfem_attachment_def def = lfem_attachment_def_default();
    def.body = hit.body;
    def.nodes = nodes;
    def.node_count = held > 0 ? (uint32_t)held : 0;
    memcpy(def.frame, hit.point, sizeof(double) * 3); /* the identity rotation stays */
    const lfem_status s = held > 0 ? lfem_attachment_create(room->world, &def, &grab->attachment)
                                   : LFEM_OUT_OF_MEMORY;
    free(nodes);
    PG_TRY(s);
    grab->active = 1;
    grab->rigid = 0;
    grab->body = hit.body;
    grab->node_count = (uint32_t)held;
    memcpy(grab->point, hit.point, sizeof grab->point);
    v3_set(grab->last_move, 0, 0, 0);
    memcpy(grab->plane_normal, forward, sizeof grab->plane_normal);
    return 1;
}

/* The lowest point of a body's nodes (m), into *z. */
static int lowest(const lfem_world* world, lfem_body body, double* z) {
    uint32_t n = 0;
    PG_TRY(lfem_body_get_node_count(world, body, &n));
    double* x = (double*)malloc(sizeof(double) * 3 * n);
    if (!x) return -1;
    const lfem_status s = lfem_body_get_positions(world, body, x, n);
    *z = HUGE_VAL;
    for (uint32_t i = 0; i < n; ++i) *z = fmin(*z, x[3 * i + 2]);
    free(x);
    PG_TRY(s);
    return 0;
}

int pg_grab_drag(pg_grab* grab, pg_room* room, const double origin[3], const double direction[3],
                 double max_move, double dt) {
    if (!grab->active) return 0;
    const double along = v3_dot(direction, grab->plane_normal);
    if (along < 1e-3) return 0; /* the cursor's ray runs (nearly) in the plane: stay */
    double to_plane[3], target[3], move[3];
    v3_sub(grab->point, origin, to_plane);
    v3_add_scaled(origin, v3_dot(to_plane, grab->plane_normal) / along, direction, target);
    /* The hand closes kFollow of its distance to the cursor each tick (a lag of about 50 ms),
     * so a jerk of the mouse becomes a swing: the velocity of the held nodes changes over a
     * few ticks instead of in one, which would crush the tets around the grip. */
    const double kFollow = 0.3;
    v3_sub(target, grab->point, move);
    const double length = kFollow * v3_length(move);
    if (length > 0) v3_add_scaled(grab->point, fmin(length, max_move) / v3_length(move), move, target);
    if (target[2] < 0.02) target[2] = 0.02; /* never drag nodes into the floor */
    if (grab->rigid) {
        /* A kinematic body passes through the static floor: its lowest node stays above it. */
        double low = 0;
        if (lowest(room->world, grab->body, &low) != 0) return -1;
        if (low + target[2] - grab->point[2] < 0.002) target[2] = grab->point[2] + 0.002 - low;
        double v[3];
        const double still[3] = {0, 0, 0};
        v3_sub(target, grab->point, v);
        for (int k = 0; k < 3; ++k) v[k] /= dt;
        PG_TRY(lfem_body_set_kinematic_velocity(room->world, grab->body, v, still));
    } else {
        double frame[7] = {target[0], target[1], target[2], 1, 0, 0, 0};
        PG_TRY(lfem_attachment_set_frame(room->world, grab->attachment, frame));
    }
    v3_sub(target, grab->point, grab->last_move);
    memcpy(grab->point, target, sizeof grab->point);
    return 0;
}

int pg_grab_release(pg_grab* grab, pg_room* room, double velocity[3]) {
    if (!grab->active) return 0;
    grab->active = 0;
    if (grab->rigid) /* rigid again, at the velocity it was carried with (the throw) */
        PG_TRY(lfem_body_set_type(room->world, grab->body, LFEM_BODY_RIGID));
    else if (lfem_attachment_is_valid(room->world, grab->attachment))
        PG_TRY(lfem_attachment_destroy(room->world, grab->attachment));
    if (velocity) {
        double momentum[3], mass = 0;
        PG_TRY(lfem_body_get_momentum(room->world, grab->body, momentum, NULL));
        PG_TRY(lfem_body_get_mass(room->world, grab->body, &mass));
        for (int k = 0; k < 3; ++k) velocity[k] = momentum[k] / mass;
    }
    return 0;
}
