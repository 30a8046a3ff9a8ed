#!/usr/bin/env python3
"""Writes the inputs of fuzz_api as small programs in the byte encoding of fuzz_input.h and
fuzz_api.cpp: the seeds (tests/fuzz/corpus/api), so that the fuzzer starts from scenes that
collide, sleep, attach and break, not from noise, and the regression inputs
(tests/fuzz/regressions/api), the call sequences of bugs the fuzzer once found, written out so
that they keep their meaning when the call table changes.
Run it again after changing what fuzz_api.cpp reads (every input's meaning depends on it), and
check with LFEM_FUZZ_VERBOSE=1 build/tests/fuzz/fuzz_api_replay FILE that each does what its
comment says; tests/fuzz/api_coverage.sh tells which functions the seeds reach."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# The calls of one_call in fuzz_api.cpp, by number.
(BODY_CREATE, ADD_BUILDER_MESH, ADD_RAW_MESH, ADD_TRIANGLE_MESH, STEP, QUERY_CONTACTS,
 GET_POSITIONS, FIX_NODES, PRESCRIBE, SET_FORCES, BODY_DESTROY, ADD_SHAPE, SET_GRAVITY_OR_STEP,
 SET_KINEMATIC_VELOCITY, SAVE_LOAD, ADD_SKIN, SKIN_READ, RAY_OR_BOX, RELEASE_NODES, WORLD_CREATE,
 ATTACHMENT_CREATE, ATTACHMENT_OP, GET_EVENTS, WAKE, SET_VELOCITIES, BODY_GETTER, WORLD_GETTER,
 MISC, VTK) = range(29)
NULL_WORLD = 0xFF << 24          # selector's top byte: the call gets a NULL world


def null_arg(k):                 # selector's top byte: the call's pointer argument k is NULL
    return (0xF0 | k) << 24


DEFORMABLE, STATIC, KINEMATIC, RIGID = range(4)
PAPER, COROTATIONAL, NEO_HOOKEAN, LINEAR = range(4)
PLANE, BOX, SPHERE, CAPSULE, HULL = range(5)


class Program:
    def __init__(self):
        self.b = bytearray()

    # The reads of fuzz_input.h.
    def u32(self, v):
        self.b += struct.pack('<I', v & 0xFFFFFFFF)

    def below(self, v):  # in.below(n) reads a u32 and takes it modulo n
        self.u32(v)

    def number(self, lo, hi, v):  # a plain value: kind byte < 200, then a fraction
        self.b.append(0)
        self.u32(round((v - lo) / (hi - lo) * 4294967295.0))

    def raw(self, v):  # any double, bit for bit (NaN, infinities, denormals): kind byte >= 200
        self.b.append(255)
        self.b += struct.pack('<d', v)

    def value(self, lo, hi, v):  # v exactly: raw when the fraction cannot give it (0 in (lo, hi))
        if v != v or v in (float('inf'), float('-inf')) or not lo <= v <= hi or (v == 0 and lo < 0):
            self.raw(v)
        else:
            self.number(lo, hi, v)

    def byte(self, v):
        self.b.append(v)

    # What the harness reads, call by call.
    def world_def(self, substeps=40, iterations=30, safety=0.9, threads=1, sleep=False,
                  mass_scaling=None, sleep_velocity=None, sleep_time=None, gravity=None,
                  time_step=None, tolerance=None, raw_threads=None, cookie=None):
        self.below(substeps - 1)
        self.below(iterations - 1)
        self.value(0.05, 0.99, safety)
        self.below(threads - 1)
        flags = ((1 if sleep else 0) | (2 if mass_scaling is not None else 0)
                 | (4 if sleep_velocity is not None else 0) | (8 if gravity is not None else 0)
                 | (16 if time_step is not None else 0) | (32 if tolerance is not None else 0)
                 | (64 if raw_threads is not None else 0) | (128 if cookie is not None else 0))
        self.byte(flags)
        if mass_scaling is not None:
            self.value(0, 2e-4, mass_scaling)
        if sleep_velocity is not None:
            self.value(0, 0.5, sleep_velocity)
            self.value(0, 0.1, sleep_time)
        if gravity is not None:
            for g in gravity:
                self.value(-20, 20, g)
        if time_step is not None:
            self.value(0, 1e-3, time_step)
            self.byte(0)
        if tolerance is not None:
            self.value(1e-6, 0.1, tolerance)
        if raw_threads is not None:
            self.u32(raw_threads)
            self.byte(1 if sleep else 0)
            self.byte(0)
        if cookie is not None:
            self.byte(cookie)

    def call(self, number, flags=0):
        self.u32(number | flags)

    def pick(self, index):  # pick_body / pick_attachment: one of the handles returned so far
        self.byte(0)
        self.below(index)

    def made_up(self, index, generation):  # a handle the harness makes up (null, stale, foreign)
        self.byte(255)
        self.u32(index)
        self.u32(generation)

    def nodes(self, nodes):
        self.below(len(nodes))
        for n in nodes:
            self.below(n)

    def body(self, kind, model=PAPER, young=1e5, poisson=0.3, density=1000, damping=0,
             friction=0.5, velocity=(0, 0, 0), spin=(0, 0, 0), mask=None, category=None,
             self_contact=False, composite=False, sleep=True, raw_flags=None, cookie=None, flags=0):
        self.call(BODY_CREATE, flags)
        self.below(kind)
        self.below(model)
        self.value(1e3, 1e8, young)
        self.value(-0.2, 0.5, poisson)
        self.value(10, 2e4, density)
        self.value(0, 10, damping)
        self.value(0, 1, friction)
        for v in velocity:
            self.value(-10, 10, v)
        for v in spin:
            self.value(-5, 5, v)
        f = ((1 if mask is not None else 0) | (2 if category is not None else 0)
             | (4 if self_contact else 0) | (8 if composite else 0) | (0 if sleep else 16)
             | (32 if raw_flags is not None else 0) | (64 if cookie is not None else 0))
        self.byte(f)
        if mask is not None:
            self.u32(mask)
        if category is not None:
            self.u32(category)
        if raw_flags is not None:
            for v in raw_flags:
                self.byte(v)
        if cookie is not None:
            self.byte(cookie)

    def _mesh_tail(self, body_index, offset, quadratic, rotate, as_linear):
        for o, (lo, hi) in zip(offset, [(-1, 1), (-1, 1), (-0.2, 1)]):
            self.value(lo, hi, o)
        self.byte((1 if quadratic else 0) | (2 if rotate else 0) | (4 if as_linear else 0))
        if rotate:
            axis, angle = rotate
            for a in axis:
                self.value(-1, 1, a)
            self.value(-4, 4, angle)
        self.pick(body_index)

    def box(self, body_index, size, cells, offset, quadratic=False, rotate=None, as_linear=False,
            flags=0, fails=False):
        self.call(ADD_BUILDER_MESH, flags)
        self.below(0)
        for s in size:
            self.value(0.01, 1, s)
        for c in cells:
            self.below(c)
        if fails or 0 in cells or not all(s > 0 for s in size):  # refused: nothing more is read
            return
        self._mesh_tail(body_index, offset, quadratic, rotate, as_linear)

    # A builder that refuses its numbers (fails=True) reads nothing more.
    def cylinder(self, body_index, radius, height, segments, rings, layers, offset, quadratic=False,
                 rotate=None, fails=False):
        self.call(ADD_BUILDER_MESH)
        self.below(1)
        self.value(0.02, 0.3, radius)
        self.value(0.02, 0.3, height)
        self.below(segments)
        self.below(rings)
        self.below(layers)
        if not fails:
            self._mesh_tail(body_index, offset, quadratic, rotate, False)

    def cup(self, body_index, radius, height, wall, bottom, segments, layers, offset,
            quadratic=False, rotate=None, fails=False):
        self.call(ADD_BUILDER_MESH)
        self.below(2)
        self.value(0.03, 0.08, radius)
        self.value(0.06, 0.12, height)
        self.value(0.01, 0.03, wall)
        self.value(0.01, 0.03, bottom)
        self.below(segments)
        self.below(layers)
        if not fails:
            self._mesh_tail(body_index, offset, quadratic, rotate, False)

    def hammer(self, body_index, handle_length, handle_width, head_length, head_width, cell,
               offset, quadratic=False, rotate=None, fails=False):
        self.call(ADD_BUILDER_MESH)
        self.below(3)
        self.value(0.05, 0.3, handle_length)
        self.value(0.02, 0.1, handle_width)
        self.value(0.05, 0.2, head_length)
        self.value(0.02, 0.1, head_width)
        self.value(0.05, 0.2, cell)
        if not fails:
            self._mesh_tail(body_index, offset, quadratic, rotate, False)

    def raw_mesh(self, body_index, positions, tets, quadratic=False, flags=0):
        self.call(ADD_RAW_MESH, flags)
        self.byte(1 if quadratic else 0)
        self.below(len(positions))
        self.below(len(tets))
        for p in positions:
            for v in p:
                self.value(-0.5, 0.5, v)
        for t in tets:
            for i in t:
                self.below(i)
        self.pick(body_index)

    def triangle_mesh(self, body_index, positions, triangles):
        self.call(ADD_TRIANGLE_MESH)
        self.below(len(positions))
        self.below(len(triangles))
        for p in positions:
            for v in p:
                self.value(-1, 1, v)
        for t in triangles:
            for i in t:
                self.below(i)
        self.pick(body_index)

    def step(self, dt, flags=0):
        self.call(STEP, flags)
        if 1e-5 <= dt <= 0.02:
            self.byte(0)
            self.number(1e-5, 0.02, dt)
        else:
            self.byte(255)
            self.value(-1, 1, dt)

    def contacts(self, capacity, flags=0):
        self.call(QUERY_CONTACTS, flags)
        self.below(capacity)

    def positions(self, body_index, capacity, velocities=False, flags=0):
        self.call(GET_POSITIONS, flags)
        self.byte(1 if velocities else 0)
        self.below(capacity)
        self.pick(body_index)

    def fix(self, body_index, nodes, call=FIX_NODES):
        self.call(call)
        self.nodes(nodes)
        self.pick(body_index)

    def prescribe(self, body_index, nodes, velocity):
        self.call(PRESCRIBE)
        self.nodes(nodes)
        for v in velocity:
            self.value(-1, 1, v)
        self.pick(body_index)

    def forces(self, body_index, nodes, forces):
        self.call(SET_FORCES)
        self.nodes(nodes)
        for f in forces:
            for v in f:
                self.value(-100, 100, v)
        if not nodes:
            self.byte(0)  # an empty list of forces, not a clear
        self.pick(body_index)

    def clear_forces(self, body_index):
        self.call(SET_FORCES)
        self.nodes([])
        self.byte(1)
        self.pick(body_index)

    def destroy(self, body_index):
        self.call(BODY_DESTROY)
        self.pick(body_index)

    def shape(self, body_index, kind, center=(0, 0, 0), rotation=(1, 0, 0, 0),
              half_extents=(0.1, 0.1, 0.1), radius=0.1, half_length=0.1, points=(), cookie=False):
        self.call(ADD_SHAPE)
        self.below(kind)
        for v in center:
            self.value(-1, 1, v)
        for v in rotation:
            self.value(-1, 1, v)
        for v in half_extents:
            self.value(0, 0.5, v)
        self.value(0, 0.5, radius)
        self.value(0, 0.5, half_length)
        self.below(len(points))
        for p in points:
            for v in p:
                self.value(-0.3, 0.3, v)
        self.byte(255 if cookie else 0)
        self.pick(body_index)

    def gravity(self, g, flags=0):
        self.call(SET_GRAVITY_OR_STEP, flags)
        self.byte(1)
        for v in g:
            self.value(-20, 20, v)

    def time_step(self, h):
        self.call(SET_GRAVITY_OR_STEP)
        self.byte(0)
        if h == 0:
            self.byte(0)
        else:
            self.byte(255)
            self.value(0, 1e-3, h)

    def kinematic_velocity(self, body_index, linear, angular):
        self.call(SET_KINEMATIC_VELOCITY)
        for v in linear:
            self.value(-1, 1, v)
        for v in angular:
            self.value(-1, 1, v)
        self.pick(body_index)

    def save_load(self, how=0, where=0, value=0, flags=0):
        # how: 0 save and go on with the loaded world; 1 truncate at where; 2 change the byte at
        # where; 3 set the payload byte at where to value and make the checksum right
        self.call(SAVE_LOAD, flags)
        self.byte(how)
        self.u32(where)
        self.byte(value)

    def skin(self, body_index, vertices, triangles, flags=0):
        self.call(ADD_SKIN, flags)
        self.below(len(vertices))
        self.below(len(triangles))
        for p in vertices:
            for v in p:
                self.value(-0.5, 1, v)
        for t in triangles:
            for i in t:
                self.below(i)
        self.pick(body_index)

    # which: 0 vertices (doubles), 1 vertices (floats), 2 triangles, 3 sizes, 4 count
    def skin_read(self, body_index, which, skin=0, capacity=4, stride=3, normal_stride=3,
                  normals=True):
        self.call(SKIN_READ)
        self.pick(body_index)
        self.below(skin)
        self.below(capacity)
        self.below(stride)
        self.below(normal_stride)
        self.byte(1 if normals else 0)
        self.below(which)

    def _query(self, which, a, b, capacity, filt, max_distance=None, flags=0):
        self.call(RAY_OR_BOX, flags)
        for v in list(a) + list(b):
            self.value(-2, 2, v)
        if filt is None:
            self.byte(255)
        else:
            self.byte(0)
            self.u32(filt[0])
            self.u32(filt[1])
        self.below(capacity)
        self.below(which)
        if which != 2:
            self.value(0, 5, max_distance)

    def ray(self, origin, direction, max_distance, filt=None, flags=0):
        self._query(0, origin, direction, 0, filt, max_distance, flags)

    def ray_all(self, origin, direction, max_distance, capacity, filt=None, flags=0):
        self._query(1, origin, direction, capacity, filt, max_distance, flags)

    def overlap_box(self, lo, hi, capacity, filt=None, flags=0):
        self._query(2, lo, hi, capacity, filt, flags=flags)

    def overlap_sphere(self, center, radius, capacity, filt=None, flags=0):
        self._query(3, center, (0, 0, 0), capacity, filt, radius, flags)

    def overlap_capsule(self, a, b, radius, capacity, filt=None, flags=0):
        self._query(4, a, b, capacity, filt, radius, flags)

    def sphere_cast(self, origin, direction, max_distance, filt=None, flags=0):
        self._query(5, origin, direction, 0, filt, max_distance, flags)

    def release(self, body_index, nodes):
        self.fix(body_index, nodes, call=RELEASE_NODES)

    def world_create(self, flags=0, **kw):
        self.call(WORLD_CREATE, flags)
        self.world_def(**kw)

    def attach(self, body_index, nodes, target_index=None, frame=None, break_force=None,
               cookie=False, flags=0, points=None, spring=None, nodes_too=False):
        # points: held by position (up to 4); spring: (stiffness, damping); nodes_too: both
        # nodes and points (refused)
        self.call(ATTACHMENT_CREATE, flags)
        self.pick(body_index)
        self.byte((1 if target_index is not None else 0) | (2 if frame is not None else 0)
                  | (4 if break_force is not None else 0) | (8 if cookie else 0)
                  | (16 if points is not None else 0) | (32 if spring is not None else 0)
                  | (64 if nodes_too else 0))
        if target_index is not None:
            self.pick(target_index)
        self.nodes(nodes)
        if frame is not None:
            for v in frame:
                self.value(-1, 1, v)
        if break_force is not None:
            self.value(0, 50, break_force)
        if points is not None:
            self.below(len(points))
            for p in points:
                for v in p:
                    self.value(-0.2, 0.3, v)
        if spring is not None:
            self.value(0, 1e4, spring[0])
            self.value(0, 20, spring[1])

    def _attachment_op(self, attachment_index, which, made_up=None):
        self.call(ATTACHMENT_OP)
        if made_up is not None:
            self.made_up(*made_up)
        else:
            self.pick(attachment_index)
        self.below(which)

    def attachment_destroy(self, index, made_up=None):
        self._attachment_op(index, 0, made_up)

    def attachment_frame(self, index, frame):
        self._attachment_op(index, 1)
        for v in frame:
            self.value(-1, 1, v)

    def attachment_force(self, index, made_up=None):
        self._attachment_op(index, 2, made_up)

    def attachment_valid(self, index, made_up=None):
        self._attachment_op(index, 3, made_up)

    def events(self, capacity, flags=0):
        self.call(GET_EVENTS, flags)
        self.below(capacity)

    def wake(self, body_index, made_up=None):
        self.call(WAKE)
        if made_up is not None:
            self.made_up(*made_up)
        else:
            self.pick(body_index)
        self.byte(0)

    def is_awake(self, body_index):
        self.call(WAKE)
        self.pick(body_index)
        self.byte(1)

    def set_velocities(self, body_index, velocities, count=None, flags=0):
        # velocities: one per node of the body (the harness asks the body's count), or with
        # count given, that many (a wrong count)
        self.call(SET_VELOCITIES, flags)
        self.pick(body_index)
        self.byte(0 if count is None else 1)
        if count is not None:
            self.below(count)
        for v in velocities:
            for x in v:
                self.value(-2, 2, x)

    def set_positions(self, body_index, positions, count=None):
        # SET_VELOCITIES with flag 2: a teleport, variant 0; positions one per node, or count
        # given (a wrong count)
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2 | (0 if count is None else 1))
        self.below(0)
        if count is not None:
            self.below(count)
        for v in positions:
            for x in v:
                self.value(-1, 1, x)

    def set_transform(self, body_index, t, q=None):
        # variant 1: t (3 numbers) and a quaternion (4), or a zero quaternion when q is None
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2 | (1 if q is None else 0))
        self.below(1)
        for x in t:
            self.value(-2, 2, x)
        for x in (q or ()):
            self.value(-1, 1, x)

    def impulse(self, body_index, point, impulse):
        # variant 3: lfem_body_apply_impulse
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2)
        self.below(3)
        for x in point:
            self.value(-1, 1, x)
        for x in impulse:
            self.value(-5, 5, x)

    def setting(self, body_index, which, value=0.0, category=1, mask=0xFFFFFFFF, poisson=None, flag=0):
        # variant 4: 0 friction, 1 damping (value) or with poisson given the material
        # (E = 1e3 + 1e6 |value|), 2 filter (category, mask), 3 user data, 4 sleep allowed
        # (flag, any 32 bits read as an int), 5 the type (flag: 0 deformable .. 3 rigid, 4 none)
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2 | (1 if poisson is not None else 0))
        self.below(4)
        self.value(-1, 10, value)
        self.below(which)
        if poisson is not None:
            self.value(-1.2, 0.6, poisson)
        if which == 2:
            self.u32(category)
            self.u32(mask)
        if which in (4, 5):
            self.u32(flag & 0xFFFFFFFF)

    def force(self, body_index, point, force):
        # variant 6: lfem_body_apply_force (for the next call)
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2)
        self.below(6)
        for x in point:
            self.value(-1, 1, x)
        for x in force:
            self.value(-50, 50, x)

    def user_id(self, body_index, high, low):
        # variant 6 with flag 1: lfem_body_set_user_id and its getter
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(3)
        self.below(6)
        self.u32(high)
        self.u32(low)

    def remove_skin(self, body_index, skin):
        # variant 5
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2)
        self.below(5)
        self.below(skin)

    def read_pose(self, body_index):
        # variant 2: lfem_body_get_transform and lfem_body_get_center_of_mass
        self.call(SET_VELOCITIES)
        self.pick(body_index)
        self.byte(2)
        self.below(2)

    # which: 0 counts (capacity % 3 picks node/tet/nodes-per-tet), 1 user data, 2 mass,
    # 3 inversion, 4 momentum, 5/6 boundary triangles/faces, 7 von Mises, 8 rotation,
    # 9 nodes in box, 10 is_valid, 11 positions of exact capacity
    def getter(self, body_index, which, capacity=0, faces=False, box=((-1, -1, -1), (1, 1, 1)),
               flags=0, made_up=None):
        self.call(BODY_GETTER, flags)
        if made_up is not None:
            self.made_up(*made_up)
        else:
            self.pick(body_index)
        self.below(capacity)
        self.below(which)
        if which in (5, 6):
            self.below(1 if faces else 0)
        if which == 9:
            for v in box[0] + box[1]:
                self.value(-1, 1, v)

    # which: 0 stable step, 1 stats, 2 profile, 3 reset profile, 4 warning (kind), 5 clear
    def world_getter(self, which, kind=0, flags=0):
        self.call(WORLD_GETTER, flags)
        self.below(which)
        if which == 4:
            self.below(kind)

    def misc(self, status):
        self.call(MISC)
        self.u32(status)

    def vtk(self, frames, missing_folder=False, flags=0):
        self.call(VTK, flags)
        self.byte(1 if missing_folder else 0)
        self.below(frames)


def write(folder, name, program):
    with open(os.path.join(HERE, folder, 'api', name), 'wb') as f:
        f.write(program.b)


def seed(name, program):
    write('corpus', name, program)


def floor_and_block(model=PAPER, quadratic=False, block_z=0.005, **world):
    """A static floor (body 0) and a soft block of 27 nodes (body 1) on it."""
    p = Program()
    p.world_def(**world)
    p.body(STATIC)
    p.box(0, (0.6, 0.6, 0.1), (2, 2, 1), (-0.3, -0.3, -0.1))
    p.body(DEFORMABLE, model=model)
    p.box(1, (0.1, 0.1, 0.1), (2, 2, 2), (-0.05, -0.05, block_z), quadratic=quadratic)
    return p


# Teleports: the block read, moved up and turned, read again, stepped (its pair with the floor
# ends), its nodes put back one by one (a stretched copy), a wrong count and a zero quaternion
# refused, the static floor refused.
p = floor_and_block(model=COROTATIONAL, block_z=0.0)
p.step(0.01)
p.read_pose(1)
p.set_transform(1, (0.1, 0, 0.3), (0.5, 0.5, 0.5, 0.5))
p.read_pose(1)
p.step(0.01)
p.events(3)
p.set_positions(1, [(0.01 * i, 0.02 * (i % 3), 0.2 + 0.01 * (i % 5)) for i in range(27)])
p.set_positions(1, [(0, 0, 0)] * 3, count=3)
p.set_transform(1, (0, 0, 0))
p.set_transform(0, (0, 0, 1), (1, 0, 0, 0))
p.step(0.01)
p.events(3)
p.impulse(1, (0.05, 0.05, 0.25), (0.5, 0, 1))
p.impulse(1, (0.9, 0.9, 0.9), (0.5, 0, 1))   # refused: far from the block
p.impulse(0, (0, 0, -0.05), (1, 0, 0))       # refused: the floor is static
p.step(0.01)
p.setting(1, 0, 0.0)                          # friction 0
p.setting(1, 1, 2.0)                          # damping 2 / s
p.setting(1, 1, -1.0)                         # refused: negative damping
p.setting(1, 1, 2.0, poisson=0.25)            # the material: E = 2.001e6, nu 0.25
p.setting(1, 1, 2.0, poisson=0.5)             # refused: nu 0.5
p.setting(1, 2, category=4, mask=0xFFFFFFFE)  # a filter change
p.setting(1, 3)                               # user data set and set back
p.setting(1, 4, flag=0)                       # sleep not allowed
p.setting(1, 4, flag=2)                       # refused: 2 is no flag
p.remove_skin(1, 0)                           # refused: no skin
p.force(1, (0.05, 0.05, 0.25), (0, 20.0, 0))  # a force for the next call, inside the block
p.force(1, (0.05, 0.05, 0.9), (0, 20.0, 0))   # refused: far from the block
p.force(0, (0.05, 0.05, 0.05), (0, 20.0, 0))  # refused: the floor is static
p.user_id(1, 0xFEDCBA98, 0x76543210)          # a user id
p.setting(1, 5, flag=3)                       # refused: a deformable body keeps its type
p.setting(0, 5, flag=2)                       # the static floor made kinematic
p.setting(0, 5, flag=1)                       # and static again
p.step(0.01)
seed('teleports', p)

# A soft block dropped on a static floor, stepped and queried, its events read.
p = floor_and_block(model=NEO_HOOKEAN)
for _ in range(6):
    p.step(0.005)
p.contacts(10)
p.contacts(0)
p.contacts(200)
p.events(0)
p.events(3)
seed('block_on_floor', p)

# Two soft bodies of different models, a checkpoint in between, the loaded world stepped.
p = floor_and_block(model=COROTATIONAL, block_z=0.0)
p.body(DEFORMABLE, model=PAPER)
p.box(2, (0.08, 0.08, 0.08), (1, 1, 1), (-0.02, -0.04, 0.12), quadratic=True)
p.step(0.01)
p.save_load()
p.step(0.01)
p.contacts(3)
p.getter(2, 1)                # user data: NULL after loading
seed('two_bodies_checkpoint', p)

# Checkpoints that must be refused (truncated, a byte changed) and one whose payload is changed
# with its checksum made right (the loader's checks of the content stand alone).
p = floor_and_block(model=LINEAR)
p.step(0.005)
p.save_load(how=1, where=100)
p.save_load(how=2, where=7)
p.save_load(how=2, where=3000)
p.save_load(how=3, where=24, value=0xFF)
p.save_load(how=3, where=200, value=0x7F)
p.save_load(how=3, where=1200, value=0x80)
p.step(0.005)
seed('corrupted_checkpoints', p)

# A rigid box and a sphere shape, node constraints and a destroy.
p = Program()
p.world_def()
p.body(STATIC)
p.shape(0, SPHERE, center=(0, 0, -0.5), half_extents=(0.1, 0.1, 0.1), radius=0.5)
p.body(RIGID)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (-0.05, -0.05, 0.0), quadratic=True)
p.step(0.005)
p.fix(1, [0, 1])              # refused: a rigid body's nodes
p.step(0.005)
p.destroy(1)
p.step(0.005)
p.getter(1, 0)                # a stale handle
seed('rigid_shape_destroy', p)

# Shapes of every kind on a static and a kinematic body, one refused (its def not made by
# lfem_shape_def_default), a deformable block falling among them.
p = Program()
p.world_def()
p.body(STATIC)
p.shape(0, PLANE, center=(0, 0, -0.05))
p.shape(0, BOX, center=(0.2, 0, 0), half_extents=(0.05, 0.05, 0.05))
p.shape(0, CAPSULE, center=(-0.2, 0, 0), radius=0.05, half_length=0.1)
p.shape(0, HULL, center=(0, 0.2, 0),
        points=[(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0), (0, 0, 0.1), (0.1, 0.1, 0.1)])
p.shape(0, BOX, cookie=True)
p.body(KINEMATIC)
p.shape(1, SPHERE, center=(0, -0.2, 0.05), radius=0.05)
p.kinematic_velocity(1, (0, 0.5, 0), (0, 0, 1))
p.body(DEFORMABLE, model=COROTATIONAL)
p.box(2, (0.1, 0.1, 0.1), (1, 1, 1), (-0.05, -0.05, 0.0))
p.step(0.01)
p.step(0.01)
p.contacts(40)
p.getter(1, 8)                # the kinematic body's rotation
seed('shapes', p)

# A skin in a soft block, read back every way, and rays and boxes across it and a floor.
p = floor_and_block(model=COROTATIONAL, block_z=0.0)
p.skin(1, [(-0.02, -0.02, 0.02), (0.02, -0.02, 0.02), (-0.02, 0.02, 0.02), (0.02, 0.02, 0.08)],
       [(0, 1, 2), (1, 3, 2)])
p.skin(1, [(0.0, 0.0, 0.05), (0.01, 0.0, 0.05), (0.0, 0.01, 0.05)], [(0, 1, 2)])
p.skin(1, [(0.0, 0.0, 0.9)], [(0, 0, 0)])        # refused: a repeated vertex
p.step(0.005)
p.skin_read(1, 0, capacity=4)
p.skin_read(1, 0, capacity=3)                    # too small for skin 0
p.skin_read(1, 1, capacity=16, stride=6, normal_stride=6)
p.skin_read(1, 1, skin=1, capacity=16, stride=3, normals=False)
p.skin_read(1, 2, capacity=2)
p.skin_read(1, 2, skin=2)                        # no such skin
p.skin_read(1, 3, skin=1)
p.skin_read(1, 4)
p.ray_all((0.001, 0.002, 1.0), (0.0, 0.0, -1.0), 4.0, capacity=6)
p.ray_all((0.001, 0.002, 1.0), (0.0, 0.0, -1.0), 4.0, capacity=1)   # too small
p.ray((0.001, 0.002, 1.0), (0.0, 0.0, -1.0), 4.0)
p.ray((0.5, 0.5, 1.0), (0.0, 0.0, 1.0), 4.0)      # a miss
p.overlap_box((-0.1, -0.1, -0.1), (0.1, 0.1, 0.1), capacity=4)
p.overlap_box((-0.1, -0.1, -0.1), (0.1, 0.1, 0.1), capacity=1)     # too small
p.overlap_box((-0.1, -0.1, -0.1), (0.1, 0.1, 0.1), capacity=4, filt=(1, 0))
p.overlap_sphere((0.0, 0.0, 0.15), 0.1, capacity=4)
p.overlap_sphere((0.0, 0.0, 0.15), 0.1, capacity=0)                  # the count alone
p.overlap_capsule((-0.5, 0.0, 0.15), (0.5, 0.0, 0.2), 0.05, capacity=4)
p.overlap_capsule((-0.5, 0.0, 0.15), (0.5, 0.0, 0.2), 0.05, capacity=4, flags=null_arg(1))
p.sphere_cast((0.0, 0.0, 1.0), (0.0, 0.0, -1.0), 2.0)
p.sphere_cast((0.0, 0.0, 1.0), (0.0, 0.0, -1.0), 0.1)                # short of everything
p.world_getter(2)             # the profile counts the queries
seed('skin_and_rays', p)

# A block held at two corners by a frame the caller moves, its force read; the attachment then
# destroyed, a destroyed and a made-up one used.
p = Program()
p.world_def(gravity=(0, 0, -9.81))
p.body(DEFORMABLE, model=COROTATIONAL)
p.box(0, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0))
p.attach(0, [0, 1], frame=(0, 0, 0, 1, 0, 0, 0))
p.step(0.005)
p.attachment_frame(0, (0.01, 0, 0.02, 1, 0, 0, 0.1))
p.attachment_frame(0, (0, 0, 0, 0, 0, 0, 0))       # refused: a zero quaternion
p.step(0.005)
p.attachment_force(0)
p.attachment_valid(0)
p.attachment_destroy(0)
p.attachment_destroy(0)       # stale
p.attachment_force(0)
p.attachment_frame(0, (0, 0, 0, 1, 0, 0, 0))
p.attachment_valid(0, made_up=(3, 7))
p.attach(0, [0, 99])          # refused: a node out of range
p.attach(0, [])               # refused: no nodes
p.attach(0, [2], cookie=True)  # refused: not made by lfem_attachment_def_default
p.step(0.005)
seed('attach_to_frame', p)

# A soft block hanging from a rigid body and from a static one; destroying the rigid body
# destroys its attachment, the other stays.
p = Program()
p.world_def()
p.body(RIGID)
p.box(0, (0.1, 0.1, 0.05), (1, 1, 1), (0, 0, 0.1))
p.body(DEFORMABLE, model=NEO_HOOKEAN)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0))
p.body(STATIC)
p.box(2, (0.05, 0.05, 0.05), (1, 1, 1), (0.2, 0, 0.1))
p.attach(1, [4, 5, 6, 7], target_index=0)
p.attach(1, [1], target_index=2)
p.attach(1, [0], target_index=1)  # refused: the body as its own target
p.step(0.005)
p.attachment_force(0)
p.destroy(0)
p.attachment_valid(0)
p.step(0.005)
p.attachment_force(1)
seed('attach_to_bodies', p)

# Points by position: a soft block held at two points on springs to the caller's frame, and by
# a point to another soft block below it (its material point there); refused: nodes and points
# together, a point far from the block, a damper without a spring.
p = Program()
p.world_def()
p.body(DEFORMABLE, model=COROTATIONAL)
p.box(0, (0.1, 0.1, 0.1), (2, 2, 2), (0, 0, 0.1))
p.body(DEFORMABLE, model=PAPER)
p.box(1, (0.1, 0.1, 0.1), (2, 2, 2), (0, 0, -0.005))
p.attach(0, [], points=[(0.02, 0.05, 0.19), (0.08, 0.05, 0.19)], spring=(500.0, 2.0))
p.attach(1, [], target_index=0, points=[(0.05, 0.05, 0.1)])
p.attach(1, [0], points=[(0.05, 0.05, 0.05)], nodes_too=True)
p.attach(1, [], points=[(0.05, 0.05, 0.29)])
p.attach(1, [], points=[(0.05, 0.05, 0.05)], spring=(0.0, 3.0))
p.step(0.005)
p.attachment_force(0)
p.attachment_force(1)
p.save_load()
p.step(0.005)
seed('attach_points', p)

# An attachment with a small break force breaks under the block's weight: its event, read with
# buffers too small, then large enough.
p = Program()
p.world_def()
p.body(STATIC)
p.box(0, (0.1, 0.1, 0.05), (1, 1, 1), (0, 0, 0.1))
p.body(DEFORMABLE, model=COROTATIONAL, density=5000)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, -0.0))
p.attach(1, [4, 5, 6, 7], target_index=0, break_force=0.5)
p.attach(1, [0, 1], frame=(0, 0, 0, 1, 0, 0, 0), break_force=30)
for _ in range(3):
    p.step(0.01)
    p.events(0)
    p.events(1)
    p.events(3)
p.attachment_valid(0)
p.attachment_valid(1)
seed('attachment_breaks', p)

# Sleep: without gravity a block at rest falls asleep after sleep_time; read its state and
# events, wake it, set its velocities (wakes it), let it fall asleep again; a body that may not
# sleep stays awake.
p = Program()
p.world_def(sleep=True, sleep_velocity=0.05, sleep_time=0.01, gravity=(0, 0, 0))
p.body(DEFORMABLE, model=LINEAR)
p.box(0, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0))
p.body(DEFORMABLE, sleep=False)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0.3, 0, 0))
for _ in range(3):
    p.step(0.01)
    p.events(3)
p.is_awake(0)
p.is_awake(1)
p.wake(0)
p.step(0.01)
p.events(3)
p.step(0.01)
p.set_velocities(0, [(0.1, 0, 0)] * 8)
p.is_awake(0)
p.set_velocities(0, [(0.1, 0, 0)] * 3, count=3)          # refused: the body has 8 nodes
p.set_velocities(0, [(float('nan'), 0, 0)] + [(0, 0, 0)] * 7)  # refused: a NaN
p.step(0.01)
p.events(0)
p.wake(0, made_up=(5, 9))
p.events(3)
seed('sleep_and_wake', p)

# Sleep in a pile on a floor, on two threads, with the bodies' default sleep flag.
p = floor_and_block(model=COROTATIONAL, block_z=0.0, threads=2, sleep=True, sleep_velocity=0.5,
                    sleep_time=0.02)
for _ in range(5):
    p.step(0.01)
    p.events(3)
p.is_awake(1)
p.gravity((0, 0, -5))         # wakes the pile
p.events(3)
p.step(0.01)
p.events(3)
seed('sleep_pile_threads', p)

# Mass scaling: the added mass and the mass of a small stiff block, and the stable step.
p = Program()
p.world_def(substeps=64, mass_scaling=1e-4)
p.body(STATIC)
p.box(0, (0.6, 0.6, 0.1), (1, 1, 1), (-0.3, -0.3, -0.1))
p.body(DEFORMABLE, young=1e8, model=LINEAR)
p.box(1, (0.02, 0.02, 0.02), (1, 1, 1), (0, 0, 0.001))
p.getter(1, 2)
p.getter(0, 2)
p.world_getter(0)
p.step(0.002)
p.world_getter(1)
seed('mass_scaling', p)

# Self-contact: a long soft bar on a post folds over it; a rigid body asking for self-contact is
# refused.
p = Program()
p.world_def()
p.body(STATIC)
p.box(0, (0.04, 0.04, 0.1), (1, 1, 1), (-0.02, -0.02, -0.1))
p.body(DEFORMABLE, model=COROTATIONAL, young=2e4, self_contact=True)
p.box(1, (0.4, 0.04, 0.02), (3, 1, 1), (-0.2, -0.02, 0.0))
p.body(RIGID, self_contact=True)
for _ in range(4):
    p.step(0.01)
p.contacts(60)
p.world_getter(4, kind=2)
seed('self_contact', p)

# Composite 10-node tets on a floor: boundary faces of 6 nodes, von Mises stress, inversion.
p = Program()
p.world_def()
p.body(STATIC)
p.box(0, (0.6, 0.6, 0.1), (2, 2, 1), (-0.3, -0.3, -0.1))
p.body(DEFORMABLE, model=NEO_HOOKEAN, composite=True)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (-0.05, -0.05, 0.0), quadratic=True)
p.step(0.005)
p.step(0.005)
p.getter(1, 5, faces=True)
p.getter(1, 5, faces=False)
p.getter(1, 5, capacity=151, faces=True)     # too small
p.getter(1, 7)
p.getter(1, 7, capacity=152)                 # too small
p.getter(1, 3)
p.getter(1, 0, capacity=2)                   # nodes per tet: 10
p.getter(1, 0, capacity=1)                   # tet count
seed('composite_quadratic', p)

# Category and mask bits: a block that does not collide with the floor falls through it, one
# that does rests; rays and boxes with filters.
p = Program()
p.world_def()
p.body(STATIC, category=2)
p.box(0, (0.6, 0.6, 0.1), (1, 1, 1), (-0.3, -0.3, -0.1))
p.body(DEFORMABLE, mask=~2 & 0xFFFFFFFF)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (-0.2, -0.05, 0.0))
p.body(DEFORMABLE, category=4)
p.box(2, (0.1, 0.1, 0.1), (1, 1, 1), (0.1, -0.05, 0.0))
for _ in range(4):
    p.step(0.01)
p.contacts(30)
p.ray_all((-0.15, 0, 1), (0, 0, -1), 3, capacity=6, filt=(1, 0xFFFFFFFF))
p.ray_all((-0.15, 0, 1), (0, 0, -1), 3, capacity=6, filt=(4, 2))
p.overlap_box((-1, -1, -1), (1, 1, 1), capacity=3, filt=(0xFFFFFFFF, 4))
seed('categories', p)

# Three threads: three blocks on a floor.
p = floor_and_block(model=COROTATIONAL, threads=3, block_z=0.0)
p.body(DEFORMABLE, model=NEO_HOOKEAN)
p.box(2, (0.1, 0.1, 0.1), (1, 1, 1), (0.12, -0.05, 0.0))
p.body(DEFORMABLE, model=LINEAR)
p.box(3, (0.1, 0.1, 0.1), (1, 1, 2), (-0.2, -0.05, 0.0), quadratic=True)
for _ in range(3):
    p.step(0.005)
p.contacts(100)
p.world_getter(2)
p.world_getter(3)
p.world_getter(2)
seed('three_threads', p)

# World definitions: some refused (0 and 65 threads, a def not made by lfem_world_def_default,
# NaN gravity, a sleep flag of 2), then a world of two threads with a fixed time step replaces
# the first; the first world's handles are foreign in it.
p = floor_and_block()
p.world_create(raw_threads=0)
p.world_create(raw_threads=65)
p.world_create(cookie=3)
p.world_create(gravity=(0, float('nan'), 0))
p.world_create(raw_threads=2, sleep=True)  # raw sleep flag 1
p.world_create(threads=2, time_step=5e-5, tolerance=1e-4, mass_scaling=0.0)
p.world_create(threads=2, flags=null_arg(0))  # NULL def
p.getter(1, 0)
p.body(DEFORMABLE)
p.box(2, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0))
p.step(0.001)
p.step(0.01)                  # a fixed step above the stable limit: refused
p.time_step(0)
p.step(0.01)
seed('world_create', p)

# Every mesh builder, rotated and quadratic, into bodies; refused builders.
p = Program()
p.world_def(gravity=(0, 0, 0))
p.body(DEFORMABLE, model=COROTATIONAL)
p.cylinder(0, 0.05, 0.1, 5, 1, 1, (0, 0, 0))
p.body(DEFORMABLE, model=NEO_HOOKEAN)
p.cup(1, 0.08, 0.1, 0.02, 0.02, 4, 1, (0.3, 0, 0), rotate=((0, 0, 1), 0.5))
p.body(RIGID)
p.hammer(2, 0.2, 0.04, 0.12, 0.05, 0.1, (-0.3, 0, 0), quadratic=True)
p.body(KINEMATIC)
p.cylinder(3, 0.05, 0.05, 3, 1, 1, (0, 0.3, 0), quadratic=True, rotate=((1, 0, 0), 1.0))
p.cylinder(3, 0.05, 0.05, 2, 1, 1, (0, 0.3, 0), fails=True)  # refused: 2 segments
p.cup(3, 0.05, 0.08, -0.01, 0.01, 4, 1, (0, 0, 0), fails=True)  # refused: a negative wall
p.hammer(3, float('nan'), 0.04, 0.1, 0.05, 0.1, (0, 0, 0), fails=True)
p.box(3, (0.1, 0.1, 0.1), (1, 0, 1), (0, 0, 0))          # refused: 0 cells
p.box(0, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0.3), quadratic=True, as_linear=True)  # refused
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0.5, 0, 0.3), quadratic=True)  # mixes 4- and 10-node
p.step(0.002)
p.getter(2, 0, capacity=2)
seed('builders', p)

# Raw meshes: one good tet, and refused ones (inverted, an index out of range, unused nodes,
# a repeated node, NaN), a raw 10-node tet, a triangle mesh on a static body.
p = Program()
p.world_def()
p.body(DEFORMABLE)
tet = [(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0), (0, 0, 0.1)]
p.raw_mesh(0, tet, [(0, 1, 2, 3)])
p.raw_mesh(0, tet, [(0, 2, 1, 3)])
p.raw_mesh(0, tet, [(0, 1, 2, 13)])
p.raw_mesh(0, tet + [(0.2, 0.2, 0.2)], [(0, 1, 2, 3)])
p.raw_mesh(0, tet, [(0, 1, 1, 3)])
p.raw_mesh(0, [(float('nan'), 0, 0)] + tet[1:], [(0, 1, 2, 3)])
p.body(DEFORMABLE)
mid = [(0.05, 0, 0), (0.05, 0.05, 0), (0, 0.05, 0), (0, 0, 0.05), (0.05, 0, 0.05), (0, 0.05, 0.05)]
p.raw_mesh(1, tet + mid, [tuple(range(10))], quadratic=True)
p.raw_mesh(1, tet + mid, [(0, 1, 2, 3, 4, 5, 6, 7, 8, 8)], quadratic=True)
p.body(STATIC)
p.triangle_mesh(2, [(-1, -1, -0.01), (1, -1, -0.01), (1, 1, -0.01), (-1, 1, -0.01)],
                [(0, 1, 2), (0, 2, 3)])
p.triangle_mesh(2, [(-1, -1, -0.5), (1, -1, -0.5), (1, 1, -0.5)], [(0, 1, 2)])  # refused: second
p.body(DEFORMABLE)
p.triangle_mesh(3, [(-1, -1, 0), (1, -1, 0), (1, 1, 0)], [(0, 1, 2)])  # refused: deformable
p.step(0.005)
p.step(0.005)
p.getter(0, 0)
p.getter(1, 5, faces=True)
p.getter(2, 5)
seed('raw_meshes', p)

# Node constraints and forces: fix, prescribe, release, set and clear forces; refused lists.
p = floor_and_block(model=COROTATIONAL, block_z=0.0)
p.fix(1, [0, 1, 2])
p.fix(1, [0, 0])              # refused: repeated
p.fix(1, [30])                # refused: out of range
p.prescribe(1, [3, 4], (0, 0, 0.1))
p.forces(1, [5, 6], [(0, 0, 10), (1, 0, 0)])
p.forces(1, [5], [(float('inf'), 0, 0)])   # refused: not finite
p.step(0.005)
p.release(1, [0, 3])
p.release(1, [39])            # refused
p.clear_forces(1)
p.clear_forces(0)             # a static body: no forces to clear
p.step(0.005)
p.positions(1, 27, velocities=True)
p.getter(1, 4)
p.getter(1, 9, capacity=30, box=((-1, -1, -1), (1, 1, 0.01)))
p.getter(1, 9, capacity=2, box=((-1, -1, -1), (1, 1, 1)))       # too small
p.getter(1, 9, capacity=0, box=((-1, -1, -1), (1, 1, 1)))
seed('constraints_and_forces', p)

# Every getter of a body and of the world after a few steps, and the warnings.
p = floor_and_block(model=NEO_HOOKEAN, block_z=0.0)
p.step(0.005)
p.step(0.005)
for which in range(12):
    p.getter(1, which)
p.getter(0, 2)
p.getter(0, 5, faces=True)
p.getter(1, 11, capacity=0)
for which in range(6):
    p.world_getter(which, kind=1)
p.world_getter(4, kind=5)     # refused: no such kind
p.world_getter(4, kind=3)
p.positions(1, 26)            # too small
p.positions(1, 0)
p.positions(0, 27)
seed('getters', p)

# Arguments that must be refused: a NULL world, NULL pointers, NaN, stale and made-up handles,
# too-small buffers.
p = floor_and_block()
p.step(0.005)
p.step(0.005, flags=NULL_WORLD)
p.step(float('nan'))
p.step(-0.01)
p.step(0.0)
p.contacts(5, flags=null_arg(1))     # NULL count
p.contacts(5, flags=null_arg(0))     # NULL out with a capacity
p.events(2, flags=null_arg(0))
p.events(2, flags=NULL_WORLD)
p.positions(1, 27, flags=null_arg(0))
p.gravity((0, 0, float('nan')))
p.gravity((0, 0, -9.81), flags=null_arg(0))
p.time_step(-1.0)
p.body(DEFORMABLE, flags=null_arg(0))
p.body(DEFORMABLE, flags=null_arg(1))
p.body(DEFORMABLE, cookie=1)
p.body(RIGID, raw_flags=(2, 0, 1))
p.body(DEFORMABLE, density=float('nan'))
p.body(DEFORMABLE, flags=NULL_WORLD)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0), flags=null_arg(2), fails=True)  # NULL mesh out
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0), flags=null_arg(5))  # NULL positions
p.box(1, (0.1, float('nan'), 0.1), (1, 1, 1), (0, 0, 0))
p.destroy(0)
p.destroy(0)                  # stale
p.getter(0, 2)                # stale
p.getter(0, 0, made_up=(0, 0))
p.getter(0, 0, made_up=(6, 1))
p.set_velocities(0, [])
p.wake(0)
p.is_awake(0)
p.ray((0, 0, 1), (0, 0, 0), 3)                # a zero direction
p.ray((0, 0, 1), (0, 0, -1), float('nan'))
p.ray((0, 0, 1), (0, 0, -1), 3, flags=null_arg(3))
p.ray_all((0, 0, 1), (0, 0, -1), 3, capacity=0)
p.overlap_box((0.1, 0, 0), (-0.1, 0, 0), capacity=2)    # lo > hi
p.overlap_box((0, 0, 0), (0.1, 0.1, 0.1), capacity=2, flags=null_arg(0))
p.skin(1, [(0, 0, 0.05)] * 3, [(0, 1, 2)], flags=null_arg(0))
p.skin(1, [(0.5, 0.5, 0.9)] * 3, [(0, 1, 2)])   # refused: too far from the block
p.skin(0, [(0, 0, 0.05)] * 3, [(0, 1, 2)])      # stale
p.save_load(flags=null_arg(0))
p.save_load(flags=NULL_WORLD)
p.vtk(1, flags=null_arg(0))
p.world_getter(0, flags=null_arg(0))
p.world_getter(1, flags=NULL_WORLD)
p.attach(1, [0], flags=null_arg(1))
p.contacts(3)
seed('invalid_arguments', p)

# VTK frames into a folder, and into one that does not exist; status strings and versions.
p = floor_and_block(quadratic=True, block_z=0.0)
p.step(0.005)
p.vtk(2)
p.vtk(1, missing_folder=True)
p.vtk(0)
for status in (0, 1, 4, 9, 10, 11):
    p.misc(status)
seed('vtk_and_misc', p)

# Kinematic bodies: a moving box pushes a soft block, and its rotation and momentum are read.
p = Program()
p.world_def(gravity=(0, 0, 0))
p.body(KINEMATIC, velocity=(0.5, 0, 0))
p.box(0, (0.05, 0.1, 0.1), (1, 1, 1), (-0.06, -0.05, 0.0))
p.body(DEFORMABLE, model=COROTATIONAL)
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (0.0, -0.05, 0.0))
p.kinematic_velocity(0, (0.5, 0, 0), (0, 0, 0.5))
p.kinematic_velocity(1, (0.5, 0, 0), (0, 0, 0))  # refused: not kinematic
for _ in range(3):
    p.step(0.01)
p.getter(0, 8)
p.getter(1, 4)
p.events(3)
seed('kinematic_push', p)

# Regression inputs: bugs the fuzzer once found, as their call sequences.

# Destroying a body left its contacts, and a contact query then read the destroyed body's nodes
# (fixed in 6553bc2): a floor and a falling block in contact, the floor destroyed, the contacts
# queried.
p = Program()
p.world_def()
p.body(STATIC)
p.box(0, (0.6, 0.6, 0.1), (2, 2, 1), (-0.3, -0.3, -0.1))
p.body(DEFORMABLE, model=NEO_HOOKEAN, velocity=(0, 0, -2.1875))
p.box(1, (0.1, 0.1, 0.1), (2, 2, 2), (-0.05, -0.05, 0.005))
p.step(0.005)
p.step(0.005)
p.step(0.0058110566699111493)
p.destroy(0)
p.contacts(10)
p.contacts(0)
p.events(3)
write('regressions', 'query_contacts_after_body_destroyed', p)

# A step safety factor so small (a denormal, 1.9e-314) that a step needs an infinite number of
# sub-steps, which overflowed when converted to an integer for the refusal message (fixed in
# 95b111d): refused with a message.
p = Program()
p.world_def(safety=1.9188258789309249e-314)
p.body(DEFORMABLE, young=1386.7045490505884, poisson=-0.19804687511596059)
p.box(0, (0.1, 0.1, 0.1), (1, 1, 1), (-0.05, -0.05, 0.0))
p.step(0.0049999999985797334)
p.fix(0, [0])
p.step(0.005)
write('regressions', 'step_substep_count_overflow', p)

# Sleep allowed set from a huge number: the harness converted a double of -2.2e168 to int (UB,
# found by the fuzzer in CI; the harness now reads the flag as 32 bits): every int but 0 and 1,
# here INT_MIN and -1, is refused with a message.
p = floor_and_block()
p.setting(1, 4, flag=0x80000000)
p.setting(1, 4, flag=0xFFFFFFFF)
p.step(0.005)
write('regressions', 'sleep_allowed_from_any_int', p)
