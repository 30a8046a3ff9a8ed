/**
 * \file
 * lfem_types.h - the types of lfem's C API: the export macro and version, the status codes,
 * the opaque objects and value handles, and the definitions and reports that the functions of
 * lfem.h take and fill, with the *_default functions that fill a definition.
 *
 * Include lfem.h, which includes this header; the conventions written at its top (SI units,
 * "nullable", ownership, threads) hold here too. Plain C99, inside extern "C".
 */
#ifndef LFEM_TYPES_H
#define LFEM_TYPES_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** \def LFEM_API
 * Marks the functions lfem exports: __declspec(dllexport) while building the library on
 * Windows, dllimport for its users there, default visibility elsewhere. */
#if defined(_WIN32)
#  if defined(LFEM_BUILDING_LIBRARY)
#    define LFEM_API __declspec(dllexport)
#  else
#    define LFEM_API __declspec(dllimport)
#  endif
#else
#  define LFEM_API __attribute__((visibility("default")))
#endif

#define LFEM_VERSION_MAJOR 0 /**< this header's version; lfem_version() gives the library's */
#define LFEM_VERSION_MINOR 5 /**< this header's minor version */
#define LFEM_VERSION_PATCH 0 /**< this header's patch version */

/* ---------------------------------------------------------------------------------------- */
/* Status and errors                                                                          */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup status Status and errors
 * @{ */

/** What a call returns: LFEM_OK, or why it failed (lfem_last_error() gives the details). */
typedef enum lfem_status {
    LFEM_OK = 0,               /**< success */
    LFEM_INVALID_ARGUMENT = 1, /**< a null pointer, a NaN, a number out of its range */
    LFEM_INVALID_MESH = 2,     /**< bad indices, inverted or zero-volume tets, unused nodes */
    LFEM_INVALID_HANDLE = 3,   /**< a stale, foreign or null body handle */
    LFEM_BUFFER_TOO_SMALL = 4, /**< the caller's capacity is below what the answer needs */
    LFEM_UNSTABLE = 5,         /**< the state blew up; the world was rolled back */
    LFEM_IO_ERROR = 6,         /**< a file could not be read or written, or is malformed */
    LFEM_OUT_OF_MEMORY = 7,    /**< an allocation failed; nothing changed */
    LFEM_INTERNAL_ERROR = 8,   /**< a bug in lfem: please report it with the message */
    LFEM_UNSUPPORTED = 9,      /**< this build leaves the feature out (LFEM_WITH_CCD,
                                    LFEM_WITH_IO); the message names the option */
    LFEM_STATUS_FORCE32 = 0x7fffffff /**< not a status: keeps the enum 32 bits wide */
} lfem_status;
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* World                                                                                      */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup world World
 * @{ */

typedef struct lfem_world lfem_world; /**< opaque: the bodies and the step's settings */

/** What lfem_world_create takes: start from lfem_world_def_default(). */
typedef struct lfem_world_def {
    double gravity[3];          /**< m/s^2, default (0, 0, -9.81) */
    double time_step;           /**< s; 0 (default) = automatic: step_safety * stable limit. > 0
                                     = fixed sub-step; refused by lfem_world_step when above
                                     the stable limit unless allow_unstable_step is set */
    double step_safety;         /**< fraction of the stable limit used by the automatic step,
                                     in (0, 1); default 0.9 */
    uint32_t contact_iterations; /**< cap on contact solver sweeps per step, default 200 */
    uint32_t thread_count;      /**< threads that run a step's element and node loops (a big
                                     body's loops, or small bodies side by side), contact
                                     detection and the contact groups' solves, 1..64,
                                     default 1. Results are bitwise identical for every count. A
                                     library built with LFEM_WITH_THREADS=OFF accepts any valid
                                     count and runs on one thread */
    double contact_tolerance;   /**< relative stopping tolerance of the contact solve,
                                     default 1e-3 */
    uint32_t max_substeps;      /**< a call of lfem_world_step needing more sub-steps than this is
                                     refused up front, default 1000000 */
    uint8_t allow_unstable_step; /**< 1 = skip the up-front stability check of a fixed time_step
                                      (for experiments; instability is still caught), default 0 */
    uint8_t enable_sleep;       /**< 1 = bodies at rest fall asleep (see sleep_velocity), default 0:
                                     off, so that a scene's physics does not depend on it */
    uint8_t padding[2];         /**< unused, 0 */
    uint32_t internal_value;    /**< set by lfem_world_def_default; do not change */
    uint32_t padding2;          /**< unused, 0 */
    double mass_scaling_step;   /**< s; 0 (default) = off. Mass scaling, the explicit codes' tool
                                     for a step that stiff or small elements would shorten
                                     (OpenRadioss /DT/NODA/CST, LS-DYNA DT2MS): the nodes of each
                                     tet that would need a shorter sub-step than this get the
                                     added mass that lets the automatic step be at least
                                     mass_scaling_step (the stable limit at least
                                     mass_scaling_step / step_safety). Applied to the deformable
                                     meshes added to the world; the added mass acts fully (inertia
                                     and gravity) and is reported by lfem_body_get_added_mass and
                                     stats.added_mass. It changes the physics: waves run slower in
                                     the scaled elements (tests/bench's error-against-run-time
                                     report shows what it costs). Neo-Hookean bodies crushed
                                     beyond the reference still stiffen below it */
    double sleep_velocity;      /**< m/s, default 0.01. With enable_sleep, a deformable or rigid
                                     body that has moved slower than this for sleep_time, both as
                                     a whole (the rigid motion of its momentum, at its farthest
                                     node) and in its vibration (the mass-weighted RMS speed of
                                     the rest), and everything touching or attached to it too (a
                                     pile sleeps as a whole), falls asleep: its velocities are
                                     set to zero (booked as dissipated energy) and it is not
                                     stepped (no element forces, no predictor, no detection among
                                     sleeping bodies: it costs nothing) until it wakes */
    double sleep_time;          /**< s, default 0.5 */
} lfem_world_def;

/** A definition filled with the defaults above. Always start from it. */
LFEM_API lfem_world_def lfem_world_def_default(void);

/** Time, energies, momenta and contact figures of a world (lfem_world_get_stats). */
typedef struct lfem_world_stats {
    double time;              /**< s, simulated time */
    uint64_t steps;           /**< sub-steps taken since creation */
    double step_size;         /**< s, size of the last sub-step (0 before the first) */
    double stable_step;       /**< s, the stable limit (see lfem_world_get_stable_step) */
    uint32_t substeps_last_call; /**< sub-steps taken by the last lfem_world_step */
    uint32_t body_count;      /**< live bodies of every type */
    /** \name Energies and momenta of the moving (deformable) bodies
     * Static and kinematic bodies carry none. Velocities are the synchronized ones
     * (lfem_body_get_velocities).
     * @{ */
    double kinetic_energy;    /**< J */
    double strain_energy;     /**< J */
    double external_work;     /**< J, work done since creation by gravity, node forces and
                                   prescribed node velocities */
    double dissipated_energy; /**< J, removed since creation by damping (and contact) */
    double energy_error;      /**< J, kinetic + strain + dissipated - external_work - initial
                                   energy: a run-time error indicator, ideally 0 */
    double linear_momentum[3];  /**< kg m/s */
    double angular_momentum[3]; /**< kg m^2/s, about the world origin */
    /** @} */
    uint32_t contact_count;   /**< active contacts after the last step */
    uint32_t solver_iterations; /**< contact solver sweeps in the last sub-step */
    double solver_residual;   /**< m, largest remaining constraint violation, last sub-step */
    double max_penetration;   /**< m, largest penetration after the last sub-step */
    double rotation_drift;    /**< rad, largest angle between the global rotation integrated
                                   by eq.\ (2) and the one re-fitted to the nodes, last sub-step
                                   ("paper" model only, else 0) */
    double added_mass;        /**< kg, added by mass scaling to every body (world_def) */
    uint32_t inverted_tets;   /**< tets turned inside out (volume ratio J = det F <= 0) over the
                                   deformable bodies after the last sub-step */
    uint32_t padding;         /**< unused, 0 */
    double min_jacobian;      /**< the smallest volume ratio J of their tets after the last
                                   sub-step (1 without any). The materials resist crushing
                                   without bound below J = 0.2, so J near 0 or below means a
                                   body driven far past what its stiffness holds */
} lfem_world_stats;

/** Where the step spends its time. Each phase accumulates, over every sub-step since the world
 * was created (or since lfem_world_reset_profile), the wall time measured around it
 * (std::chrono::steady_clock, taken once per phase per sub-step, never per element; phases that
 * run in one round of the thread pool share its wall time by the CPU time each took in it) and
 * how often it ran. The counts are exact and repeatable; the seconds are measurements. A call of
 * lfem_world_step that fails is rolled back, the profile with the rest of the world. Not saved
 * in checkpoints (a loaded world starts from zero). */
typedef struct lfem_phase_time {
    double seconds;           /**< s, wall time spent in the phase */
    uint64_t calls;           /**< how often it ran (the unit is given per phase below) */
} lfem_phase_time;

/** The profile of a world (lfem_world_get_profile): the phases of the step (lfem_phase_time)
 * and counts. */
typedef struct lfem_profile {
    uint64_t substeps;                  /**< sub-steps profiled */
    lfem_phase_time internal_forces;    /**< elastic forces element by element at x^{n+1};
                                             calls: deformable bodies x sub-steps */
    lfem_phase_time predictor;          /**< central-difference predictor (eqs.\ 1, 3) and the
                                             rigid bodies' free motion; calls: deformable and
                                             rigid bodies x sub-steps (never a static body) */
    lfem_phase_time kinematic_motion;   /**< rigid motion of kinematic bodies; calls: kinematic
                                             bodies x sub-steps */
    lfem_phase_time broad_phase;        /**< swept boxes of the boundary triangles and the spatial
                                             hash; calls: sub-steps that ran detection */
    lfem_phase_time narrow_phase;       /**< per slave node: hash query and node-triangle tests
                                             (eqs.\ 5, 6); calls: sub-steps that ran detection */
    lfem_phase_time shape_queries;      /**< node against rigid shapes; calls: sub-steps in which
                                             some body had shapes to test against */
    uint64_t shape_tests;               /**< point queries of shapes: closed form and libccd */
    uint64_t ccd_queries;               /**< of those, libccd MPR queries (convex hulls) */
    lfem_phase_time normal_solve;       /**< multiplier solve: set-up, warm start, normal
                                             (tension release) updates; calls: sub-steps with
                                             pairs to solve */
    lfem_phase_time friction;           /**< multiplier solve: tangential updates and the return
                                             onto the Coulomb cone (eq.\ 7); calls: sub-steps with
                                             a pair of non-zero friction */
    lfem_phase_time global_rotation;    /**< eq.\ (2) and the re-fit of the floating frame;
                                             calls: "paper"-model bodies x sub-steps */
    lfem_phase_time commit;             /**< velocities, contact forces, energy bookkeeping;
                                             calls: deformable and rigid bodies x sub-steps */
    uint64_t candidate_searches;        /**< how often contact searched for candidate faces
                                             anew (part of the broad phase): only when a body
                                             moved beyond the margin of the last search, or the
                                             bodies changed; the sub-steps in between test the
                                             candidates only */
    /** \name The queries (lfem_world_cast_ray, lfem_world_cast_ray_all, lfem_world_overlap_box)
     * What they cost, as counts. A query pays for what its ray or box meets, not for the scene.
     * @{ */
    uint64_t queries;                   /**< rays and boxes answered */
    uint64_t query_bodies;              /**< bodies a query reached (their box met, the filter
                                             passed) */
    uint64_t query_primitives;          /**< triangles and shapes a query tested exactly */
    uint64_t query_refits;              /**< trees of a moving body's triangles built or
                                             refitted for the queries: at most once per body
                                             between two steps, and only for bodies a query
                                             reaches */
    uint64_t contact_sweeps;            /**< sweeps of the contact solve, its slowest group's
                                             per sub-step, summed: over `substeps`, the mean
                                             sweeps a sub-step needed (version 0.2) */
    uint64_t constraint_updates;        /**< updates of one constraint in a sweep (a contact
                                             pair's normal and friction, a held node), summed
                                             over every group and sweep: the solve's time over
                                             this is its cost per update (version 0.2) */
    /** @} */
} lfem_profile;
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Bodies                                                                                     */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup bodies Bodies
 * @{ */

/** A body handle: a value, not a pointer. {0, 0} is the null handle. A handle of a destroyed
 * body (stale) or of another world (foreign) is answered with LFEM_INVALID_HANDLE. */
typedef struct lfem_body {
    uint32_t index;      /**< the body's slot in its world */
    uint32_t generation; /**< which body held the slot: 0 in the null handle */
} lfem_body;

/** What a body is (lfem_body_def.type). */
typedef enum lfem_body_type {
    LFEM_BODY_DEFORMABLE = 0, /**< finite elements, moves and deforms */
    LFEM_BODY_STATIC = 1,     /**< never moves (a floor, a wall) */
    LFEM_BODY_KINEMATIC = 2,  /**< moves rigidly with a prescribed velocity, unaffected by forces */
    LFEM_BODY_RIGID = 3,      /**< the paper's global translation and rotation alone (eq.\ 2, no
                                   local deformation): mass and inertia from its tet mesh and
                                   density, moved by gravity, node forces and contacts */
    LFEM_BODY_TYPE_FORCE32 = 0x7fffffff /**< not a type: keeps the enum 32 bits wide */
} lfem_body_type;

/** How a deformable body's tets deform (lfem_body_def.model). */
typedef enum lfem_model {
    LFEM_MODEL_PAPER = 0,        /**< floating frame: one global rotation per body integrated by
                                      Lagrangian dynamics (eq.\ 2) and re-fitted to the nodes;
                                      linear elasticity in that frame. Moderate local rotations. */
    LFEM_MODEL_COROTATIONAL = 1, /**< one rotation per tet: large local rotations (bending) */
    LFEM_MODEL_NEO_HOOKEAN = 2,  /**< stable neo-Hookean hyperelasticity: large strains */
    LFEM_MODEL_LINEAR = 3,       /**< small-strain linear elasticity, no rotation at all: the
                                      cheapest, only right for tiny rotations (waves, impacts) */
    LFEM_MODEL_FORCE32 = 0x7fffffff /**< not a model: keeps the enum 32 bits wide */
} lfem_model;

/** What lfem_body_create takes: start from lfem_body_def_default(). */
typedef struct lfem_body_def {
    lfem_body_type type;      /**< default LFEM_BODY_DEFORMABLE */
    lfem_model model;         /**< default LFEM_MODEL_PAPER */
    double young_modulus;     /**< Pa, > 0, default 1e6 */
    double poisson_ratio;     /**< in (-1, 0.5), default 0.3 (negative: auxetic materials) */
    double density;           /**< kg/m^3, > 0, default 1000 */
    double damping;           /**< 1/s, mass-proportional damping alpha (force -alpha m v), >= 0,
                                   default 0 */
    double friction;          /**< Coulomb coefficient mu = tan(friction angle), >= 0,
                                   default 0.5 */
    double linear_velocity[3];  /**< m/s, initial velocity given to the nodes of each added mesh
                                     (kinematic bodies: their constant velocity) */
    double angular_velocity[3]; /**< rad/s, initial spin about the centre of mass of the body as
                                     it is when a mesh is added */
    uint32_t category_bits;   /**< collision filter: what this body is, default 1 */
    uint32_t mask_bits;       /**< collision filter: what it collides with, default all bits.
                                   Two bodies touch only if each one's category is in the
                                   other's mask */
    void* user_data;          /**< nullable, returned by lfem_body_get_user_data */
    uint32_t internal_value;  /**< set by lfem_body_def_default; do not change */
    uint8_t enable_sleep;     /**< 1 (default) = may fall asleep when the world's enable_sleep is
                                   set; 0 = always awake */
    uint8_t self_contact;     /**< 1 = the body's surface collides with itself (a bar folding over
                                   a post, a sheet piling up, a squashed jelly's folds): each
                                   boundary node against the body's own boundary triangles, except
                                   the ones around it, by the same multipliers as contact between
                                   bodies; a node found inside the body's own tets is pushed out.
                                   Deformable bodies only; default 0 (it costs a search of the
                                   body's own surface) */
    uint8_t composite_tets;   /**< 10-node tets only (ignored for 4-node ones): 1 = the composite
                                   element, whose strain is the projection of its eight linear
                                   sub-tets' (the ones of its lumped mass) onto a field linear over
                                   the tet, as the explicit codes' modified tets. A smooth load
                                   then moves a section's nodes alike (plane waves, impacts carry
                                   as with 4-node tets) and it still bends without locking; a
                                   quadratic displacement is no longer reproduced exactly.
                                   0 (default) = the quadratic shape functions' strain */
    uint8_t report_contacts;  /**< 1 = every call reports each pair of this body that stays in
                                   touch (LFEM_EVENT_CONTACT_PERSIST: its impulse, peak force and
                                   contact count), as a game reads a resting load; default 0
                                   (begins and ends only) */
    uint8_t edge_contacts;    /**< 1 (default) = the sharp edges of the body's surface (faces
                                   meeting at more than 15 degrees in the mesh as added, or a
                                   border) are held apart from those of other bodies that
                                   also have it where they cross between nodes
                                   (LFEM_CONTACT_EDGE_EDGE); 0 = its contacts are its nodes'
                                   only (and shapes between them), which saves the edge pass's
                                   detection and constraints where a scene needs none */
    uint8_t padding[7];       /**< unused, 0 */
} lfem_body_def;

/** A definition filled with the defaults above. Always start from it. */
LFEM_API lfem_body_def lfem_body_def_default(void);

/** Warnings: trouble the step recovers from but the caller may want to know of, counted as
 * MuJoCo counts its warnings (how often, when last, for which body). They never change the
 * physics; they say where the scene asks more than the bodies or the settings give. */
typedef enum lfem_warning_kind {
    LFEM_WARNING_INVERTED_TETS = 0,  /**< a sub-step ended with inverted tets in a body: once per
                                          body and sub-step */
    LFEM_WARNING_STAYS_INVERTED = 1, /**< a body kept inverted tets for 0.5 s in a row: once per
                                          spell (it is crushed harder than its material holds) */
    LFEM_WARNING_FALLEN_IN = 2,      /**< nodes found inside another body (or a shape), or with
                                          self-contact inside their own, during the run, pushed
                                          back out: once per node and fall (not counted: overlaps
                                          of newly added bodies) */
    LFEM_WARNING_UNCONVERGED = 3,    /**< a contact solve used every one of contact_iterations
                                          sweeps and ended above its tolerance (no body) */
    LFEM_WARNING_KIND_COUNT = 4      /**< the number of kinds, not a kind */
} lfem_warning_kind;

/** How often one kind of warning came, when last and for which body (lfem_world_get_warning). */
typedef struct lfem_warning {
    uint64_t count;      /**< since the world was created or lfem_world_clear_warnings */
    double last_time;    /**< s, the simulated time of the last one (0 before any) */
    lfem_body last_body; /**< the body of the last one; the null handle when none is concerned
                              (it may since have been destroyed: then stale) */
} lfem_warning;
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Attachments                                                                                */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup attachments Attachments
 * @{ */

/** Nodes of a deformable body held at fixed offsets in the frame of a target: a rigid body (the
 * attachment pulls both ways: a soft rope holds a rigid weight and the weight swings it), a
 * kinematic body (an animated bone), a static body, or a frame the caller moves every frame (a
 * hand; the null target). Each node is a hard constraint of the contact solve (three
 * multipliers, pulling or pushing), so a held node is exactly at its place at the end of every
 * sub-step up to the solve's tolerance. The offsets are where the nodes are when the attachment
 * is created. A value handle like lfem_body; destroying the body or the target destroys it. */
typedef struct lfem_attachment {
    uint32_t index;      /**< the attachment's slot in its world */
    uint32_t generation; /**< which attachment held the slot: 0 in the null handle */
} lfem_attachment;

/** What lfem_attachment_create takes: start from lfem_attachment_def_default(). */
typedef struct lfem_attachment_def {
    lfem_body body;           /**< the deformable body whose nodes or points are held */
    lfem_body target;         /**< a rigid, kinematic or static body with geometry, another
                                   deformable body with tets (the held points are held to its
                                   material points where they are: each bound once to the tet of
                                   the target around it, within one boundary edge of its
                                   surface), or the null handle {0, 0}: the frame below */
    const uint32_t* nodes;    /**< node_count indices of body's nodes (copied), distinct; or
                                   NULL with node_count 0 and points given */
    uint32_t node_count;      /**< >= 1, or 0 with points */
    uint32_t internal_value;  /**< set by lfem_attachment_def_default; do not change */
    double frame[7];          /**< null target: the frame at creation, centre (m) and unit
                                   quaternion (w, x, y, z); default the identity at the origin */
    double break_force;       /**< N: the attachment breaks (is destroyed, with an
                                   LFEM_EVENT_ATTACHMENT_BROKEN event) when the total force on its
                                   nodes exceeds this at the end of a sub-step; 0 (default) =
                                   never */
    const double* points;     /**< instead of nodes: point_count points (m, 3 each, copied) of
                                   body, held where they are: each bound once to the tet around
                                   it (within one boundary edge of the surface), whose nodes then
                                   carry it by their shape functions; NULL (default) with nodes */
    uint32_t point_count;     /**< 0 (default), or >= 1 with points and node_count 0 */
    double stiffness;         /**< N/m per held point and axis: 0 (default) holds it rigidly (a
                                   constraint); > 0 holds it by a spring (an implicit one: stable
                                   at any stiffness) */
    double damping;           /**< N s/m per held point and axis, with stiffness > 0: a damper
                                   beside the spring, on the point's velocity relative to its
                                   target's; 0 (default) */
} lfem_attachment_def;

/** A definition filled with the defaults above. Always start from it. */
LFEM_API lfem_attachment_def lfem_attachment_def_default(void);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Rigid shapes of static and kinematic bodies                                                */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup shapes Rigid shapes of static and kinematic bodies
 * @{ */

/** The kinds of rigid shape (lfem_shape_def.type), each in its local frame. */
typedef enum lfem_shape_type {
    LFEM_SHAPE_PLANE = 0,       /**< the half-space below the plane through `center` with normal
                                     local +z (solid side: local -z) */
    LFEM_SHAPE_BOX = 1,         /**< half_extents along the local axes */
    LFEM_SHAPE_SPHERE = 2,      /**< radius */
    LFEM_SHAPE_CAPSULE = 3,     /**< segment from -half_length to +half_length along local z,
                                     swept by a sphere of radius */
    LFEM_SHAPE_CONVEX_HULL = 4, /**< convex hull of `points` (local coordinates), through libccd */
    LFEM_SHAPE_TYPE_FORCE32 = 0x7fffffff /**< not a type: keeps the enum 32 bits wide */
} lfem_shape_type;

/** What lfem_body_add_shape takes: start from lfem_shape_def_default(). */
typedef struct lfem_shape_def {
    lfem_shape_type type;     /**< default LFEM_SHAPE_PLANE */
    uint32_t point_count;     /**< convex hull: number of points (>= 4, not all coplanar) */
    double center[3];         /**< m, world position of the shape's local origin, default 0 */
    double rotation[4];       /**< unit quaternion (w, x, y, z) of the local frame, default
                                   identity (a plane then faces +z) */
    double half_extents[3];   /**< m, box, default 0.5 */
    double radius;            /**< m, sphere and capsule, default 0.5 */
    double half_length;       /**< m, capsule, default 0.5 */
    const double* points;     /**< convex hull: 3 * point_count local coordinates (m), copied;
                                   nullable otherwise */
    uint32_t internal_value;  /**< set by lfem_shape_def_default; do not change */
    uint32_t padding;         /**< unused, 0 */
} lfem_shape_def;

/** A definition filled with the defaults above. Always start from it. */
LFEM_API lfem_shape_def lfem_shape_def_default(void);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Contacts                                                                                   */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup contacts Contacts
 * @{ */

/** What a contact record joins (lfem_contact::kind). */
typedef enum lfem_contact_kind {
    LFEM_CONTACT_NODE_FACE = 0,  /**< a node of body_a against a triangle of body_b */
    LFEM_CONTACT_NODE_SHAPE = 1, /**< a node of body_a against a rigid shape of body_b */
    LFEM_CONTACT_FACE_SHAPE = 2, /**< a rigid shape of body_b poking into a boundary triangle of
                                      body_a between its nodes: `node` is the triangle's first
                                      corner, `position` the shape's point, `normal` out of the
                                      shape, `force` on the face's point (its three nodes share
                                      it); triangle[] is UINT32_MAX as for a node on a shape */
    LFEM_CONTACT_EDGE_EDGE = 3   /**< a boundary edge of body_a crossing one of body_b between
                                      their nodes, one of the two a sharp edge (of its rest
                                      shape: faces meeting at more than 15 degrees, or a border)
                                      and the other a sharp edge too or a fold of a face that the
                                      load bends outward: `node` is the first node of body_a's
                                      edge, triangle[0] and triangle[1] body_b's edge
                                      (triangle[2] repeats triangle[1]), `position` the point of
                                      body_b's edge at weights 1 - t2, t2 (barycentric = (0, t2)),
                                      `normal` out of body_b, across both edges, `force` on the
                                      point of body_a's edge (its two nodes share it). Or an edge
                                      of body_b's box or convex hull shape `shape`: then
                                      `position` is the shape edge's point, triangle[] is
                                      UINT32_MAX for a box, and for a hull triangle[0] and
                                      triangle[1] are the edge's two points (indices into the
                                      hull's lfem_shape_def.points), triangle[2] UINT32_MAX */
} lfem_contact_kind;

/** One active contact of the last step (src/DESIGN.md section 5, eqs. 4 to 7): a point of
 * body_a (nodes_a, weights_a) against a point of body_b. On body_b's triangle (a, b, c) that
 * point is (1 - t1 - t2) a + t2 b + t1 c with (t1, t2) = barycentric; on a shape, position. */
typedef struct lfem_contact {
    lfem_body body_a;        /**< the body that owns the node (the face) */
    lfem_body body_b;        /**< the body that owns the triangle (the shape) */
    uint32_t node;           /**< node index in body_a */
    uint32_t triangle[3];    /**< node indices a, b, c in body_b (for a body of 10-node tets,
                                  one of the 4 flat triangles of a 6-node face) */
    double barycentric[2];   /**< t1, t2 */
    double position[3];      /**< m, the contact point on the triangle */
    double normal[3];        /**< unit, out of body_b's surface (towards body_a) */
    double force[3];         /**< N, the contact force on the node, normal and friction; the
                                  triangle's nodes receive its opposite, split by barycentric
                                  weights */
    uint8_t sliding;         /**< 1 when friction is on the Coulomb cone (slipping), else 0 */
    uint8_t kind;            /**< an lfem_contact_kind: what the record joins */
    uint8_t padding[2];      /**< unused, 0 */
    uint32_t shape;          /**< index of body_b's shape (lfem_body_add_shape) when the node
                                  touches a shape; UINT32_MAX when it touches a triangle. For a
                                  shape, triangle[] is UINT32_MAX and barycentric is 0 */
    double weights_a[3];     /**< body_a's point as a weighted sum of its nodes nodes_a[] (the
                                  weights sum to 1): the node alone (1, 0, 0) for a node's
                                  record, a face's three corners, an edge's two ends (then the
                                  third is 0) */
    uint32_t nodes_a[3];     /**< node indices in body_a (unused: UINT32_MAX); nodes_a[0] is
                                  `node` */
    uint32_t padding2;       /**< unused, 0 */
} lfem_contact;

/** Events of the last lfem_world_step, fetched rather than called back (as in Box2D v3), so game
 * logic can play a sound or deal damage without reading every node contact. A pair of bodies
 * touches while any node of one presses a face or shape of the other. */
typedef enum lfem_event_type {
    LFEM_EVENT_CONTACT_BEGIN = 0,      /**< a pair began to touch during the call */
    LFEM_EVENT_CONTACT_END = 1,        /**< a pair that touched stopped (a pair that touched and
                                            parted within one call gives both) */
    LFEM_EVENT_SLEEP = 2,              /**< body_a fell asleep */
    LFEM_EVENT_WAKE = 3,               /**< body_a woke */
    LFEM_EVENT_ATTACHMENT_BROKEN = 4,  /**< attachment (now stale) broke; body_a, body_b: its body
                                            and target */
    LFEM_EVENT_CONTACT_PERSIST = 5,    /**< a pair that touched at the end of the last call and
                                            still does, reported when either body asks
                                            (lfem_body_def.report_contacts) */
    LFEM_EVENT_TYPE_FORCE32 = 0x7fffffff /**< not a type: keeps the enum 32 bits wide */
} lfem_event_type;

/** One event of the last step (lfem_world_get_events). */
typedef struct lfem_event {
    lfem_event_type type;          /**< what happened */
    uint32_t contact_count;        /**< contact events: the pair's active node contacts at the end
                                        of the call (0 for an end); else 0 */
    lfem_body body_a,              /**< contact: the pair, body_a the lower slot; sleep, wake:
                                        the body; broken: the attachment's body */
              body_b;              /**< contact: the pair's other body; sleep, wake: null;
                                        broken: the attachment's target */
    lfem_attachment attachment;    /**< LFEM_EVENT_ATTACHMENT_BROKEN; else null */
    double normal_impulse;         /**< N s: contact events, the pair's summed normal impulse over
                                        the call (both ways: nodes of each on faces of the other);
                                        broken: the attachment's impulse over its last sub-step */
    double max_force;              /**< N: contact events, the largest summed normal force of the
                                        pair at a sub-step of the call; broken: the force that
                                        broke it */
    double approach_speed;         /**< m/s: contact events, the fastest a touching node of one
                                        body closed on the other along the normal in the first
                                        sub-step of the call in which they touched, before the
                                        contact stopped it: for a begin, the impact's speed (size
                                        a sound or damage by it); about g h for a pair at rest.
                                        0 for the other events and for the ends a destroyed
                                        body's pairs give */
    double point[3];               /**< m: contact events, where that node was at the end of
                                        that sub-step; else 0 */
    double normal[3];              /**< contact events, the unit contact normal there, pointing
                                        from body_a toward body_b; else 0 */
} lfem_event;
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Queries: rays and boxes against the current geometry                                       */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup queries Queries: rays and boxes against the current geometry
 * @{ */

/** A collision filter for a query, as the bodies' own: a body is seen when
 * (body.category_bits & filter.mask_bits) != 0 and (filter.category_bits & body.mask_bits) != 0. */
typedef struct lfem_query_filter {
    uint32_t category_bits; /**< what the query is */
    uint32_t mask_bits;     /**< the bodies' categories it sees */
} lfem_query_filter;

/** category 1, mask all bits: sees every body whose mask has bit 0 (the bodies' default). */
LFEM_API lfem_query_filter lfem_query_filter_default(void);

/** Where a ray crosses a surface. */
typedef struct lfem_ray_hit {
    lfem_body body;          /**< the body hit */
    uint32_t triangle;       /**< the body's boundary triangle (lfem_body_get_boundary_triangles
                                  order), UINT32_MAX when a shape was hit */
    uint32_t shape;          /**< the shape's index (lfem_body_add_shape), UINT32_MAX when a
                                  triangle was hit */
    double barycentric[2];   /**< t1, t2 as in lfem_contact: the point is (1 - t1 - t2) a + t2 b +
                                  t1 c of the triangle (a, b, c); 0 for a shape */
    double point[3];         /**< m, origin + distance * the unit direction */
    double normal[3];        /**< unit, out of the surface hit (out of the body or the shape's
                                  solid; a triangle's (b - a) x (c - a) direction) */
    double distance;         /**< m from the origin along the unit ray */
} lfem_ray_hit;

/** A body a sphere or capsule overlaps, and where (lfem_world_overlap_sphere, _capsule). */
typedef struct lfem_overlap {
    lfem_body body;          /**< the body overlapped */
    uint32_t triangle;       /**< its boundary triangle (lfem_body_get_boundary_triangles order)
                                  nearest the query's core (the centre, or the capsule's
                                  segment), UINT32_MAX when a shape is nearer or none is in
                                  reach */
    uint32_t shape;          /**< the shape's index (lfem_body_add_shape) when a shape is
                                  nearest, else UINT32_MAX */
    double point[3];         /**< m: the point of that triangle or shape nearest the core (of a
                                  convex hull the core is in: the core's point); a body of tets
                                  that holds the core inside, its surface out of reach (triangle
                                  and shape UINT32_MAX): the core's first point */
    double distance;         /**< m from the core to point, <= radius; 0 when the core is inside
                                  a shape or held by the body */
} lfem_overlap;
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Meshes: builders and Gmsh import                                                           */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup meshes Meshes: builders and Gmsh import
 * @{ */

typedef struct lfem_mesh lfem_mesh; /**< opaque: node positions and tets (4 or 10 nodes each),
                                         owned by the caller */
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Output: a VTK time series that ParaView opens                                              */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup output Output: a VTK time series that ParaView opens
 * @{ */

typedef struct lfem_vtk_series lfem_vtk_series; /**< opaque: a series being written */
/** @} */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* LFEM_TYPES_H */
