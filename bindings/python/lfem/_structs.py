"""The C structs of lfem.h as ctypes structures (same layout; checked by the tests against the
sizes bindings/abi_layout.c asserts in C), and the enums.

The definitions (WorldDef, BodyDef, ShapeDef) start from the library's defaults, take their
fields as keywords (BodyDef(density=400)) and check every field that is set: a value of the wrong
type raises TypeError, a vector of the wrong length InvalidArgumentError, an unknown name
AttributeError. Enum fields read back as their enum."""

from __future__ import annotations

import ctypes
import enum
import numbers
from typing import Any, Callable, ClassVar, Dict, Tuple, Type

import numpy as np

from . import _convert
from ._errors import InvalidArgumentError


class BodyType(enum.IntEnum):
    """lfem_body_type."""

    DEFORMABLE = 0  # finite elements, moves and deforms
    STATIC = 1      # never moves (a floor, a wall)
    KINEMATIC = 2   # moves rigidly with a prescribed velocity, unaffected by forces
    RIGID = 3       # the global translation and rotation alone, moved by forces and contacts


class Model(enum.IntEnum):
    """lfem_model: the material model of a deformable body."""

    PAPER = 0         # floating frame: one global rotation per body (the paper's eq. 2)
    COROTATIONAL = 1  # one rotation per tet: large local rotations (bending)
    NEO_HOOKEAN = 2   # stable neo-Hookean hyperelasticity: large strains
    LINEAR = 3        # small-strain linear elasticity, no rotation at all


class WarningKind(enum.IntEnum):
    """lfem_warning_kind: what a warning counts (trouble the step recovers from)."""

    INVERTED_TETS = 0   # a sub-step ended with inverted tets in a body: once per body and sub-step
    STAYS_INVERTED = 1  # a body kept inverted tets for 0.5 s in a row: once per spell
    FALLEN_IN = 2       # nodes found inside another body (or their own), pushed out
    UNCONVERGED = 3     # a contact solve used every sweep and ended above its tolerance


class ShapeType(enum.IntEnum):
    """lfem_shape_type: the kind of a rigid shape."""

    PLANE = 0        # the half-space below the plane through center with normal local +z
    BOX = 1          # half_extents along the local axes
    SPHERE = 2       # radius
    CAPSULE = 3      # segment -half_length..+half_length along local z, swept by radius
    CONVEX_HULL = 4  # convex hull of points (local coordinates), see World.add_shape


_d3 = ctypes.c_double * 3
_enum = ctypes.c_int  # C enums are 32-bit

# Set by _native once the library is loaded: a definition's class -> its lfem_*_def_default.
DEFAULTS: Dict[type, Callable[[], Any]] = {}


def _enum_property(raw: str, kind: Type[enum.IntEnum]) -> property:
    """A public enum field over the raw C int field `raw` (an unknown value reads as int)."""

    def get(self: Any) -> Any:
        value = getattr(self, raw)
        try:
            return kind(value)
        except ValueError:
            return value

    def put(self: Any, value: Any) -> None:
        public = raw.lstrip("_")
        if not isinstance(value, kind) and (isinstance(value, (bool, enum.Enum))
                                            or not isinstance(value, numbers.Integral)):
            raise TypeError("lfem: %s must be a %s, not %r" % (public, kind.__name__, value))
        try:
            member = kind(int(value))
        except ValueError:
            raise InvalidArgumentError("lfem: %s = %d is no %s" % (public, value,
                                                                   kind.__name__)) from None
        ctypes.Structure.__setattr__(self, raw, int(member))

    return property(get, put, doc="%s (the C field %s)" % (kind.__name__, raw.lstrip("_")))


class _Definition(ctypes.Structure):
    """Base of WorldDef, BodyDef and ShapeDef (see the module docstring)."""

    _enums: ClassVar[Tuple[str, ...]] = ()  # public names of the enum properties

    def __init__(self, **fields: Any) -> None:
        super().__init__()
        defaults = DEFAULTS[type(self)]()  # kept alive until copied
        ctypes.memmove(ctypes.addressof(self), ctypes.addressof(defaults), ctypes.sizeof(self))
        for name, value in fields.items():
            if name not in self._public():
                raise TypeError("lfem: %s() got an unexpected keyword argument %r"
                                % (type(self).__name__, name))
            setattr(self, name, value)

    @classmethod
    def default(cls) -> Any:
        """The library's defaults (the same as cls())."""
        return cls()

    @classmethod
    def _public(cls) -> Tuple[str, ...]:
        names = tuple(f[0] for f in cls._fields_ if not f[0].startswith("_"))
        return names + cls._enums

    def __setattr__(self, name: str, value: Any) -> None:
        if name in self._enums or name.startswith("_"):
            return super().__setattr__(name, value)
        ctype = dict((f[0], f[1]) for f in self._fields_).get(name)
        if ctype is None:
            raise AttributeError("lfem: %s has no field %r (fields: %s)"
                                 % (type(self).__name__, name, ", ".join(self._public())))
        if issubclass(ctype, ctypes.Array):
            value = tuple(_convert.vector(value, name, ctype._length_))
        elif ctype is ctypes.c_double:
            value = _convert.real(value, name)
        elif ctype is ctypes.c_uint32:
            value = _convert.count(value, name)
        elif ctype is ctypes.c_uint8:
            value = _convert.flag(value, name)
        elif ctype is ctypes.c_void_p:
            if value is not None and not isinstance(value, int):
                raise TypeError("lfem: %s must be an int address or None, not %s"
                                % (name, type(value).__name__))
        super().__setattr__(name, value)

    def __repr__(self) -> str:
        def show(value: Any) -> str:
            if isinstance(value, ctypes.Array):
                return repr(tuple(value))
            return repr(value)
        return "%s(%s)" % (type(self).__name__, ", ".join(
            "%s=%s" % (name, show(getattr(self, name))) for name in self._enums
            + tuple(f[0] for f in self._fields_ if not f[0].startswith("_"))))


class WorldDef(_Definition):
    """lfem_world_def: how a world is set up. WorldDef(time_step=1e-3) is the defaults with
    the fields given changed."""

    _fields_ = [
        ("gravity", _d3),                     # m/s^2, default (0, 0, -9.81)
        ("time_step", ctypes.c_double),       # s, 0 = automatic (default), > 0 fixed sub-step
        ("step_safety", ctypes.c_double),     # in (0, 1), default 0.9
        ("contact_iterations", ctypes.c_uint32),
        ("thread_count", ctypes.c_uint32),    # 1..64, default 1; results independent of it
        ("contact_tolerance", ctypes.c_double),
        ("max_substeps", ctypes.c_uint32),
        ("allow_unstable_step", ctypes.c_uint8),
        ("enable_sleep", ctypes.c_uint8),     # 1 = bodies at rest fall asleep, default 0
        ("_padding", ctypes.c_uint8 * 2),
        ("_internal_value", ctypes.c_uint32),  # set by the default; never changed
        ("_padding2", ctypes.c_uint32),
        ("mass_scaling_step", ctypes.c_double),  # s, 0 = off (default): see lfem_world_def
        ("sleep_velocity", ctypes.c_double),  # m/s, default 0.01
        ("sleep_time", ctypes.c_double),      # s, default 0.5
    ]


class BodyDef(_Definition):
    """lfem_body_def: how a body is set up. BodyDef(density=400, model=Model.NEO_HOOKEAN) is
    the defaults with the fields given changed."""

    _fields_ = [
        ("_type", _enum),                     # BodyType, default DEFORMABLE
        ("_model", _enum),                    # Model, default PAPER
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
        ("_internal_value", ctypes.c_uint32),  # set by the default; never changed
        ("enable_sleep", ctypes.c_uint8),     # 1 (default) = may fall asleep when the world allows
        ("self_contact", ctypes.c_uint8),     # 1 = the surface collides with itself (deformable)
        ("composite_tets", ctypes.c_uint8),   # 1 = 10-node tets as the composite element
        ("report_contacts", ctypes.c_uint8),  # 1 = every step reports the pairs that stay in touch
        ("edge_contacts", ctypes.c_uint8),    # 1 (default) = sharp edges crossing others' held apart
        ("_padding", ctypes.c_uint8 * 7),
    ]
    _enums = ("type", "model")
    type = _enum_property("_type", BodyType)
    model = _enum_property("_model", Model)


class ShapeDef(_Definition):
    """lfem_shape_def: a rigid shape of a static or kinematic body. ShapeDef(type=ShapeType.BOX,
    half_extents=(1, 1, 0.1)) is the defaults with the fields given changed; convex hull points
    are passed to World.add_shape."""

    _fields_ = [
        ("_type", _enum),                     # ShapeType, default PLANE
        ("_point_count", ctypes.c_uint32),    # set by World.add_shape
        ("center", _d3),                      # m, default 0
        ("rotation", ctypes.c_double * 4),    # unit quaternion (w, x, y, z), default identity
        ("half_extents", _d3),                # m, box, default 0.5
        ("radius", ctypes.c_double),          # m, sphere and capsule, default 0.5
        ("half_length", ctypes.c_double),     # m, capsule, default 0.5
        ("_points", ctypes.POINTER(ctypes.c_double)),  # set by World.add_shape
        ("_internal_value", ctypes.c_uint32),  # set by the default; never changed
        ("_padding", ctypes.c_uint32),
    ]
    _enums = ("type",)
    type = _enum_property("_type", ShapeType)


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
        ("added_mass", ctypes.c_double),      # kg, by mass scaling
        ("inverted_tets", ctypes.c_uint32),   # tets with J = det F <= 0 after the last sub-step
        ("_padding", ctypes.c_uint32),
        ("min_jacobian", ctypes.c_double),    # the smallest volume ratio J (1 without any)
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
        ("candidate_searches", ctypes.c_uint64),  # contact's searches for candidate faces anew
        ("queries", ctypes.c_uint64),           # rays and boxes the queries answered
        ("query_bodies", ctypes.c_uint64),      # bodies a query reached (box met, filter passed)
        ("query_primitives", ctypes.c_uint64),  # triangles and shapes a query tested exactly
        ("query_refits", ctypes.c_uint64),      # moving bodies' trees built or refitted for queries
        ("contact_sweeps", ctypes.c_uint64),    # contact solve sweeps (slowest group per sub-step)
        ("constraint_updates", ctypes.c_uint64),  # updates of one constraint in a sweep, summed
    ]


class Body(ctypes.Structure):
    """A body handle (lfem_body), a value; Body() is the null handle."""

    _fields_ = [("index", ctypes.c_uint32), ("generation", ctypes.c_uint32)]

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, Body) and self.index == other.index
                and self.generation == other.generation)

    def __hash__(self) -> int:
        return hash((self.index, self.generation))

    def __repr__(self) -> str:
        return "Body(index=%d, generation=%d)" % (self.index, self.generation)


class Attachment(ctypes.Structure):
    """An attachment handle (lfem_attachment), a value."""

    _fields_ = [("index", ctypes.c_uint32), ("generation", ctypes.c_uint32)]

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, Attachment) and self.index == other.index
                and self.generation == other.generation)

    def __hash__(self) -> int:
        return hash((self.index, self.generation))


class AttachmentDef(ctypes.Structure):
    """lfem_attachment_def (filled by World.attach)."""

    _fields_ = [
        ("body", Body), ("target", Body), ("nodes", ctypes.POINTER(ctypes.c_uint32)),
        ("node_count", ctypes.c_uint32), ("_internal_value", ctypes.c_uint32),
        ("frame", ctypes.c_double * 7), ("break_force", ctypes.c_double),
        ("points", ctypes.POINTER(ctypes.c_double)), ("point_count", ctypes.c_uint32),
        ("stiffness", ctypes.c_double), ("damping", ctypes.c_double),
    ]


class EventType(enum.IntEnum):
    """lfem_event_type."""

    CONTACT_BEGIN = 0       # a pair began to touch during the step
    CONTACT_END = 1         # a pair that touched stopped
    SLEEP = 2               # body_a fell asleep
    WAKE = 3                # body_a woke
    ATTACHMENT_BROKEN = 4   # attachment broke (now stale)
    CONTACT_PERSIST = 5     # a pair still touching (when either body reports its contacts)


class Event(ctypes.Structure):
    """lfem_event: one event of the last step."""

    _fields_ = [
        ("_type", ctypes.c_int), ("contact_count", ctypes.c_uint32), ("body_a", Body), ("body_b", Body),
        ("attachment", Attachment), ("normal_impulse", ctypes.c_double), ("max_force", ctypes.c_double),
        ("approach_speed", ctypes.c_double), ("point", _d3), ("normal", _d3),
    ]

    @property
    def type(self) -> "EventType":
        return EventType(self._type)


class Warning(ctypes.Structure):
    """lfem_warning: how often, when last (s), for which body (Body() when none)."""

    _fields_ = [("count", ctypes.c_uint64), ("last_time", ctypes.c_double), ("last_body", Body)]


class Contact(ctypes.Structure):
    """lfem_contact: one active contact of the last step (World.contacts gives them as a numpy
    array of CONTACT_DTYPE, the same layout)."""

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
        ("kind", ctypes.c_uint8),
        ("_padding", ctypes.c_uint8 * 2),
        ("shape", ctypes.c_uint32),  # index of body_b's shape, or NO_SHAPE for a triangle
        ("weights_a", _d3),  # body_a's point: sum of weights_a[k] x node nodes_a[k]
        ("nodes_a", ctypes.c_uint32 * 3),  # node indices in body_a (NO_SHAPE: unused)
        ("_padding2", ctypes.c_uint32),
    ]


#: Contact.shape of a contact with a triangle (not a rigid shape); RayHit.shape of a hit on a
#: triangle, and RayHit.triangle of a hit on a shape.
NO_SHAPE = 0xFFFFFFFF


class QueryFilter(_Definition):
    """lfem_query_filter: what a query sees, as the bodies' own filter (a body is seen when
    body.category_bits & mask_bits and category_bits & body.mask_bits). QueryFilter() is
    lfem_query_filter_default(): category 1, every mask bit."""

    _fields_ = [("category_bits", ctypes.c_uint32), ("mask_bits", ctypes.c_uint32)]


class RayHit(ctypes.Structure):
    """lfem_ray_hit: where a ray crossed a surface (World.cast_ray_all gives them as a numpy
    array of RAY_HIT_DTYPE, the same layout)."""

    _fields_ = [
        ("body", Body),
        ("triangle", ctypes.c_uint32),        # the body's boundary triangle, or NO_SHAPE
        ("shape", ctypes.c_uint32),           # the body's shape, or NO_SHAPE
        ("barycentric", ctypes.c_double * 2),  # t1, t2 as in Contact (0 for a shape)
        ("point", _d3),                       # m, on the ray
        ("normal", _d3),                      # unit, out of the surface hit
        ("distance", ctypes.c_double),        # m from the origin along the unit ray
    ]

class Overlap(ctypes.Structure):
    """lfem_overlap: a body a sphere or capsule overlaps, and where."""

    _fields_ = [
        ("body", Body),
        ("triangle", ctypes.c_uint32),  # its boundary triangle nearest the query's core, or NO_SHAPE
        ("shape", ctypes.c_uint32),     # its shape nearest the core, or NO_SHAPE
        ("point", _d3),                 # m, the point of that triangle or shape nearest the core
        ("distance", ctypes.c_double),  # m from the core to point; 0 inside
    ]

_BODY_DTYPE = np.dtype([("index", "<u4"), ("generation", "<u4")])

_CONTACT_FIELDS = ["body_a", "body_b", "node", "triangle", "barycentric", "position", "normal",
                   "force", "sliding", "kind", "shape", "weights_a", "nodes_a"]

#: The numpy dtype of lfem_contact (same offsets and size as Contact).
CONTACT_DTYPE = np.dtype({
    "names": _CONTACT_FIELDS,
    "formats": [_BODY_DTYPE, _BODY_DTYPE, np.uint32, (np.uint32, 3), (np.float64, 2),
                (np.float64, 3), (np.float64, 3), (np.float64, 3), np.uint8, np.uint8, np.uint32,
                (np.float64, 3), (np.uint32, 3)],
    "offsets": [getattr(Contact, name).offset for name in _CONTACT_FIELDS],
    "itemsize": ctypes.sizeof(Contact),
})

_RAY_HIT_FIELDS = ["body", "triangle", "shape", "barycentric", "point", "normal", "distance"]

#: The numpy dtype of lfem_ray_hit (same offsets and size as RayHit).
RAY_HIT_DTYPE = np.dtype({
    "names": _RAY_HIT_FIELDS,
    "formats": [_BODY_DTYPE, np.uint32, np.uint32, (np.float64, 2), (np.float64, 3),
                (np.float64, 3), np.float64],
    "offsets": [getattr(RayHit, name).offset for name in _RAY_HIT_FIELDS],
    "itemsize": ctypes.sizeof(RayHit),
})
