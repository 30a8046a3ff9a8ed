/**
 * \file
 * lfem.h - the one public header of lfem: deformable bodies that collide, simulated by an
 * explicit local finite element method (no global matrix anywhere) with contact by forward
 * increment Lagrange multipliers.
 *
 * Plain C99; usable from C++ (everything is inside extern "C"). No C++ type, exception or STL
 * object crosses this boundary. Include this header only: it holds the functions, and includes
 * lfem_types.h, which holds the types they take (status codes, handles, definitions, reports).
 *
 * Conventions used by every function below
 * - Units are SI throughout: metres, seconds, kilograms, newtons, pascals, joules, radians.
 * - Every call that can fail returns an lfem_status. On failure nothing changes: the world, the
 *   body and every output argument are left exactly as they were, and lfem_last_error() holds a
 *   message for the calling thread.
 * - Pointers are non-null unless the comment says "nullable". A null pointer where one is
 *   required is answered with LFEM_INVALID_ARGUMENT, never a crash.
 * - Arrays of vectors are flat: node i's position is positions[3*i+0..2]. Indices are 0-based.
 * - Ownership: lfem never keeps a pointer the caller passed in (definitions and arrays are
 *   copied). Objects it creates (world, mesh, series) are owned by the caller until the matching
 *   *_destroy call. Returned strings are owned by lfem and must not be freed.
 * - Thread safety: distinct worlds (and meshes and series) may be used from distinct threads at
 *   the same time. One world must not be used by two threads at once (no internal locking),
 *   not even by two queries (they keep a cache inside the world).
 *   lfem_last_error() is per thread. The *_default, lfem_status_string and lfem_version*
 *   functions may be called from any thread at any time. A world created with thread_count > 1
 *   owns that many worker threads (created with it, joined by lfem_world_destroy); they work
 *   only inside its lfem_world_step and lfem_body_add_mesh calls, and results do not depend on
 *   their number. Between the short parallel loops of a step they spin for up to 50 us before
 *   sleeping, so a world stepped in a loop keeps its threads' cores busy while it steps.
 */
#ifndef LFEM_H
#define LFEM_H

#include "lfem_types.h" /* the types: status codes, handles, definitions, reports */

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------- */
/* Status and errors                                                                          */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup status Status and errors
 * @{ */

/** A fixed English name and meaning of a status, e.g.\ "LFEM_INVALID_MESH: invalid mesh".
 * Never NULL; unknown values give "unknown status". */
LFEM_API const char* lfem_status_string(lfem_status status);

/** The message of the most recent failed call made on this thread,
 * e.g.\ "lfem_body_add_mesh: tet 17 is inverted (volume -2.1e-09 m^3)". Never NULL ("" before
 * any failure). Valid until the next lfem call on this thread. */
LFEM_API const char* lfem_last_error(void);

/** (major << 16) | (minor << 8) | patch of the library actually loaded. Compare with
 * LFEM_VERSION_* to detect a header/library mismatch. */
LFEM_API uint32_t lfem_version(void);
/** "major.minor.patch". Never NULL. */
LFEM_API const char* lfem_version_string(void);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* World                                                                                      */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup world World
 * @{ */

/** Create an empty world. *out receives the world (unchanged on failure). */
LFEM_API lfem_status lfem_world_create(const lfem_world_def* def, lfem_world** out);

/** Destroy a world and everything in it. Nullable (NULL is a no-op). */
LFEM_API void lfem_world_destroy(lfem_world* world);

/** Advance the world by dt seconds (dt > 0, finite). The interval is split into equal sub-steps
 * no larger than the allowed step (automatic or fixed). With the automatic step, a call in which
 * a body stiffens beyond its sub-step (neo-Hookean bodies, re-checked after every sub-step) or
 * the state blows up is redone from its start with more sub-steps (at least twice as many, up
 * to 4 times); stats.substeps_last_call reports the sub-steps of the run that was kept. If the
 * state still blows up, the call returns LFEM_UNSTABLE; if memory runs out,
 * LFEM_OUT_OF_MEMORY. Whatever the failure, the world is rolled back, bitwise, to its state
 * before the call, and stepping may go on. */
LFEM_API lfem_status lfem_world_step(lfem_world* world, double dt);

/** Checkpoints: lfem_world_save writes everything a step depends on (definition, bodies,
 * counters, the contacts that warm-start the next solve) to a versioned binary file: first to
 * `<path>.tmp`, then renamed over path, so an existing checkpoint is only ever replaced by a
 * complete one. lfem_world_load creates a new world from such a file; stepping it gives results
 * bitwise identical to the saved world's. Body handles of the saved world are valid in the
 * loaded one. user_data pointers are not saved (NULL after loading); user ids are
 * (lfem_body_set_user_id). A missing, truncated,
 * corrupted (checksum) or foreign file (other format version, byte order or build layout) gives
 * LFEM_IO_ERROR and *out unchanged; no partial world is ever returned. */
LFEM_API lfem_status lfem_world_save(const lfem_world* world, const char* path);
/** Create a new world from a checkpoint file (see lfem_world_save). */
LFEM_API lfem_status lfem_world_load(const char* path, lfem_world** out);

/** Change gravity (m/s^2) of an existing world. */
LFEM_API lfem_status lfem_world_set_gravity(lfem_world* world, const double gravity[3]);
/** Change the fixed time step (s, 0 = automatic) of an existing world. */
LFEM_API lfem_status lfem_world_set_time_step(lfem_world* world, double time_step);

/** The stable limit of the central difference step, in seconds: 2/omega_max of the stiffest
 * deformable body (Lanczos iteration on the element-by-element operator, capped by a proven
 * Gershgorin bound). For neo-Hookean bodies it is taken at the current shape (a crushed body is
 * stiffer), so it may change from step to step. Infinity (HUGE_VAL) when the world has no
 * deformable body. */
LFEM_API lfem_status lfem_world_get_stable_step(const lfem_world* world, double* out);

/** Time, energies, momenta and contact figures of the world after the last step
 * (lfem_world_stats). */
LFEM_API lfem_status lfem_world_get_stats(const lfem_world* world, lfem_world_stats* out);

/** Where the step spent its time: the accumulated profile (lfem_profile). */
LFEM_API lfem_status lfem_world_get_profile(const lfem_world* world, lfem_profile* out);
/** Set every time and count of the profile back to zero. */
LFEM_API lfem_status lfem_world_reset_profile(lfem_world* world);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Bodies                                                                                     */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup bodies Bodies
 * @{ */

/** Create a body without nodes; give it a mesh with lfem_body_add_mesh. */
LFEM_API lfem_status lfem_body_create(lfem_world* world, const lfem_body_def* def,
                                      lfem_body* out);

/** Destroy a body; its handle (and copies of it) become stale. Each pair of bodies it touched
 * ends: an LFEM_EVENT_CONTACT_END for it comes with the next step's events (naming the
 * destroyed body by its now stale handle), and sleeping bodies it touched wake. */
LFEM_API lfem_status lfem_body_destroy(lfem_world* world, lfem_body body);

/** 1 if the handle names a live body of this world, else 0. world is nullable (gives 0). */
LFEM_API int lfem_body_is_valid(const lfem_world* world, lfem_body body);

/** Add a tetrahedral mesh to a body. positions: 3*node_count doubles (m); tets: 4*tet_count
 * node indices into this mesh (0-based), each tet with positive volume
 * (det[x1-x0, x2-x0, x3-x0] > 0). Every node must belong to a tet, no tet may repeat a node,
 * and no triangle may be shared by more than two tets. The boundary triangles are extracted
 * automatically. A body may receive several meshes; node and tet indices of a later mesh
 * continue after the earlier ones. The body def's velocities are given to the new nodes. */
LFEM_API lfem_status lfem_body_add_mesh(lfem_world* world, lfem_body body,
                                        const double* positions, uint32_t node_count,
                                        const uint32_t* tets, uint32_t tet_count);

/** Add a mesh of 10-node (quadratic) tets, as lfem_body_add_mesh otherwise: tets holds 10 node
 * indices per tet, its corners c0..c3 first (det[c1-c0, c2-c0, c3-c0] > 0), then the mid-edge
 * nodes of the edges (c0,c1), (c1,c2), (c0,c2), (c0,c3), (c1,c3), (c2,c3), VTK's order
 * (lfem_mesh_load_gmsh turns Gmsh's type 11 into it). Tets that share an edge share its
 * mid-edge node. Mid-edge nodes may lie off the straight edge (a curved element, as Gmsh puts
 * them on a curved boundary) as long as the element does not fold over (det J > 0 at its 4
 * quadrature points and corners). The element integrates its stiffness with 4 points and lumps
 * its mass rho V / 32 to each corner and 7 rho V / 48 to each mid-edge node. All meshes of a
 * body have tets of one kind; lfem_mesh_make_quadratic makes such a mesh of any linear one. */
LFEM_API lfem_status lfem_body_add_quadratic_mesh(lfem_world* world, lfem_body body,
                                                  const double* positions, uint32_t node_count,
                                                  const uint32_t* tets, uint32_t tet_count);

/** Give a static or kinematic body a surface of triangles instead of tets (terrain, a wall, a
 * ramp): 3 node indices per triangle, counter-clockwise seen from the side bodies touch (the
 * normal (b-a)x(c-a) points towards them). Only one mesh per such body. Its boundary
 * triangles are the triangles themselves. */
LFEM_API lfem_status lfem_body_add_triangle_mesh(lfem_world* world, lfem_body body,
                                                 const double* positions, uint32_t node_count,
                                                 const uint32_t* triangles,
                                                 uint32_t triangle_count);

/** The number of nodes of the body. */
LFEM_API lfem_status lfem_body_get_node_count(const lfem_world* world, lfem_body body,
                                              uint32_t* out);
/** The number of tets of the body. */
LFEM_API lfem_status lfem_body_get_tet_count(const lfem_world* world, lfem_body body,
                                             uint32_t* out);
/** Nodes per tet of the body: 4, 10 (quadratic tets), or 0 for a body without tets. */
LFEM_API lfem_status lfem_body_get_nodes_per_tet(const lfem_world* world, lfem_body body,
                                                 uint32_t* out);
/** The body def's user_data. */
LFEM_API lfem_status lfem_body_get_user_data(const lfem_world* world, lfem_body body,
                                             void** out);

/** Total mass of the body (kg): the sum of its lumped node masses, rho V, plus what mass scaling
 * added (lfem_world_def.mass_scaling_step). */
LFEM_API lfem_status lfem_body_get_mass(const lfem_world* world, lfem_body body, double* out);
/** The mass (kg) that mass scaling added to the body's nodes (0 without mass scaling). */
LFEM_API lfem_status lfem_body_get_added_mass(const lfem_world* world, lfem_body body, double* out);

/** The body's inverted tets after the last sub-step (J = det F <= 0), the smallest volume
 * ratio J of its tets, and for how long (s) it has had inverted tets without a break (0 when
 * it has none). 0, 1, 0 for a body that is not deformable. A 10-node tet's J varies inside it:
 * it counts as inverted when J <= 0 at one of its 4 quadrature points, and its J is the
 * smallest at them. Each output is nullable. */
LFEM_API lfem_status lfem_body_get_inversion(const lfem_world* world, lfem_body body, uint32_t* inverted_tets,
                                             double* min_jacobian, double* inverted_for);

/** Linear momentum (kg m/s) and angular momentum about the world origin (kg m^2/s) of the
 * body, from its synchronized velocities. Static and kinematic bodies report zero. Either
 * output is nullable. */
LFEM_API lfem_status lfem_body_get_momentum(const lfem_world* world, lfem_body body,
                                            double linear[3], double angular[3]);

/** How often one kind of warning came, when last and for which body (lfem_warning_kind). */
LFEM_API lfem_status lfem_world_get_warning(const lfem_world* world, lfem_warning_kind kind, lfem_warning* out);
/** Set every warning's count and last time back to zero. */
LFEM_API lfem_status lfem_world_clear_warnings(lfem_world* world);

/** Copy the current node positions (m) into out[3*node_capacity]. LFEM_BUFFER_TOO_SMALL when
 * node_capacity < node count (nothing written). */
LFEM_API lfem_status lfem_body_get_positions(const lfem_world* world, lfem_body body,
                                             double* out, uint32_t node_capacity);

/** Copy the node velocities (m/s) at the current time into out[3*node_capacity]. These are
 * the synchronized central-difference velocities (the mid-step velocity advanced by half a
 * step of the current acceleration); a node pressed by a contact, and a rigid body pressed by
 * one or held by an attachment, report the last step's velocity instead (the extrapolation
 * would know gravity but not the support: a body at rest would report -g h/2). */
LFEM_API lfem_status lfem_body_get_velocities(const lfem_world* world, lfem_body body,
                                              double* out, uint32_t node_capacity);

/** Overwrite the velocities (m/s, 3 per node, node_count must equal the body's). A rigid body
 * (with a mesh) takes the rigid motion nearest the field: the one with its momentum and its
 * angular momentum about the centre of mass. The change of kinetic energy is the caller's work. */
LFEM_API lfem_status lfem_body_set_velocities(lfem_world* world, lfem_body body,
                                              const double* velocities, uint32_t node_count);

/** Teleport a deformable body's nodes to new positions (m, 3 per node; node_count must equal
 * the body's), deformed or not. Its velocities are kept, the change of strain energy is booked as
 * external work, and the body and what rested on it wake. Its pairs end (an
 * LFEM_EVENT_CONTACT_END each with the next step's events; touching where it lands begins anew).
 * Attachments hold: held nodes are pulled back to their target at the next step (move it too). */
LFEM_API lfem_status lfem_body_set_positions(lfem_world* world, lfem_body body,
                                             const double* positions, uint32_t node_count);

/** Settings changed after creation, as lfem_body_def gives them at creation (same ranges); the
 * handle, meshes, skins and attachments stay, and the body wakes. Friction (>= 0): the pairs'
 * friction from the next step on. Damping (>= 0, 1/s). The collision filter: pairs it now
 * forbids end with the next step's events, and what the body touched wakes. User data: returned
 * by lfem_body_get_user_data (it does not wake the body). */
LFEM_API lfem_status lfem_body_set_friction(lfem_world* world, lfem_body body, double friction);
/** See lfem_body_set_friction. */
LFEM_API lfem_status lfem_body_set_damping(lfem_world* world, lfem_body body, double damping);
/** A deformable body's Young's modulus (Pa, > 0) and Poisson's ratio (in (-1, 0.5)), as at
 * creation: its elastic forces at its current shape and its stable step follow (the step of the
 * next call with them), the change of strain energy is the caller's work, the body wakes. Under
 * mass scaling (lfem_world_def.mass_scaling_step) its added masses are fitted to the new
 * material as a body made of it would have them (its velocities kept: the change of kinetic
 * energy is the caller's work too). */
LFEM_API lfem_status lfem_body_set_material(lfem_world* world, lfem_body body, double young_modulus,
                                            double poisson_ratio);
/** See lfem_body_set_friction. */
LFEM_API lfem_status lfem_body_set_filter(lfem_world* world, lfem_body body, uint32_t category_bits,
                                          uint32_t mask_bits);
/** See lfem_body_set_friction. */
LFEM_API lfem_status lfem_body_set_user_data(lfem_world* world, lfem_body body, void* user_data);
/** Change a body's type between rigid, kinematic and static, as Box2D's b2Body_SetType: the
 * handle, its meshes, shapes, skins and attachments stay, its pose carries over. A rigid body
 * made kinematic moves on at its velocity and spin (lfem_body_set_kinematic_velocity changes
 * them); a kinematic one made rigid starts from its velocities; a static body stops (where it is
 * becomes its reference). Its contacts end (with their events) and are found again; the change
 * of kinetic energy is the caller's work; the body and what it touched wake. A rigid body needs
 * tets and no shapes. A deformable body keeps its type, and no body becomes deformable:
 * LFEM_INVALID_ARGUMENT, the world unchanged. The same type: nothing happens. */
LFEM_API lfem_status lfem_body_set_type(lfem_world* world, lfem_body body, lfem_body_type type);
/** The body's type (lfem_body_def.type, or as lfem_body_set_type last set it). */
LFEM_API lfem_status lfem_body_get_type(const lfem_world* world, lfem_body body, lfem_body_type* out);
/** An opaque 64-bit value the caller keeps on the body (an entity id, an index): never read by
 * lfem, 0 at creation. Unlike user_data (a pointer, meaningless in another process), checkpoints
 * keep it: a loaded world's bodies find their entities again. */
LFEM_API lfem_status lfem_body_set_user_id(lfem_world* world, lfem_body body, uint64_t user_id);
/** See lfem_body_set_user_id. */
LFEM_API lfem_status lfem_body_get_user_id(const lfem_world* world, lfem_body body, uint64_t* out);

/** A one-shot impulse (N s) at a world point (m), as a hit gives it: a deformable body takes it on
 * the nodes of the tet around the point (where the nodes are now; a point on the surface, within
 * one boundary edge of the body, counts), each node its share by the tet's shape functions
 * there, so the body gains the impulse as momentum and point x impulse as angular momentum
 * about the origin (a fixed or prescribed node's share goes to its support); a rigid body takes
 * it as a whole. The change of kinetic energy is the caller's work; the body wakes. Finding the
 * tet costs O(T log T) for T tets. A deformable or rigid body with a mesh. */
LFEM_API lfem_status lfem_body_apply_impulse(lfem_world* world, lfem_body body, const double point[3],
                                             const double impulse[3]);

/** A force (N) at a world point (m) for the next lfem_world_step call only, over all its
 * sub-steps, on top of the node forces (lfem_body_set_node_forces); the call's end drops it (a
 * call that fails keeps it for the next). Forces applied before one call add up. The point is
 * bound to the body where it is now (the nodes of the tet around it, each its share by the
 * tet's shape functions, as lfem_body_apply_impulse) and moves with the body during the call;
 * the body feels the force and its moment about any point. A deformable body: a point inside
 * it or within one boundary edge of its surface; a rigid body: any point (its nearest tet's
 * weights, extrapolated). A fixed or prescribed node's share goes to its support. The body
 * wakes; checkpoints keep a pending force. A deformable or rigid body with a mesh. */
LFEM_API lfem_status lfem_body_apply_force(lfem_world* world, lfem_body body, const double point[3],
                                           const double force[3]);

/** The body's pose: the rigid motion x = R X + t that carries its mesh as added (X) to where its
 * nodes are now (x); out[0..2] = t (m), out[3..6] = R as a unit quaternion (w, x, y, z). A rigid
 * body's exactly, a kinematic body's as it has moved and turned, a static body's the identity;
 * a deformable body's best fit (the polar rotation of sum m (x - c)(X - C)^T about the centres
 * of mass, the floating frame of the "paper" model), for an engine to parent objects to. */
LFEM_API lfem_status lfem_body_get_transform(const lfem_world* world, lfem_body body, double out[7]);

/** The centre of mass where the nodes are now (m): a rigid body's centre, a kinematic body's
 * pivot, a static body's centre as added. */
LFEM_API lfem_status lfem_body_get_center_of_mass(const lfem_world* world, lfem_body body,
                                                  double out[3]);

/** Teleport a body rigidly, at once, to the pose `transform` (t, then a quaternion w x y z,
 * normalised here: lfem_body_get_transform then gives it). Its velocities are kept (a rigid
 * body's spin turns with it) and no work is done; its pairs end and what rested on it wakes, as
 * with lfem_body_set_positions. Rigid, kinematic and deformable bodies with a mesh or shapes; a
 * static body does not move (LFEM_INVALID_ARGUMENT). */
LFEM_API lfem_status lfem_body_set_transform(lfem_world* world, lfem_body body,
                                             const double transform[7]);

/** Boundary triangles (3 node indices each, counter-clockwise seen from outside): the flat
 * triangles contact uses, which for a body of 10-node tets are the 4 triangles of each 6-node
 * face (corner, mid-edge nodes): (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca). */
LFEM_API lfem_status lfem_body_get_boundary_triangle_count(const lfem_world* world,
                                                           lfem_body body, uint32_t* out);
/** Copy the boundary triangles into out[3*triangle_capacity]. */
LFEM_API lfem_status lfem_body_get_boundary_triangles(const lfem_world* world, lfem_body body,
                                                      uint32_t* out,
                                                      uint32_t triangle_capacity);

/** The boundary as faces: for a body of 10-node tets its 6-node triangles (6 node indices each:
 * corners a, b, c counter-clockwise seen from outside, then the mid-edge nodes of ab, bc, ca),
 * for any other body its boundary triangles (3 each). face_capacity counts faces. */
LFEM_API lfem_status lfem_body_get_boundary_face_count(const lfem_world* world, lfem_body body,
                                                       uint32_t* out);
/** Copy the boundary faces into out[6*face_capacity] (10-node tets) or out[3*face_capacity]. */
LFEM_API lfem_status lfem_body_get_boundary_faces(const lfem_world* world, lfem_body body,
                                                  uint32_t* out, uint32_t face_capacity);

/** Von Mises equivalent of the Cauchy stress in each tet (Pa), into out[tet_capacity]; of a
 * 10-node tet, of its mean stress over its quadrature points. */
LFEM_API lfem_status lfem_body_get_von_mises_stress(const lfem_world* world, lfem_body body,
                                                    double* out, uint32_t tet_capacity);

/** The body's global rotation (row-major 3x3): a rigid body's rotation, the floating frame of
 * the "paper" model (re-fitted to the nodes), or how far a kinematic body has turned since it
 * was created. Identity otherwise. */
LFEM_API lfem_status lfem_body_get_rotation(const lfem_world* world, lfem_body body,
                                            double out[9]);

/** The nodes whose current position lies inside the axis-aligned box [lo, hi] (m). *count is
 * always the total found; LFEM_BUFFER_TOO_SMALL when it exceeds capacity (out untouched).
 * out is nullable when capacity is 0 (to ask for the count). */
LFEM_API lfem_status lfem_body_find_nodes_in_box(const lfem_world* world, lfem_body body,
                                                 const double lo[3], const double hi[3],
                                                 uint32_t* out, uint32_t capacity,
                                                 uint32_t* count);

/** Fix nodes in place (velocity 0 from now on). Indices must be in range and distinct. */
LFEM_API lfem_status lfem_body_fix_nodes(lfem_world* world, lfem_body body,
                                         const uint32_t* nodes, uint32_t count);
/** Prescribe a constant velocity (m/s) for nodes: they move at it, whatever the forces. */
LFEM_API lfem_status lfem_body_prescribe_node_velocity(lfem_world* world, lfem_body body,
                                                       const uint32_t* nodes, uint32_t count,
                                                       const double velocity[3]);
/** Give fixed or prescribed nodes back to the dynamics. */
LFEM_API lfem_status lfem_body_release_nodes(lfem_world* world, lfem_body body,
                                             const uint32_t* nodes, uint32_t count);

/** Set a constant external force (N, 3 per listed node) that acts on every following step
 * until changed; it replaces any earlier force on those nodes. Added to gravity. */
LFEM_API lfem_status lfem_body_set_node_forces(lfem_world* world, lfem_body body,
                                               const uint32_t* nodes, uint32_t count,
                                               const double* forces);
/** Remove every external node force of the body. */
LFEM_API lfem_status lfem_body_clear_node_forces(lfem_world* world, lfem_body body);

/** The velocity of a kinematic body: linear (m/s) of its centre and angular (rad/s) about it. */
LFEM_API lfem_status lfem_body_set_kinematic_velocity(lfem_world* world, lfem_body body,
                                                      const double linear[3],
                                                      const double angular[3]);

/** Sleeping (lfem_world_def.enable_sleep). A sleeping body wakes when an awake body touches
 * it, when its velocities, node forces, supports or attachments change (or those of a kinematic
 * body touching it), when gravity changes, or on request. Waking a body does not wake what
 * touches it until that is touched in turn. Both are reported as events (lfem_world_get_events). */
LFEM_API lfem_status lfem_body_wake(lfem_world* world, lfem_body body);
/** Whether the body may fall asleep (lfem_body_def.enable_sleep after creation: 1 or 0); 0 wakes
 * it. */
LFEM_API lfem_status lfem_body_set_sleep_allowed(lfem_world* world, lfem_body body, int allowed);
/** 1 when the body is awake (static bodies and bodies without a mesh: 1), 0 when asleep, -1 for
 * an invalid world or handle. */
LFEM_API int lfem_body_is_awake(const lfem_world* world, lfem_body body);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Attachments                                                                                */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup attachments Attachments
 * @{ */

/** Hold nodes, or points found by position, of a deformable body in the frame of a target or at
 * material points of another deformable body, rigidly or by a spring and damper
 * (lfem_attachment_def says how), from a definition started with lfem_attachment_def_default().
 * A spring is solved implicitly with the contacts (its force at the end of each sub-step):
 * stable at any stiffness, with a numerical damping ratio of omega h / 2 for its frequency omega
 * and the sub-step h. Bad input (nodes and points together or neither, a point farther than one
 * boundary edge from the body or from a deformable target, a negative stiffness, a damper
 * without a spring) is refused with the world unchanged. */
LFEM_API lfem_status lfem_attachment_create(lfem_world* world, const lfem_attachment_def* def,
                                            lfem_attachment* out);
/** Destroy an attachment; its handle becomes stale. */
LFEM_API lfem_status lfem_attachment_destroy(lfem_world* world, lfem_attachment attachment);
/** 1 when the handle names a live attachment of this world, else 0. */
LFEM_API int lfem_attachment_is_valid(const lfem_world* world, lfem_attachment attachment);
/** Null target only: where the frame is to be at the end of the next lfem_world_step (centre and
 * unit quaternion); the step moves it there uniformly over its sub-steps (a lerp of the
 * centre, an nlerp of the rotation), so a frame set once per frame drags the nodes smoothly. */
LFEM_API lfem_status lfem_attachment_set_frame(lfem_world* world, lfem_attachment attachment,
                                               const double frame[7]);
/** Null target only: the frame the attachment holds its nodes to (centre, unit quaternion w x y
 * z) as the caller last set it (where it is at the end of the next step). */
LFEM_API lfem_status lfem_attachment_get_frame(const lfem_world* world, lfem_attachment attachment,
                                               double frame[7]);
/** The total force (N) the attachment put on the body's nodes at the last sub-step (the target
 * feels the opposite). */
LFEM_API lfem_status lfem_attachment_get_force(const lfem_world* world, lfem_attachment attachment,
                                               double force[3]);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Rigid shapes of static and kinematic bodies                                                */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup shapes Rigid shapes of static and kinematic bodies
 * @{ */

/** Give a static or kinematic body a rigid shape (a body may have several, with or without a
 * tet mesh). Deformable bodies' boundary nodes collide with it. A kinematic body's shapes move
 * with its velocity (about the body's centre: its mesh's centre of mass, or the first shape's
 * centre for a body without mesh). *index (nullable) receives the shape's index on the body,
 * 0 for its first shape: the `shape` of the contacts that touch it. */
LFEM_API lfem_status lfem_body_add_shape(lfem_world* world, lfem_body body,
                                         const lfem_shape_def* def, uint32_t* index);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Contacts                                                                                   */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup contacts Contacts
 * @{ */

/** Copy the active contacts of the last step into out[capacity]. *count is always the total;
 * LFEM_BUFFER_TOO_SMALL (nothing copied) when it exceeds capacity. out is nullable when
 * capacity is 0 (to ask for the count). Contacts are listed in a fixed order (by body_a, then
 * node, then body_b and shape), so repeated runs give the same list. */
LFEM_API lfem_status lfem_world_query_contacts(const lfem_world* world, lfem_contact* out,
                                               uint32_t capacity, uint32_t* count);

/** Copy the events of the last step (lfem_event) into out[capacity], in a fixed order (contact
 * events by pair, then sleep and wake events by body, then broken attachments). Same capacity
 * rules as lfem_world_query_contacts. */
LFEM_API lfem_status lfem_world_get_events(const lfem_world* world, lfem_event* out, uint32_t capacity,
                                           uint32_t* count);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Skins: render meshes embedded in a body's tets                                             */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup skins Skins: render meshes embedded in a body's tets
 * A game draws a fine triangle mesh, not the simulation's tets. lfem_body_add_skin takes such a
 * mesh in the body's rest frame (the coordinates of the meshes given to lfem_body_add_mesh) and
 * binds each vertex once, by barycentric weights, to the tet that contains it; a vertex just
 * outside the body (within one mean boundary edge of it) is bound to the nearest tet by the
 * same weights extended affinely (some negative). Farther vertices are refused. The deformed
 * vertex is then the weighted sum of the tet's corner nodes at their current positions: a
 * vertex follows its tet exactly, and any affine motion of the tet (a stretch, a shear, a
 * rotation, a translation) is reproduced to round-off, inside the tet or out. On a body of
 * 10-node tets a vertex is bound to all ten nodes of its tet, by the element's quadratic shape
 * functions at the vertex (in a curved element, one whose mid-edge nodes sit off its edges, at
 * the element coordinates that reach the vertex, found by Newton's iterations; where those do
 * not converge, far outside a strongly curved element, by its corners' barycentric weights
 * alone): the skin bends with the element as its displacement field and its contact surface
 * (through the mid-edge nodes) do, reproduces any quadratic displacement of a straight-sided
 * element and any affine motion to round-off; "just outside" is measured to the tet's corners'
 * straight tet. Several skins
 * per body; skins are the body's data: checkpoints keep them, and no step reads them, so they
 * cost nothing until read. Any body with tets may have skins (deformable, rigid, static,
 * kinematic: they follow its nodes); not a body of a triangle mesh or shapes alone. A mesh
 * added to the body later leaves the skins bound as they were (to the tets they were bound
 * to). Vertices and triangles are the caller's own numbering, kept as given. Like every call on
 * a world, not to be made from two threads at once.
 * @{ */

/** Bind a triangle mesh to the body's tets. positions: 3*vertex_count doubles (m, finite, the
 * body's rest frame); triangles: 3*triangle_count vertex indices (< vertex_count, three
 * different ones per triangle; counter-clockwise seen from outside for outward normals).
 * vertex_count and triangle_count >= 1. A triangle index out of range or repeated gives
 * LFEM_INVALID_MESH; a vertex farther than one mean boundary edge from every tet,
 * LFEM_INVALID_ARGUMENT naming it; a body without tets, LFEM_INVALID_ARGUMENT. The arrays are
 * copied. *skin_index (nullable) receives the skin's index on the body, 0 for its first. */
LFEM_API lfem_status lfem_body_add_skin(lfem_world* world, lfem_body body, const double* positions,
                                        uint32_t vertex_count, const uint32_t* triangles,
                                        uint32_t triangle_count, uint32_t* skin_index);
/** Remove a skin; the skins after it move down one index (skin < lfem_body_get_skin_count). */
LFEM_API lfem_status lfem_body_remove_skin(lfem_world* world, lfem_body body, uint32_t skin);
/** The number of skins of the body. */
LFEM_API lfem_status lfem_body_get_skin_count(const lfem_world* world, lfem_body body, uint32_t* out);
/** The vertex and triangle counts of a skin (skin < lfem_body_get_skin_count, else
 * LFEM_INVALID_ARGUMENT). Either output is nullable. */
LFEM_API lfem_status lfem_body_get_skin_sizes(const lfem_world* world, lfem_body body, uint32_t skin,
                                              uint32_t* vertex_count, uint32_t* triangle_count);
/** The skin's triangles as given, into out[3*triangle_capacity]. LFEM_BUFFER_TOO_SMALL when
 * triangle_capacity is below its triangle count (nothing written). */
LFEM_API lfem_status lfem_body_get_skin_triangles(const lfem_world* world, lfem_body body, uint32_t skin,
                                                  uint32_t* out, uint32_t triangle_capacity);
/** The deformed skin: positions (m) into positions[3*vertex_capacity] and, when normals is not
 * NULL, unit smooth normals into normals[3*vertex_capacity]: at each vertex the normalised sum
 * of (b - a) x (c - a) over the skin's triangles (a, b, c) around it, i.e.\ their unit normals
 * weighted by area; a vertex whose triangles have no area gets (0, 0, 0). LFEM_BUFFER_TOO_SMALL
 * when vertex_capacity is below the vertex count (nothing written). */
LFEM_API lfem_status lfem_body_get_skin_vertices(const lfem_world* world, lfem_body body, uint32_t skin,
                                                 double* positions, double* normals, uint32_t vertex_capacity);
/** The same as floats for a vertex buffer: vertex i at positions[i*position_stride + 0..2]
 * and its normal (when normals is not NULL) at normals[i*normal_stride + 0..2]; strides are in
 * floats, >= 3 (normal_stride is checked only with normals), so positions and normals may
 * interleave in one buffer (normals = positions + 3, both strides 6). The floats between are not
 * touched.
 * The buffers must hold (vertex_capacity - 1) * stride + 3 floats. */
LFEM_API lfem_status lfem_body_get_skin_vertices_f32(const lfem_world* world, lfem_body body, uint32_t skin,
                                                     float* positions, uint32_t position_stride, float* normals,
                                                     uint32_t normal_stride, uint32_t vertex_capacity);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Queries: rays and boxes against the current geometry                                       */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup queries Queries: rays and boxes against the current geometry
 * The queries read the world as it is after the last call (the bodies' current, deformed
 * boundary triangles, for a body of 10-node tets the 4 flat triangles of each 6-node face
 * through its mid-edge nodes, as contact sees them, and their rigid shapes) and change nothing
 * a step reads: stepping gives
 * bitwise the same results whether or not queries were made. Their cost follows what the ray or
 * box meets, not the size of the scene: the step keeps a box per body and a tree of them
 * current once queries are in use; a static body's triangle tree is the one built with its mesh,
 * and a moving body's tree is refitted only when a query reaches it after it moved (the profile
 * counts queries, bodies reached, triangles and shapes tested and refits). The queries keep
 * that cache inside the world: although they take a const world, do not make them from two
 * threads at once, nor beside any other call on the same world.
 * @{ */

/** Cast the ray origin + t * direction / |direction| (m), t in [0, max_distance]: the nearest
 * crossing of the surface of a body the filter sees (a boundary triangle, from either side, at
 * its current position; or a plane, box, sphere, capsule or convex hull shape's surface). A ray
 * starting inside a body or a shape meets its surface on the way out (the normal then points
 * along the ray). direction: finite, any non-zero length; max_distance >= 0 (HUGE_VAL for no
 * limit). *hit = 1 and *out set when something was hit, else *hit = 0 and *out untouched.
 * Equally near hits are ordered by body index, triangles before shapes, then index: the answer
 * depends on the geometry alone (a ray through an edge or a corner shared by several triangles
 * reports one of them). */
LFEM_API lfem_status lfem_world_cast_ray(const lfem_world* world, const double origin[3],
                                         const double direction[3], double max_distance,
                                         lfem_query_filter filter, lfem_ray_hit* out, int* hit);

/** A sphere of radius (m, finite, >= 0) swept along the ray (origin, direction, max_distance as
 * lfem_world_cast_ray): the first place it touches a surface the filter sees, a boundary
 * triangle at its current position or a shape. out->distance: how far its centre went along the
 * unit ray; out->point: the point of the surface it touches (on the triangle, with its
 * barycentric weights; or on the shape); out->normal: unit, from that point towards the
 * sphere's centre. A sphere that starts touching or overlapping something hits it at distance
 * 0. Radius 0 is a ray that also meets edges it grazes. *hit = 1 and *out set on a hit, else
 * *hit = 0 and *out untouched. Found by conservative advancement on each candidate (the
 * distance to a convex piece less the radius, stepped until it is within 1e-12 m): exact head
 * on, converging at a grazing touch. */
LFEM_API lfem_status lfem_world_cast_sphere(const lfem_world* world, const double origin[3],
                                            const double direction[3], double radius, double max_distance,
                                            lfem_query_filter filter, lfem_ray_hit* out, int* hit);

/** The point of the body's surface (its boundary triangles where its nodes are now) nearest to
 * `point` (m): into out_point; *triangle (nullable) its triangle in lfem_body_get_boundary_triangles
 * order (the first among equally near ones), *distance (nullable) how far (m; a point inside the
 * body gets its distance to the nearest face). A body with boundary triangles (a body of shapes
 * alone: LFEM_INVALID_ARGUMENT); O(T) in its triangles. Nothing written on failure. */
LFEM_API lfem_status lfem_body_closest_point(const lfem_world* world, lfem_body body, const double point[3],
                                             double out_point[3], uint32_t* triangle, double* distance);

/** Every crossing along the ray, nearest first (ties as above); a ray through a body crosses
 * its surface where it enters and where it leaves, a sphere or box shape twice, a plane once
 * (and a ray through an edge or corner may list each triangle that shares it). *count is always
 * the total; LFEM_BUFFER_TOO_SMALL when it exceeds capacity (out untouched). out is nullable
 * when capacity is 0 (to ask for the count). */
LFEM_API lfem_status lfem_world_cast_ray_all(const lfem_world* world, const double origin[3],
                                             const double direction[3], double max_distance,
                                             lfem_query_filter filter, lfem_ray_hit* out,
                                             uint32_t capacity, uint32_t* count);

/** The bodies the filter sees whose current geometry overlaps the box [lo, hi] (m, finite, lo <=
 * hi on every axis; touching counts): a boundary triangle or a shape (solid: a box inside a
 * sphere overlaps it) that meets the box, or a body of tets that holds the box inside it. In
 * body index order. *count is always the total; LFEM_BUFFER_TOO_SMALL when it exceeds capacity
 * (out untouched). out is nullable when capacity is 0. */
LFEM_API lfem_status lfem_world_overlap_box(const lfem_world* world, const double lo[3], const double hi[3],
                                            lfem_query_filter filter, lfem_body* out, uint32_t capacity,
                                            uint32_t* count);

/** The bodies the filter sees that the solid sphere (center, radius: m, finite, radius >= 0)
 * overlaps, touching counting: one of their boundary triangles or shapes (solid) within radius
 * of the centre, or a body of tets that holds the centre inside. In body index order, each with
 * its triangle or shape nearest the centre and the point of it (lfem_overlap). *count is always
 * the total; LFEM_BUFFER_TOO_SMALL when it exceeds capacity (out untouched). out is nullable when
 * capacity is 0. */
LFEM_API lfem_status lfem_world_overlap_sphere(const lfem_world* world, const double center[3], double radius,
                                               lfem_query_filter filter, lfem_overlap* out, uint32_t capacity,
                                               uint32_t* count);
/** The same for the capsule of the segment from a to b (m) swept by radius; a == b is a sphere.
 * The point of each body nearest the segment is found to 1e-16 of its length (a search along it:
 * the distance to a triangle or a convex shape is convex there). */
LFEM_API lfem_status lfem_world_overlap_capsule(const lfem_world* world, const double a[3], const double b[3],
                                                double radius, lfem_query_filter filter, lfem_overlap* out,
                                                uint32_t capacity, uint32_t* count);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Meshes: builders and Gmsh import                                                           */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup meshes Meshes: builders and Gmsh import
 * @{ */

/** A box [0,size[0]] x [0,size[1]] x [0,size[2]] (m) of cells[0]*cells[1]*cells[2] hexahedra,
 * each split into 6 tets (all cells >= 1). */
LFEM_API lfem_status lfem_mesh_create_box(const double size[3], const uint32_t cells[3],
                                          lfem_mesh** out);
/** A solid cylinder along +z from z = 0 to height, radius (m); segments around (>= 3),
 * rings across the radius (>= 1), layers along the height (>= 1). */
LFEM_API lfem_status lfem_mesh_create_cylinder(double radius, double height, uint32_t segments,
                                               uint32_t rings, uint32_t layers,
                                               lfem_mesh** out);
/** A hollow cup with a bottom, open at the top: outer radius, height (m, along +z from z = 0),
 * wall thickness and bottom thickness (m); segments around (>= 3), layers along the wall
 * (>= 1). */
LFEM_API lfem_status lfem_mesh_create_cup(double outer_radius, double height, double wall,
                                          double bottom, uint32_t segments, uint32_t layers,
                                          lfem_mesh** out);
/** A hammer: a square handle of side handle_width along +z from z = 0 to handle_length, and a
 * head (head_length along x, head_width in y and z) centred on the handle's top end, one
 * conforming mesh of cells of about cell_size (m). */
LFEM_API lfem_status lfem_mesh_create_hammer(double handle_length, double handle_width,
                                             double head_length, double head_width,
                                             double cell_size, lfem_mesh** out);

/** Read the tetrahedra of a Gmsh .msh file (ASCII format 2.2 or 4.1): 4-node tets (element
 * type 4) or 10-node tets (type 11, turned into lfem's node order, see
 * lfem_body_add_quadratic_mesh), not both in one file; other cell types are skipped, unused
 * nodes dropped, negatively oriented tets reordered. A missing or malformed file gives
 * LFEM_IO_ERROR with the line number in the message. */
LFEM_API lfem_status lfem_mesh_load_gmsh(const char* path, lfem_mesh** out);

/** Turn a mesh of 4-node tets into 10-node (quadratic) tets: a node at the middle of every edge
 * (numbered after the corners, which keep their indices), shared by the tets around the edge.
 * Serves every builder and any linear mesh. LFEM_INVALID_ARGUMENT for a mesh that already has
 * 10-node tets (the mesh is then unchanged). */
LFEM_API lfem_status lfem_mesh_make_quadratic(lfem_mesh* mesh);

/** Destroy a mesh. Nullable. */
LFEM_API void lfem_mesh_destroy(lfem_mesh* mesh);

/** \name Read-only views
 * Valid until the mesh is changed or destroyed. NULL / 0 for a NULL mesh.
 * @{ */
/** The number of nodes. */
LFEM_API uint32_t lfem_mesh_get_node_count(const lfem_mesh* mesh);
/** The number of tets. */
LFEM_API uint32_t lfem_mesh_get_tet_count(const lfem_mesh* mesh);
/** 4, or 10 for a mesh of quadratic tets (lfem_mesh_make_quadratic, a Gmsh file of type 11). */
LFEM_API uint32_t lfem_mesh_get_nodes_per_tet(const lfem_mesh* mesh);
/** The node positions (m), 3 per node. */
LFEM_API const double* lfem_mesh_get_positions(const lfem_mesh* mesh);
/** The tets: nodes_per_tet node indices per tet. */
LFEM_API const uint32_t* lfem_mesh_get_tets(const lfem_mesh* mesh);
/** @} */

/** Move a mesh by offset (m). */
LFEM_API lfem_status lfem_mesh_translate(lfem_mesh* mesh, const double offset[3]);
/** Rotate a mesh about the origin by angle (rad) around axis. */
LFEM_API lfem_status lfem_mesh_rotate(lfem_mesh* mesh, const double axis[3], double angle);
/** @} */

/* ---------------------------------------------------------------------------------------- */
/* Output: a VTK time series that ParaView opens                                              */
/* ---------------------------------------------------------------------------------------- */
/** \addtogroup output Output: a VTK time series that ParaView opens
 * @{ */

/** Start a series: pvd_path names the .pvd collection file; frames go beside it as
 * `<stem>_<frame>.vtu`. Nothing is written yet: a folder that does not exist or cannot be written
 * is reported (LFEM_IO_ERROR) by the first lfem_vtk_series_write_frame. */
LFEM_API lfem_status lfem_vtk_series_create(const char* pvd_path, lfem_vtk_series** out);
/** Write every body of the world (positions, velocities, von Mises stress, body index) as the
 * next frame at the world's time, and rewrite the .pvd so it is valid after every frame. Tets
 * are VTK_TETRA cells, 10-node tets VTK_QUADRATIC_TETRA (24). */
LFEM_API lfem_status lfem_vtk_series_write_frame(lfem_vtk_series* series,
                                                 const lfem_world* world);
/** Destroy a series. Nullable. */
LFEM_API void lfem_vtk_series_destroy(lfem_vtk_series* series);
/** @} */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* LFEM_H */
