/* room: see room.h. */
#include "room.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pg_math.h"
#include "skin.h"

/* Quaternions (w, x, y, z) that turn a plane's normal, local +z, to face each way. */
static const double kFacePlusZ[4] = {1, 0, 0, 0};
#define H 0.70710678118654752440
static const double kFaceMinusY[4] = {H, H, 0, 0};
static const double kFacePlusY[4] = {H, -H, 0, 0};
static const double kFacePlusX[4] = {H, 0, H, 0};
static const double kFaceMinusX[4] = {H, 0, -H, 0};
static const double kAlongX[4] = {H, 0, H, 0}; /* a capsule's axis, local z, along world x */
#undef H

static void set_colour(float out[3], double r, double g, double b) {
    out[0] = (float)r, out[1] = (float)g, out[2] = (float)b;
}

/* The drawn surface of a shape, placed where the shape is. */
static pg_shape* new_shape(pg_room* room, double r, double g, double b) {
    if (room->shape_count == PG_MAX_SHAPES) return NULL;
    pg_shape* s = &room->shapes[room->shape_count++];
    memset(s, 0, sizeof *s);
    set_colour(s->colour, r, g, b);
    return s;
}

/* Adds the shape to the static body and the drawing of it (mesh made in the local frame). */
static int add_shape(pg_room* room, lfem_body ground, const lfem_shape_def* def, pg_shape* drawn) {
    PG_TRY(lfem_body_add_shape(room->world, ground, def, NULL));
    if (!drawn) return 0;
    pg_mesh_transform(&drawn->mesh, def->rotation, def->center);
    return 0;
}

/* A wall: the half-space behind the plane through center facing `facing`, drawn (when drawn
 * is set) as a grid of half_x by half_y in the plane. */
static int add_wall(pg_room* room, lfem_body ground, const double center[3],
                    const double facing[4], double half_x, double half_y, int drawn, double shade) {
    lfem_shape_def def = lfem_shape_def_default();
    def.type = LFEM_SHAPE_PLANE;
    memcpy(def.center, center, sizeof def.center);
    memcpy(def.rotation, facing, sizeof def.rotation);
    pg_shape* s = NULL;
    if (drawn) {
        s = new_shape(room, shade, shade, 0.95 * shade);
        if (!s || pg_mesh_grid(&s->mesh, half_x, half_y, 12, 2) != 0) return -1;
    }
    return add_shape(room, ground, &def, s);
}

/* The floor: a plane drawn as a checkerboard (two meshes of alternate squares). */
static int add_floor(pg_room* room, lfem_body ground) {
    lfem_shape_def def = lfem_shape_def_default();
    def.type = LFEM_SHAPE_PLANE;
    memcpy(def.rotation, kFacePlusZ, sizeof def.rotation);
    PG_TRY(lfem_body_add_shape(room->world, ground, &def, NULL));
    for (int parity = 0; parity < 2; ++parity) {
        pg_shape* s = new_shape(room, parity ? 0.55 : 0.75, parity ? 0.57 : 0.77, parity ? 0.62 : 0.80);
        if (!s || pg_mesh_grid(&s->mesh, 3.0, 2.5, 12, parity) != 0) return -1;
    }
    return 0;
}

static int add_solid(pg_room* room, lfem_body ground, lfem_shape_type type, const double center[3],
                     const double rotation[4], const double size[3], double r, double g, double b) {
    lfem_shape_def def = lfem_shape_def_default();
    def.type = type;
    memcpy(def.center, center, sizeof def.center);
    memcpy(def.rotation, rotation, sizeof def.rotation);
    pg_shape* s = new_shape(room, r, g, b);
    if (!s) return -1;
    int made = -1;
    if (type == LFEM_SHAPE_BOX) {
        memcpy(def.half_extents, size, sizeof def.half_extents);
        made = pg_mesh_box(&s->mesh, size);
    } else if (type == LFEM_SHAPE_SPHERE) {
        def.radius = size[0];
        made = pg_mesh_sphere(&s->mesh, size[0], 48);
    } else {
        def.radius = size[0];
        def.half_length = size[1];
        made = pg_mesh_capsule(&s->mesh, size[0], size[1], 48);
    }
    return made == 0 ? add_shape(room, ground, &def, s) : -1;
}

/* The static part, two bodies: the room (floor, three walls and an invisible fourth in front
 * of the camera, so that a throw stays in the room), in category PG_ROOM_CATEGORY which the
 * hand's ray does not see (the eye stands behind the front wall, inside its half-space); and
 * the furniture (a block, a ball, a log and a ramp), in the bodies' category, which hides
 * what is behind it from the hand. */
static int build_static(pg_room* room) {
    lfem_body_def def = lfem_body_def_default();
    def.type = LFEM_BODY_STATIC;
    def.friction = 0.6;
    def.category_bits = PG_ROOM_CATEGORY;
    lfem_body ground, furniture;
    PG_TRY(lfem_body_create(room->world, &def, &ground));
    def.category_bits = lfem_body_def_default().category_bits;
    PG_TRY(lfem_body_create(room->world, &def, &furniture));
    if (add_floor(room, ground) != 0) return -1;
    const double back[3] = {0, 2.5, 1.5}, front[3] = {0, -2.5, 1.5};
    const double left[3] = {-3, 0, 1.5}, right[3] = {3, 0, 1.5};
    if (add_wall(room, ground, back, kFaceMinusY, 3.0, 1.5, 1, 0.85) != 0 ||
        add_wall(room, ground, left, kFacePlusX, 1.5, 2.5, 1, 0.78) != 0 ||
        add_wall(room, ground, right, kFaceMinusX, 1.5, 2.5, 1, 0.78) != 0 ||
        add_wall(room, ground, front, kFacePlusY, 0, 0, 0, 0) != 0)
        return -1;
    const double block_c[3] = {1.5, 1.0, 0.3}, block_h[3] = {0.6, 0.45, 0.3};
    const double ball_c[3] = {-1.6, 1.2, 0.45}, ball_r[3] = {0.45, 0, 0};
    const double log_c[3] = {0.0, 1.4, 0.18}, log_s[3] = {0.18, 0.7, 0};
    const double ramp_c[3] = {-1.7, -0.6, 0.05}, ramp_h[3] = {0.7, 0.5, 0.25};
    const double ramp_q[4] = {0.98480775301220806, 0.17364817766693033, 0, 0}; /* 20 deg about x */
    return add_solid(room, furniture, LFEM_SHAPE_BOX, block_c, kFacePlusZ, block_h, 0.45, 0.55, 0.70) ||
           add_solid(room, furniture, LFEM_SHAPE_SPHERE, ball_c, kFacePlusZ, ball_r, 0.85, 0.75, 0.35) ||
           add_solid(room, furniture, LFEM_SHAPE_CAPSULE, log_c, kAlongX, log_s, 0.60, 0.42, 0.30) ||
           add_solid(room, furniture, LFEM_SHAPE_BOX, ramp_c, ramp_q, ramp_h, 0.50, 0.62, 0.50);
}

/* A body of a box mesh (size, cells) with its corner at `at`, and its skin: the box rounded by
 * `rounding`, `skin_cells` squares a face, in the same rest frame. */
static int add_box_body(pg_room* room, const lfem_body_def* def, const double at[3],
                        const double size[3], const uint32_t cells[3], double rounding,
                        uint32_t skin_cells, double r, double g, double b) {
    if (room->body_count == PG_MAX_BODIES) return -1;
    pg_body* pb = &room->bodies[room->body_count];
    memset(pb, 0, sizeof *pb);
    lfem_mesh* mesh = NULL;
    PG_TRY(lfem_mesh_create_box(size, cells, &mesh));
    lfem_status s = lfem_mesh_translate(mesh, at);
    if (s == LFEM_OK) s = lfem_body_create(room->world, def, &pb->body);
    if (s == LFEM_OK)
        s = lfem_body_add_mesh(room->world, pb->body, lfem_mesh_get_positions(mesh),
                               lfem_mesh_get_node_count(mesh), lfem_mesh_get_tets(mesh),
                               lfem_mesh_get_tet_count(mesh));
    lfem_mesh_destroy(mesh);
    PG_TRY(s);
    if (pg_skin_bind(room->world, pb->body, size, at, rounding, skin_cells, &pb->skin) != 0) return -1;
    pb->deformable = def->type == LFEM_BODY_DEFORMABLE;
    set_colour(pb->colour, r, g, b);
    room->body_count++;
    return 0;
}

static int build_bodies(pg_room* room) {
    lfem_body_def jelly = lfem_body_def_default();
    jelly.model = LFEM_MODEL_COROTATIONAL;
    jelly.young_modulus = 1e5;
    jelly.poisson_ratio = 0.3;
    jelly.density = 300;
    jelly.damping = 0.2;
    jelly.friction = 0.6;
    const double cube[3] = {0.3, 0.3, 0.3}, small[3] = {0.24, 0.24, 0.24}, bar[3] = {0.9, 0.16, 0.16};
    const uint32_t cube_cells[3] = {4, 4, 4}, bar_cells[3] = {10, 2, 2};
    const double a[3] = {-0.45, -0.15, 0.02}, b[3] = {0.25, -0.35, 0.02};
    const double c[3] = {1.3, 0.8, 0.62}, d[3] = {-0.45, 1.3, 0.40};
    if (add_box_body(room, &jelly, a, cube, cube_cells, 0.06, 12, 0.90, 0.25, 0.25) != 0 ||
        add_box_body(room, &jelly, b, small, cube_cells, 0.05, 12, 0.25, 0.75, 0.30) != 0 ||
        add_box_body(room, &jelly, c, cube, cube_cells, 0.06, 12, 0.95, 0.60, 0.15) != 0 ||
        add_box_body(room, &jelly, d, bar, bar_cells, 0.05, 8, 0.55, 0.35, 0.85) != 0)
        return -1;
    lfem_body_def crate = lfem_body_def_default();
    crate.type = LFEM_BODY_RIGID;
    crate.density = 300;
    crate.friction = 0.5;
    const double crate_at[3] = {0.9, -0.6, 0.02}, crate_size[3] = {0.35, 0.35, 0.35};
    const uint32_t crate_cells[3] = {2, 2, 2};
    if (add_box_body(room, &crate, crate_at, crate_size, crate_cells, 0.02, 6, 0.65, 0.50, 0.35) != 0) return -1;
    /* A soft tail beside the crate, held to it by four points inside its near end on springs
     * (an attachment at points, compliant, to a rigid body): drag the crate and it follows. */
    const double tail_at[3] = {1.27, -0.485, 0.02}, tail_size[3] = {0.45, 0.12, 0.12};
    const uint32_t tail_cells[3] = {6, 2, 2};
    if (add_box_body(room, &jelly, tail_at, tail_size, tail_cells, 0.04, 8, 0.30, 0.55, 0.90) != 0) return -1;
    const double points[12] = {1.285, -0.46, 0.05, 1.285, -0.39, 0.05, 1.285, -0.46, 0.11, 1.285, -0.39, 0.11};
    lfem_attachment_def hold = lfem_attachment_def_default();
    hold.body = room->bodies[room->body_count - 1].body;
    hold.target = room->bodies[room->body_count - 2].body;
    hold.points = points, hold.point_count = 4;
    hold.stiffness = 2000, hold.damping = 10;
    lfem_attachment held;
    PG_TRY(lfem_attachment_create(room->world, &hold, &held));
    return 0;
}

/* Each body's nodes as built, for pg_room_reset. */
static int keep_start(pg_room* room) {
    for (int i = 0; i < room->body_count; ++i) {
        pg_body* b = &room->bodies[i];
        PG_TRY(lfem_body_get_node_count(room->world, b->body, &b->node_count));
        b->start = (double*)malloc(sizeof(double) * 3 * b->node_count);
        if (!b->start) return -1;
        PG_TRY(lfem_body_get_positions(room->world, b->body, b->start, b->node_count));
    }
    return 0;
}

int pg_room_reset(pg_room* room) {
    for (int i = 0; i < room->body_count; ++i) {
        pg_body* b = &room->bodies[i];
        double* zero = (double*)calloc(3 * (size_t)b->node_count, sizeof(double));
        if (!zero) return -1;
        lfem_status s;
        if (b->deformable) {
            s = lfem_body_set_positions(room->world, b->body, b->start, b->node_count);
        } else {
            /* The crate's mesh as built is its reference: the identity pose puts it back. */
            const double identity[7] = {0, 0, 0, 1, 0, 0, 0};
            s = lfem_body_set_transform(room->world, b->body, identity);
        }
        if (s == LFEM_OK) s = lfem_body_set_velocities(room->world, b->body, zero, b->node_count);
        free(zero);
        if (s != LFEM_OK) {
            fprintf(stderr, "playground: resetting body %d failed: %s\n", i, lfem_last_error());
            return -1;
        }
        b->flash = 0;
    }
    return 0;
}

int pg_room_create(pg_room* room, uint32_t thread_count) {
    memset(room, 0, sizeof *room);
    lfem_world_def def = lfem_world_def_default();
    def.thread_count = thread_count;
    def.enable_sleep = 1;
    lfem_status s = lfem_world_create(&def, &room->world);
    if (s != LFEM_OK) {
        fprintf(stderr, "playground: lfem_world_create failed: %s\n", lfem_last_error());
        return -1;
    }
    if (build_static(room) != 0 || build_bodies(room) != 0 || keep_start(room) != 0) {
        pg_room_destroy(room);
        return -1;
    }
    return 0;
}

void pg_room_destroy(pg_room* room) {
    for (int i = 0; i < room->body_count; ++i) pg_mesh_destroy(&room->bodies[i].skin), free(room->bodies[i].start);
    for (int i = 0; i < room->shape_count; ++i) pg_mesh_destroy(&room->shapes[i].mesh);
    free(room->events);
    lfem_world_destroy(room->world);
    memset(room, 0, sizeof *room);
}

pg_body* pg_room_find(pg_room* room, lfem_body body) {
    for (int i = 0; i < room->body_count; ++i)
        if (room->bodies[i].body.index == body.index && room->bodies[i].body.generation == body.generation)
            return &room->bodies[i];
    return NULL;
}

int pg_room_read_skins(pg_room* room) {
    for (int i = 0; i < room->body_count; ++i)
        if (pg_skin_read(room->world, room->bodies[i].body, &room->bodies[i].skin) != 0) return -1;
    return 0;
}

int pg_room_sleeping(const pg_room* room) {
    int n = 0;
    for (int i = 0; i < room->body_count; ++i) n += lfem_body_is_awake(room->world, room->bodies[i].body) == 0;
    return n;
}

/* An impact worth a flash: bodies that met at 0.3 m/s or faster (a body put down or settling
 * meets at about g h, a few cm/s at the sub-steps of these jellies; a cube dropped from its own
 * height at 1.7 m/s); the flash grows with the speed, full from 3 m/s. */
static const double kImpactSpeed = 0.3, kFullFlashSpeed = 3.0;

static lfem_status read_events(pg_room* room) {
    lfem_status s = lfem_world_get_events(room->world, room->events, room->event_capacity, &room->event_count);
    if (s == LFEM_BUFFER_TOO_SMALL) {
        lfem_event* grown = (lfem_event*)realloc(room->events, sizeof(lfem_event) * room->event_count);
        if (!grown) return LFEM_OUT_OF_MEMORY;
        room->events = grown;
        room->event_capacity = room->event_count;
        s = lfem_world_get_events(room->world, room->events, room->event_capacity, &room->event_count);
    }
    return s;
}

lfem_status pg_room_step(pg_room* room, double dt) {
    lfem_status s = lfem_world_step(room->world, dt);
    if (s != LFEM_OK) return s;
    for (int i = 0; i < room->body_count; ++i) {
        float* f = &room->bodies[i].flash;
        *f = *f > 0.05f ? *f - 0.05f : 0.0f; /* fades in 20 frames, a third of a second */
    }
    s = read_events(room);
    if (s != LFEM_OK) return s;
    for (uint32_t i = 0; i < room->event_count; ++i) {
        const lfem_event* e = &room->events[i];
        if (e->type != LFEM_EVENT_CONTACT_BEGIN || e->approach_speed < kImpactSpeed) continue;
        room->impacts++;
        const float strength = (float)(e->approach_speed < kFullFlashSpeed ? e->approach_speed / kFullFlashSpeed : 1.0);
        pg_body* hit[2] = {pg_room_find(room, e->body_a), pg_room_find(room, e->body_b)};
        for (int k = 0; k < 2; ++k)
            if (hit[k] && hit[k]->flash < strength) hit[k]->flash = strength;
    }
    return LFEM_OK;
}
