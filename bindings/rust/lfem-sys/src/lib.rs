//! Raw declarations of `lfem.h`, the C ABI of lfem, written by hand: one `extern "C"` item per
//! function, `#[repr(C)]` structs with the C layout (checked at compile time against the sizes
//! that `bindings/abi_layout.c` asserts in C), enums as 32-bit integers with constants.
//!
//! Everything here is `unsafe` and follows the C contract documented in `lfem.h`. Use the `lfem`
//! crate for a safe API.
#![allow(non_camel_case_types)]

use std::marker::{PhantomData, PhantomPinned};
use std::mem::size_of;
use std::os::raw::{c_char, c_double, c_int, c_void};

pub const LFEM_VERSION_MAJOR: u32 = 0;
pub const LFEM_VERSION_MINOR: u32 = 5;
pub const LFEM_VERSION_PATCH: u32 = 0;

// ---- enums: 32-bit integers in C; kept as integers here (an unknown value is not UB) ---------

pub type lfem_status = c_int;
pub const LFEM_OK: lfem_status = 0;
pub const LFEM_INVALID_ARGUMENT: lfem_status = 1;
pub const LFEM_INVALID_MESH: lfem_status = 2;
pub const LFEM_INVALID_HANDLE: lfem_status = 3;
pub const LFEM_BUFFER_TOO_SMALL: lfem_status = 4;
pub const LFEM_UNSTABLE: lfem_status = 5;
pub const LFEM_IO_ERROR: lfem_status = 6;
pub const LFEM_OUT_OF_MEMORY: lfem_status = 7;
pub const LFEM_INTERNAL_ERROR: lfem_status = 8;
pub const LFEM_UNSUPPORTED: lfem_status = 9;

pub type lfem_body_type = c_int;
pub const LFEM_BODY_DEFORMABLE: lfem_body_type = 0;
pub const LFEM_BODY_STATIC: lfem_body_type = 1;
pub const LFEM_BODY_KINEMATIC: lfem_body_type = 2;
pub const LFEM_BODY_RIGID: lfem_body_type = 3;

pub type lfem_model = c_int;
pub const LFEM_MODEL_PAPER: lfem_model = 0;
pub const LFEM_MODEL_COROTATIONAL: lfem_model = 1;
pub const LFEM_MODEL_NEO_HOOKEAN: lfem_model = 2;
pub const LFEM_MODEL_LINEAR: lfem_model = 3;

pub type lfem_shape_type = c_int;
pub const LFEM_SHAPE_PLANE: lfem_shape_type = 0;
pub const LFEM_SHAPE_BOX: lfem_shape_type = 1;
pub const LFEM_SHAPE_SPHERE: lfem_shape_type = 2;
pub const LFEM_SHAPE_CAPSULE: lfem_shape_type = 3;
pub const LFEM_SHAPE_CONVEX_HULL: lfem_shape_type = 4;

// ---- opaque objects ------------------------------------------------------------------------

/// Opaque world (`lfem_world*`).
#[repr(C)]
pub struct lfem_world {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}

/// Opaque mesh (`lfem_mesh*`).
#[repr(C)]
pub struct lfem_mesh {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}

/// Opaque VTK time series (`lfem_vtk_series*`).
#[repr(C)]
pub struct lfem_vtk_series {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}

// ---- structs ---------------------------------------------------------------------------------

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct lfem_world_def {
    pub gravity: [c_double; 3],
    pub time_step: c_double,
    pub step_safety: c_double,
    pub contact_iterations: u32,
    pub thread_count: u32,
    pub contact_tolerance: c_double,
    pub max_substeps: u32,
    pub allow_unstable_step: u8,
    pub enable_sleep: u8,
    pub padding: [u8; 2],
    pub internal_value: u32,
    pub padding2: u32,
    pub mass_scaling_step: c_double,
    pub sleep_velocity: c_double,
    pub sleep_time: c_double,
}

/// Statistics of a world (lfem_world_stats): time, energies and momenta of the moving
/// (deformable) bodies, solver figures.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_world_stats {
    /// s, simulated time.
    pub time: c_double,
    /// Sub-steps taken since creation.
    pub steps: u64,
    /// s, size of the last sub-step (0 before the first).
    pub step_size: c_double,
    /// s, the stable limit (see `lfem_world_get_stable_step`).
    pub stable_step: c_double,
    /// Sub-steps taken by the last `lfem_world_step`.
    pub substeps_last_call: u32,
    /// Live bodies of every type.
    pub body_count: u32,
    /// J, of the moving (deformable) bodies, from the synchronized velocities.
    pub kinetic_energy: c_double,
    /// J, of the deformable bodies.
    pub strain_energy: c_double,
    /// J, work done since creation by gravity, node forces and prescribed node velocities.
    pub external_work: c_double,
    /// J, removed since creation by damping (and contact).
    pub dissipated_energy: c_double,
    /// J, kinetic + strain + dissipated - external_work - initial energy: a run-time error indicator, ideally 0.
    pub energy_error: c_double,
    /// kg m/s, of the moving bodies.
    pub linear_momentum: [c_double; 3],
    /// kg m^2/s, about the world origin.
    pub angular_momentum: [c_double; 3],
    /// Active contacts after the last step.
    pub contact_count: u32,
    /// Contact solver sweeps in the last sub-step.
    pub solver_iterations: u32,
    /// m, largest remaining constraint violation, last sub-step.
    pub solver_residual: c_double,
    /// m, largest penetration after the last sub-step.
    pub max_penetration: c_double,
    /// rad, largest angle between the global rotation integrated by eq. (2) and the one re-fitted to the nodes, last sub-step ("paper" model only, else 0).
    pub rotation_drift: c_double,
    /// kg, added by mass scaling to every body.
    pub added_mass: c_double,
    /// Tets turned inside out (J = det F <= 0) over the deformable bodies after the last sub-step.
    pub inverted_tets: u32,
    pub padding: u32,
    /// The smallest volume ratio J of their tets after the last sub-step (1 without any).
    pub min_jacobian: c_double,
}

/// An attachment handle (lfem_attachment).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct lfem_attachment {
    pub index: u32,
    pub generation: u32,
}

/// How an attachment is set up (lfem_attachment_def).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct lfem_attachment_def {
    pub body: lfem_body,
    pub target: lfem_body,
    pub nodes: *const u32,
    pub node_count: u32,
    pub internal_value: u32,
    pub frame: [c_double; 7],
    pub break_force: c_double,
    pub points: *const c_double,
    pub point_count: u32,
    pub stiffness: c_double,
    pub damping: c_double,
}

/// The kinds of event (lfem_event_type).
pub type lfem_event_type = c_int;
pub const LFEM_EVENT_CONTACT_BEGIN: lfem_event_type = 0;
pub const LFEM_EVENT_CONTACT_END: lfem_event_type = 1;
pub const LFEM_EVENT_SLEEP: lfem_event_type = 2;
pub const LFEM_EVENT_WAKE: lfem_event_type = 3;
pub const LFEM_EVENT_ATTACHMENT_BROKEN: lfem_event_type = 4;
pub const LFEM_EVENT_CONTACT_PERSIST: lfem_event_type = 5;

/// One event of the last step (lfem_event).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_event {
    pub type_: lfem_event_type,
    pub contact_count: u32,
    pub body_a: lfem_body,
    pub body_b: lfem_body,
    pub attachment: lfem_attachment,
    pub normal_impulse: c_double,
    pub max_force: c_double,
    pub approach_speed: c_double,
    pub point: [c_double; 3],
    pub normal: [c_double; 3],
}

/// The kinds of warning (lfem_warning_kind).
pub type lfem_warning_kind = c_int;
pub const LFEM_WARNING_INVERTED_TETS: lfem_warning_kind = 0;
pub const LFEM_WARNING_STAYS_INVERTED: lfem_warning_kind = 1;
pub const LFEM_WARNING_FALLEN_IN: lfem_warning_kind = 2;
pub const LFEM_WARNING_UNCONVERGED: lfem_warning_kind = 3;
pub const LFEM_WARNING_KIND_COUNT: lfem_warning_kind = 4;

/// One warning counter (lfem_warning): how often, when last, for which body.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_warning {
    /// Since the world was created or `lfem_world_clear_warnings`.
    pub count: u64,
    /// s, the simulated time of the last one (0 before any).
    pub last_time: c_double,
    /// The body of the last one; the null handle when none is concerned.
    pub last_body: lfem_body,
}

/// Time (s) and count of one phase of the step (lfem_phase_time).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_phase_time {
    /// s, wall time spent in the phase.
    pub seconds: c_double,
    /// How often it ran (the unit is given per phase in `lfem_profile`).
    pub calls: u64,
}

/// Per-phase time and counts of the step, accumulated (lfem_profile).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_profile {
    /// Sub-steps profiled.
    pub substeps: u64,
    /// Elastic forces element by element; calls: deformable bodies x sub-steps.
    pub internal_forces: lfem_phase_time,
    /// Central-difference predictor (eqs. 1, 3) and the rigid bodies' free motion; calls: deformable and rigid bodies x sub-steps.
    pub predictor: lfem_phase_time,
    /// Rigid motion of kinematic bodies; calls: kinematic bodies x sub-steps.
    pub kinematic_motion: lfem_phase_time,
    /// Swept boxes of the boundary triangles and the spatial hash; calls: sub-steps that ran detection.
    pub broad_phase: lfem_phase_time,
    /// Per slave node: hash query and node-triangle tests (eqs. 5, 6); calls: sub-steps that ran detection.
    pub narrow_phase: lfem_phase_time,
    /// Nodes against rigid shapes; calls: sub-steps in which some body had shapes to test against.
    pub shape_queries: lfem_phase_time,
    /// Point queries of shapes: closed form and libccd.
    pub shape_tests: u64,
    /// Of those, libccd MPR queries (convex hulls).
    pub ccd_queries: u64,
    /// Multiplier solve: set-up, warm start, normal (tension release) updates; calls: sub-steps with pairs to solve.
    pub normal_solve: lfem_phase_time,
    /// Multiplier solve: tangential updates and the return onto the Coulomb cone (eq. 7); calls: sub-steps with a pair of non-zero friction.
    pub friction: lfem_phase_time,
    /// Eq. (2) and the re-fit of the floating frame; calls: "paper"-model bodies x sub-steps.
    pub global_rotation: lfem_phase_time,
    /// Velocities, contact forces, energy bookkeeping; calls: sub-steps.
    pub commit: lfem_phase_time,
    /// How often contact searched for candidate faces anew (only when a body moved beyond the
    /// margin of the last search, or the bodies changed).
    pub candidate_searches: u64,
    /// Rays and boxes the queries answered.
    pub queries: u64,
    /// Bodies a query reached (their box met, the filter passed).
    pub query_bodies: u64,
    /// Triangles and shapes a query tested exactly.
    pub query_primitives: u64,
    /// Trees of moving bodies' triangles built or refitted for the queries.
    pub query_refits: u64,
    /// Sweeps of the contact solve (its slowest group's per sub-step), summed.
    pub contact_sweeps: u64,
    /// Updates of one constraint in a sweep, summed over every group and sweep.
    pub constraint_updates: u64,
}

/// A body handle: a value, `{0, 0}` is the null handle.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct lfem_body {
    pub index: u32,
    pub generation: u32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct lfem_body_def {
    pub type_: lfem_body_type,
    pub model: lfem_model,
    pub young_modulus: c_double,
    pub poisson_ratio: c_double,
    pub density: c_double,
    pub damping: c_double,
    pub friction: c_double,
    pub linear_velocity: [c_double; 3],
    pub angular_velocity: [c_double; 3],
    pub category_bits: u32,
    pub mask_bits: u32,
    pub user_data: *mut c_void,
    pub internal_value: u32,
    pub enable_sleep: u8,
    pub self_contact: u8,
    pub composite_tets: u8,
    pub report_contacts: u8,
    pub edge_contacts: u8,
    pub padding: [u8; 7],
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_contact {
    pub body_a: lfem_body,
    pub body_b: lfem_body,
    pub node: u32,
    pub triangle: [u32; 3],
    pub barycentric: [c_double; 2],
    pub position: [c_double; 3],
    pub normal: [c_double; 3],
    pub force: [c_double; 3],
    pub sliding: u8,
    pub kind: u8,
    pub padding: [u8; 2],
    /// Index of body_b's shape, or u32::MAX when the node touches a triangle.
    pub shape: u32,
    pub weights_a: [c_double; 3],
    pub nodes_a: [u32; 3],
    pub padding2: u32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct lfem_shape_def {
    pub type_: lfem_shape_type,
    pub point_count: u32,
    pub center: [c_double; 3],
    pub rotation: [c_double; 4],
    pub half_extents: [c_double; 3],
    pub radius: c_double,
    pub half_length: c_double,
    pub points: *const c_double,
    pub internal_value: u32,
    pub padding: u32,
}

/// A query's collision filter (lfem_query_filter): a body is seen when each one's category is
/// in the other's mask.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct lfem_query_filter {
    pub category_bits: u32,
    pub mask_bits: u32,
}

/// Where a ray crossed a surface (lfem_ray_hit).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_ray_hit {
    pub body: lfem_body,
    /// Boundary triangle of the body, or u32::MAX when a shape was hit.
    pub triangle: u32,
    /// Shape index, or u32::MAX when a triangle was hit.
    pub shape: u32,
    /// t1, t2 as in lfem_contact (0 for a shape).
    pub barycentric: [c_double; 2],
    pub point: [c_double; 3],
    pub normal: [c_double; 3],
    pub distance: c_double,
}

/// A body a sphere or capsule overlaps, and where (lfem_overlap).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct lfem_overlap {
    pub body: lfem_body,
    /// Boundary triangle nearest the query's core, or u32::MAX.
    pub triangle: u32,
    /// Shape index when a shape is nearest, or u32::MAX.
    pub shape: u32,
    pub point: [c_double; 3],
    pub distance: c_double,
}

// The C sizes (bindings/abi_layout.c asserts the same numbers with _Static_assert).
const _: () = assert!(size_of::<lfem_status>() == 4);
const _: () = assert!(size_of::<lfem_body_type>() == 4);
const _: () = assert!(size_of::<lfem_model>() == 4);
const _: () = assert!(size_of::<lfem_shape_type>() == 4);
const _: () = assert!(size_of::<lfem_body>() == 8);
const _: () = assert!(size_of::<lfem_world_def>() == 96);
const _: () = assert!(size_of::<lfem_attachment>() == 8);
const _: () = assert!(size_of::<lfem_event>() == 104);
#[cfg(target_pointer_width = "64")]
const _: () = assert!(size_of::<lfem_attachment_def>() == 128);
const _: () = assert!(size_of::<lfem_world_stats>() == 184);
const _: () = assert!(size_of::<lfem_warning_kind>() == 4);
const _: () = assert!(size_of::<lfem_warning>() == 24);
const _: () = assert!(size_of::<lfem_contact>() == 168);
const _: () = assert!(size_of::<lfem_phase_time>() == 16);
const _: () = assert!(size_of::<lfem_profile>() == 240);
const _: () = assert!(size_of::<lfem_query_filter>() == 8);
const _: () = assert!(size_of::<lfem_ray_hit>() == 88);
#[cfg(target_pointer_width = "64")]
const _: () = assert!(size_of::<lfem_body_def>() == 128);
#[cfg(target_pointer_width = "64")]
const _: () = assert!(size_of::<lfem_shape_def>() == 120);

// ---- functions -------------------------------------------------------------------------------
// Linked by build.rs (cargo:rustc-link-lib=dylib=lfem).

extern "C" {
    // status and errors
    pub fn lfem_status_string(status: lfem_status) -> *const c_char;
    pub fn lfem_last_error() -> *const c_char;
    pub fn lfem_version() -> u32;
    pub fn lfem_version_string() -> *const c_char;

    // world
    pub fn lfem_world_def_default() -> lfem_world_def;
    pub fn lfem_world_create(def: *const lfem_world_def, out: *mut *mut lfem_world) -> lfem_status;
    pub fn lfem_world_destroy(world: *mut lfem_world);
    pub fn lfem_world_step(world: *mut lfem_world, dt: c_double) -> lfem_status;
    pub fn lfem_world_save(world: *const lfem_world, path: *const c_char) -> lfem_status;
    pub fn lfem_world_load(path: *const c_char, out: *mut *mut lfem_world) -> lfem_status;
    pub fn lfem_world_set_gravity(world: *mut lfem_world, gravity: *const c_double) -> lfem_status;
    pub fn lfem_world_set_time_step(world: *mut lfem_world, time_step: c_double) -> lfem_status;
    pub fn lfem_world_get_stable_step(world: *const lfem_world, out: *mut c_double) -> lfem_status;
    pub fn lfem_world_get_stats(world: *const lfem_world, out: *mut lfem_world_stats) -> lfem_status;
    pub fn lfem_world_get_profile(world: *const lfem_world, out: *mut lfem_profile) -> lfem_status;
    pub fn lfem_world_reset_profile(world: *mut lfem_world) -> lfem_status;

    // bodies
    pub fn lfem_body_def_default() -> lfem_body_def;
    pub fn lfem_body_create(
        world: *mut lfem_world,
        def: *const lfem_body_def,
        out: *mut lfem_body,
    ) -> lfem_status;
    pub fn lfem_body_destroy(world: *mut lfem_world, body: lfem_body) -> lfem_status;
    pub fn lfem_body_is_valid(world: *const lfem_world, body: lfem_body) -> c_int;
    pub fn lfem_body_add_mesh(
        world: *mut lfem_world,
        body: lfem_body,
        positions: *const c_double,
        node_count: u32,
        tets: *const u32,
        tet_count: u32,
    ) -> lfem_status;
    pub fn lfem_body_add_quadratic_mesh(
        world: *mut lfem_world,
        body: lfem_body,
        positions: *const c_double,
        node_count: u32,
        tets: *const u32,
        tet_count: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_node_count(world: *const lfem_world, body: lfem_body, out: *mut u32) -> lfem_status;
    pub fn lfem_body_get_tet_count(world: *const lfem_world, body: lfem_body, out: *mut u32) -> lfem_status;
    pub fn lfem_body_get_nodes_per_tet(world: *const lfem_world, body: lfem_body, out: *mut u32) -> lfem_status;
    pub fn lfem_body_get_user_data(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut *mut c_void,
    ) -> lfem_status;
    pub fn lfem_body_get_mass(world: *const lfem_world, body: lfem_body, out: *mut c_double) -> lfem_status;
    pub fn lfem_body_get_added_mass(world: *const lfem_world, body: lfem_body, out: *mut c_double) -> lfem_status;
    pub fn lfem_body_get_inversion(
        world: *const lfem_world,
        body: lfem_body,
        inverted_tets: *mut u32,
        min_jacobian: *mut c_double,
        inverted_for: *mut c_double,
    ) -> lfem_status;
    pub fn lfem_world_get_warning(
        world: *const lfem_world,
        kind: lfem_warning_kind,
        out: *mut lfem_warning,
    ) -> lfem_status;
    pub fn lfem_world_clear_warnings(world: *mut lfem_world) -> lfem_status;
    pub fn lfem_body_wake(world: *mut lfem_world, body: lfem_body) -> lfem_status;
    pub fn lfem_body_is_awake(world: *const lfem_world, body: lfem_body) -> c_int;
    pub fn lfem_attachment_def_default() -> lfem_attachment_def;
    pub fn lfem_attachment_create(
        world: *mut lfem_world,
        def: *const lfem_attachment_def,
        out: *mut lfem_attachment,
    ) -> lfem_status;
    pub fn lfem_attachment_destroy(world: *mut lfem_world, attachment: lfem_attachment) -> lfem_status;
    pub fn lfem_attachment_is_valid(world: *const lfem_world, attachment: lfem_attachment) -> c_int;
    pub fn lfem_attachment_set_frame(
        world: *mut lfem_world,
        attachment: lfem_attachment,
        frame: *const c_double,
    ) -> lfem_status;
    pub fn lfem_attachment_get_force(
        world: *const lfem_world,
        attachment: lfem_attachment,
        force: *mut c_double,
    ) -> lfem_status;
    pub fn lfem_world_get_events(
        world: *const lfem_world,
        out: *mut lfem_event,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;
    pub fn lfem_body_get_momentum(
        world: *const lfem_world,
        body: lfem_body,
        linear: *mut c_double,
        angular: *mut c_double,
    ) -> lfem_status;

    // state
    pub fn lfem_body_get_positions(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut c_double,
        node_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_velocities(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut c_double,
        node_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_set_velocities(
        world: *mut lfem_world,
        body: lfem_body,
        velocities: *const c_double,
        node_count: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_boundary_triangle_count(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut u32,
    ) -> lfem_status;
    pub fn lfem_body_get_boundary_triangles(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut u32,
        triangle_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_boundary_face_count(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut u32,
    ) -> lfem_status;
    pub fn lfem_body_get_boundary_faces(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut u32,
        face_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_von_mises_stress(
        world: *const lfem_world,
        body: lfem_body,
        out: *mut c_double,
        tet_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_rotation(world: *const lfem_world, body: lfem_body, out: *mut c_double) -> lfem_status;
    pub fn lfem_body_set_positions(
        world: *mut lfem_world,
        body: lfem_body,
        positions: *const c_double,
        node_count: u32,
    ) -> lfem_status;
    pub fn lfem_body_set_friction(world: *mut lfem_world, body: lfem_body, friction: c_double) -> lfem_status;
    pub fn lfem_body_set_material(world: *mut lfem_world, body: lfem_body, young_modulus: c_double, poisson_ratio: c_double)
        -> lfem_status;
    pub fn lfem_body_set_sleep_allowed(world: *mut lfem_world, body: lfem_body, allowed: c_int) -> lfem_status;
    pub fn lfem_attachment_get_frame(world: *const lfem_world, attachment: lfem_attachment, frame: *mut c_double)
        -> lfem_status;
    pub fn lfem_body_set_damping(world: *mut lfem_world, body: lfem_body, damping: c_double) -> lfem_status;
    pub fn lfem_body_set_filter(world: *mut lfem_world, body: lfem_body, category_bits: u32, mask_bits: u32)
        -> lfem_status;
    pub fn lfem_body_set_user_data(world: *mut lfem_world, body: lfem_body, user_data: *mut c_void) -> lfem_status;
    pub fn lfem_body_remove_skin(world: *mut lfem_world, body: lfem_body, skin: u32) -> lfem_status;
    pub fn lfem_body_apply_impulse(
        world: *mut lfem_world,
        body: lfem_body,
        point: *const c_double,
        impulse: *const c_double,
    ) -> lfem_status;
    pub fn lfem_body_apply_force(
        world: *mut lfem_world,
        body: lfem_body,
        point: *const c_double,
        force: *const c_double,
    ) -> lfem_status;
    pub fn lfem_body_set_type(world: *mut lfem_world, body: lfem_body, body_type: lfem_body_type) -> lfem_status;
    pub fn lfem_body_get_type(world: *const lfem_world, body: lfem_body, out: *mut lfem_body_type) -> lfem_status;
    pub fn lfem_body_set_user_id(world: *mut lfem_world, body: lfem_body, user_id: u64) -> lfem_status;
    pub fn lfem_body_get_user_id(world: *const lfem_world, body: lfem_body, out: *mut u64) -> lfem_status;
    pub fn lfem_body_closest_point(
        world: *const lfem_world,
        body: lfem_body,
        point: *const c_double,
        out_point: *mut c_double,
        triangle: *mut u32,
        distance: *mut c_double,
    ) -> lfem_status;
    pub fn lfem_body_get_transform(world: *const lfem_world, body: lfem_body, out: *mut c_double) -> lfem_status;
    pub fn lfem_body_get_center_of_mass(world: *const lfem_world, body: lfem_body, out: *mut c_double) -> lfem_status;
    pub fn lfem_body_set_transform(world: *mut lfem_world, body: lfem_body, transform: *const c_double) -> lfem_status;
    pub fn lfem_body_find_nodes_in_box(
        world: *const lfem_world,
        body: lfem_body,
        lo: *const c_double,
        hi: *const c_double,
        out: *mut u32,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;

    // loads and supports
    pub fn lfem_body_fix_nodes(world: *mut lfem_world, body: lfem_body, nodes: *const u32, count: u32) -> lfem_status;
    pub fn lfem_body_prescribe_node_velocity(
        world: *mut lfem_world,
        body: lfem_body,
        nodes: *const u32,
        count: u32,
        velocity: *const c_double,
    ) -> lfem_status;
    pub fn lfem_body_release_nodes(world: *mut lfem_world, body: lfem_body, nodes: *const u32, count: u32) -> lfem_status;
    pub fn lfem_body_set_node_forces(
        world: *mut lfem_world,
        body: lfem_body,
        nodes: *const u32,
        count: u32,
        forces: *const c_double,
    ) -> lfem_status;
    pub fn lfem_body_clear_node_forces(world: *mut lfem_world, body: lfem_body) -> lfem_status;
    pub fn lfem_body_set_kinematic_velocity(
        world: *mut lfem_world,
        body: lfem_body,
        linear: *const c_double,
        angular: *const c_double,
    ) -> lfem_status;

    // rigid shapes
    pub fn lfem_shape_def_default() -> lfem_shape_def;
    pub fn lfem_body_add_shape(
        world: *mut lfem_world,
        body: lfem_body,
        def: *const lfem_shape_def,
        index: *mut u32,
    ) -> lfem_status;

    // contacts
    pub fn lfem_world_query_contacts(
        world: *const lfem_world,
        out: *mut lfem_contact,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;

    // skins
    pub fn lfem_body_add_skin(
        world: *mut lfem_world,
        body: lfem_body,
        positions: *const c_double,
        vertex_count: u32,
        triangles: *const u32,
        triangle_count: u32,
        skin_index: *mut u32,
    ) -> lfem_status;
    pub fn lfem_body_get_skin_count(world: *const lfem_world, body: lfem_body, out: *mut u32) -> lfem_status;
    pub fn lfem_body_get_skin_sizes(
        world: *const lfem_world,
        body: lfem_body,
        skin: u32,
        vertex_count: *mut u32,
        triangle_count: *mut u32,
    ) -> lfem_status;
    pub fn lfem_body_get_skin_triangles(
        world: *const lfem_world,
        body: lfem_body,
        skin: u32,
        out: *mut u32,
        triangle_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_skin_vertices(
        world: *const lfem_world,
        body: lfem_body,
        skin: u32,
        positions: *mut c_double,
        normals: *mut c_double,
        vertex_capacity: u32,
    ) -> lfem_status;
    pub fn lfem_body_get_skin_vertices_f32(
        world: *const lfem_world,
        body: lfem_body,
        skin: u32,
        positions: *mut f32,
        position_stride: u32,
        normals: *mut f32,
        normal_stride: u32,
        vertex_capacity: u32,
    ) -> lfem_status;

    // queries
    pub fn lfem_query_filter_default() -> lfem_query_filter;
    pub fn lfem_world_cast_ray(
        world: *const lfem_world,
        origin: *const c_double,
        direction: *const c_double,
        max_distance: c_double,
        filter: lfem_query_filter,
        out: *mut lfem_ray_hit,
        hit: *mut c_int,
    ) -> lfem_status;
    pub fn lfem_world_cast_sphere(
        world: *const lfem_world,
        origin: *const c_double,
        direction: *const c_double,
        radius: c_double,
        max_distance: c_double,
        filter: lfem_query_filter,
        out: *mut lfem_ray_hit,
        hit: *mut c_int,
    ) -> lfem_status;
    pub fn lfem_world_cast_ray_all(
        world: *const lfem_world,
        origin: *const c_double,
        direction: *const c_double,
        max_distance: c_double,
        filter: lfem_query_filter,
        out: *mut lfem_ray_hit,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;
    pub fn lfem_world_overlap_box(
        world: *const lfem_world,
        lo: *const c_double,
        hi: *const c_double,
        filter: lfem_query_filter,
        out: *mut lfem_body,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;
    pub fn lfem_world_overlap_sphere(
        world: *const lfem_world,
        center: *const c_double,
        radius: c_double,
        filter: lfem_query_filter,
        out: *mut lfem_overlap,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;
    pub fn lfem_world_overlap_capsule(
        world: *const lfem_world,
        a: *const c_double,
        b: *const c_double,
        radius: c_double,
        filter: lfem_query_filter,
        out: *mut lfem_overlap,
        capacity: u32,
        count: *mut u32,
    ) -> lfem_status;

    // meshes
    pub fn lfem_mesh_create_box(size: *const c_double, cells: *const u32, out: *mut *mut lfem_mesh) -> lfem_status;
    pub fn lfem_mesh_create_cylinder(
        radius: c_double,
        height: c_double,
        segments: u32,
        rings: u32,
        layers: u32,
        out: *mut *mut lfem_mesh,
    ) -> lfem_status;
    pub fn lfem_mesh_create_cup(
        outer_radius: c_double,
        height: c_double,
        wall: c_double,
        bottom: c_double,
        segments: u32,
        layers: u32,
        out: *mut *mut lfem_mesh,
    ) -> lfem_status;
    pub fn lfem_mesh_create_hammer(
        handle_length: c_double,
        handle_width: c_double,
        head_length: c_double,
        head_width: c_double,
        cell_size: c_double,
        out: *mut *mut lfem_mesh,
    ) -> lfem_status;
    pub fn lfem_mesh_load_gmsh(path: *const c_char, out: *mut *mut lfem_mesh) -> lfem_status;
    pub fn lfem_mesh_make_quadratic(mesh: *mut lfem_mesh) -> lfem_status;
    pub fn lfem_mesh_get_nodes_per_tet(mesh: *const lfem_mesh) -> u32;
    pub fn lfem_mesh_destroy(mesh: *mut lfem_mesh);
    pub fn lfem_mesh_get_node_count(mesh: *const lfem_mesh) -> u32;
    pub fn lfem_mesh_get_tet_count(mesh: *const lfem_mesh) -> u32;
    pub fn lfem_mesh_get_positions(mesh: *const lfem_mesh) -> *const c_double;
    pub fn lfem_mesh_get_tets(mesh: *const lfem_mesh) -> *const u32;
    pub fn lfem_mesh_translate(mesh: *mut lfem_mesh, offset: *const c_double) -> lfem_status;
    pub fn lfem_mesh_rotate(mesh: *mut lfem_mesh, axis: *const c_double, angle: c_double) -> lfem_status;

    // output
    pub fn lfem_vtk_series_create(pvd_path: *const c_char, out: *mut *mut lfem_vtk_series) -> lfem_status;
    pub fn lfem_vtk_series_write_frame(series: *mut lfem_vtk_series, world: *const lfem_world) -> lfem_status;
    pub fn lfem_vtk_series_destroy(series: *mut lfem_vtk_series);
}
