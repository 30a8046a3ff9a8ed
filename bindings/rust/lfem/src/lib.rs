//! Safe Rust API of lfem: deformable bodies simulated by an explicit local finite element method.
//!
//! ```no_run
//! use lfem::{BodyDef, Mesh, Model, World, WorldDef};
//!
//! let mut world = World::new(&WorldDef::default())?;        // gravity (0, 0, -9.81) m/s^2
//! let mut mesh = Mesh::new_box([0.3, 0.2, 0.1], [3, 2, 1])?; // m, cells
//! mesh.translate([0.0, 0.0, 2.0])?;
//! let mut def = BodyDef::default();
//! def.model = Model::NeoHookean;
//! let block = world.create_body(&def)?;
//! world.add_mesh(block, &mesh)?;
//! world.step(0.5)?;
//! println!("{:?}", world.positions(block)?[0]);
//! # Ok::<(), lfem::Error>(())
//! ```
//!
//! Every fallible call returns [`Result`]; an [`Error`] carries the [`Status`] and the message
//! of `lfem_last_error`. A failed call changes nothing. [`World`] and [`Mesh`] free themselves
//! when dropped. [`Body`] is a plain value handle: a handle of a destroyed body (or of another
//! world) is answered with [`Status::InvalidHandle`], never undefined behaviour.

#![deny(missing_docs)]

use std::ffi::{CStr, CString};
use std::fmt;
use std::mem::{align_of, size_of};
use std::os::raw::{c_char, c_int};
use std::path::Path;
use std::ptr::{self, NonNull};

pub use lfem_sys as sys;

// ---- errors ----------------------------------------------------------------------------------

/// Why a call failed (`lfem_status` without `LFEM_OK`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Status {
    /// A null pointer, a NaN, a number out of its range.
    InvalidArgument,
    /// Bad indices, inverted or zero-volume tets, unused nodes.
    InvalidMesh,
    /// A stale, foreign or null body handle.
    InvalidHandle,
    /// The caller's capacity is below what the answer needs.
    BufferTooSmall,
    /// The state blew up; the world was rolled back.
    Unstable,
    /// A file could not be read or written, or is malformed.
    IoError,
    /// An allocation failed; nothing was changed.
    OutOfMemory,
    /// A bug in lfem: please report it with the message.
    InternalError,
    /// This build leaves the feature out (LFEM_WITH_CCD, LFEM_WITH_IO).
    Unsupported,
    /// A status this binding does not know (a newer library).
    Unknown(i32),
}

impl Status {
    /// The status of a raw value; `None` for `LFEM_OK`.
    pub fn from_raw(raw: sys::lfem_status) -> Option<Status> {
        Some(match raw {
            sys::LFEM_OK => return None,
            sys::LFEM_INVALID_ARGUMENT => Status::InvalidArgument,
            sys::LFEM_INVALID_MESH => Status::InvalidMesh,
            sys::LFEM_INVALID_HANDLE => Status::InvalidHandle,
            sys::LFEM_BUFFER_TOO_SMALL => Status::BufferTooSmall,
            sys::LFEM_UNSTABLE => Status::Unstable,
            sys::LFEM_IO_ERROR => Status::IoError,
            sys::LFEM_OUT_OF_MEMORY => Status::OutOfMemory,
            sys::LFEM_INTERNAL_ERROR => Status::InternalError,
            sys::LFEM_UNSUPPORTED => Status::Unsupported,
            other => Status::Unknown(other),
        })
    }

    /// The C value.
    pub fn raw(self) -> sys::lfem_status {
        match self {
            Status::InvalidArgument => sys::LFEM_INVALID_ARGUMENT,
            Status::InvalidMesh => sys::LFEM_INVALID_MESH,
            Status::InvalidHandle => sys::LFEM_INVALID_HANDLE,
            Status::BufferTooSmall => sys::LFEM_BUFFER_TOO_SMALL,
            Status::Unstable => sys::LFEM_UNSTABLE,
            Status::IoError => sys::LFEM_IO_ERROR,
            Status::OutOfMemory => sys::LFEM_OUT_OF_MEMORY,
            Status::InternalError => sys::LFEM_INTERNAL_ERROR,
            Status::Unsupported => sys::LFEM_UNSUPPORTED,
            Status::Unknown(raw) => raw,
        }
    }

    /// lfem's fixed name and meaning, e.g. "LFEM_INVALID_MESH: invalid mesh".
    pub fn description(self) -> String {
        // SAFETY: lfem_status_string never returns NULL and its strings are static.
        unsafe { c_string(sys::lfem_status_string(self.raw())) }
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.description())
    }
}

/// A failed lfem call: its status and the message of `lfem_last_error`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    status: Status,
    message: String,
}

impl Error {
    /// The error of a call that just returned `raw` (not `LFEM_OK`) on this thread.
    fn last(status: Status) -> Error {
        // SAFETY: lfem_last_error never returns NULL; the string is copied at once, on the
        // thread that made the failing call.
        let message = unsafe { c_string(sys::lfem_last_error()) };
        Error { status, message }
    }

    /// An error found by this binding before reaching the library.
    fn local(status: Status, message: String) -> Error {
        Error { status, message }
    }

    /// The same error naming the call the user made (`outer`, e.g. lfem_body_get_positions)
    /// instead of the helper call that failed first inside it (`inner`, a count).
    fn renamed(self, inner: &str, outer: &str) -> Error {
        match self.message.strip_prefix(inner) {
            Some(rest) if rest.starts_with(':') => Error { status: self.status, message: format!("{}{}", outer, rest) },
            _ => self,
        }
    }

    /// Why the call failed.
    pub fn status(&self) -> Status {
        self.status
    }

    /// The message, e.g. "lfem_world_step: dt must be finite and > 0, got -1.000000".
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.message, self.status.description())
    }
}

impl std::error::Error for Error {}

/// The result of every fallible call of this crate.
pub type Result<T> = std::result::Result<T, Error>;

/// A list a C call fills after telling its length: asked with no buffer for the count (`out`
/// empty, LFEM_BUFFER_TOO_SMALL when there is something), then filled.
fn counted_list<T: Clone>(empty: T, call: impl Fn(&mut [T], &mut u32) -> sys::lfem_status) -> Result<Vec<T>> {
    let mut count = 0u32;
    let first = call(&mut [], &mut count);
    if first != sys::LFEM_BUFFER_TOO_SMALL {
        check(first)?;
    }
    let mut out = vec![empty; count as usize];
    if count > 0 {
        check(call(&mut out, &mut count))?;
    }
    Ok(out)
}

fn check(raw: sys::lfem_status) -> Result<()> {
    match Status::from_raw(raw) {
        None => Ok(()),
        Some(status) => Err(Error::last(status)),
    }
}

/// Copies a NUL-terminated string owned by lfem. `ptr` must be non-null and valid.
unsafe fn c_string(ptr: *const c_char) -> String {
    CStr::from_ptr(ptr).to_string_lossy().into_owned()
}

fn to_u32(n: usize, what: &str) -> Result<u32> {
    u32::try_from(n).map_err(|_| {
        Error::local(Status::InvalidArgument, format!("lfem (Rust): {} = {} does not fit in 32 bits", what, n))
    })
}

fn to_c_path(path: &Path) -> Result<CString> {
    let bytes = {
        #[cfg(unix)]
        {
            use std::os::unix::ffi::OsStrExt;
            path.as_os_str().as_bytes().to_vec()
        }
        #[cfg(not(unix))]
        {
            path.to_string_lossy().into_owned().into_bytes()
        }
    };
    CString::new(bytes).map_err(|_| {
        Error::local(Status::InvalidArgument, format!("lfem (Rust): path {:?} contains a NUL byte", path))
    })
}

/// `(major, minor, patch)` of the library actually loaded.
pub fn version() -> (u32, u32, u32) {
    // SAFETY: no arguments.
    let v = unsafe { sys::lfem_version() };
    (v >> 16, (v >> 8) & 0xff, v & 0xff)
}

/// "major.minor.patch" of the library actually loaded.
pub fn version_string() -> String {
    // SAFETY: never NULL, static.
    unsafe { c_string(sys::lfem_version_string()) }
}

// ---- definitions -----------------------------------------------------------------------------

/// How a world is set up. Start from `WorldDef::default()` (lfem_world_def_default) and edit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorldDef {
    /// m/s^2, default (0, 0, -9.81).
    pub gravity: [f64; 3],
    /// s; 0 (default) = automatic, > 0 = fixed sub-step.
    pub time_step: f64,
    /// Fraction of the stable limit used by the automatic step, in (0, 1); default 0.9.
    pub step_safety: f64,
    /// Cap on contact solver sweeps per step, default 200.
    pub contact_iterations: u32,
    /// Threads that run a step's element and node loops, 1..64, default 1; results are
    /// bitwise identical for every count.
    pub thread_count: u32,
    /// Relative stopping tolerance of the contact solve, default 1e-3.
    pub contact_tolerance: f64,
    /// A step needing more sub-steps than this is refused up front, default 1000000.
    pub max_substeps: u32,
    /// Skip the up-front stability check of a fixed time step, default false.
    pub allow_unstable_step: bool,
    /// s; 0 (default) = off. Mass scaling: tets that would need a shorter sub-step get added
    /// mass, so that the automatic step is at least this (see `lfem_world_def`).
    pub mass_scaling_step: f64,
    /// Bodies at rest fall asleep (see `sleep_velocity`), default false.
    pub enable_sleep: bool,
    /// m/s, default 0.01: a body whose every node moved slower than this for `sleep_time`
    /// (and everything touching it) falls asleep.
    pub sleep_velocity: f64,
    /// s, default 0.5.
    pub sleep_time: f64,
    internal_value: u32,
}

impl Default for WorldDef {
    fn default() -> WorldDef {
        // SAFETY: returns a value.
        let d = unsafe { sys::lfem_world_def_default() };
        WorldDef {
            gravity: d.gravity,
            time_step: d.time_step,
            step_safety: d.step_safety,
            contact_iterations: d.contact_iterations,
            thread_count: d.thread_count,
            contact_tolerance: d.contact_tolerance,
            max_substeps: d.max_substeps,
            allow_unstable_step: d.allow_unstable_step != 0,
            mass_scaling_step: d.mass_scaling_step,
            enable_sleep: d.enable_sleep != 0,
            sleep_velocity: d.sleep_velocity,
            sleep_time: d.sleep_time,
            internal_value: d.internal_value,
        }
    }
}

impl WorldDef {
    fn to_raw(self) -> sys::lfem_world_def {
        sys::lfem_world_def {
            gravity: self.gravity,
            time_step: self.time_step,
            step_safety: self.step_safety,
            contact_iterations: self.contact_iterations,
            thread_count: self.thread_count,
            contact_tolerance: self.contact_tolerance,
            max_substeps: self.max_substeps,
            allow_unstable_step: u8::from(self.allow_unstable_step),
            enable_sleep: u8::from(self.enable_sleep),
            padding: [0; 2],
            internal_value: self.internal_value,
            padding2: 0,
            mass_scaling_step: self.mass_scaling_step,
            sleep_velocity: self.sleep_velocity,
            sleep_time: self.sleep_time,
        }
    }
}

/// What a body is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BodyType {
    /// Finite elements, moves and deforms.
    Deformable,
    /// Never moves (a floor, a wall).
    Static,
    /// Moves rigidly with a prescribed velocity, unaffected by forces.
    Kinematic,
    /// The paper's global translation and rotation alone: moved by forces and contacts.
    Rigid,
}

impl BodyType {
    fn raw(self) -> sys::lfem_body_type {
        match self {
            BodyType::Deformable => sys::LFEM_BODY_DEFORMABLE,
            BodyType::Static => sys::LFEM_BODY_STATIC,
            BodyType::Kinematic => sys::LFEM_BODY_KINEMATIC,
            BodyType::Rigid => sys::LFEM_BODY_RIGID,
        }
    }

    fn from_raw(t: sys::lfem_body_type) -> BodyType {
        match t {
            sys::LFEM_BODY_STATIC => BodyType::Static,
            sys::LFEM_BODY_KINEMATIC => BodyType::Kinematic,
            sys::LFEM_BODY_RIGID => BodyType::Rigid,
            _ => BodyType::Deformable,
        }
    }
}

/// The material model of a deformable body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Model {
    /// Floating frame: one global rotation per body (the paper's eq. 2), linear elasticity in it.
    Paper,
    /// One rotation per tet: large local rotations (bending).
    Corotational,
    /// Stable neo-Hookean hyperelasticity: large strains.
    NeoHookean,
    /// Small-strain linear elasticity, no rotation at all.
    Linear,
}

/// How a body is set up. Start from `BodyDef::default()` (lfem_body_def_default) and edit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyDef {
    /// Default `BodyType::Deformable`.
    pub body_type: BodyType,
    /// Default `Model::Paper`.
    pub model: Model,
    /// Pa, > 0, default 1e6.
    pub young_modulus: f64,
    /// In (-1, 0.5), default 0.3.
    pub poisson_ratio: f64,
    /// kg/m^3, > 0, default 1000.
    pub density: f64,
    /// 1/s, mass-proportional damping, >= 0, default 0.
    pub damping: f64,
    /// Coulomb coefficient, >= 0, default 0.5.
    pub friction: f64,
    /// m/s, initial velocity of the nodes of each added mesh (kinematic: constant velocity).
    pub linear_velocity: [f64; 3],
    /// rad/s, initial spin about the centre of mass when a mesh is added.
    pub angular_velocity: [f64; 3],
    /// Collision filter: what this body is, default 1.
    pub category_bits: u32,
    /// Collision filter: what it collides with, default all bits.
    pub mask_bits: u32,
    /// The body's surface collides with itself (deformable bodies only), default false.
    pub self_contact: bool,
    /// May fall asleep when the world allows it, default true.
    pub enable_sleep: bool,
    /// 10-node tets as the composite element (linear sub-tets, projected strain: plane waves
    /// and impacts carry as with 4-node tets), default false.
    pub composite_tets: bool,
    /// Every step reports each pair of this body that stays in touch
    /// ([`EventType::ContactPersist`]), default false.
    pub report_contacts: bool,
    /// Its sharp edges (faces meeting at more than 15 degrees, or a border) are held apart from
    /// other bodies' where they cross between nodes (contacts of kind edge-edge), default true;
    /// false leaves its contacts to its nodes, saving the edge pass where a scene needs none.
    pub edge_contacts: bool,
    internal_value: u32,
}

impl Default for BodyDef {
    fn default() -> BodyDef {
        // SAFETY: returns a value.
        let d = unsafe { sys::lfem_body_def_default() };
        BodyDef {
            body_type: BodyType::from_raw(d.type_),
            model: match d.model {
                sys::LFEM_MODEL_COROTATIONAL => Model::Corotational,
                sys::LFEM_MODEL_NEO_HOOKEAN => Model::NeoHookean,
                sys::LFEM_MODEL_LINEAR => Model::Linear,
                _ => Model::Paper,
            },
            young_modulus: d.young_modulus,
            poisson_ratio: d.poisson_ratio,
            density: d.density,
            damping: d.damping,
            friction: d.friction,
            linear_velocity: d.linear_velocity,
            angular_velocity: d.angular_velocity,
            category_bits: d.category_bits,
            mask_bits: d.mask_bits,
            self_contact: d.self_contact != 0,
            enable_sleep: d.enable_sleep != 0,
            composite_tets: d.composite_tets != 0,
            report_contacts: d.report_contacts != 0,
            edge_contacts: d.edge_contacts != 0,
            internal_value: d.internal_value,
        }
    }
}

impl BodyDef {
    fn to_raw(self) -> sys::lfem_body_def {
        sys::lfem_body_def {
            type_: self.body_type.raw(),
            model: match self.model {
                Model::Paper => sys::LFEM_MODEL_PAPER,
                Model::Corotational => sys::LFEM_MODEL_COROTATIONAL,
                Model::NeoHookean => sys::LFEM_MODEL_NEO_HOOKEAN,
                Model::Linear => sys::LFEM_MODEL_LINEAR,
            },
            young_modulus: self.young_modulus,
            poisson_ratio: self.poisson_ratio,
            density: self.density,
            damping: self.damping,
            friction: self.friction,
            linear_velocity: self.linear_velocity,
            angular_velocity: self.angular_velocity,
            category_bits: self.category_bits,
            mask_bits: self.mask_bits,
            user_data: ptr::null_mut(),
            internal_value: self.internal_value,
            enable_sleep: u8::from(self.enable_sleep),
            self_contact: u8::from(self.self_contact),
            composite_tets: u8::from(self.composite_tets),
            report_contacts: u8::from(self.report_contacts),
            edge_contacts: u8::from(self.edge_contacts),
            padding: [0; 7],
        }
    }
}

/// The kind of a rigid shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShapeType {
    /// The half-space below the plane through `center` with normal local +z.
    Plane,
    /// `half_extents` along the local axes.
    Box,
    /// `radius`.
    Sphere,
    /// A segment from -half_length to +half_length along local z, swept by a sphere of radius.
    Capsule,
    /// The convex hull of `points` (local coordinates, at least 4, not all coplanar).
    ConvexHull,
}

/// A rigid shape of a static or kinematic body. Start from `ShapeDef::default()`
/// (lfem_shape_def_default) and edit.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeDef {
    /// Default `ShapeType::Plane`.
    pub shape_type: ShapeType,
    /// m, world position of the shape's local origin, default 0.
    pub center: [f64; 3],
    /// Unit quaternion (w, x, y, z) of the local frame, default identity.
    pub rotation: [f64; 4],
    /// m, box, default 0.5.
    pub half_extents: [f64; 3],
    /// m, sphere and capsule, default 0.5.
    pub radius: f64,
    /// m, capsule, default 0.5.
    pub half_length: f64,
    /// Convex hull points (m, local coordinates); empty otherwise.
    pub points: Vec<[f64; 3]>,
    internal_value: u32,
}

impl Default for ShapeDef {
    fn default() -> ShapeDef {
        // SAFETY: returns a value.
        let d = unsafe { sys::lfem_shape_def_default() };
        ShapeDef {
            shape_type: match d.type_ {
                sys::LFEM_SHAPE_BOX => ShapeType::Box,
                sys::LFEM_SHAPE_SPHERE => ShapeType::Sphere,
                sys::LFEM_SHAPE_CAPSULE => ShapeType::Capsule,
                sys::LFEM_SHAPE_CONVEX_HULL => ShapeType::ConvexHull,
                _ => ShapeType::Plane,
            },
            center: d.center,
            rotation: d.rotation,
            half_extents: d.half_extents,
            radius: d.radius,
            half_length: d.half_length,
            points: Vec::new(),
            internal_value: d.internal_value,
        }
    }
}

// ---- handles and records -----------------------------------------------------------------------

/// A body handle: a value (copy it freely), valid while the body lives. `Body::NULL` is
/// `{0, 0}`. Same layout as `lfem_body`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Body {
    /// The slot of the body in its world.
    pub index: u32,
    /// Counts the bodies that held the slot: a stale handle has an old one.
    pub generation: u32,
}

impl Body {
    /// The null handle, never valid.
    pub const NULL: Body = Body { index: 0, generation: 0 };

    fn raw(self) -> sys::lfem_body {
        sys::lfem_body { index: self.index, generation: self.generation }
    }
}

/// One active node-to-triangle contact of the last step. Same layout as `lfem_contact`, so
/// [`World::contacts_into`] fills a slice of them directly.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// The body that owns the node.
    pub body_a: Body,
    /// The body that owns the triangle.
    pub body_b: Body,
    /// Node index in body_a.
    pub node: u32,
    /// Node indices a, b, c in body_b.
    pub triangle: [u32; 3],
    /// t1, t2: the point is (1 - t1 - t2) a + t2 b + t1 c.
    pub barycentric: [f64; 2],
    /// m, the contact point on the triangle.
    pub position: [f64; 3],
    /// Unit, out of body_b's surface.
    pub normal: [f64; 3],
    /// N, the contact force on the node.
    pub force: [f64; 3],
    /// 1 when friction is on the Coulomb cone, else 0 (see [`Contact::is_sliding`]).
    pub sliding: u8,
    /// What the record joins: 0 node-face, 1 node-shape, 2 face-shape, 3 edge-edge
    /// (`lfem_contact_kind`).
    pub kind: u8,
    padding: [u8; 2],
    /// Index of body_b's rigid shape the node touches, or `u32::MAX` for a triangle (then
    /// `triangle` and `barycentric` are meaningful; for a shape they are `u32::MAX` and 0).
    pub shape: u32,
    /// body_a's point as a weighted sum of `nodes_a` (the node alone, a face's three corners
    /// or an edge's two ends).
    pub weights_a: [f64; 3],
    /// Node indices in body_a (`u32::MAX` where unused); the first is `node`.
    pub nodes_a: [u32; 3],
    padding2: u32,
}

impl Default for Contact {
    fn default() -> Contact {
        Contact {
            body_a: Body::NULL,
            body_b: Body::NULL,
            node: 0,
            triangle: [0; 3],
            barycentric: [0.0; 2],
            position: [0.0; 3],
            normal: [0.0; 3],
            force: [0.0; 3],
            sliding: 0,
            kind: 0,
            padding: [0; 2],
            shape: u32::MAX,
            weights_a: [0.0; 3],
            nodes_a: [u32::MAX; 3],
            padding2: 0,
        }
    }
}

impl Contact {
    /// Whether friction is on the Coulomb cone (the node slides).
    pub fn is_sliding(&self) -> bool {
        self.sliding != 0
    }

    /// The rigid shape of body_b that the node touches, if any (else a triangle).
    pub fn shape(&self) -> Option<u32> {
        if self.shape == u32::MAX {
            None
        } else {
            Some(self.shape)
        }
    }
}

const _: () = assert!(size_of::<Body>() == size_of::<sys::lfem_body>());
const _: () = assert!(align_of::<Body>() == align_of::<sys::lfem_body>());
const _: () = assert!(size_of::<Contact>() == size_of::<sys::lfem_contact>());
const _: () = assert!(align_of::<Contact>() == align_of::<sys::lfem_contact>());
const _: () = assert!(size_of::<Contact>() == 168);

/// Statistics of a world (lfem_world_stats): time, energies, momenta, solver figures.
pub type WorldStats = sys::lfem_world_stats;

/// What a warning counts (lfem_warning_kind): trouble the step recovers from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WarningKind {
    /// A sub-step ended with inverted tets in a body: once per body and sub-step.
    InvertedTets,
    /// A body kept inverted tets for 0.5 s in a row: once per spell.
    StaysInverted,
    /// Nodes found inside another body (or a shape), or inside their own with self-contact,
    /// pushed back out.
    FallenIn,
    /// A contact solve used every sweep and ended above its tolerance.
    Unconverged,
}

impl WarningKind {
    /// Every kind, in the C order.
    pub const ALL: [WarningKind; 4] =
        [WarningKind::InvertedTets, WarningKind::StaysInverted, WarningKind::FallenIn, WarningKind::Unconverged];

    fn raw(self) -> sys::lfem_warning_kind {
        match self {
            WarningKind::InvertedTets => sys::LFEM_WARNING_INVERTED_TETS,
            WarningKind::StaysInverted => sys::LFEM_WARNING_STAYS_INVERTED,
            WarningKind::FallenIn => sys::LFEM_WARNING_FALLEN_IN,
            WarningKind::Unconverged => sys::LFEM_WARNING_UNCONVERGED,
        }
    }
}

/// One warning counter (lfem_warning).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Warning {
    /// How often, since the world was created or [`World::clear_warnings`].
    pub count: u64,
    /// s, simulated time of the last one (0 before any).
    pub last_time: f64,
    /// The body of the last one; [`Body::NULL`] when none is concerned.
    pub last_body: Body,
}

/// An attachment handle (lfem_attachment): a value, valid while the attachment lives.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Attachment {
    /// The slot of the attachment in its world.
    pub index: u32,
    /// Counts the attachments that held the slot.
    pub generation: u32,
}

impl Attachment {
    fn raw(self) -> sys::lfem_attachment {
        sys::lfem_attachment { index: self.index, generation: self.generation }
    }
}

/// What an attachment holds its nodes to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AttachTo {
    /// A rigid, kinematic or static body (or, for points, a deformable one).
    Body(Body),
    /// A frame the caller moves ([`World::set_attachment_frame`]): centre and unit quaternion
    /// (w, x, y, z) at creation.
    Frame([f64; 7]),
}

/// What an event of the last step is (lfem_event_type).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EventType {
    /// A pair of bodies began to touch during the step.
    ContactBegin,
    /// A pair that touched stopped.
    ContactEnd,
    /// `body_a` fell asleep.
    Sleep,
    /// `body_a` woke.
    Wake,
    /// `attachment` broke (its handle is stale now).
    AttachmentBroken,
    /// A pair that touched at the end of the last step still does (reported when either body
    /// asks, [`BodyDef::report_contacts`]).
    ContactPersist,
}

/// One event of the last step (lfem_event).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    /// What happened.
    pub event_type: EventType,
    /// The pair (lower slot first), or the body that slept or woke, or the broken attachment's body.
    pub body_a: Body,
    /// The other body of a pair, the broken attachment's target; else [`Body::NULL`].
    pub body_b: Body,
    /// The broken attachment; else the null handle.
    pub attachment: Attachment,
    /// N s: a contact pair's summed normal impulse over the step.
    pub normal_impulse: f64,
    /// N: a pair's largest summed normal force at a sub-step; the force that broke an attachment.
    pub max_force: f64,
    /// m/s: a contact pair's fastest approach at a sub-step of the step (an impact's speed).
    pub approach_speed: f64,
    /// A contact pair's active node contacts at the end of the step (0 for an end).
    pub contact_count: u32,
    /// m: where that approach was, at the end of its sub-step (contact events).
    pub point: [f64; 3],
    /// The unit contact normal there, from `body_a` toward `body_b` (contact events).
    pub normal: [f64; 3],
}

/// A body's inverted tets after the last sub-step (lfem_body_get_inversion).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inversion {
    /// Tets with volume ratio J = det F <= 0.
    pub inverted_tets: u32,
    /// The smallest J of the body's tets.
    pub min_jacobian: f64,
    /// s, for how long the body has had inverted tets without a break (0 when none).
    pub inverted_for: f64,
}
/// A query's collision filter (lfem_query_filter), as the bodies' own: a body is seen when
/// `body.category_bits & mask_bits != 0` and `category_bits & body.mask_bits != 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct QueryFilter {
    /// What the query is; default 1.
    pub category_bits: u32,
    /// What it sees; default all bits.
    pub mask_bits: u32,
}

impl Default for QueryFilter {
    fn default() -> QueryFilter {
        // SAFETY: returns a value.
        let f = unsafe { sys::lfem_query_filter_default() };
        QueryFilter { category_bits: f.category_bits, mask_bits: f.mask_bits }
    }
}

impl QueryFilter {
    fn raw(self) -> sys::lfem_query_filter {
        sys::lfem_query_filter { category_bits: self.category_bits, mask_bits: self.mask_bits }
    }
}

/// Where a ray crossed a surface (lfem_ray_hit; same layout).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RayHit {
    /// The body hit.
    pub body: Body,
    /// Its boundary triangle ([`World::boundary_triangles`] order), u32::MAX for a shape.
    pub triangle: u32,
    /// Its shape ([`World::add_shape`]'s index), u32::MAX for a triangle.
    pub shape: u32,
    /// t1, t2 as in [`Contact`]: the point is (1 - t1 - t2) a + t2 b + t1 c (0 for a shape).
    pub barycentric: [f64; 2],
    /// m, on the ray.
    pub point: [f64; 3],
    /// Unit, out of the surface hit.
    pub normal: [f64; 3],
    /// m from the origin along the unit ray.
    pub distance: f64,
}

impl RayHit {
    /// The triangle hit, `None` for a shape.
    pub fn triangle(&self) -> Option<u32> {
        if self.triangle == u32::MAX {
            None
        } else {
            Some(self.triangle)
        }
    }

    /// The shape hit, `None` for a triangle.
    pub fn shape(&self) -> Option<u32> {
        if self.shape == u32::MAX {
            None
        } else {
            Some(self.shape)
        }
    }
}

const _: () = assert!(size_of::<RayHit>() == size_of::<sys::lfem_ray_hit>());
const _: () = assert!(align_of::<RayHit>() == align_of::<sys::lfem_ray_hit>());

/// A body a sphere or capsule overlaps, and where (lfem_overlap; same layout).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Overlap {
    /// The body overlapped.
    pub body: Body,
    /// Its boundary triangle nearest the query's core, u32::MAX when a shape is nearer or none is
    /// in reach (a body that holds the core inside).
    pub triangle: u32,
    /// Its shape nearest the core, u32::MAX otherwise.
    pub shape: u32,
    /// m: the point of that triangle or shape nearest the core (the core's first point for a
    /// body that holds it inside).
    pub point: [f64; 3],
    /// m from the core to `point`; 0 inside.
    pub distance: f64,
}

const _: () = assert!(size_of::<Overlap>() == size_of::<sys::lfem_overlap>());
const _: () = assert!(align_of::<Overlap>() == align_of::<sys::lfem_overlap>());

/// A skin's deformed vertices: positions (m) and unit smooth normals, one each per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SkinVertices {
    /// m, the vertices where the tets have carried them.
    pub positions: Vec<[f64; 3]>,
    /// Unit, area-weighted over the skin's triangles around each vertex (zero where they have
    /// no area).
    pub normals: Vec<[f64; 3]>,
}

/// Where the step spends its time (lfem_profile): seconds and call counts per phase.
pub type Profile = sys::lfem_profile;
/// Time and count of one phase (lfem_phase_time).
pub type PhaseTime = sys::lfem_phase_time;

// ---- world -------------------------------------------------------------------------------------

/// A simulation world; destroyed (with all its bodies) when dropped.
///
/// `Send` (a world may move to another thread) but not `Sync`: lfem does no internal locking.
pub struct World {
    raw: NonNull<sys::lfem_world>,
}

// SAFETY: lfem allows distinct worlds on distinct threads; &mut self / !Sync prevent two threads
// from using one world at once.
unsafe impl Send for World {}

impl Drop for World {
    fn drop(&mut self) {
        // SAFETY: the pointer came from lfem_world_create and is destroyed once.
        unsafe { sys::lfem_world_destroy(self.raw.as_ptr()) }
    }
}

impl fmt::Debug for World {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("World").field("raw", &self.raw).finish()
    }
}

impl World {
    /// An empty world.
    pub fn new(def: &WorldDef) -> Result<World> {
        let raw_def = def.to_raw();
        let mut out: *mut sys::lfem_world = ptr::null_mut();
        // SAFETY: valid pointers to a def and to the output.
        check(unsafe { sys::lfem_world_create(&raw_def, &mut out) })?;
        NonNull::new(out)
            .map(|raw| World { raw })
            .ok_or_else(|| Error::local(Status::InternalError, "lfem_world_create returned NULL".into()))
    }

    /// A new world from a checkpoint written by [`World::save`]; stepping it continues the
    /// saved run bit for bit. Body handles of the saved world are valid in it.
    pub fn load<P: AsRef<Path>>(path: P) -> Result<World> {
        let c_path = to_c_path(path.as_ref())?;
        let mut out: *mut sys::lfem_world = ptr::null_mut();
        // SAFETY: NUL-terminated path, valid output.
        check(unsafe { sys::lfem_world_load(c_path.as_ptr(), &mut out) })?;
        NonNull::new(out)
            .map(|raw| World { raw })
            .ok_or_else(|| Error::local(Status::InternalError, "lfem_world_load returned NULL".into()))
    }

    /// Write a checkpoint of the whole world (replaces `path` only once complete).
    pub fn save<P: AsRef<Path>>(&self, path: P) -> Result<()> {
        let c_path = to_c_path(path.as_ref())?;
        // SAFETY: live world, NUL-terminated path.
        check(unsafe { sys::lfem_world_save(self.ptr(), c_path.as_ptr()) })
    }

    /// The C pointer, for calls this crate does not wrap. Stays owned by `self`.
    pub fn as_ptr(&self) -> *mut sys::lfem_world {
        self.raw.as_ptr()
    }

    fn ptr(&self) -> *const sys::lfem_world {
        self.raw.as_ptr()
    }

    fn ptr_mut(&mut self) -> *mut sys::lfem_world {
        self.raw.as_ptr()
    }

    /// Advance by `dt` seconds (split into stable sub-steps). On `Status::Unstable` the world is
    /// rolled back to its state before the call.
    pub fn step(&mut self, dt: f64) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_world_step(self.ptr_mut(), dt) })
    }

    /// Gravity (m/s^2) from now on.
    pub fn set_gravity(&mut self, gravity: [f64; 3]) -> Result<()> {
        // SAFETY: live world, 3 doubles.
        check(unsafe { sys::lfem_world_set_gravity(self.ptr_mut(), gravity.as_ptr()) })
    }

    /// Fixed sub-step (s), 0 = automatic.
    pub fn set_time_step(&mut self, time_step: f64) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_world_set_time_step(self.ptr_mut(), time_step) })
    }

    /// The stable limit of the step (s); infinity without deformable bodies.
    pub fn stable_step(&self) -> Result<f64> {
        let mut out = 0.0;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_world_get_stable_step(self.ptr(), &mut out) })?;
        Ok(out)
    }

    /// Time, energies, momenta and solver figures.
    pub fn stats(&self) -> Result<WorldStats> {
        let mut out = WorldStats::default();
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_world_get_stats(self.ptr(), &mut out) })?;
        Ok(out)
    }

    /// Per-phase time and counts accumulated since creation or the last reset.
    pub fn profile(&self) -> Result<Profile> {
        let mut out = Profile::default();
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_world_get_profile(self.ptr(), &mut out) })?;
        Ok(out)
    }

    /// Set the profile back to zero.
    pub fn reset_profile(&mut self) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_world_reset_profile(self.ptr_mut()) })
    }

    /// Hold `nodes` of the deformable `body` at their current offsets in the frame of `target`;
    /// it breaks above `break_force` N (0: never).
    pub fn create_attachment(&mut self, body: Body, nodes: &[u32], target: AttachTo, break_force: f64) -> Result<Attachment> {
        // SAFETY: returns a value.
        let mut def = unsafe { sys::lfem_attachment_def_default() };
        def.body = body.raw();
        def.nodes = nodes.as_ptr();
        def.node_count = to_u32(nodes.len(), "node count")?;
        match target {
            AttachTo::Body(b) => def.target = b.raw(),
            AttachTo::Frame(f) => def.frame = f,
        }
        def.break_force = break_force;
        let mut out = sys::lfem_attachment::default();
        // SAFETY: live world; def points at node_count indices for the duration of the call.
        check(unsafe { sys::lfem_attachment_create(self.ptr_mut(), &def, &mut out) })?;
        Ok(Attachment { index: out.index, generation: out.generation })
    }

    /// Hold `points` (m) of the deformable `body` where they are (each bound once to the tet
    /// around it) at their offsets in the frame of `target`, or at the same material points of
    /// a deformable target body; rigidly (`stiffness` 0) or by a spring of `stiffness` N/m with a
    /// damper of `damping` N s/m; it breaks above `break_force` N (0: never).
    pub fn create_point_attachment(
        &mut self,
        body: Body,
        points: &[[f64; 3]],
        target: AttachTo,
        stiffness: f64,
        damping: f64,
        break_force: f64,
    ) -> Result<Attachment> {
        // SAFETY: returns a value.
        let mut def = unsafe { sys::lfem_attachment_def_default() };
        def.body = body.raw();
        def.points = points.as_ptr() as *const f64;
        def.point_count = to_u32(points.len(), "point count")?;
        match target {
            AttachTo::Body(b) => def.target = b.raw(),
            AttachTo::Frame(f) => def.frame = f,
        }
        def.stiffness = stiffness;
        def.damping = damping;
        def.break_force = break_force;
        let mut out = sys::lfem_attachment::default();
        // SAFETY: live world; def points at 3 * point_count doubles for the duration of the call.
        check(unsafe { sys::lfem_attachment_create(self.ptr_mut(), &def, &mut out) })?;
        Ok(Attachment { index: out.index, generation: out.generation })
    }

    /// Destroy an attachment.
    pub fn destroy_attachment(&mut self, attachment: Attachment) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_attachment_destroy(self.ptr_mut(), attachment.raw()) })
    }

    /// Whether the handle names a live attachment of this world.
    pub fn is_attachment_valid(&self, attachment: Attachment) -> bool {
        // SAFETY: live world.
        unsafe { sys::lfem_attachment_is_valid(self.ptr(), attachment.raw()) == 1 }
    }

    /// Where the caller's frame of an attachment is to be at the end of the next step.
    pub fn set_attachment_frame(&mut self, attachment: Attachment, frame: [f64; 7]) -> Result<()> {
        // SAFETY: live world, 7 doubles.
        check(unsafe { sys::lfem_attachment_set_frame(self.ptr_mut(), attachment.raw(), frame.as_ptr()) })
    }

    /// The total force (N) the attachment put on its nodes at the last sub-step.
    pub fn attachment_force(&self, attachment: Attachment) -> Result<[f64; 3]> {
        let mut out = [0.0; 3];
        // SAFETY: live world, 3 doubles.
        check(unsafe { sys::lfem_attachment_get_force(self.ptr(), attachment.raw(), out.as_mut_ptr()) })?;
        Ok(out)
    }

    /// Wake a sleeping body.
    pub fn wake(&mut self, body: Body) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_wake(self.ptr_mut(), body.raw()) })
    }

    /// Whether a body is awake (`Err` for a bad handle).
    pub fn is_awake(&self, body: Body) -> Result<bool> {
        // SAFETY: live world.
        match unsafe { sys::lfem_body_is_awake(self.ptr(), body.raw()) } {
            1 => Ok(true),
            0 => Ok(false),
            _ => Err(Error { status: Status::InvalidHandle, message: "body handle is stale or of another world".into() }),
        }
    }

    /// The events of the last step.
    pub fn events(&self) -> Result<Vec<Event>> {
        let mut count = 0u32;
        // SAFETY: live world; capacity 0 asks for the count (BUFFER_TOO_SMALL when there are some).
        let _ = unsafe { sys::lfem_world_get_events(self.ptr(), ptr::null_mut(), 0, &mut count) };
        let mut raw = vec![sys::lfem_event::default(); count as usize];
        // SAFETY: room for count events.
        check(unsafe { sys::lfem_world_get_events(self.ptr(), raw.as_mut_ptr(), count, &mut count) })?;
        let body = |b: sys::lfem_body| Body { index: b.index, generation: b.generation };
        Ok(raw
            .iter()
            .map(|e| Event {
                event_type: match e.type_ {
                    sys::LFEM_EVENT_CONTACT_BEGIN => EventType::ContactBegin,
                    sys::LFEM_EVENT_CONTACT_END => EventType::ContactEnd,
                    sys::LFEM_EVENT_SLEEP => EventType::Sleep,
                    sys::LFEM_EVENT_WAKE => EventType::Wake,
                    sys::LFEM_EVENT_CONTACT_PERSIST => EventType::ContactPersist,
                    _ => EventType::AttachmentBroken,
                },
                body_a: body(e.body_a),
                body_b: body(e.body_b),
                attachment: Attachment { index: e.attachment.index, generation: e.attachment.generation },
                normal_impulse: e.normal_impulse,
                max_force: e.max_force,
                approach_speed: e.approach_speed,
                contact_count: e.contact_count,
                point: e.point,
                normal: e.normal,
            })
            .collect())
    }

    /// One warning counter.
    pub fn warning(&self, kind: WarningKind) -> Result<Warning> {
        let mut out = sys::lfem_warning::default();
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_world_get_warning(self.ptr(), kind.raw(), &mut out) })?;
        let b = out.last_body;
        Ok(Warning { count: out.count, last_time: out.last_time, last_body: Body { index: b.index, generation: b.generation } })
    }

    /// Set every warning counter back to zero.
    pub fn clear_warnings(&mut self) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_world_clear_warnings(self.ptr_mut()) })
    }

    // -- bodies --

    /// A body without nodes; give it a mesh with [`World::add_mesh`].
    pub fn create_body(&mut self, def: &BodyDef) -> Result<Body> {
        let raw_def = def.to_raw();
        let mut out = sys::lfem_body::default();
        // SAFETY: live world, valid def and output.
        check(unsafe { sys::lfem_body_create(self.ptr_mut(), &raw_def, &mut out) })?;
        Ok(Body { index: out.index, generation: out.generation })
    }

    /// Destroy a body; its handle (and every copy) becomes stale.
    pub fn destroy_body(&mut self, body: Body) -> Result<()> {
        // SAFETY: live world; any handle value is allowed.
        check(unsafe { sys::lfem_body_destroy(self.ptr_mut(), body.raw()) })
    }

    /// Whether the handle names a live body of this world.
    pub fn is_valid(&self, body: Body) -> bool {
        // SAFETY: live world; any handle value is allowed.
        unsafe { sys::lfem_body_is_valid(self.ptr(), body.raw()) != 0 }
    }

    /// Add the tets of a mesh to a body (copied; the mesh stays yours): 4-node tets, or
    /// 10-node ones ([`Mesh::make_quadratic`], a Gmsh file of type 11).
    pub fn add_mesh(&mut self, body: Body, mesh: &Mesh) -> Result<()> {
        if mesh.nodes_per_tet() == 10 {
            self.add_quadratic_mesh_data(body, mesh.positions(), mesh.quadratic_tets())
        } else {
            self.add_mesh_data(body, mesh.positions(), mesh.tets())
        }
    }

    /// Add a mesh of 10-node tets: node positions (m) and tets of 10 node indices each, the
    /// corners first (positive volume), then the mid-edge nodes of the edges 01, 12, 02, 03,
    /// 13, 23 (see lfem_body_add_quadratic_mesh).
    pub fn add_quadratic_mesh_data(&mut self, body: Body, positions: &[[f64; 3]], tets: &[[u32; 10]]) -> Result<()> {
        let tet_count = to_u32(tets.len(), "tet count")?;
        // SAFETY: 10*tet_count indices.
        unsafe {
            self.add_tets(sys::lfem_body_add_quadratic_mesh, body, positions, tets.as_ptr() as *const u32, tet_count)
        }
    }

    /// Nodes per tet of a body: 4, 10 for quadratic tets, 0 for a body without tets.
    pub fn nodes_per_tet(&self, body: Body) -> Result<u32> {
        let mut out = 0u32;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_nodes_per_tet(self.ptr(), body.raw(), &mut out) })?;
        Ok(out)
    }

    /// Add a tetrahedral mesh given as node positions (m) and tets (4 node indices, 0-based,
    /// positive volume).
    pub fn add_mesh_data(&mut self, body: Body, positions: &[[f64; 3]], tets: &[[u32; 4]]) -> Result<()> {
        let tet_count = to_u32(tets.len(), "tet count")?;
        // SAFETY: 4*tet_count indices.
        unsafe { self.add_tets(sys::lfem_body_add_mesh, body, positions, tets.as_ptr() as *const u32, tet_count) }
    }

    /// Adds nodes and tets through `add` (lfem_body_add_mesh or lfem_body_add_quadratic_mesh).
    ///
    /// # Safety
    /// `tets` must hold as many indices as `add` reads for `tet_count` tets.
    unsafe fn add_tets(
        &mut self,
        add: unsafe extern "C" fn(*mut sys::lfem_world, sys::lfem_body, *const f64, u32, *const u32, u32) -> sys::lfem_status,
        body: Body,
        positions: &[[f64; 3]],
        tets: *const u32,
        tet_count: u32,
    ) -> Result<()> {
        let node_count = to_u32(positions.len(), "node count")?;
        // SAFETY: live world; 3*node_count doubles, and the caller's promise for tets.
        check(add(self.ptr_mut(), body.raw(), positions.as_ptr() as *const f64, node_count, tets, tet_count))
    }

    /// Give a static or kinematic body a rigid shape; returns its index on the body (the
    /// `shape` of the contacts that touch it).
    pub fn add_shape(&mut self, body: Body, def: &ShapeDef) -> Result<u32> {
        let raw = sys::lfem_shape_def {
            type_: match def.shape_type {
                ShapeType::Plane => sys::LFEM_SHAPE_PLANE,
                ShapeType::Box => sys::LFEM_SHAPE_BOX,
                ShapeType::Sphere => sys::LFEM_SHAPE_SPHERE,
                ShapeType::Capsule => sys::LFEM_SHAPE_CAPSULE,
                ShapeType::ConvexHull => sys::LFEM_SHAPE_CONVEX_HULL,
            },
            point_count: to_u32(def.points.len(), "point count")?,
            center: def.center,
            rotation: def.rotation,
            half_extents: def.half_extents,
            radius: def.radius,
            half_length: def.half_length,
            points: if def.points.is_empty() { ptr::null() } else { def.points.as_ptr() as *const f64 },
            internal_value: def.internal_value,
            padding: 0,
        };
        // SAFETY: live world; raw.points holds 3*point_count doubles (copied by lfem).
        let mut index = 0u32;
        check(unsafe { sys::lfem_body_add_shape(self.ptr_mut(), body.raw(), &raw, &mut index) })?;
        Ok(index)
    }

    /// Total mass (kg) of a body: the sum of its lumped node masses, rho V.
    pub fn mass(&self, body: Body) -> Result<f64> {
        let mut out = 0.0;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_mass(self.ptr(), body.raw(), &mut out) })?;
        Ok(out)
    }

    /// The mass (kg) that mass scaling added to a body's nodes (`WorldDef::mass_scaling_step`).
    pub fn added_mass(&self, body: Body) -> Result<f64> {
        let mut out = 0.0;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_added_mass(self.ptr(), body.raw(), &mut out) })?;
        Ok(out)
    }

    /// The body's inverted tets, smallest volume ratio and how long it has been inverted.
    pub fn inversion(&self, body: Body) -> Result<Inversion> {
        let mut out = Inversion { inverted_tets: 0, min_jacobian: 0.0, inverted_for: 0.0 };
        // SAFETY: live world, three valid outputs.
        check(unsafe {
            sys::lfem_body_get_inversion(
                self.ptr(),
                body.raw(),
                &mut out.inverted_tets,
                &mut out.min_jacobian,
                &mut out.inverted_for,
            )
        })?;
        Ok(out)
    }

    /// Linear momentum (kg m/s) and angular momentum about the origin (kg m^2/s) of a body.
    pub fn momentum(&self, body: Body) -> Result<([f64; 3], [f64; 3])> {
        let (mut linear, mut angular) = ([0.0; 3], [0.0; 3]);
        // SAFETY: live world, two outputs of 3 doubles.
        check(unsafe {
            sys::lfem_body_get_momentum(self.ptr(), body.raw(), linear.as_mut_ptr(), angular.as_mut_ptr())
        })?;
        Ok((linear, angular))
    }

    /// The number of nodes of a body.
    pub fn node_count(&self, body: Body) -> Result<usize> {
        let mut out = 0u32;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_node_count(self.ptr(), body.raw(), &mut out) })?;
        Ok(out as usize)
    }

    /// The number of tets of a body.
    pub fn tet_count(&self, body: Body) -> Result<usize> {
        let mut out = 0u32;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_tet_count(self.ptr(), body.raw(), &mut out) })?;
        Ok(out as usize)
    }

    /// Node positions (m) into `out` (at least one entry per node). `Status::BufferTooSmall`
    /// (nothing written) when it is shorter.
    pub fn positions_into(&self, body: Body, out: &mut [[f64; 3]]) -> Result<()> {
        let capacity = u32::try_from(out.len()).unwrap_or(u32::MAX);
        // SAFETY: live world; out holds 3*capacity doubles.
        check(unsafe {
            sys::lfem_body_get_positions(self.ptr(), body.raw(), out.as_mut_ptr() as *mut f64, capacity)
        })
    }

    /// Node positions (m), one `[x, y, z]` per node.
    pub fn positions(&self, body: Body) -> Result<Vec<[f64; 3]>> {
        let n = self.node_count(body).map_err(|e| e.renamed("lfem_body_get_node_count", "lfem_body_get_positions"))?;
        let mut out = vec![[0.0; 3]; n];
        self.positions_into(body, &mut out)?;
        Ok(out)
    }

    /// Node velocities (m/s) into `out` (see [`World::positions_into`]).
    pub fn velocities_into(&self, body: Body, out: &mut [[f64; 3]]) -> Result<()> {
        let capacity = u32::try_from(out.len()).unwrap_or(u32::MAX);
        // SAFETY: live world; out holds 3*capacity doubles.
        check(unsafe {
            sys::lfem_body_get_velocities(self.ptr(), body.raw(), out.as_mut_ptr() as *mut f64, capacity)
        })
    }

    /// Node velocities (m/s) at the current time, one `[vx, vy, vz]` per node.
    pub fn velocities(&self, body: Body) -> Result<Vec<[f64; 3]>> {
        let n = self.node_count(body).map_err(|e| e.renamed("lfem_body_get_node_count", "lfem_body_get_velocities"))?;
        let mut out = vec![[0.0; 3]; n];
        self.velocities_into(body, &mut out)?;
        Ok(out)
    }

    /// Overwrite the velocities (m/s), one per node.
    pub fn set_velocities(&mut self, body: Body, velocities: &[[f64; 3]]) -> Result<()> {
        let n = to_u32(velocities.len(), "node count")?;
        // SAFETY: live world; 3*n doubles.
        check(unsafe { sys::lfem_body_set_velocities(self.ptr_mut(), body.raw(), velocities.as_ptr() as *const f64, n) })
    }

    /// Boundary triangles, counter-clockwise seen from outside.
    pub fn boundary_triangles(&self, body: Body) -> Result<Vec<[u32; 3]>> {
        let mut n = 0u32;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_boundary_triangle_count(self.ptr(), body.raw(), &mut n) })
            .map_err(|e| e.renamed("lfem_body_get_boundary_triangle_count", "lfem_body_get_boundary_triangles"))?;
        let mut out = vec![[0u32; 3]; n as usize];
        // SAFETY: out holds 3*n indices.
        check(unsafe {
            sys::lfem_body_get_boundary_triangles(self.ptr(), body.raw(), out.as_mut_ptr() as *mut u32, n)
        })?;
        Ok(out)
    }

    /// The boundary of a body of 10-node tets as 6-node triangles: corners a, b, c
    /// counter-clockwise seen from outside, then the mid-edge nodes of ab, bc, ca. An error
    /// for a body of other tets (use [`World::boundary_triangles`]).
    pub fn quadratic_boundary_faces(&self, body: Body) -> Result<Vec<[u32; 6]>> {
        let call = "lfem_body_get_boundary_faces";
        if self.nodes_per_tet(body).map_err(|e| e.renamed("lfem_body_get_nodes_per_tet", call))? != 10 {
            return Err(Error::local(Status::InvalidArgument, "the body has no 10-node tets".into()));
        }
        let mut n = 0u32;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_boundary_face_count(self.ptr(), body.raw(), &mut n) })
            .map_err(|e| e.renamed("lfem_body_get_boundary_face_count", call))?;
        let mut out = vec![[0u32; 6]; n as usize];
        // SAFETY: out holds 6*n indices.
        check(unsafe { sys::lfem_body_get_boundary_faces(self.ptr(), body.raw(), out.as_mut_ptr() as *mut u32, n) })?;
        Ok(out)
    }

    /// Von Mises stress (Pa), one per tet.
    pub fn von_mises_stress(&self, body: Body) -> Result<Vec<f64>> {
        let n = self.tet_count(body).map_err(|e| e.renamed("lfem_body_get_tet_count", "lfem_body_get_von_mises_stress"))?;
        let mut out = vec![0.0; n];
        let capacity = to_u32(out.len(), "tet count")?;
        // SAFETY: out holds capacity doubles.
        check(unsafe { sys::lfem_body_get_von_mises_stress(self.ptr(), body.raw(), out.as_mut_ptr(), capacity) })?;
        Ok(out)
    }

    /// The global rotation of the paper model, rows of a 3x3 matrix (identity otherwise).
    pub fn rotation(&self, body: Body) -> Result<[[f64; 3]; 3]> {
        let mut out = [[0.0; 3]; 3];
        // SAFETY: 9 contiguous doubles.
        check(unsafe { sys::lfem_body_get_rotation(self.ptr(), body.raw(), out.as_mut_ptr() as *mut f64) })?;
        Ok(out)
    }

    /// Teleport a deformable body's nodes (m, one per node): velocities kept, the change of
    /// strain energy booked as work, its pairs end.
    pub fn set_positions(&mut self, body: Body, positions: &[[f64; 3]]) -> Result<()> {
        let n = to_u32(positions.len(), "node count")?;
        // SAFETY: live world; 3*n doubles.
        check(unsafe { sys::lfem_body_set_positions(self.ptr_mut(), body.raw(), positions.as_ptr() as *const f64, n) })
    }

    /// A one-shot impulse (N s) at a world point (m): a deformable body's tet around the point
    /// takes it by its shape functions, a rigid body as a whole.
    pub fn apply_impulse(&mut self, body: Body, point: [f64; 3], impulse: [f64; 3]) -> Result<()> {
        // SAFETY: live world; 3 doubles each.
        check(unsafe { sys::lfem_body_apply_impulse(self.ptr_mut(), body.raw(), point.as_ptr(), impulse.as_ptr()) })
    }

    /// A force (N) at a world point (m) for the next `step` call only: bound to the body where it
    /// is now (the tet around the point) and moved with it; the body gains force * dt.
    pub fn apply_force(&mut self, body: Body, point: [f64; 3], force: [f64; 3]) -> Result<()> {
        // SAFETY: live world; 3 doubles each.
        check(unsafe { sys::lfem_body_apply_force(self.ptr_mut(), body.raw(), point.as_ptr(), force.as_ptr()) })
    }

    /// Change the body's type between rigid, kinematic and static (the pose carries over; a
    /// deformable body keeps its type).
    pub fn set_type(&mut self, body: Body, body_type: BodyType) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_type(self.ptr_mut(), body.raw(), body_type.raw()) })
    }

    /// The body's type.
    pub fn body_type(&self, body: Body) -> Result<BodyType> {
        let mut out: sys::lfem_body_type = sys::LFEM_BODY_DEFORMABLE;
        // SAFETY: live world; one enum written on success.
        check(unsafe { sys::lfem_body_get_type(self.ptr(), body.raw(), &mut out) })?;
        Ok(BodyType::from_raw(out))
    }

    /// An opaque 64-bit number kept on the body (an entity id); checkpoints keep it.
    pub fn set_user_id(&mut self, body: Body, user_id: u64) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_user_id(self.ptr_mut(), body.raw(), user_id) })
    }

    /// The body's user id (0 at creation).
    pub fn user_id(&self, body: Body) -> Result<u64> {
        let mut out = 0u64;
        // SAFETY: live world; one u64 written on success.
        check(unsafe { sys::lfem_body_get_user_id(self.ptr(), body.raw(), &mut out) })?;
        Ok(out)
    }

    /// The point of the body's surface nearest to `point`, its boundary triangle and the
    /// distance (m).
    pub fn closest_point(&self, body: Body, point: [f64; 3]) -> Result<([f64; 3], u32, f64)> {
        let (mut q, mut t, mut d) = ([0.0; 3], 0u32, 0.0);
        // SAFETY: 3 doubles in, 3 out, two outputs.
        check(unsafe { sys::lfem_body_closest_point(self.ptr(), body.raw(), point.as_ptr(), q.as_mut_ptr(), &mut t, &mut d) })?;
        Ok((q, t, d))
    }

    /// The body's pose x = R X + t: `[t, quaternion w x y z]` (a deformable body's best fit).
    pub fn transform(&self, body: Body) -> Result<[f64; 7]> {
        let mut out = [0.0; 7];
        // SAFETY: 7 doubles.
        check(unsafe { sys::lfem_body_get_transform(self.ptr(), body.raw(), out.as_mut_ptr()) })?;
        Ok(out)
    }

    /// Teleport a body rigidly to the pose `[t, quaternion w x y z]`: velocities kept, no work.
    pub fn set_transform(&mut self, body: Body, transform: [f64; 7]) -> Result<()> {
        // SAFETY: live world; 7 doubles.
        check(unsafe { sys::lfem_body_set_transform(self.ptr_mut(), body.raw(), transform.as_ptr()) })
    }

    /// The centre of mass where the nodes are now (m).
    pub fn center_of_mass(&self, body: Body) -> Result<[f64; 3]> {
        let mut out = [0.0; 3];
        // SAFETY: 3 doubles.
        check(unsafe { sys::lfem_body_get_center_of_mass(self.ptr(), body.raw(), out.as_mut_ptr()) })?;
        Ok(out)
    }

    /// The nodes whose current position lies in the box [lo, hi] (m).
    pub fn find_nodes_in_box(&self, body: Body, lo: [f64; 3], hi: [f64; 3]) -> Result<Vec<u32>> {
        let mut count = 0u32;
        // SAFETY: capacity 0 with a null out asks for the count.
        let first = unsafe {
            sys::lfem_body_find_nodes_in_box(self.ptr(), body.raw(), lo.as_ptr(), hi.as_ptr(), ptr::null_mut(), 0, &mut count)
        };
        if first != sys::LFEM_BUFFER_TOO_SMALL {
            check(first)?;
        }
        let mut out = vec![0u32; count as usize];
        if count > 0 {
            // SAFETY: out holds count indices.
            check(unsafe {
                sys::lfem_body_find_nodes_in_box(
                    self.ptr(),
                    body.raw(),
                    lo.as_ptr(),
                    hi.as_ptr(),
                    out.as_mut_ptr(),
                    count,
                    &mut count,
                )
            })?;
            out.truncate(count as usize);
        }
        Ok(out)
    }

    // -- loads and supports --

    /// Fix nodes in place (velocity 0 from now on).
    pub fn fix_nodes(&mut self, body: Body, nodes: &[u32]) -> Result<()> {
        let n = to_u32(nodes.len(), "node count")?;
        // SAFETY: n indices.
        check(unsafe { sys::lfem_body_fix_nodes(self.ptr_mut(), body.raw(), nodes.as_ptr(), n) })
    }

    /// Make nodes move at a constant velocity (m/s), whatever the forces.
    pub fn prescribe_node_velocity(&mut self, body: Body, nodes: &[u32], velocity: [f64; 3]) -> Result<()> {
        let n = to_u32(nodes.len(), "node count")?;
        // SAFETY: n indices, 3 doubles.
        check(unsafe {
            sys::lfem_body_prescribe_node_velocity(self.ptr_mut(), body.raw(), nodes.as_ptr(), n, velocity.as_ptr())
        })
    }

    /// Give fixed or prescribed nodes back to the dynamics.
    pub fn release_nodes(&mut self, body: Body, nodes: &[u32]) -> Result<()> {
        let n = to_u32(nodes.len(), "node count")?;
        // SAFETY: n indices.
        check(unsafe { sys::lfem_body_release_nodes(self.ptr_mut(), body.raw(), nodes.as_ptr(), n) })
    }

    /// Constant external forces (N), one per listed node, added to gravity from now on.
    pub fn set_node_forces(&mut self, body: Body, nodes: &[u32], forces: &[[f64; 3]]) -> Result<()> {
        if nodes.len() != forces.len() {
            return Err(Error::local(
                Status::InvalidArgument,
                format!("lfem (Rust): {} nodes but {} forces", nodes.len(), forces.len()),
            ));
        }
        let n = to_u32(nodes.len(), "node count")?;
        // SAFETY: n indices, 3*n doubles.
        check(unsafe {
            sys::lfem_body_set_node_forces(self.ptr_mut(), body.raw(), nodes.as_ptr(), n, forces.as_ptr() as *const f64)
        })
    }

    /// Remove every external node force of the body.
    pub fn clear_node_forces(&mut self, body: Body) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_clear_node_forces(self.ptr_mut(), body.raw()) })
    }

    /// The velocity of a kinematic body: linear (m/s) of its centre, angular (rad/s) about it.
    pub fn set_kinematic_velocity(&mut self, body: Body, linear: [f64; 3], angular: [f64; 3]) -> Result<()> {
        // SAFETY: 3 + 3 doubles.
        check(unsafe {
            sys::lfem_body_set_kinematic_velocity(self.ptr_mut(), body.raw(), linear.as_ptr(), angular.as_ptr())
        })
    }

    // -- skins --

    /// Bind a render mesh (vertices in the body's rest frame, m; triangles of vertex indices)
    /// to the body's tets; returns the skin's index on the body (lfem_body_add_skin).
    pub fn add_skin(&mut self, body: Body, positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> Result<u32> {
        let vertex_count = to_u32(positions.len(), "vertex count")?;
        let triangle_count = to_u32(triangles.len(), "triangle count")?;
        let mut index = 0u32;
        // SAFETY: live world; the arrays hold 3*vertex_count doubles and 3*triangle_count indices.
        check(unsafe {
            sys::lfem_body_add_skin(
                self.ptr_mut(),
                body.raw(),
                positions.as_ptr() as *const f64,
                vertex_count,
                triangles.as_ptr() as *const u32,
                triangle_count,
                &mut index,
            )
        })?;
        Ok(index)
    }

    /// Remove a skin; the skins after it move down one index.
    pub fn remove_skin(&mut self, body: Body, skin: u32) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_remove_skin(self.ptr_mut(), body.raw(), skin) })
    }

    /// Change the body's Coulomb friction (>= 0); the body wakes.
    pub fn set_friction(&mut self, body: Body, friction: f64) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_friction(self.ptr_mut(), body.raw(), friction) })
    }

    /// Change a deformable body's Young's modulus (Pa) and Poisson's ratio; its stable step
    /// follows, the change of strain energy is booked as work (not under mass scaling).
    pub fn set_material(&mut self, body: Body, young_modulus: f64, poisson_ratio: f64) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_material(self.ptr_mut(), body.raw(), young_modulus, poisson_ratio) })
    }

    /// Whether the body may fall asleep; false wakes it.
    pub fn set_sleep_allowed(&mut self, body: Body, allowed: bool) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_sleep_allowed(self.ptr_mut(), body.raw(), c_int::from(allowed)) })
    }

    /// The caller's frame an attachment holds its nodes to, as last set (null target only).
    pub fn attachment_frame(&self, attachment: Attachment) -> Result<[f64; 7]> {
        let mut out = [0.0; 7];
        // SAFETY: 7 doubles.
        check(unsafe { sys::lfem_attachment_get_frame(self.ptr(), attachment.raw(), out.as_mut_ptr()) })?;
        Ok(out)
    }

    /// Change the body's mass-proportional damping (>= 0, 1/s); the body wakes.
    pub fn set_damping(&mut self, body: Body, damping: f64) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_damping(self.ptr_mut(), body.raw(), damping) })
    }

    /// Change the body's collision filter; pairs it now forbids end with the next step's events.
    pub fn set_filter(&mut self, body: Body, category_bits: u32, mask_bits: u32) -> Result<()> {
        // SAFETY: live world.
        check(unsafe { sys::lfem_body_set_filter(self.ptr_mut(), body.raw(), category_bits, mask_bits) })
    }

    /// The number of skins of a body.
    pub fn skin_count(&self, body: Body) -> Result<usize> {
        let mut out = 0u32;
        // SAFETY: live world, valid output.
        check(unsafe { sys::lfem_body_get_skin_count(self.ptr(), body.raw(), &mut out) })?;
        Ok(out as usize)
    }

    /// The vertex and triangle counts of a skin.
    pub fn skin_sizes(&self, body: Body, skin: u32) -> Result<(usize, usize)> {
        let (mut vertices, mut triangles) = (0u32, 0u32);
        // SAFETY: live world, two valid outputs.
        check(unsafe { sys::lfem_body_get_skin_sizes(self.ptr(), body.raw(), skin, &mut vertices, &mut triangles) })?;
        Ok((vertices as usize, triangles as usize))
    }

    /// A skin's triangles, as given.
    pub fn skin_triangles(&self, body: Body, skin: u32) -> Result<Vec<[u32; 3]>> {
        let (_, n) =
            self.skin_sizes(body, skin).map_err(|e| e.renamed("lfem_body_get_skin_sizes", "lfem_body_get_skin_triangles"))?;
        let mut out = vec![[0u32; 3]; n];
        // SAFETY: out holds n triangles of 3 indices.
        check(unsafe {
            sys::lfem_body_get_skin_triangles(self.ptr(), body.raw(), skin, out.as_mut_ptr() as *mut u32, n as u32)
        })?;
        Ok(out)
    }

    /// A skin's deformed vertices and smooth normals.
    pub fn skin_vertices(&self, body: Body, skin: u32) -> Result<SkinVertices> {
        let (n, _) =
            self.skin_sizes(body, skin).map_err(|e| e.renamed("lfem_body_get_skin_sizes", "lfem_body_get_skin_vertices"))?;
        let mut out = SkinVertices { positions: vec![[0.0; 3]; n], normals: vec![[0.0; 3]; n] };
        // SAFETY: both outputs hold n vertices of 3 doubles.
        check(unsafe {
            sys::lfem_body_get_skin_vertices(
                self.ptr(),
                body.raw(),
                skin,
                out.positions.as_mut_ptr() as *mut f64,
                out.normals.as_mut_ptr() as *mut f64,
                n as u32,
            )
        })?;
        Ok(out)
    }

    /// A skin's vertices into an interleaved float vertex buffer, `stride` floats per vertex:
    /// the position at `[i * stride ..][..3]` and, with `normals`, the unit normal right after
    /// it (`[i * stride + 3 ..][..3]`); the other floats are left alone. `stride` >= 3 (6 with
    /// normals); `buffer` must hold every vertex (else `Status::BufferTooSmall`, nothing
    /// written).
    pub fn skin_vertex_buffer(&self, body: Body, skin: u32, buffer: &mut [f32], stride: usize, normals: bool) -> Result<()> {
        let (n, _) = self
            .skin_sizes(body, skin)
            .map_err(|e| e.renamed("lfem_body_get_skin_sizes", "lfem_body_get_skin_vertices_f32"))?;
        let width = if normals { 6 } else { 3 };
        if stride < width {
            return Err(Error::local(
                Status::InvalidArgument,
                format!("lfem (Rust): stride {} is below the {} floats of a vertex", stride, width),
            ));
        }
        if n > 0 && buffer.len() < (n - 1) * stride + width {
            return Err(Error::local(
                Status::BufferTooSmall,
                format!("lfem (Rust): a buffer of {} floats is below the {} that {} vertices need", buffer.len(), (n - 1) * stride + width, n),
            ));
        }
        let stride32 = to_u32(stride, "stride")?;
        let base = buffer.as_mut_ptr();
        // SAFETY: the buffer holds (n - 1) * stride + width floats (checked above); normals, when
        // asked for, start 3 floats in.
        check(unsafe {
            sys::lfem_body_get_skin_vertices_f32(
                self.ptr(),
                body.raw(),
                skin,
                base,
                stride32,
                if normals { base.add(3) } else { ptr::null_mut() },
                stride32,
                n as u32,
            )
        })
    }

    // -- queries --

    /// The nearest crossing of the ray `origin + t direction / |direction|`, t in
    /// [0, max_distance] (m; `f64::INFINITY` for no limit), with the surface of a body the
    /// filter sees; `None` when it meets nothing (lfem_world_cast_ray).
    pub fn cast_ray(&self, origin: [f64; 3], direction: [f64; 3], max_distance: f64, filter: QueryFilter) -> Result<Option<RayHit>> {
        let mut out = RayHit::default();
        let mut hit = 0;
        // SAFETY: 3 + 3 doubles; RayHit has the layout of lfem_ray_hit.
        check(unsafe {
            sys::lfem_world_cast_ray(
                self.ptr(),
                origin.as_ptr(),
                direction.as_ptr(),
                max_distance,
                filter.raw(),
                &mut out as *mut RayHit as *mut sys::lfem_ray_hit,
                &mut hit,
            )
        })?;
        Ok(if hit == 1 { Some(out) } else { None })
    }

    /// A sphere of `radius` swept along the ray: where it first touches a surface the filter
    /// sees (`distance` its centre's travel, `point` the point touched, `normal` from it towards
    /// the centre), or `None` (lfem_world_cast_sphere).
    pub fn cast_sphere(
        &self,
        origin: [f64; 3],
        direction: [f64; 3],
        radius: f64,
        max_distance: f64,
        filter: QueryFilter,
    ) -> Result<Option<RayHit>> {
        let mut out = RayHit::default();
        let mut hit = 0;
        // SAFETY: 3 + 3 doubles; RayHit has the layout of lfem_ray_hit.
        check(unsafe {
            sys::lfem_world_cast_sphere(
                self.ptr(),
                origin.as_ptr(),
                direction.as_ptr(),
                radius,
                max_distance,
                filter.raw(),
                &mut out as *mut RayHit as *mut sys::lfem_ray_hit,
                &mut hit,
            )
        })?;
        Ok(if hit == 1 { Some(out) } else { None })
    }

    /// Every crossing along the ray, nearest first (lfem_world_cast_ray_all).
    pub fn cast_ray_all(&self, origin: [f64; 3], direction: [f64; 3], max_distance: f64, filter: QueryFilter) -> Result<Vec<RayHit>> {
        let call = |out: &mut [RayHit], count: &mut u32| {
            // SAFETY: out holds out.len() hits of lfem_ray_hit's layout (none: a null pointer).
            unsafe {
                sys::lfem_world_cast_ray_all(
                    self.ptr(),
                    origin.as_ptr(),
                    direction.as_ptr(),
                    max_distance,
                    filter.raw(),
                    if out.is_empty() { ptr::null_mut() } else { out.as_mut_ptr() as *mut sys::lfem_ray_hit },
                    out.len() as u32,
                    count,
                )
            }
        };
        counted_list(RayHit::default(), call)
    }

    /// The bodies the filter sees that the solid sphere overlaps (touching counts), in body
    /// order, each with its triangle or shape nearest the centre and the point of it.
    pub fn overlap_sphere(&self, center: [f64; 3], radius: f64, filter: QueryFilter) -> Result<Vec<Overlap>> {
        self.overlap_capsule(center, center, radius, filter)
    }

    /// The same for the capsule of the segment a-b swept by radius.
    pub fn overlap_capsule(&self, a: [f64; 3], b: [f64; 3], radius: f64, filter: QueryFilter) -> Result<Vec<Overlap>> {
        let call = |out: &mut [Overlap], count: &mut u32| {
            // SAFETY: 3 + 3 doubles; out holds out.len() records of lfem_overlap's layout (none:
            // a null pointer).
            unsafe {
                sys::lfem_world_overlap_capsule(
                    self.ptr(),
                    a.as_ptr(),
                    b.as_ptr(),
                    radius,
                    filter.raw(),
                    if out.is_empty() { ptr::null_mut() } else { out.as_mut_ptr() as *mut sys::lfem_overlap },
                    out.len() as u32,
                    count,
                )
            }
        };
        counted_list(Overlap::default(), call)
    }

    /// The bodies the filter sees whose current geometry overlaps the box [lo, hi] (m), in body
    /// order (lfem_world_overlap_box).
    pub fn overlap_box(&self, lo: [f64; 3], hi: [f64; 3], filter: QueryFilter) -> Result<Vec<Body>> {
        let call = |out: &mut [Body], count: &mut u32| {
            // SAFETY: out holds out.len() handles of lfem_body's layout (none: a null pointer).
            unsafe {
                sys::lfem_world_overlap_box(
                    self.ptr(),
                    lo.as_ptr(),
                    hi.as_ptr(),
                    filter.raw(),
                    if out.is_empty() { ptr::null_mut() } else { out.as_mut_ptr() as *mut sys::lfem_body },
                    out.len() as u32,
                    count,
                )
            }
        };
        counted_list(Body::NULL, call)
    }

    // -- contacts --

    /// The number of active contacts of the last step.
    pub fn contact_count(&self) -> Result<usize> {
        let mut count = 0u32;
        // SAFETY: capacity 0 with a null out asks for the count.
        let status = unsafe { sys::lfem_world_query_contacts(self.ptr(), ptr::null_mut(), 0, &mut count) };
        if status != sys::LFEM_BUFFER_TOO_SMALL {
            check(status)?;
        }
        Ok(count as usize)
    }

    /// Copy the active contacts into the front of `out`; returns how many. When `out` is too
    /// short: `Status::BufferTooSmall` and nothing copied (ask [`World::contact_count`]).
    pub fn contacts_into(&self, out: &mut [Contact]) -> Result<usize> {
        let mut count = 0u32;
        // A capacity beyond u32 is as good as u32::MAX (lfem counts contacts in u32).
        let capacity = out.len().min(u32::MAX as usize) as u32;
        // SAFETY: Contact has the layout of lfem_contact; out holds at least capacity of them.
        check(unsafe {
            sys::lfem_world_query_contacts(self.ptr(), out.as_mut_ptr() as *mut sys::lfem_contact, capacity, &mut count)
        })?;
        Ok(count as usize)
    }

    /// The active contacts of the last step, in lfem's fixed order.
    pub fn contacts(&self) -> Result<Vec<Contact>> {
        let mut out = vec![Contact::default(); self.contact_count()?];
        let n = self.contacts_into(&mut out)?;
        out.truncate(n);
        Ok(out)
    }
}

// ---- meshes ------------------------------------------------------------------------------------

/// A tetrahedral mesh (node positions and tets) owned by Rust; destroyed when dropped.
pub struct Mesh {
    raw: NonNull<sys::lfem_mesh>,
}

// SAFETY: a mesh is plain data; &mut self guards mutation.
unsafe impl Send for Mesh {}

impl Drop for Mesh {
    fn drop(&mut self) {
        // SAFETY: from an lfem_mesh_* constructor, destroyed once.
        unsafe { sys::lfem_mesh_destroy(self.raw.as_ptr()) }
    }
}

impl fmt::Debug for Mesh {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Mesh")
            .field("nodes", &self.node_count())
            .field("tets", &self.tet_count())
            .field("nodes_per_tet", &self.nodes_per_tet())
            .finish()
    }
}

fn mesh_from(status: sys::lfem_status, out: *mut sys::lfem_mesh) -> Result<Mesh> {
    check(status)?;
    NonNull::new(out)
        .map(|raw| Mesh { raw })
        .ok_or_else(|| Error::local(Status::InternalError, "lfem returned a NULL mesh".into()))
}

impl Mesh {
    /// A box from the origin to `size` (m) of `cells[0] x cells[1] x cells[2]` hexahedra of 6
    /// tets each.
    pub fn new_box(size: [f64; 3], cells: [u32; 3]) -> Result<Mesh> {
        let mut out = ptr::null_mut();
        // SAFETY: 3 doubles, 3 integers, valid output.
        let status = unsafe { sys::lfem_mesh_create_box(size.as_ptr(), cells.as_ptr(), &mut out) };
        mesh_from(status, out)
    }

    /// A solid cylinder along +z from z = 0 (see lfem_mesh_create_cylinder).
    pub fn new_cylinder(radius: f64, height: f64, segments: u32, rings: u32, layers: u32) -> Result<Mesh> {
        let mut out = ptr::null_mut();
        // SAFETY: valid output.
        let status = unsafe { sys::lfem_mesh_create_cylinder(radius, height, segments, rings, layers, &mut out) };
        mesh_from(status, out)
    }

    /// A hollow cup open at the top (see lfem_mesh_create_cup).
    pub fn new_cup(outer_radius: f64, height: f64, wall: f64, bottom: f64, segments: u32, layers: u32) -> Result<Mesh> {
        let mut out = ptr::null_mut();
        // SAFETY: valid output.
        let status =
            unsafe { sys::lfem_mesh_create_cup(outer_radius, height, wall, bottom, segments, layers, &mut out) };
        mesh_from(status, out)
    }

    /// A hammer (see lfem_mesh_create_hammer).
    pub fn new_hammer(
        handle_length: f64,
        handle_width: f64,
        head_length: f64,
        head_width: f64,
        cell_size: f64,
    ) -> Result<Mesh> {
        let mut out = ptr::null_mut();
        // SAFETY: valid output.
        let status = unsafe {
            sys::lfem_mesh_create_hammer(handle_length, handle_width, head_length, head_width, cell_size, &mut out)
        };
        mesh_from(status, out)
    }

    /// The tetrahedra of a Gmsh .msh file (ASCII 2.2 or 4.1): 4-node ones, or 10-node ones
    /// (type 11).
    pub fn load_gmsh<P: AsRef<Path>>(path: P) -> Result<Mesh> {
        let c_path = to_c_path(path.as_ref())?;
        let mut out = ptr::null_mut();
        // SAFETY: NUL-terminated path, valid output.
        let status = unsafe { sys::lfem_mesh_load_gmsh(c_path.as_ptr(), &mut out) };
        mesh_from(status, out)
    }

    /// The number of nodes.
    pub fn node_count(&self) -> usize {
        // SAFETY: live mesh.
        unsafe { sys::lfem_mesh_get_node_count(self.raw.as_ptr()) as usize }
    }

    /// The number of tets.
    pub fn tet_count(&self) -> usize {
        // SAFETY: live mesh.
        unsafe { sys::lfem_mesh_get_tet_count(self.raw.as_ptr()) as usize }
    }

    /// Nodes per tet: 4, or 10 for quadratic tets.
    pub fn nodes_per_tet(&self) -> u32 {
        // SAFETY: live mesh.
        unsafe { sys::lfem_mesh_get_nodes_per_tet(self.raw.as_ptr()) }
    }

    /// Turn the 4-node tets into 10-node ones: a node at the middle of every edge, numbered
    /// after the corners (see lfem_mesh_make_quadratic). An error when they already are.
    pub fn make_quadratic(&mut self) -> Result<()> {
        // SAFETY: live mesh.
        check(unsafe { sys::lfem_mesh_make_quadratic(self.raw.as_ptr()) })
    }

    /// The raw tet indices, `nodes_per_tet()` per tet.
    fn tet_indices(&self, per_tet: u32) -> Option<*const u32> {
        // SAFETY: live mesh.
        let p = unsafe { sys::lfem_mesh_get_tets(self.raw.as_ptr()) };
        if p.is_null() || self.tet_count() == 0 || self.nodes_per_tet() != per_tet {
            None
        } else {
            Some(p)
        }
    }

    /// Node positions (m), a view into the mesh.
    pub fn positions(&self) -> &[[f64; 3]] {
        let n = self.node_count();
        // SAFETY: lfem keeps 3*n doubles there until the mesh changes (needs &mut self) or dies.
        unsafe {
            let p = sys::lfem_mesh_get_positions(self.raw.as_ptr());
            if p.is_null() || n == 0 {
                &[]
            } else {
                std::slice::from_raw_parts(p as *const [f64; 3], n)
            }
        }
    }

    /// Tets (4 node indices each), a view into the mesh; empty for a mesh of 10-node tets
    /// (see [`Mesh::quadratic_tets`]).
    pub fn tets(&self) -> &[[u32; 4]] {
        // SAFETY: as for positions, 4 indices per tet.
        self.tet_indices(4)
            .map_or(&[], |p| unsafe { std::slice::from_raw_parts(p as *const [u32; 4], self.tet_count()) })
    }

    /// 10-node tets (corners, then the mid-edge nodes of the edges 01, 12, 02, 03, 13, 23), a
    /// view into the mesh; empty for a mesh of 4-node tets.
    pub fn quadratic_tets(&self) -> &[[u32; 10]] {
        // SAFETY: as for positions, 10 indices per tet.
        self.tet_indices(10)
            .map_or(&[], |p| unsafe { std::slice::from_raw_parts(p as *const [u32; 10], self.tet_count()) })
    }

    /// Move the mesh by `offset` (m).
    pub fn translate(&mut self, offset: [f64; 3]) -> Result<()> {
        // SAFETY: live mesh, 3 doubles.
        check(unsafe { sys::lfem_mesh_translate(self.raw.as_ptr(), offset.as_ptr()) })
    }

    /// Rotate the mesh about the origin by `angle` (rad) around `axis`.
    pub fn rotate(&mut self, axis: [f64; 3], angle: f64) -> Result<()> {
        // SAFETY: live mesh, 3 doubles.
        check(unsafe { sys::lfem_mesh_rotate(self.raw.as_ptr(), axis.as_ptr(), angle) })
    }
}

// ---- output --------------------------------------------------------------------------------------

/// A ParaView time series (.pvd plus one .vtu per frame); closed when dropped.
pub struct VtkSeries {
    raw: NonNull<sys::lfem_vtk_series>,
}

// SAFETY: owned exclusively; &mut self guards writes.
unsafe impl Send for VtkSeries {}

impl Drop for VtkSeries {
    fn drop(&mut self) {
        // SAFETY: from lfem_vtk_series_create, destroyed once.
        unsafe { sys::lfem_vtk_series_destroy(self.raw.as_ptr()) }
    }
}

impl VtkSeries {
    /// Start a series at `pvd_path`; frames go beside it. Nothing is written yet.
    pub fn new<P: AsRef<Path>>(pvd_path: P) -> Result<VtkSeries> {
        let c_path = to_c_path(pvd_path.as_ref())?;
        let mut out = ptr::null_mut();
        // SAFETY: NUL-terminated path, valid output.
        check(unsafe { sys::lfem_vtk_series_create(c_path.as_ptr(), &mut out) })?;
        NonNull::new(out)
            .map(|raw| VtkSeries { raw })
            .ok_or_else(|| Error::local(Status::InternalError, "lfem returned a NULL series".into()))
    }

    /// Write every body of the world as the next frame.
    pub fn write_frame(&mut self, world: &World) -> Result<()> {
        // SAFETY: live series and world.
        check(unsafe { sys::lfem_vtk_series_write_frame(self.raw.as_ptr(), world.ptr()) })
    }
}
