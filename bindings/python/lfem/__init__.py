"""Python bindings of lfem (include_c/lfem.h) through ctypes, with numpy arrays.

Deformable bodies simulated by an explicit local finite element method. SI units throughout.

    import lfem
    with lfem.World() as world:                       # gravity (0, 0, -9.81) m/s^2
        mesh = lfem.Mesh.box((0.3, 0.2, 0.1), (3, 2, 1))
        mesh.translate((0, 0, 2))
        block = world.create_body(lfem.BodyDef(model=lfem.Model.NEO_HOOKEAN))
        world.add_mesh(block, mesh)
        world.step(0.5)
        print(world.positions(block)[:, 2].min())     # numpy (n, 3)

- Every failing call raises LfemError carrying .status (a Status) and .message (lfem_last_error);
  INVALID_ARGUMENT comes as InvalidArgumentError, also a ValueError. A failed call changes
  nothing. An argument of the wrong type raises TypeError naming it.
- WorldDef(), BodyDef() and ShapeDef() start from the library's defaults and take fields as
  keywords; enum fields read back as enums; a vector of the wrong length is refused.
- Positions and velocities come as numpy float64 arrays of shape (n, 3) that lfem writes into
  directly; pass out= to reuse a buffer. Contacts come as a numpy structured array whose dtype
  (CONTACT_DTYPE) is the C struct lfem_contact, also filled in place, and so do all of a ray's
  hits (RAY_HIT_DTYPE). A skin's vertices go straight into an engine's float32 vertex buffer
  (World.skin_vertex_buffer).
- World, Mesh and VtkSeries free their native object on close(), at the end of a with block, or
  when garbage collected. Body is a value handle; a destroyed body's handle raises
  LfemError(Status.INVALID_HANDLE).

Where the library is loaded from: see lfem._library (LFEM_LIBRARY, else the checkout's build/
when run from the source tree, the install prefix of this package, pkg-config's libdir for lfem,
then liblfem.so.0 through the dynamic loader); library_path tells which.
"""

from __future__ import annotations

import ctypes
import math
from typing import Any, Optional, Tuple

import numpy as np
import numpy.typing as npt

from . import _convert, _errors
from ._errors import InvalidArgumentError, LfemError, Status
from ._native import c_string as _c_string
from ._native import lib as native
from ._native import library_path
from ._structs import (CONTACT_DTYPE, NO_SHAPE, RAY_HIT_DTYPE, Attachment, AttachmentDef, Body,
                       BodyDef, BodyType, Contact, Event, EventType, Model, Overlap, PhaseTime,
                       Profile, QueryFilter, RayHit, ShapeDef, ShapeType, Warning, WarningKind,
                       WorldDef, WorldStats)
from ._version import __version__

__all__ = [
    "__version__", "Status", "BodyType", "Model", "ShapeType", "WarningKind", "Warning", "LfemError",
    "Attachment", "Event", "EventType",
    "InvalidArgumentError", "WorldDef", "WorldStats", "PhaseTime", "Profile", "Body", "BodyDef",
    "Contact", "CONTACT_DTYPE", "NO_SHAPE", "ShapeDef", "QueryFilter", "RayHit", "RAY_HIT_DTYPE",
    "Overlap", "AttachmentDef",
    "World", "Mesh", "VtkSeries", "version",
    "version_string", "status_string", "last_error", "library_path", "native", "VERSION_MAJOR",
    "VERSION_MINOR", "VERSION_PATCH",
]

VERSION_MAJOR, VERSION_MINOR, VERSION_PATCH = (int(part) for part in __version__.split("."))

_dp = ctypes.POINTER(ctypes.c_double)
_up = ctypes.POINTER(ctypes.c_uint32)
_vp = ctypes.c_void_p
_U32_MAX = 0xFFFFFFFF

Vectors = npt.NDArray[np.float64]
Indices = npt.NDArray[np.uint32]


def version() -> Tuple[int, int, int]:
    """(major, minor, patch) of the library loaded."""
    v = native.lfem_version()
    return (v >> 16, (v >> 8) & 0xFF, v & 0xFF)


def version_string() -> str:
    """"major.minor.patch" of the library loaded."""
    return _c_string(native.lfem_version_string())


def status_string(status: Status | int) -> str:
    """lfem's fixed name and meaning, e.g. "LFEM_INVALID_MESH: invalid mesh"."""
    return _c_string(native.lfem_status_string(_convert.count(status, "status")))


def last_error() -> str:
    """The message of this thread's last failed call ("" before any)."""
    return _c_string(native.lfem_last_error())


def _dptr(a: np.ndarray) -> Any:
    return a.ctypes.data_as(_dp)


def _uptr(a: np.ndarray) -> Any:
    return a.ctypes.data_as(_up)


def _body(body: Any) -> Body:
    if not isinstance(body, Body):
        raise TypeError("lfem: body must be an lfem.Body, not %s" % type(body).__name__)
    return body


def _definition(definition: Any, kind: type, name: str = "definition") -> Any:
    if definition is None:
        return kind()
    if not isinstance(definition, kind):
        raise TypeError("lfem: %s must be an lfem.%s, not %s"
                        % (name, kind.__name__, type(definition).__name__))
    return definition


# ---- world ------------------------------------------------------------------------------------


class World:
    """A simulation world. close() (or a with block, or garbage collection) destroys it."""

    _handle: Optional[ctypes.c_void_p] = None

    def __init__(self, definition: Optional[WorldDef] = None) -> None:
        d = _definition(definition, WorldDef)
        handle = _vp()
        native.lfem_world_create(ctypes.byref(d), ctypes.byref(handle))
        self._handle = handle

    @classmethod
    def load(cls, path: Any) -> "World":
        """A new world from a checkpoint written by save(); stepping it continues the saved
        run bit for bit. Body handles of the saved world are valid in it."""
        handle = _vp()
        native.lfem_world_load(_convert.path(path, "path"), ctypes.byref(handle))
        world = cls.__new__(cls)
        world._handle = handle
        return world

    def save(self, path: Any) -> None:
        """Write a checkpoint of the whole world (replaces path only once complete)."""
        native.lfem_world_save(self.handle, _convert.path(path, "path"))

    @property
    def handle(self) -> ctypes.c_void_p:
        """The raw lfem_world* (a ctypes c_void_p)."""
        if self._handle is None:
            raise ValueError("lfem: the world is closed")
        return self._handle

    def close(self) -> None:
        """Destroy the world and its bodies (twice is harmless)."""
        if self._handle is not None:
            native.lfem_world_destroy(self._handle)
            self._handle = None

    def __enter__(self) -> "World":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __del__(self) -> None:
        self.close()

    def step(self, dt: float) -> None:
        """Advance by dt seconds (split into stable sub-steps). On Status.UNSTABLE the world
        is rolled back to its state before the call."""
        native.lfem_world_step(self.handle, _convert.real(dt, "dt"))

    def set_gravity(self, gravity: npt.ArrayLike) -> None:
        """Gravity (m/s^2), 3 components."""
        native.lfem_world_set_gravity(self.handle, _dptr(_convert.vector(gravity, "gravity")))

    def set_time_step(self, time_step: float) -> None:
        """Fixed sub-step (s), 0 = automatic."""
        native.lfem_world_set_time_step(self.handle, _convert.real(time_step, "time_step"))

    @property
    def stable_step(self) -> float:
        """The stable limit of the sub-step (s); infinity without deformable bodies."""
        out = ctypes.c_double()
        native.lfem_world_get_stable_step(self.handle, ctypes.byref(out))
        return out.value

    @property
    def stats(self) -> WorldStats:
        """Time, energies, momenta and solver figures (a WorldStats)."""
        out = WorldStats()
        native.lfem_world_get_stats(self.handle, ctypes.byref(out))
        return out

    @property
    def profile(self) -> Profile:
        """Per-phase time (s) and counts since creation or reset_profile()."""
        out = Profile()
        native.lfem_world_get_profile(self.handle, ctypes.byref(out))
        return out

    def reset_profile(self) -> None:
        """Set the profile back to zero."""
        native.lfem_world_reset_profile(self.handle)

    def warning(self, kind: WarningKind) -> Warning:
        """One warning counter: count, last_time (s), last_body."""
        out = Warning()
        native.lfem_world_get_warning(self.handle, int(kind), ctypes.byref(out))
        return out

    def clear_warnings(self) -> None:
        """Set every warning counter back to zero."""
        native.lfem_world_clear_warnings(self.handle)

    # -- bodies --

    def create_body(self, definition: Optional[BodyDef] = None) -> Body:
        """A body without nodes (BodyDef() when definition is None); give it a mesh with
        add_mesh, or shapes with add_shape."""
        d = _definition(definition, BodyDef)
        out = Body()
        native.lfem_body_create(self.handle, ctypes.byref(d), ctypes.byref(out))
        return out

    def destroy_body(self, body: Body) -> None:
        """Destroy a body; its handle (and every copy) becomes stale."""
        native.lfem_body_destroy(self.handle, _body(body))

    def is_valid(self, body: Body) -> bool:
        """Whether the handle names a live body of this world."""
        return native.lfem_body_is_valid(self.handle, _body(body)) != 0

    def add_mesh(self, body: Body, mesh: "Mesh") -> None:
        """Add the tets of a Mesh (copied; the mesh stays yours): 4-node tets, or 10-node ones
        (Mesh.make_quadratic, a Gmsh file of type 11) through lfem_body_add_quadratic_mesh."""
        if not isinstance(mesh, Mesh):
            raise TypeError("lfem: mesh must be an lfem.Mesh, not %s" % type(mesh).__name__)
        m = mesh.handle
        add = (native.lfem_body_add_quadratic_mesh if mesh.nodes_per_tet == 10
               else native.lfem_body_add_mesh)
        add(self.handle, _body(body), native.lfem_mesh_get_positions(m),
            native.lfem_mesh_get_node_count(m), native.lfem_mesh_get_tets(m),
            native.lfem_mesh_get_tet_count(m))

    def add_mesh_arrays(self, body: Body, positions: npt.ArrayLike, tets: npt.ArrayLike) -> None:
        """Add nodes (an (n, 3) array, m) and tets: an (m, 4) array of node indices, or an
        (m, 10) array of 10-node tets (corners, then the mid-edge nodes of the edges 01, 12,
        02, 03, 13, 23)."""
        x = _convert.vectors(positions, "positions")
        shape = np.shape(tets)
        per_tet = 10 if len(shape) == 2 and shape[1] == 10 else 4
        t = _convert.indices(tets, "tets")
        if t.size % per_tet:
            raise InvalidArgumentError("lfem: tets must be an (m, 4) or (m, 10) array, got %d indices"
                                       % t.size)
        add = native.lfem_body_add_quadratic_mesh if per_tet == 10 else native.lfem_body_add_mesh
        add(self.handle, _body(body), _dptr(x), x.shape[0], _uptr(t), t.size // per_tet)

    def add_shape(self, body: Body, definition: Optional[ShapeDef] = None,
                  points: Optional[npt.ArrayLike] = None) -> int:
        """Give a static or kinematic body a rigid shape (ShapeDef, default a plane z = 0);
        points: the convex hull's (n, 3) local coordinates (m), None for the other shapes.
        Returns the shape's index on the body (the `shape` of the contacts that touch it)."""
        d = ShapeDef.from_buffer_copy(_definition(definition, ShapeDef))
        keep = None
        if points is not None:
            keep = _convert.vectors(points, "points")
            d._points = _dptr(keep)
            d._point_count = keep.shape[0]
        else:
            d._points = None
            d._point_count = 0
        index = ctypes.c_uint32()
        native.lfem_body_add_shape(self.handle, _body(body), ctypes.byref(d), ctypes.byref(index))
        del keep  # lfem has copied the points
        return index.value

    def mass(self, body: Body) -> float:
        """Total mass (kg) of a body: the sum of its lumped node masses, rho V, and what mass
        scaling added."""
        out = ctypes.c_double()
        native.lfem_body_get_mass(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def added_mass(self, body: Body) -> float:
        """The mass (kg) mass scaling added to a body (WorldDef.mass_scaling_step)."""
        out = ctypes.c_double()
        native.lfem_body_get_added_mass(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def inversion(self, body: Body) -> Tuple[int, float, float]:
        """The body's inverted tets after the last sub-step (J = det F <= 0), the smallest
        volume ratio J of its tets, and for how long (s) it has been inverted (0 when not)."""
        count, min_j, since = ctypes.c_uint32(), ctypes.c_double(), ctypes.c_double()
        native.lfem_body_get_inversion(self.handle, _body(body), ctypes.byref(count), ctypes.byref(min_j),
                                       ctypes.byref(since))
        return count.value, min_j.value, since.value

    def momentum(self, body: Body) -> Tuple[Vectors, Vectors]:
        """(linear, angular): linear momentum (kg m/s) and angular momentum about the origin
        (kg m^2/s) of a body, two float64 arrays of 3."""
        linear, angular = np.zeros(3), np.zeros(3)
        native.lfem_body_get_momentum(self.handle, _body(body), _dptr(linear), _dptr(angular))
        return linear, angular

    def node_count(self, body: Body) -> int:
        """The number of nodes of a body."""
        out = ctypes.c_uint32()
        native.lfem_body_get_node_count(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def tet_count(self, body: Body) -> int:
        """The number of tets of a body."""
        out = ctypes.c_uint32()
        native.lfem_body_get_tet_count(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def nodes_per_tet(self, body: Body) -> int:
        """4, or 10 for a body of quadratic tets (0 without tets)."""
        out = ctypes.c_uint32()
        native.lfem_body_get_nodes_per_tet(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def user_data(self, body: Body) -> Optional[int]:
        """The BodyDef.user_data the body was created with."""
        out = _vp()
        native.lfem_body_get_user_data(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def set_type(self, body: Body, body_type: BodyType) -> None:
        """Change the body's type between RIGID, KINEMATIC and STATIC (the pose carries over; a
        deformable body keeps its type)."""
        native.lfem_body_set_type(self.handle, _body(body), int(body_type))

    def body_type(self, body: Body) -> BodyType:
        """The body's type."""
        out = ctypes.c_int()
        native.lfem_body_get_type(self.handle, _body(body), ctypes.byref(out))
        return BodyType(out.value)

    def user_id(self, body: Body) -> int:
        """The body's opaque 64-bit id (0 at creation; kept by checkpoints)."""
        out = ctypes.c_uint64()
        native.lfem_body_get_user_id(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def set_user_id(self, body: Body, user_id: int) -> None:
        """An opaque 64-bit number kept on the body (an entity id); checkpoints keep it."""
        if not 0 <= user_id < 2**64:
            raise ValueError(f"user_id must fit in 64 unsigned bits, got {user_id}")
        native.lfem_body_set_user_id(self.handle, _body(body), user_id)

    def _count(self, function: Any, body: Body, reported_as: str) -> int:
        """A count asked before the call the user made; an error names that call."""
        out = ctypes.c_uint32()
        try:
            function(self.handle, _body(body), ctypes.byref(out))
        except LfemError as e:
            raise _errors.renamed(e, function.__name__, reported_as) from None
        return out.value

    def _node_vectors(self, function: Any, body: Body, out: Optional[np.ndarray]) -> Vectors:
        n = self._count(native.lfem_body_get_node_count, body, function.__name__)
        buf = np.empty((n, 3)) if out is None else _convert.out_buffer(out, "out")
        function(self.handle, body, _dptr(buf), min(buf.shape[0], _U32_MAX))
        return buf[:n]

    def positions(self, body: Body, out: Optional[np.ndarray] = None) -> Vectors:
        """Node positions (m) as a float64 (n, 3) array that lfem fills directly. With out=
        (a C-contiguous float64 (k, 3) array, k >= n) lfem fills its first n rows and out[:n]
        is returned; BUFFER_TOO_SMALL (nothing written) when k < n."""
        return self._node_vectors(native.lfem_body_get_positions, body, out)

    def velocities(self, body: Body, out: Optional[np.ndarray] = None) -> Vectors:
        """Node velocities (m/s), like positions()."""
        return self._node_vectors(native.lfem_body_get_velocities, body, out)

    def set_velocities(self, body: Body, velocities: npt.ArrayLike) -> None:
        """Overwrite the node velocities (m/s), an (n, 3) array, one row per node."""
        v = _convert.vectors(velocities, "velocities")
        native.lfem_body_set_velocities(self.handle, _body(body), _dptr(v), v.shape[0])

    def boundary_triangles(self, body: Body) -> Indices:
        """Boundary triangles, an (n, 3) uint32 array, counter-clockwise seen from outside."""
        f = native.lfem_body_get_boundary_triangles
        n = self._count(native.lfem_body_get_boundary_triangle_count, body, f.__name__)
        out = np.empty((n, 3), dtype=np.uint32)
        f(self.handle, body, _uptr(out), n)
        return out

    def boundary_faces(self, body: Body) -> Indices:
        """The boundary as faces: an (n, 6) uint32 array of 6-node triangles for a body of
        10-node tets (corners a, b, c counter-clockwise from outside, then the mid-edge nodes of
        ab, bc, ca), the (n, 3) boundary triangles for any other body."""
        f = native.lfem_body_get_boundary_faces
        n = self._count(native.lfem_body_get_boundary_face_count, body, f.__name__)
        width = 6 if self._count(native.lfem_body_get_nodes_per_tet, body, f.__name__) == 10 else 3
        out = np.empty((n, width), dtype=np.uint32)
        f(self.handle, body, _uptr(out), n)
        return out

    def von_mises_stress(self, body: Body) -> Vectors:
        """Von Mises stress (Pa), one per tet."""
        f = native.lfem_body_get_von_mises_stress
        out = np.empty(self._count(native.lfem_body_get_tet_count, body, f.__name__))
        f(self.handle, body, _dptr(out), out.size)
        return out

    def rotation(self, body: Body) -> Vectors:
        """The paper model's global rotation, a 3x3 array (identity for the other models)."""
        out = np.empty((3, 3), dtype=np.float64)
        native.lfem_body_get_rotation(self.handle, _body(body), _dptr(out))
        return out

    def set_positions(self, body: Body, positions: npt.ArrayLike) -> None:
        """Teleport a deformable body's nodes (m), an (n, 3) array: velocities kept, the change of
        strain energy booked as work, its pairs end."""
        x = _convert.vectors(positions, "positions")
        native.lfem_body_set_positions(self.handle, _body(body), _dptr(x), x.shape[0])

    def apply_impulse(self, body: Body, point: npt.ArrayLike, impulse: npt.ArrayLike) -> None:
        """A one-shot impulse (N s) at a world point (m): a deformable body's tet around the point
        takes it by its shape functions, a rigid body as a whole."""
        p, j = _convert.vector(point, "point"), _convert.vector(impulse, "impulse")
        native.lfem_body_apply_impulse(self.handle, _body(body), _dptr(p), _dptr(j))

    def apply_force(self, body: Body, point: npt.ArrayLike, force: npt.ArrayLike) -> None:
        """A force (N) at a world point (m) for the next step() call only: bound to the body where
        it is now (the tet around the point) and moved with it; the body gains force * dt."""
        p, f = _convert.vector(point, "point"), _convert.vector(force, "force")
        native.lfem_body_apply_force(self.handle, _body(body), _dptr(p), _dptr(f))

    def closest_point(self, body: Body, point: npt.ArrayLike) -> Tuple[Vectors, int, float]:
        """The point of the body's surface nearest to point (m), its boundary triangle and the
        distance (m)."""
        p = _convert.vector(point, "point")
        q = np.empty(3, dtype=np.float64)
        t, d = ctypes.c_uint32(), ctypes.c_double()
        native.lfem_body_closest_point(self.handle, _body(body), _dptr(p), _dptr(q), ctypes.byref(t), ctypes.byref(d))
        return q, t.value, d.value

    def transform(self, body: Body) -> Vectors:
        """The body's pose x = R X + t: 7 numbers, t then R as a quaternion (w, x, y, z) (a
        deformable body's best fit)."""
        out = np.empty(7, dtype=np.float64)
        native.lfem_body_get_transform(self.handle, _body(body), _dptr(out))
        return out

    def set_transform(self, body: Body, transform: npt.ArrayLike) -> None:
        """Teleport a body rigidly to the pose (t, then a quaternion w, x, y, z): velocities
        kept, no work."""
        t = np.ascontiguousarray(transform, dtype=np.float64).reshape(-1)
        if t.size != 7:
            raise InvalidArgumentError("transform must hold 7 numbers")
        native.lfem_body_set_transform(self.handle, _body(body), _dptr(t))

    def center_of_mass(self, body: Body) -> Vectors:
        """The centre of mass where the nodes are now (m)."""
        out = np.empty(3, dtype=np.float64)
        native.lfem_body_get_center_of_mass(self.handle, _body(body), _dptr(out))
        return out

    def find_nodes_in_box(self, body: Body, lo: npt.ArrayLike, hi: npt.ArrayLike) -> Indices:
        """Indices of the nodes whose current position lies in the box [lo, hi] (m)."""
        lo, hi, body = _convert.vector(lo, "lo"), _convert.vector(hi, "hi"), _body(body)
        count = ctypes.c_uint32()
        try:
            native.lfem_body_find_nodes_in_box(self.handle, body, _dptr(lo), _dptr(hi), None, 0,
                                               ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        out = np.empty(count.value, dtype=np.uint32)
        if count.value:
            native.lfem_body_find_nodes_in_box(self.handle, body, _dptr(lo), _dptr(hi),
                                               _uptr(out), out.size, ctypes.byref(count))
        return out[:count.value]

    # -- attachments, sleeping, events --

    def attach(self, body: Body, nodes: npt.ArrayLike, target: Optional[Body] = None,
               frame: npt.ArrayLike = (0, 0, 0, 1, 0, 0, 0), break_force: float = 0.0,
               stiffness: float = 0.0, damping: float = 0.0) -> Attachment:
        """Hold nodes of a deformable body at their offsets in the frame of target (a rigid,
        kinematic or static body, or a deformable one: its material points there), or, when
        target is None, of a frame the caller moves (centre and quaternion w x y z at creation;
        see set_attachment_frame); rigidly (stiffness 0) or by a spring (N/m) and a damper
        (N s/m)."""
        n = _convert.indices(nodes, "nodes")
        d = self._attachment_def(body, target, frame, break_force, stiffness, damping)
        d.nodes = _uptr(n)
        d.node_count = n.size
        out = Attachment()
        native.lfem_attachment_create(self.handle, ctypes.byref(d), ctypes.byref(out))
        return out

    def attach_points(self, body: Body, points: npt.ArrayLike, target: Optional[Body] = None,
                      frame: npt.ArrayLike = (0, 0, 0, 1, 0, 0, 0), break_force: float = 0.0,
                      stiffness: float = 0.0, damping: float = 0.0) -> Attachment:
        """As attach, for points (m, an (n, 3) array) of the body held where they are: each bound
        once to the tet around it."""
        p = _convert.vectors(points, "points")
        d = self._attachment_def(body, target, frame, break_force, stiffness, damping)
        d.points = _dptr(p)
        d.point_count = p.shape[0]
        out = Attachment()
        native.lfem_attachment_create(self.handle, ctypes.byref(d), ctypes.byref(out))
        return out

    def _attachment_def(self, body: Body, target: Optional[Body], frame: npt.ArrayLike,
                        break_force: float, stiffness: float, damping: float) -> Any:
        d = native.lfem_attachment_def_default()
        d.body = _body(body)
        d.target = _body(target) if target is not None else Body()
        f = np.asarray(frame, dtype=np.float64).reshape(-1)
        if f.size != 7:
            raise InvalidArgumentError("frame must hold 7 numbers")
        for k in range(7):
            d.frame[k] = float(f[k])
        d.break_force = _convert.real(break_force, "break_force")
        d.stiffness = _convert.real(stiffness, "stiffness")
        d.damping = _convert.real(damping, "damping")
        return d

    def destroy_attachment(self, attachment: Attachment) -> None:
        native.lfem_attachment_destroy(self.handle, attachment)

    def attachment_is_valid(self, attachment: Attachment) -> bool:
        return bool(native.lfem_attachment_is_valid(self.handle, attachment))

    def set_attachment_frame(self, attachment: Attachment, frame: npt.ArrayLike) -> None:
        """Where the caller's frame is to be at the end of the next step."""
        f = np.ascontiguousarray(frame, dtype=np.float64).reshape(-1)
        if f.size != 7:
            raise InvalidArgumentError("frame must hold 7 numbers")
        native.lfem_attachment_set_frame(self.handle, attachment, _dptr(f))

    def attachment_force(self, attachment: Attachment) -> np.ndarray:
        """The total force (N) on the attachment's nodes at the last sub-step."""
        out = np.zeros(3)
        native.lfem_attachment_get_force(self.handle, attachment, _dptr(out))
        return out

    def wake(self, body: Body) -> None:
        native.lfem_body_wake(self.handle, _body(body))

    def is_awake(self, body: Body) -> bool:
        r = native.lfem_body_is_awake(self.handle, _body(body))
        if r < 0:
            raise _errors.error(Status.INVALID_HANDLE, "body handle is stale or of another world")
        return r == 1

    def events(self) -> list:
        """The events of the last step (a list of Event)."""
        count = ctypes.c_uint32()
        try:
            native.lfem_world_get_events(self.handle, None, 0, ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        out = (Event * max(count.value, 1))()
        if count.value:
            native.lfem_world_get_events(self.handle, out, count.value, ctypes.byref(count))
        return list(out[:count.value])

    # -- loads and supports --

    def fix_nodes(self, body: Body, nodes: npt.ArrayLike) -> None:
        """Fix nodes in place (velocity 0 from now on)."""
        n = _convert.indices(nodes, "nodes")
        native.lfem_body_fix_nodes(self.handle, _body(body), _uptr(n), n.size)

    def prescribe_node_velocity(self, body: Body, nodes: npt.ArrayLike,
                                velocity: npt.ArrayLike) -> None:
        """Make nodes move at a constant velocity (m/s), whatever the forces."""
        n = _convert.indices(nodes, "nodes")
        native.lfem_body_prescribe_node_velocity(self.handle, _body(body), _uptr(n), n.size,
                                                 _dptr(_convert.vector(velocity, "velocity")))

    def release_nodes(self, body: Body, nodes: npt.ArrayLike) -> None:
        """Give fixed or prescribed nodes back to the dynamics."""
        n = _convert.indices(nodes, "nodes")
        native.lfem_body_release_nodes(self.handle, _body(body), _uptr(n), n.size)

    def set_node_forces(self, body: Body, nodes: npt.ArrayLike, forces: npt.ArrayLike) -> None:
        """Constant external forces (N): forces[i] on nodes[i], from now on."""
        n = _convert.indices(nodes, "nodes")
        f = _convert.vectors(forces, "forces", rows=n.size)
        native.lfem_body_set_node_forces(self.handle, _body(body), _uptr(n), n.size, _dptr(f))

    def clear_node_forces(self, body: Body) -> None:
        """Remove every external node force of the body."""
        native.lfem_body_clear_node_forces(self.handle, _body(body))

    def set_kinematic_velocity(self, body: Body, linear: npt.ArrayLike,
                               angular: npt.ArrayLike) -> None:
        """The velocity of a kinematic body: linear (m/s) of its centre, angular (rad/s)."""
        native.lfem_body_set_kinematic_velocity(
            self.handle, _body(body), _dptr(_convert.vector(linear, "linear")),
            _dptr(_convert.vector(angular, "angular")))

    # -- skins --

    def add_skin(self, body: Body, positions: npt.ArrayLike, triangles: npt.ArrayLike) -> int:
        """Bind a render mesh to the body's tets: positions (m, (n, 3), the body's rest frame)
        and triangles ((k, 3) vertex indices); returns the skin's index on the body."""
        x = _convert.vectors(positions, "positions")
        t = _convert.indices(triangles, "triangles")
        if t.size % 3:
            raise InvalidArgumentError("lfem: triangles must hold 3 indices per triangle, got %d"
                                       % t.size)
        index = ctypes.c_uint32()
        native.lfem_body_add_skin(self.handle, _body(body), _dptr(x), x.shape[0], _uptr(t),
                                  t.size // 3, ctypes.byref(index))
        return index.value

    def remove_skin(self, body: Body, skin: int) -> None:
        """Remove a skin; the skins after it move down one index."""
        native.lfem_body_remove_skin(self.handle, _body(body), skin)

    def set_friction(self, body: Body, friction: float) -> None:
        """Change the body's Coulomb friction (>= 0); the body wakes."""
        native.lfem_body_set_friction(self.handle, _body(body), friction)

    def set_material(self, body: Body, young_modulus: float, poisson_ratio: float) -> None:
        """Change a deformable body's Young's modulus (Pa) and Poisson's ratio; its stable step
        follows, the change of strain energy is booked as work (not under mass scaling)."""
        native.lfem_body_set_material(self.handle, _body(body), young_modulus, poisson_ratio)

    def set_sleep_allowed(self, body: Body, allowed: bool) -> None:
        """Whether the body may fall asleep; False wakes it."""
        native.lfem_body_set_sleep_allowed(self.handle, _body(body), 1 if allowed else 0)

    def attachment_frame(self, attachment: Attachment) -> Vectors:
        """The caller's frame an attachment holds its nodes to, as last set (7 numbers)."""
        out = np.empty(7, dtype=np.float64)
        native.lfem_attachment_get_frame(self.handle, attachment, _dptr(out))
        return out

    def set_damping(self, body: Body, damping: float) -> None:
        """Change the body's mass-proportional damping (>= 0, 1/s); the body wakes."""
        native.lfem_body_set_damping(self.handle, _body(body), damping)

    def set_filter(self, body: Body, category_bits: int, mask_bits: int) -> None:
        """Change the body's collision filter; pairs it now forbids end with the next step's events."""
        native.lfem_body_set_filter(self.handle, _body(body), category_bits, mask_bits)

    def set_user_data(self, body: Body, user_data: Optional[int]) -> None:
        """Change the user data user_data() returns (an address, or None)."""
        native.lfem_body_set_user_data(self.handle, _body(body), user_data)

    def skin_count(self, body: Body) -> int:
        """The number of skins of a body."""
        out = ctypes.c_uint32()
        native.lfem_body_get_skin_count(self.handle, _body(body), ctypes.byref(out))
        return out.value

    def skin_sizes(self, body: Body, skin: int) -> Tuple[int, int]:
        """The vertex and triangle counts of a skin."""
        return self._skin_sizes(body, skin, "")

    def _skin_sizes(self, body: Body, skin: int, reported_as: str) -> Tuple[int, int]:
        """The sizes asked before the call the user made; an error names that call."""
        vertices, triangles = ctypes.c_uint32(), ctypes.c_uint32()
        try:
            native.lfem_body_get_skin_sizes(self.handle, _body(body), _convert.count(skin, "skin"),
                                            ctypes.byref(vertices), ctypes.byref(triangles))
        except LfemError as e:
            if not reported_as:
                raise
            raise _errors.renamed(e, "lfem_body_get_skin_sizes", reported_as) from None
        return vertices.value, triangles.value

    def skin_triangles(self, body: Body, skin: int) -> Indices:
        """A skin's triangles as given, a (k, 3) uint32 array."""
        f = native.lfem_body_get_skin_triangles
        _, k = self._skin_sizes(body, skin, f.__name__)
        out = np.empty((k, 3), dtype=np.uint32)
        f(self.handle, body, skin, _uptr(out), k)
        return out

    def skin_vertices(self, body: Body, skin: int) -> Tuple[Vectors, Vectors]:
        """A skin's deformed vertices (m) and unit smooth normals (area-weighted over its
        triangles), two float64 (n, 3) arrays."""
        f = native.lfem_body_get_skin_vertices
        n, _ = self._skin_sizes(body, skin, f.__name__)
        positions, normals = np.empty((n, 3)), np.empty((n, 3))
        f(self.handle, body, skin, _dptr(positions), _dptr(normals), n)
        return positions, normals

    def skin_vertex_buffer(self, body: Body, skin: int, out: np.ndarray,
                           normals: bool = True) -> np.ndarray:
        """A skin's vertices into an engine's vertex buffer: out, a writeable C-contiguous
        float32 (m, stride) array (m >= the vertex count, stride >= 6 with normals, else 3),
        gets each vertex's position in columns 0..2 and its unit normal in columns 3..5; the
        other columns are left alone. Returns out."""
        f = native.lfem_body_get_skin_vertices_f32
        n, _ = self._skin_sizes(body, skin, f.__name__)
        width = 6 if normals else 3
        if not isinstance(out, np.ndarray):
            raise TypeError("lfem: out must be a numpy array, not %s" % type(out).__name__)
        if (out.dtype != np.float32 or out.ndim != 2 or out.shape[1] < width
                or not out.flags.c_contiguous or not out.flags.writeable):
            raise InvalidArgumentError("lfem: out must be a writeable C-contiguous float32 "
                                       "(m, >= %d) array, got %s %s" % (width, out.dtype, out.shape))
        if out.shape[0] < n:
            raise _errors.error(int(Status.BUFFER_TOO_SMALL), "lfem: out has %d rows, below the "
                                "skin's %d vertices" % (out.shape[0], n))
        base = out.ctypes.data
        fp = ctypes.POINTER(ctypes.c_float)
        f(self.handle, body, skin, ctypes.cast(base, fp), out.shape[1],
          ctypes.cast(base + 12, fp) if normals else None, out.shape[1], n)
        return out

    # -- queries --

    def _ray(self, origin: npt.ArrayLike, direction: npt.ArrayLike, max_distance: float,
             flt: Optional[QueryFilter]) -> Tuple[Any, Any, float, QueryFilter]:
        return (_convert.vector(origin, "origin"), _convert.vector(direction, "direction"),
                _convert.real(max_distance, "max_distance"),
                _definition(flt, QueryFilter, "filter"))

    def cast_ray(self, origin: npt.ArrayLike, direction: npt.ArrayLike,
                 max_distance: float = math.inf,
                 filter: Optional[QueryFilter] = None) -> Optional[RayHit]:
        """The nearest crossing of the ray origin + t direction / |direction| (t in [0,
        max_distance], m) with the surface of a body the filter sees, or None."""
        o, d, m, flt = self._ray(origin, direction, max_distance, filter)
        out, hit = RayHit(), ctypes.c_int()
        native.lfem_world_cast_ray(self.handle, _dptr(o), _dptr(d), m, flt, ctypes.byref(out),
                                   ctypes.byref(hit))
        return out if hit.value == 1 else None

    def cast_sphere(self, origin: npt.ArrayLike, direction: npt.ArrayLike, radius: float,
                    max_distance: float = math.inf,
                    filter: Optional[QueryFilter] = None) -> Optional[RayHit]:
        """A sphere of radius swept along the ray: where it first touches a surface the filter
        sees (distance: its centre's travel; point: the point touched; normal: from it towards
        the centre), or None."""
        o, d, m, flt = self._ray(origin, direction, max_distance, filter)
        out, hit = RayHit(), ctypes.c_int()
        native.lfem_world_cast_sphere(self.handle, _dptr(o), _dptr(d),
                                      _convert.real(radius, "radius"), m, flt, ctypes.byref(out),
                                      ctypes.byref(hit))
        return out if hit.value == 1 else None

    def cast_ray_all(self, origin: npt.ArrayLike, direction: npt.ArrayLike,
                     max_distance: float = math.inf,
                     filter: Optional[QueryFilter] = None) -> np.ndarray:
        """Every crossing along the ray, nearest first: a numpy structured array of
        RAY_HIT_DTYPE (fields body, triangle, shape, barycentric, point, normal, distance)."""
        o, d, m, flt = self._ray(origin, direction, max_distance, filter)
        count = ctypes.c_uint32()
        try:
            native.lfem_world_cast_ray_all(self.handle, _dptr(o), _dptr(d), m, flt, None, 0,
                                           ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        out = np.zeros(count.value, dtype=RAY_HIT_DTYPE)
        if count.value:
            native.lfem_world_cast_ray_all(self.handle, _dptr(o), _dptr(d), m, flt,
                                           out.ctypes.data, out.size, ctypes.byref(count))
        return out

    def overlap_sphere(self, center: npt.ArrayLike, radius: float,
                       filter: Optional[QueryFilter] = None) -> "list[Overlap]":
        """The bodies the filter sees that the solid sphere overlaps (touching counts), in body
        order, each an Overlap: its triangle or shape nearest the centre and the point of it."""
        return self.overlap_capsule(center, center, radius, filter)

    def overlap_capsule(self, a: npt.ArrayLike, b: npt.ArrayLike, radius: float,
                        filter: Optional[QueryFilter] = None) -> "list[Overlap]":
        """The same for the capsule of the segment a-b swept by radius (m)."""
        pa, pb = _convert.vector(a, "a"), _convert.vector(b, "b")
        flt = _definition(filter, QueryFilter, "filter")
        count = ctypes.c_uint32()
        try:
            native.lfem_world_overlap_capsule(self.handle, _dptr(pa), _dptr(pb), float(radius), flt,
                                              None, 0, ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        out = (Overlap * count.value)()
        if count.value:
            native.lfem_world_overlap_capsule(self.handle, _dptr(pa), _dptr(pb), float(radius), flt,
                                              ctypes.addressof(out), count.value, ctypes.byref(count))
        return list(out)

    def overlap_box(self, lo: npt.ArrayLike, hi: npt.ArrayLike,
                    filter: Optional[QueryFilter] = None) -> "list[Body]":
        """The bodies the filter sees whose current geometry overlaps the box [lo, hi] (m),
        in body order."""
        lo, hi = _convert.vector(lo, "lo"), _convert.vector(hi, "hi")
        flt = _definition(filter, QueryFilter, "filter")
        count = ctypes.c_uint32()
        try:
            native.lfem_world_overlap_box(self.handle, _dptr(lo), _dptr(hi), flt, None, 0,
                                          ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        out = (Body * count.value)()
        if count.value:
            native.lfem_world_overlap_box(self.handle, _dptr(lo), _dptr(hi), flt,
                                          ctypes.addressof(out), count.value, ctypes.byref(count))
        return [Body(b.index, b.generation) for b in out]

    # -- contacts --

    def contact_count(self) -> int:
        """The number of active contacts of the last step."""
        count = ctypes.c_uint32()
        try:
            native.lfem_world_query_contacts(self.handle, None, 0, ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        return count.value

    def contacts(self, out: Optional[np.ndarray] = None) -> np.ndarray:
        """The active contacts of the last step as a numpy structured array of CONTACT_DTYPE
        (fields body_a, body_b, node, triangle, barycentric, position, normal, force, sliding,
        kind, shape), filled by lfem directly. With out= (a CONTACT_DTYPE array), the contacts go to
        its front and out[:count] is returned; BUFFER_TOO_SMALL (nothing copied) when it is too
        short."""
        if out is None:
            out = np.zeros(self.contact_count(), dtype=CONTACT_DTYPE)
        elif not isinstance(out, np.ndarray):
            raise TypeError("lfem: out must be a numpy array, not %s" % type(out).__name__)
        elif (out.dtype != CONTACT_DTYPE or out.ndim != 1 or not out.flags.c_contiguous
              or not out.flags.writeable):
            raise InvalidArgumentError("lfem: out must be a writeable 1-d array of "
                                       "CONTACT_DTYPE")
        count = ctypes.c_uint32()
        native.lfem_world_query_contacts(self.handle, out.ctypes.data if out.size else None,
                                         min(out.size, _U32_MAX), ctypes.byref(count))
        return out[:count.value]


# ---- meshes -----------------------------------------------------------------------------------


class Mesh:
    """A tetrahedral mesh owned by Python; close() (or garbage collection) frees it. Made by
    the class methods box, cylinder, cup, hammer and load_gmsh."""

    _handle: Optional[ctypes.c_void_p] = None

    def __init__(self, handle: ctypes.c_void_p) -> None:
        self._handle = handle

    @property
    def handle(self) -> ctypes.c_void_p:
        """The raw lfem_mesh* (a ctypes c_void_p)."""
        if self._handle is None:
            raise ValueError("lfem: the mesh is closed")
        return self._handle

    def close(self) -> None:
        """Free the mesh (twice is harmless)."""
        if self._handle is not None:
            native.lfem_mesh_destroy(self._handle)
            self._handle = None

    def __enter__(self) -> "Mesh":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __del__(self) -> None:
        self.close()

    @classmethod
    def box(cls, size: npt.ArrayLike, cells: npt.ArrayLike) -> "Mesh":
        """A box [0, size] (m) of cells[0] x cells[1] x cells[2] hexahedra, 6 tets each."""
        s = _convert.vector(size, "size")
        c = _convert.indices(cells, "cells")
        if c.size != 3:
            raise InvalidArgumentError("lfem: cells must have 3 entries, got %d" % c.size)
        out = _vp()
        native.lfem_mesh_create_box(_dptr(s), _uptr(c), ctypes.byref(out))
        return cls(out)

    @classmethod
    def cylinder(cls, radius: float, height: float, segments: int, rings: int,
                 layers: int) -> "Mesh":
        """A solid cylinder along +z from z = 0 (see lfem_mesh_create_cylinder)."""
        out = _vp()
        native.lfem_mesh_create_cylinder(
            _convert.real(radius, "radius"), _convert.real(height, "height"),
            _convert.count(segments, "segments"), _convert.count(rings, "rings"),
            _convert.count(layers, "layers"), ctypes.byref(out))
        return cls(out)

    @classmethod
    def cup(cls, outer_radius: float, height: float, wall: float, bottom: float, segments: int,
            layers: int) -> "Mesh":
        """A hollow cup open at the top (see lfem_mesh_create_cup)."""
        out = _vp()
        native.lfem_mesh_create_cup(
            _convert.real(outer_radius, "outer_radius"), _convert.real(height, "height"),
            _convert.real(wall, "wall"), _convert.real(bottom, "bottom"),
            _convert.count(segments, "segments"), _convert.count(layers, "layers"),
            ctypes.byref(out))
        return cls(out)

    @classmethod
    def hammer(cls, handle_length: float, handle_width: float, head_length: float,
               head_width: float, cell_size: float) -> "Mesh":
        """A hammer (see lfem_mesh_create_hammer)."""
        out = _vp()
        native.lfem_mesh_create_hammer(
            _convert.real(handle_length, "handle_length"),
            _convert.real(handle_width, "handle_width"),
            _convert.real(head_length, "head_length"), _convert.real(head_width, "head_width"),
            _convert.real(cell_size, "cell_size"), ctypes.byref(out))
        return cls(out)

    @classmethod
    def load_gmsh(cls, path: Any) -> "Mesh":
        """The tetrahedra of a Gmsh .msh file (ASCII 2.2 or 4.1): 4-node ones, or 10-node ones
        (type 11)."""
        out = _vp()
        native.lfem_mesh_load_gmsh(_convert.path(path, "path"), ctypes.byref(out))
        return cls(out)

    @property
    def node_count(self) -> int:
        """The number of nodes."""
        return native.lfem_mesh_get_node_count(self.handle)

    @property
    def tet_count(self) -> int:
        """The number of tets."""
        return native.lfem_mesh_get_tet_count(self.handle)

    @property
    def nodes_per_tet(self) -> int:
        """4, or 10 for quadratic tets."""
        return native.lfem_mesh_get_nodes_per_tet(self.handle)

    def make_quadratic(self) -> None:
        """Turn the 4-node tets into 10-node ones: a node at the middle of every edge, numbered
        after the corners (see lfem_mesh_make_quadratic)."""
        native.lfem_mesh_make_quadratic(self.handle)

    @property
    def positions(self) -> Vectors:
        """A copy of the node positions (m), an (n, 3) float64 array."""
        n = self.node_count
        if n == 0:
            return np.empty((0, 3), dtype=np.float64)
        return np.ctypeslib.as_array(native.lfem_mesh_get_positions(self.handle), (n, 3)).copy()

    @property
    def tets(self) -> Indices:
        """A copy of the tets, an (m, 4) uint32 array of node indices ((m, 10) for 10-node
        tets)."""
        n, width = self.tet_count, self.nodes_per_tet
        if n == 0:
            return np.empty((0, width), dtype=np.uint32)
        return np.ctypeslib.as_array(native.lfem_mesh_get_tets(self.handle), (n, width)).copy()

    def translate(self, offset: npt.ArrayLike) -> None:
        """Move the mesh by offset (m)."""
        native.lfem_mesh_translate(self.handle, _dptr(_convert.vector(offset, "offset")))

    def rotate(self, axis: npt.ArrayLike, angle: float) -> None:
        """Rotate about the origin by angle (rad) around axis."""
        native.lfem_mesh_rotate(self.handle, _dptr(_convert.vector(axis, "axis")),
                                _convert.real(angle, "angle"))


# ---- output -----------------------------------------------------------------------------------


class VtkSeries:
    """A ParaView time series (.pvd plus one .vtu per frame); close() finishes it."""

    _handle: Optional[ctypes.c_void_p] = None

    def __init__(self, pvd_path: Any) -> None:
        out = _vp()
        native.lfem_vtk_series_create(_convert.path(pvd_path, "pvd_path"), ctypes.byref(out))
        self._handle = out

    def write_frame(self, world: World) -> None:
        """Write every body of the world as the next frame."""
        if self._handle is None:
            raise ValueError("lfem: the series is closed")
        if not isinstance(world, World):
            raise TypeError("lfem: world must be an lfem.World, not %s" % type(world).__name__)
        native.lfem_vtk_series_write_frame(self._handle, world.handle)

    def close(self) -> None:
        """Finish and free the series (twice is harmless)."""
        if self._handle is not None:
            native.lfem_vtk_series_destroy(self._handle)
            self._handle = None

    def __enter__(self) -> "VtkSeries":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __del__(self) -> None:
        self.close()
