"""Python bindings of lfem (include_c/lfem.h) through ctypes, with numpy arrays.

Deformable bodies simulated by an explicit local finite element method. SI units throughout.

    import lfem
    with lfem.World() as world:                       # gravity (0, 0, -9.81) m/s^2
        mesh = lfem.Mesh.box((0.3, 0.2, 0.1), (3, 2, 1))
        mesh.translate((0, 0, 2))
        d = lfem.BodyDef.default()
        d.model = lfem.Model.NEO_HOOKEAN
        block = world.create_body(d)
        world.add_mesh(block, mesh)
        world.step(0.5)
        print(world.positions(block)[:, 2].min())     # numpy (n, 3)

- Every failing call raises LfemError carrying .status (a Status) and .message (lfem_last_error).
  A failed call changes nothing.
- Positions and velocities come as numpy float64 arrays of shape (n, 3) that lfem writes into
  directly; pass out= to reuse a buffer. Contacts come as a numpy structured array whose dtype
  (CONTACT_DTYPE) is the C struct lfem_contact, also filled in place.
- World, Mesh and VtkSeries free their native object on close(), at the end of a with block, or
  when garbage collected. Body is a value handle; a destroyed body's handle raises
  LfemError(Status.INVALID_HANDLE).

The library is loaded from the LFEM_LIBRARY environment variable (a file, or a folder holding
liblfem.so) if set, else from the CMake build folder of this source tree (build/ at the
repository root), else wherever ctypes.util.find_library("lfem") finds it.
"""

import ctypes
import ctypes.util
import enum
import os
import sys

import numpy as np

__all__ = [
    "Status", "BodyType", "Model", "LfemError", "WorldDef", "WorldStats", "PhaseTime", "Profile",
    "Body", "BodyDef",
    "Contact", "CONTACT_DTYPE", "NO_SHAPE", "ShapeType", "ShapeDef", "World", "Mesh", "VtkSeries", "version", "version_string",
    "status_string", "last_error", "library_path", "VERSION_MAJOR", "VERSION_MINOR",
    "VERSION_PATCH",
]

VERSION_MAJOR, VERSION_MINOR, VERSION_PATCH = 0, 1, 0

# ---- loading ----------------------------------------------------------------------------------

_NAMES = {"darwin": ["liblfem.dylib"], "win32": ["lfem.dll"]}.get(sys.platform, ["liblfem.so"])


def _find_library():
    env = os.environ.get("LFEM_LIBRARY")
    if env:
        if os.path.isdir(env):
            for name in _NAMES:
                if os.path.exists(os.path.join(env, name)):
                    return os.path.join(env, name)
            raise OSError("LFEM_LIBRARY=%s is a folder without %s" % (env, " or ".join(_NAMES)))
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    build = os.path.normpath(os.path.join(here, os.pardir, os.pardir, os.pardir, "build"))
    for name in _NAMES:
        if os.path.exists(os.path.join(build, name)):
            return os.path.join(build, name)
    found = ctypes.util.find_library("lfem")
    if found:
        return found
    raise OSError("liblfem not found: set LFEM_LIBRARY, build it with cmake into %s, or install it"
                  % build)


library_path = _find_library()
_lib = ctypes.CDLL(library_path)

# ---- enums ------------------------------------------------------------------------------------


class Status(enum.IntEnum):
    OK = 0
    INVALID_ARGUMENT = 1  # a null pointer, a NaN, a number out of its range
    INVALID_MESH = 2      # bad indices, inverted or zero-volume tets, unused nodes
    INVALID_HANDLE = 3    # a stale, foreign or null body handle
    BUFFER_TOO_SMALL = 4  # the caller's capacity is below what the answer needs
    UNSTABLE = 5          # the state blew up; the world was rolled back
    IO_ERROR = 6          # a file could not be read or written, or is malformed
    OUT_OF_MEMORY = 7
    INTERNAL_ERROR = 8    # a bug in lfem: please report it with the message
    UNSUPPORTED = 9       # this build leaves the feature out (LFEM_WITH_CCD, LFEM_WITH_IO)


class BodyType(enum.IntEnum):
    DEFORMABLE = 0
    STATIC = 1
    KINEMATIC = 2
    RIGID = 3


class Model(enum.IntEnum):
    PAPER = 0
    COROTATIONAL = 1
    NEO_HOOKEAN = 2
    LINEAR = 3


class ShapeType(enum.IntEnum):
    PLANE = 0        # the half-space below the plane through center with normal local +z
    BOX = 1          # half_extents along the local axes
    SPHERE = 2       # radius
    CAPSULE = 3      # segment -half_length..+half_length along local z, swept by radius
    CONVEX_HULL = 4  # convex hull of points (local coordinates), see World.add_shape


# ---- structs (laid out as in lfem.h; sizes checked by tests/test_lfem.py) ----------------------

_d3 = ctypes.c_double * 3
_enum = ctypes.c_int  # C enums are 32-bit


class WorldDef(ctypes.Structure):
    """lfem_world_def. Start from WorldDef.default() and edit."""
    _fields_ = [
        ("gravity", _d3),                     # m/s^2, default (0, 0, -9.81)
        ("time_step", ctypes.c_double),       # s, 0 = automatic (default)
        ("step_safety", ctypes.c_double),     # in (0, 1), default 0.9
        ("contact_iterations", ctypes.c_uint32),
        ("thread_count", ctypes.c_uint32),    # 1..64, default 1; results independent of it
        ("contact_tolerance", ctypes.c_double),
        ("max_substeps", ctypes.c_uint32),
        ("allow_unstable_step", ctypes.c_uint8),
        ("padding", ctypes.c_uint8 * 3),
        ("internal_value", ctypes.c_uint32),  # set by the default; do not change
    ]

    @staticmethod
    def default():
        return _lib.lfem_world_def_default()


class WorldStats(ctypes.Structure):
    """lfem_world_stats: time, energies (J), momenta, solver figures."""
    _fields_ = [
        ("time", ctypes.c_double),
        ("steps", ctypes.c_uint64),
        ("step_size", ctypes.c_double),
        ("stable_step", ctypes.c_double),
        ("substeps_last_call", ctypes.c_uint32),
        ("body_count", ctypes.c_uint32),
        ("kinetic_energy", ctypes.c_double),
        ("strain_energy", ctypes.c_double),
        ("external_work", ctypes.c_double),
        ("dissipated_energy", ctypes.c_double),
        ("energy_error", ctypes.c_double),
        ("linear_momentum", _d3),
        ("angular_momentum", _d3),
        ("contact_count", ctypes.c_uint32),
        ("solver_iterations", ctypes.c_uint32),
        ("solver_residual", ctypes.c_double),
        ("max_penetration", ctypes.c_double),
        ("rotation_drift", ctypes.c_double),
    ]


class PhaseTime(ctypes.Structure):
    """lfem_phase_time: wall time (s) and run count of one phase of the step."""
    _fields_ = [("seconds", ctypes.c_double), ("calls", ctypes.c_uint64)]


class Profile(ctypes.Structure):
    """lfem_profile: per-phase time and counts of the step, accumulated."""
    _fields_ = [
        ("substeps", ctypes.c_uint64),
        ("internal_forces", PhaseTime),
        ("predictor", PhaseTime),
        ("kinematic_motion", PhaseTime),
        ("broad_phase", PhaseTime),
        ("narrow_phase", PhaseTime),
        ("shape_queries", PhaseTime),
        ("shape_tests", ctypes.c_uint64),
        ("ccd_queries", ctypes.c_uint64),
        ("normal_solve", PhaseTime),
        ("friction", PhaseTime),
        ("global_rotation", PhaseTime),
        ("commit", PhaseTime),
    ]


class Body(ctypes.Structure):
    """A body handle (lfem_body), a value; Body() is the null handle."""
    _fields_ = [("index", ctypes.c_uint32), ("generation", ctypes.c_uint32)]

    def __eq__(self, other):
        return (isinstance(other, Body) and self.index == other.index
                and self.generation == other.generation)

    def __hash__(self):
        return hash((self.index, self.generation))

    def __repr__(self):
        return "Body(index=%d, generation=%d)" % (self.index, self.generation)


class BodyDef(ctypes.Structure):
    """lfem_body_def. Start from BodyDef.default() and edit."""
    _fields_ = [
        ("type", _enum),                      # BodyType, default DEFORMABLE
        ("model", _enum),                     # Model, default PAPER
        ("young_modulus", ctypes.c_double),   # Pa, default 1e6
        ("poisson_ratio", ctypes.c_double),   # (-1, 0.5), default 0.3
        ("density", ctypes.c_double),         # kg/m^3, default 1000
        ("damping", ctypes.c_double),         # 1/s, default 0
        ("friction", ctypes.c_double),        # default 0.5
        ("linear_velocity", _d3),             # m/s
        ("angular_velocity", _d3),            # rad/s
        ("category_bits", ctypes.c_uint32),   # default 1
        ("mask_bits", ctypes.c_uint32),       # default all bits
        ("user_data", ctypes.c_void_p),
        ("internal_value", ctypes.c_uint32),  # set by the default; do not change
        ("padding", ctypes.c_uint32),
    ]

    @staticmethod
    def default():
        return _lib.lfem_body_def_default()


class Contact(ctypes.Structure):
    """lfem_contact: one active node-to-triangle contact of the last step."""
    _fields_ = [
        ("body_a", Body),
        ("body_b", Body),
        ("node", ctypes.c_uint32),
        ("triangle", ctypes.c_uint32 * 3),
        ("barycentric", ctypes.c_double * 2),
        ("position", _d3),
        ("normal", _d3),
        ("force", _d3),
        ("sliding", ctypes.c_uint8),
        ("padding", ctypes.c_uint8 * 3),
        ("shape", ctypes.c_uint32),  # index of body_b's shape, or NO_SHAPE for a triangle
    ]


#: Contact.shape of a contact with a triangle (not a rigid shape).
NO_SHAPE = 0xFFFFFFFF


class ShapeDef(ctypes.Structure):
    """lfem_shape_def: a rigid shape of a static or kinematic body. Start from
    ShapeDef.default(); convex hull points are passed to World.add_shape."""
    _fields_ = [
        ("type", _enum),                      # ShapeType, default PLANE
        ("point_count", ctypes.c_uint32),     # set by World.add_shape
        ("center", _d3),                      # m, default 0
        ("rotation", ctypes.c_double * 4),    # unit quaternion (w, x, y, z), default identity
        ("half_extents", _d3),                # m, box, default 0.5
        ("radius", ctypes.c_double),          # m, sphere and capsule, default 0.5
        ("half_length", ctypes.c_double),     # m, capsule, default 0.5
        ("points", ctypes.POINTER(ctypes.c_double)),  # set by World.add_shape
        ("internal_value", ctypes.c_uint32),  # set by the default; do not change
        ("padding", ctypes.c_uint32),
    ]

    @staticmethod
    def default():
        return _lib.lfem_shape_def_default()


_BODY_DTYPE = np.dtype([("index", "<u4"), ("generation", "<u4")])

#: The numpy dtype of lfem_contact (same offsets and size as Contact).
CONTACT_DTYPE = np.dtype({
    "names": ["body_a", "body_b", "node", "triangle", "barycentric", "position", "normal",
              "force", "sliding", "shape"],
    "formats": [_BODY_DTYPE, _BODY_DTYPE, np.uint32, (np.uint32, 3), (np.float64, 2),
                (np.float64, 3), (np.float64, 3), (np.float64, 3), np.uint8, np.uint32],
    "offsets": [Contact.body_a.offset, Contact.body_b.offset, Contact.node.offset,
                Contact.triangle.offset, Contact.barycentric.offset, Contact.position.offset,
                Contact.normal.offset, Contact.force.offset, Contact.sliding.offset,
                Contact.shape.offset],
    "itemsize": ctypes.sizeof(Contact),
})

# ---- errors -----------------------------------------------------------------------------------


class LfemError(Exception):
    """A failed lfem call: .status (Status) and .message (lfem_last_error)."""

    def __init__(self, status, message):
        try:
            status = Status(status)
        except ValueError:
            pass
        super().__init__(message)
        self.status = status
        self.message = message

    def __str__(self):
        name = self.status.name if isinstance(self.status, Status) else str(self.status)
        return "%s (%s)" % (self.message, name)


def _c_string(pointer):
    return pointer.decode("utf-8", "replace") if pointer is not None else ""


def _errcheck(result, func, args):
    if result != 0:
        raise LfemError(result, _c_string(_lib.lfem_last_error()))
    return result


# ---- declarations -----------------------------------------------------------------------------

_p = ctypes.POINTER
_dp = _p(ctypes.c_double)
_up = _p(ctypes.c_uint32)
_vp = ctypes.c_void_p
_u32 = ctypes.c_uint32
_dbl = ctypes.c_double
_st = object()  # marks functions returning lfem_status (a C int): they raise LfemError


def _declare(name, restype, *argtypes):
    f = getattr(_lib, name)
    f.argtypes = list(argtypes)
    if restype is _st:
        f.restype = ctypes.c_int
        f.errcheck = _errcheck
    else:
        f.restype = restype
    return f


_declare("lfem_status_string", ctypes.c_char_p, _enum)
_declare("lfem_last_error", ctypes.c_char_p)
_declare("lfem_version", _u32)
_declare("lfem_version_string", ctypes.c_char_p)

_declare("lfem_world_def_default", WorldDef)
_declare("lfem_world_create", _st, _p(WorldDef), _p(_vp))
_declare("lfem_world_destroy", None, _vp)
_declare("lfem_world_step", _st, _vp, _dbl)
_declare("lfem_world_save", _st, _vp, ctypes.c_char_p)
_declare("lfem_world_load", _st, ctypes.c_char_p, _p(_vp))
_declare("lfem_world_set_gravity", _st, _vp, _dp)
_declare("lfem_world_set_time_step", _st, _vp, _dbl)
_declare("lfem_world_get_stable_step", _st, _vp, _dp)
_declare("lfem_world_get_stats", _st, _vp, _p(WorldStats))
_declare("lfem_world_get_profile", _st, _vp, _p(Profile))
_declare("lfem_world_reset_profile", _st, _vp)

_declare("lfem_body_def_default", BodyDef)
_declare("lfem_body_create", _st, _vp, _p(BodyDef), _p(Body))
_declare("lfem_body_destroy", _st, _vp, Body)
_declare("lfem_body_is_valid", ctypes.c_int, _vp, Body)
_declare("lfem_body_add_mesh", _st, _vp, Body, _dp, _u32, _up, _u32)
_declare("lfem_body_get_node_count", _st, _vp, Body, _up)
_declare("lfem_body_get_tet_count", _st, _vp, Body, _up)
_declare("lfem_body_get_user_data", _st, _vp, Body, _p(_vp))
_declare("lfem_body_get_mass", _st, _vp, Body, _dp)
_declare("lfem_body_get_momentum", _st, _vp, Body, _dp, _dp)
_declare("lfem_body_get_positions", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_get_velocities", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_set_velocities", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_get_boundary_triangle_count", _st, _vp, Body, _up)
_declare("lfem_body_get_boundary_triangles", _st, _vp, Body, _up, _u32)
_declare("lfem_body_get_von_mises_stress", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_get_rotation", _st, _vp, Body, _dp)
_declare("lfem_body_find_nodes_in_box", _st, _vp, Body, _dp, _dp, _up, _u32, _up)
_declare("lfem_body_fix_nodes", _st, _vp, Body, _up, _u32)
_declare("lfem_body_prescribe_node_velocity", _st, _vp, Body, _up, _u32, _dp)
_declare("lfem_body_release_nodes", _st, _vp, Body, _up, _u32)
_declare("lfem_body_set_node_forces", _st, _vp, Body, _up, _u32, _dp)
_declare("lfem_body_clear_node_forces", _st, _vp, Body)
_declare("lfem_body_set_kinematic_velocity", _st, _vp, Body, _dp, _dp)

_declare("lfem_shape_def_default", ShapeDef)
_declare("lfem_body_add_shape", _st, _vp, Body, _p(ShapeDef), _p(ctypes.c_uint32))

_declare("lfem_world_query_contacts", _st, _vp, _vp, _u32, _p(ctypes.c_uint32))

_declare("lfem_mesh_create_box", _st, _dp, _up, _p(_vp))
_declare("lfem_mesh_create_cylinder", _st, _dbl, _dbl, _u32, _u32, _u32, _p(_vp))
_declare("lfem_mesh_create_cup", _st, _dbl, _dbl, _dbl, _dbl, _u32, _u32, _p(_vp))
_declare("lfem_mesh_create_hammer", _st, _dbl, _dbl, _dbl, _dbl, _dbl, _p(_vp))
_declare("lfem_mesh_load_gmsh", _st, ctypes.c_char_p, _p(_vp))
_declare("lfem_mesh_destroy", None, _vp)
_declare("lfem_mesh_get_node_count", _u32, _vp)
_declare("lfem_mesh_get_tet_count", _u32, _vp)
_declare("lfem_mesh_get_positions", _dp, _vp)
_declare("lfem_mesh_get_tets", _up, _vp)
_declare("lfem_mesh_translate", _st, _vp, _dp)
_declare("lfem_mesh_rotate", _st, _vp, _dp, _dbl)

_declare("lfem_vtk_series_create", _st, ctypes.c_char_p, _p(_vp))
_declare("lfem_vtk_series_write_frame", _st, _vp, _vp)
_declare("lfem_vtk_series_destroy", None, _vp)

#: The raw ctypes library, every function declared (status-returning ones raise LfemError).
native = _lib

# ---- helpers ----------------------------------------------------------------------------------


def version():
    """(major, minor, patch) of the library loaded."""
    v = _lib.lfem_version()
    return (v >> 16, (v >> 8) & 0xFF, v & 0xFF)


def version_string():
    return _c_string(_lib.lfem_version_string())


def status_string(status):
    """lfem's fixed name and meaning, e.g. "LFEM_INVALID_MESH: invalid mesh"."""
    return _c_string(_lib.lfem_status_string(int(status)))


def last_error():
    """The message of this thread's last failed call ("" before any)."""
    return _c_string(_lib.lfem_last_error())


def _vec3(v, name):
    a = np.ascontiguousarray(v, dtype=np.float64).reshape(-1)
    if a.shape != (3,):
        raise LfemError(Status.INVALID_ARGUMENT, "lfem (Python): %s must have 3 components" % name)
    return a


def _dptr(a):
    return a.ctypes.data_as(_dp)


def _uptr(a):
    return a.ctypes.data_as(_up)


def _indices(nodes):
    a = np.ascontiguousarray(nodes, dtype=np.int64).reshape(-1)
    if a.size and (a.min() < 0 or a.max() > 0xFFFFFFFF):
        raise LfemError(Status.INVALID_ARGUMENT, "lfem (Python): node index out of range")
    return np.ascontiguousarray(a, dtype=np.uint32)


def _vectors(values, name, rows=None):
    a = np.ascontiguousarray(values, dtype=np.float64)
    if a.ndim == 1 and a.size % 3 == 0:
        a = a.reshape(-1, 3)
    if a.ndim != 2 or a.shape[1] != 3 or (rows is not None and a.shape[0] != rows):
        raise LfemError(Status.INVALID_ARGUMENT,
                        "lfem (Python): %s must be an (n, 3) array, got shape %s"
                        % (name, np.shape(values)))
    return a


def _out_buffer(out, rows, name):
    if out is None:
        return np.empty((rows, 3), dtype=np.float64)
    if (not isinstance(out, np.ndarray) or out.dtype != np.float64 or out.ndim != 2
            or out.shape[1] != 3 or not out.flags.c_contiguous or not out.flags.writeable):
        raise LfemError(Status.INVALID_ARGUMENT,
                        "lfem (Python): %s must be a writeable C-contiguous float64 (n, 3) array"
                        % name)
    return out


# ---- world ------------------------------------------------------------------------------------


class World:
    """A simulation world. close() (or a with block, or garbage collection) destroys it."""

    def __init__(self, definition=None):
        if definition is None:
            definition = WorldDef.default()
        handle = _vp()
        _lib.lfem_world_create(ctypes.byref(definition), ctypes.byref(handle))
        self._handle = handle

    @classmethod
    def load(cls, path):
        """A new world from a checkpoint written by save(); stepping it continues the saved
        run bit for bit. Body handles of the saved world are valid in it."""
        handle = _vp()
        _lib.lfem_world_load(os.fsencode(path), ctypes.byref(handle))
        world = cls.__new__(cls)
        world._handle = handle
        return world

    def save(self, path):
        """Write a checkpoint of the whole world (replaces path only once complete)."""
        _lib.lfem_world_save(self.handle, os.fsencode(path))

    @property
    def handle(self):
        """The raw lfem_world* (a ctypes c_void_p)."""
        if self._handle is None:
            raise ValueError("lfem: the world is closed")
        return self._handle

    def close(self):
        if getattr(self, "_handle", None) is not None:
            _lib.lfem_world_destroy(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()

    def step(self, dt):
        """Advance by dt seconds (split into stable sub-steps)."""
        _lib.lfem_world_step(self.handle, dt)

    def set_gravity(self, gravity):
        _lib.lfem_world_set_gravity(self.handle, _dptr(_vec3(gravity, "gravity")))

    def set_time_step(self, time_step):
        """Fixed sub-step (s), 0 = automatic."""
        _lib.lfem_world_set_time_step(self.handle, time_step)

    @property
    def stable_step(self):
        out = ctypes.c_double()
        _lib.lfem_world_get_stable_step(self.handle, ctypes.byref(out))
        return out.value

    @property
    def stats(self):
        out = WorldStats()
        _lib.lfem_world_get_stats(self.handle, ctypes.byref(out))
        return out

    @property
    def profile(self):
        """Per-phase time (s) and counts since creation or reset_profile()."""
        out = Profile()
        _lib.lfem_world_get_profile(self.handle, ctypes.byref(out))
        return out

    def reset_profile(self):
        _lib.lfem_world_reset_profile(self.handle)

    # -- bodies --

    def create_body(self, definition=None):
        if definition is None:
            definition = BodyDef.default()
        out = Body()
        _lib.lfem_body_create(self.handle, ctypes.byref(definition), ctypes.byref(out))
        return out

    def destroy_body(self, body):
        _lib.lfem_body_destroy(self.handle, body)

    def is_valid(self, body):
        return _lib.lfem_body_is_valid(self.handle, body) != 0

    def add_mesh(self, body, mesh):
        """Add the tets of a Mesh (copied; the mesh stays yours)."""
        m = mesh.handle
        _lib.lfem_body_add_mesh(self.handle, body, _lib.lfem_mesh_get_positions(m),
                                _lib.lfem_mesh_get_node_count(m), _lib.lfem_mesh_get_tets(m),
                                _lib.lfem_mesh_get_tet_count(m))

    def add_mesh_arrays(self, body, positions, tets):
        """Add nodes (an (n, 3) array, m) and tets (an (m, 4) array of node indices)."""
        x = _vectors(positions, "positions")
        t = _indices(tets)
        if t.size % 4:
            raise LfemError(Status.INVALID_ARGUMENT, "lfem (Python): tets must be an (m, 4) array")
        _lib.lfem_body_add_mesh(self.handle, body, _dptr(x), x.shape[0], _uptr(t), t.size // 4)

    def add_shape(self, body, definition=None, points=None):
        """Give a static or kinematic body a rigid shape (ShapeDef, default a plane z = 0);
        points: the convex hull's (n, 3) local coordinates (m), None for the other shapes.
        Returns the shape's index on the body (the `shape` of the contacts that touch it)."""
        d = ShapeDef.default() if definition is None else ShapeDef.from_buffer_copy(definition)
        keep = None
        if points is not None:
            keep = _vectors(points, "points")
            d.points = _dptr(keep)
            d.point_count = keep.shape[0]
        else:
            d.points = None
            d.point_count = 0
        index = ctypes.c_uint32()
        _lib.lfem_body_add_shape(self.handle, body, ctypes.byref(d), ctypes.byref(index))
        del keep
        return index.value

    def mass(self, body):
        """Total mass (kg) of a body: the sum of its lumped node masses, rho V."""
        out = ctypes.c_double()
        _lib.lfem_body_get_mass(self.handle, body, ctypes.byref(out))
        return out.value

    def momentum(self, body):
        """(linear, angular): linear momentum (kg m/s) and angular momentum about the origin
        (kg m^2/s) of a body, two float64 arrays of 3."""
        linear, angular = np.zeros(3), np.zeros(3)
        _lib.lfem_body_get_momentum(self.handle, body, _dptr(linear), _dptr(angular))
        return linear, angular

    def node_count(self, body):
        out = ctypes.c_uint32()
        _lib.lfem_body_get_node_count(self.handle, body, ctypes.byref(out))
        return out.value

    def tet_count(self, body):
        out = ctypes.c_uint32()
        _lib.lfem_body_get_tet_count(self.handle, body, ctypes.byref(out))
        return out.value

    def user_data(self, body):
        out = _vp()
        _lib.lfem_body_get_user_data(self.handle, body, ctypes.byref(out))
        return out.value

    def positions(self, body, out=None):
        """Node positions (m) as a float64 (n, 3) array that lfem fills directly. With out=
        (a C-contiguous float64 (k, 3) array, k >= n) that array is filled and returned;
        BUFFER_TOO_SMALL (nothing written) when k < n."""
        buf = _out_buffer(out, self.node_count(body) if out is None else 0, "out")
        _lib.lfem_body_get_positions(self.handle, body, _dptr(buf), buf.shape[0])
        return buf

    def velocities(self, body, out=None):
        """Node velocities (m/s), like positions()."""
        buf = _out_buffer(out, self.node_count(body) if out is None else 0, "out")
        _lib.lfem_body_get_velocities(self.handle, body, _dptr(buf), buf.shape[0])
        return buf

    def set_velocities(self, body, velocities):
        v = _vectors(velocities, "velocities")
        _lib.lfem_body_set_velocities(self.handle, body, _dptr(v), v.shape[0])

    def boundary_triangles(self, body):
        """Boundary triangles, an (n, 3) uint32 array, counter-clockwise seen from outside."""
        n = ctypes.c_uint32()
        _lib.lfem_body_get_boundary_triangle_count(self.handle, body, ctypes.byref(n))
        out = np.empty((n.value, 3), dtype=np.uint32)
        _lib.lfem_body_get_boundary_triangles(self.handle, body, _uptr(out), n.value)
        return out

    def von_mises_stress(self, body):
        """Von Mises stress (Pa), one per tet."""
        out = np.empty(self.tet_count(body), dtype=np.float64)
        _lib.lfem_body_get_von_mises_stress(self.handle, body, _dptr(out), out.size)
        return out

    def rotation(self, body):
        """The paper model's global rotation, a 3x3 array (identity for the other models)."""
        out = np.empty((3, 3), dtype=np.float64)
        _lib.lfem_body_get_rotation(self.handle, body, _dptr(out))
        return out

    def find_nodes_in_box(self, body, lo, hi):
        """Indices of the nodes whose current position lies in the box [lo, hi] (m)."""
        lo, hi = _vec3(lo, "lo"), _vec3(hi, "hi")
        count = ctypes.c_uint32()
        try:
            _lib.lfem_body_find_nodes_in_box(self.handle, body, _dptr(lo), _dptr(hi), None, 0,
                                             ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        out = np.empty(count.value, dtype=np.uint32)
        if count.value:
            _lib.lfem_body_find_nodes_in_box(self.handle, body, _dptr(lo), _dptr(hi), _uptr(out),
                                             out.size, ctypes.byref(count))
        return out

    # -- loads and supports --

    def fix_nodes(self, body, nodes):
        n = _indices(nodes)
        _lib.lfem_body_fix_nodes(self.handle, body, _uptr(n), n.size)

    def prescribe_node_velocity(self, body, nodes, velocity):
        n = _indices(nodes)
        _lib.lfem_body_prescribe_node_velocity(self.handle, body, _uptr(n), n.size,
                                               _dptr(_vec3(velocity, "velocity")))

    def release_nodes(self, body, nodes):
        n = _indices(nodes)
        _lib.lfem_body_release_nodes(self.handle, body, _uptr(n), n.size)

    def set_node_forces(self, body, nodes, forces):
        """Constant external forces (N): forces[i] on nodes[i], from now on."""
        n = _indices(nodes)
        f = _vectors(forces, "forces", rows=n.size)
        _lib.lfem_body_set_node_forces(self.handle, body, _uptr(n), n.size, _dptr(f))

    def clear_node_forces(self, body):
        _lib.lfem_body_clear_node_forces(self.handle, body)

    def set_kinematic_velocity(self, body, linear, angular):
        _lib.lfem_body_set_kinematic_velocity(self.handle, body, _dptr(_vec3(linear, "linear")),
                                              _dptr(_vec3(angular, "angular")))

    # -- contacts --

    def contact_count(self):
        """The number of active contacts of the last step."""
        count = ctypes.c_uint32()
        try:
            _lib.lfem_world_query_contacts(self.handle, None, 0, ctypes.byref(count))
        except LfemError as e:
            if e.status != Status.BUFFER_TOO_SMALL:
                raise
        return count.value

    def contacts(self, out=None):
        """The active contacts of the last step as a numpy structured array of CONTACT_DTYPE
        (fields body_a, body_b, node, triangle, barycentric, position, normal, force, sliding),
        filled by lfem directly. With out= (a CONTACT_DTYPE array), the contacts go to its front
        and out[:count] is returned; BUFFER_TOO_SMALL (nothing copied) when it is too short."""
        if out is None:
            out = np.zeros(self.contact_count(), dtype=CONTACT_DTYPE)
        elif (not isinstance(out, np.ndarray) or out.dtype != CONTACT_DTYPE or out.ndim != 1
              or not out.flags.c_contiguous or not out.flags.writeable):
            raise LfemError(Status.INVALID_ARGUMENT,
                            "lfem (Python): out must be a writeable 1-d array of CONTACT_DTYPE")
        count = ctypes.c_uint32()
        _lib.lfem_world_query_contacts(self.handle, out.ctypes.data if out.size else None,
                                       min(out.size, 0xFFFFFFFF), ctypes.byref(count))
        return out[:count.value]


# ---- meshes -----------------------------------------------------------------------------------


class Mesh:
    """A tetrahedral mesh owned by Python; close() (or garbage collection) frees it."""

    def __init__(self, handle):
        self._handle = handle

    @property
    def handle(self):
        if self._handle is None:
            raise ValueError("lfem: the mesh is closed")
        return self._handle

    def close(self):
        if getattr(self, "_handle", None) is not None:
            _lib.lfem_mesh_destroy(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()

    @classmethod
    def box(cls, size, cells):
        """A box [0, size] (m) of cells[0] x cells[1] x cells[2] hexahedra, 6 tets each."""
        s = _vec3(size, "size")
        c = _indices(cells)
        if c.size != 3:
            raise LfemError(Status.INVALID_ARGUMENT, "lfem (Python): cells must have 3 entries")
        out = _vp()
        _lib.lfem_mesh_create_box(_dptr(s), _uptr(c), ctypes.byref(out))
        return cls(out)

    @classmethod
    def cylinder(cls, radius, height, segments, rings, layers):
        out = _vp()
        _lib.lfem_mesh_create_cylinder(radius, height, segments, rings, layers, ctypes.byref(out))
        return cls(out)

    @classmethod
    def cup(cls, outer_radius, height, wall, bottom, segments, layers):
        out = _vp()
        _lib.lfem_mesh_create_cup(outer_radius, height, wall, bottom, segments, layers,
                                  ctypes.byref(out))
        return cls(out)

    @classmethod
    def hammer(cls, handle_length, handle_width, head_length, head_width, cell_size):
        out = _vp()
        _lib.lfem_mesh_create_hammer(handle_length, handle_width, head_length, head_width,
                                     cell_size, ctypes.byref(out))
        return cls(out)

    @classmethod
    def load_gmsh(cls, path):
        """The tetrahedra of a Gmsh .msh file (ASCII 2.2 or 4.1)."""
        out = _vp()
        _lib.lfem_mesh_load_gmsh(os.fsencode(path), ctypes.byref(out))
        return cls(out)

    @property
    def node_count(self):
        return _lib.lfem_mesh_get_node_count(self.handle)

    @property
    def tet_count(self):
        return _lib.lfem_mesh_get_tet_count(self.handle)

    @property
    def positions(self):
        """A copy of the node positions (m), an (n, 3) float64 array."""
        n = self.node_count
        if n == 0:
            return np.empty((0, 3), dtype=np.float64)
        return np.ctypeslib.as_array(_lib.lfem_mesh_get_positions(self.handle), (n, 3)).copy()

    @property
    def tets(self):
        """A copy of the tets, an (m, 4) uint32 array of node indices."""
        n = self.tet_count
        if n == 0:
            return np.empty((0, 4), dtype=np.uint32)
        return np.ctypeslib.as_array(_lib.lfem_mesh_get_tets(self.handle), (n, 4)).copy()

    def translate(self, offset):
        _lib.lfem_mesh_translate(self.handle, _dptr(_vec3(offset, "offset")))

    def rotate(self, axis, angle):
        """Rotate about the origin by angle (rad) around axis."""
        _lib.lfem_mesh_rotate(self.handle, _dptr(_vec3(axis, "axis")), angle)


# ---- output -----------------------------------------------------------------------------------


class VtkSeries:
    """A ParaView time series (.pvd plus one .vtu per frame)."""

    def __init__(self, pvd_path):
        out = _vp()
        _lib.lfem_vtk_series_create(os.fsencode(pvd_path), ctypes.byref(out))
        self._handle = out

    def write_frame(self, world):
        if self._handle is None:
            raise ValueError("lfem: the series is closed")
        _lib.lfem_vtk_series_write_frame(self._handle, world.handle)

    def close(self):
        if getattr(self, "_handle", None) is not None:
            _lib.lfem_vtk_series_destroy(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()
