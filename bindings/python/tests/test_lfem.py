"""Tests of the Python bindings: struct layouts against the C sizes, real simulations against
closed forms, error handling, handle invalidation, buffers, contacts.

Run with `python3 -m pytest bindings/python/tests` or `python3 -m unittest discover -s
bindings/python/tests` (the system python3 with Debian's python3-numpy / python3-pytest).
"""
import ctypes
import math
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
import lfem  # noqa: E402

G = 9.81
SIZE = (0.3, 0.2, 0.1)
DENSITY = 400.0


def add_block(world, model):
    """A 0.3 x 0.2 x 0.1 m block of 3 x 2 x 1 cells lifted to z = 2 m."""
    mesh = lfem.Mesh.box(SIZE, (3, 2, 1))
    mesh.translate((0.0, 0.0, 2.0))
    d = lfem.BodyDef.default()
    d.model = model
    d.young_modulus = 2e5
    d.density = DENSITY
    body = world.create_body(d)
    world.add_mesh(body, mesh)
    mesh.close()
    return body


class Layout(unittest.TestCase):
    # The numbers bindings/abi_layout.c asserts in C (64-bit targets).

    def check(self, struct, size, offsets):
        self.assertEqual(ctypes.sizeof(struct), size, struct.__name__)
        for field, offset in offsets.items():
            self.assertEqual(getattr(struct, field).offset, offset, struct.__name__ + "." + field)

    def test_struct_sizes_match_c(self):
        self.assertEqual(ctypes.sizeof(ctypes.c_void_p), 8)
        self.assertEqual(ctypes.sizeof(ctypes.c_int), 4)  # enums
        self.check(lfem.Body, 8, {"index": 0, "generation": 4})
        self.check(lfem.Event, 104, {"body_a": 8, "body_b": 16, "attachment": 24, "normal_impulse": 32,
                                     "max_force": 40, "approach_speed": 48, "point": 56, "normal": 80})
        self.check(lfem.WorldDef, 96, {
            "gravity": 0, "time_step": 24, "step_safety": 32, "contact_iterations": 40,
            "thread_count": 44,
            "contact_tolerance": 48, "max_substeps": 56, "allow_unstable_step": 60,
            "_internal_value": 64, "mass_scaling_step": 72, "enable_sleep": 61, "sleep_velocity": 80,
            "sleep_time": 88})
        self.check(lfem.Warning, 24, {"count": 0, "last_time": 8, "last_body": 16})
        self.check(lfem.WorldStats, 184, {
            "steps": 8, "step_size": 16, "stable_step": 24, "substeps_last_call": 32,
            "body_count": 36, "kinetic_energy": 40, "energy_error": 72, "linear_momentum": 80,
            "angular_momentum": 104, "contact_count": 128, "solver_iterations": 132,
            "solver_residual": 136, "max_penetration": 144, "rotation_drift": 152,
            "added_mass": 160, "inverted_tets": 168, "min_jacobian": 176})
        self.check(lfem.PhaseTime, 16, {"seconds": 0, "calls": 8})
        self.check(lfem.Profile, 240, {
            "substeps": 0, "internal_forces": 8, "predictor": 24, "kinematic_motion": 40,
            "broad_phase": 56, "narrow_phase": 72, "shape_queries": 88, "shape_tests": 104,
            "ccd_queries": 112, "normal_solve": 120, "friction": 136, "global_rotation": 152,
            "commit": 168, "candidate_searches": 184, "queries": 192, "query_bodies": 200,
            "query_primitives": 208, "query_refits": 216, "contact_sweeps": 224,
            "constraint_updates": 232})
        self.check(lfem.QueryFilter, 8, {"category_bits": 0, "mask_bits": 4})
        self.check(lfem.RayHit, 88, {
            "body": 0, "triangle": 8, "shape": 12, "barycentric": 16, "point": 32, "normal": 56,
            "distance": 80})
        self.check(lfem.AttachmentDef, 128, {
            "body": 0, "target": 8, "nodes": 16, "node_count": 24, "_internal_value": 28,
            "frame": 32, "break_force": 88, "points": 96, "point_count": 104, "stiffness": 112,
            "damping": 120})
        self.check(lfem.Overlap, 48, {"body": 0, "triangle": 8, "shape": 12, "point": 16,
                                      "distance": 40})
        dt = lfem.RAY_HIT_DTYPE
        self.assertEqual(dt.itemsize, 88)
        for name in ("body", "triangle", "shape", "barycentric", "point", "normal", "distance"):
            self.assertEqual(dt.fields[name][1], getattr(lfem.RayHit, name).offset, name)
        self.check(lfem.BodyDef, 128, {
            "_type": 0, "_model": 4, "young_modulus": 8, "poisson_ratio": 16, "density": 24,
            "damping": 32, "friction": 40, "linear_velocity": 48, "angular_velocity": 72,
            "category_bits": 96, "mask_bits": 100, "user_data": 104, "_internal_value": 112,
            "enable_sleep": 116, "self_contact": 117, "composite_tets": 118,
            "edge_contacts": 120})
        self.check(lfem.Contact, 168, {
            "body_a": 0, "body_b": 8, "node": 16, "triangle": 20, "barycentric": 32,
            "position": 48, "normal": 72, "force": 96, "sliding": 120, "kind": 121,
                    "shape": 124, "weights_a": 128, "nodes_a": 152})
        self.check(lfem.ShapeDef, 120, {
            "_type": 0, "_point_count": 4, "center": 8, "rotation": 32, "half_extents": 64,
            "radius": 88, "half_length": 96, "_points": 104, "_internal_value": 112})

    def test_contact_dtype_matches_c(self):
        dt = lfem.CONTACT_DTYPE
        self.assertEqual(dt.itemsize, 168)
        expected = {"body_a": 0, "body_b": 8, "node": 16, "triangle": 20, "barycentric": 32,
                    "position": 48, "normal": 72, "force": 96, "sliding": 120, "kind": 121,
                    "shape": 124, "weights_a": 128, "nodes_a": 152}
        for name, offset in expected.items():
            self.assertEqual(dt.fields[name][1], offset, name)
        self.assertEqual(dt["normal"].shape, (3,))


class Defaults(unittest.TestCase):
    def test_defaults_come_from_c(self):
        w = lfem.WorldDef.default()
        self.assertEqual(list(w.gravity), [0.0, 0.0, -9.81])
        self.assertEqual(w.time_step, 0.0)
        self.assertEqual(w.step_safety, 0.9)
        self.assertEqual(w.contact_iterations, 200)
        self.assertEqual(w.thread_count, 1)
        self.assertEqual(w.contact_tolerance, 1e-3)
        self.assertEqual(w.max_substeps, 1000000)
        self.assertEqual(w.allow_unstable_step, 0)
        b = lfem.BodyDef.default()
        self.assertEqual(b.type, lfem.BodyType.DEFORMABLE)
        self.assertEqual(b.model, lfem.Model.PAPER)
        self.assertEqual(b.young_modulus, 1e6)
        self.assertEqual(b.poisson_ratio, 0.3)
        self.assertEqual(b.density, 1000.0)
        self.assertEqual(b.friction, 0.5)
        self.assertEqual(b.category_bits, 1)
        self.assertEqual(b.mask_bits, 0xFFFFFFFF)
        self.assertIsNone(b.user_data)
        s = lfem.ShapeDef.default()
        self.assertEqual(s.type, lfem.ShapeType.PLANE)
        self.assertEqual(list(s.center), [0.0, 0.0, 0.0])
        self.assertEqual(list(s.rotation), [1.0, 0.0, 0.0, 0.0])
        self.assertEqual(list(s.half_extents), [0.5, 0.5, 0.5])
        self.assertEqual((s.radius, s.half_length), (0.5, 0.5))
        self.assertFalse(s._points)

    def test_definitions_start_from_the_defaults_and_check_their_fields(self):
        # BodyDef() is lfem_body_def_default(), not zero-filled (which lfem refuses).
        self.assertEqual(bytes(lfem.BodyDef()), bytes(lfem.BodyDef.default()))
        self.assertEqual(bytes(lfem.WorldDef()), bytes(lfem.native.lfem_world_def_default()))
        self.assertEqual(bytes(lfem.ShapeDef()), bytes(lfem.native.lfem_shape_def_default()))
        d = lfem.BodyDef(type=lfem.BodyType.STATIC, density=400, model=2)
        self.assertIs(d.type, lfem.BodyType.STATIC)
        self.assertIs(d.model, lfem.Model.NEO_HOOKEAN)  # an int comes back as the enum
        self.assertEqual((d.density, d.young_modulus), (400.0, 1e6))
        self.assertIs(lfem.ShapeDef(type=1).type, lfem.ShapeType.BOX)
        self.assertEqual(list(lfem.WorldDef(gravity=(0, -1, 0)).gravity), [0.0, -1.0, 0.0])
        with lfem.World() as world:
            self.assertTrue(world.is_valid(world.create_body(lfem.BodyDef(friction=0.1))))

        s = lfem.ShapeDef()
        for bad in [(1, 1), (1, 1, 1, 1), 1.0]:
            with self.assertRaises(lfem.InvalidArgumentError) as cm:
                s.half_extents = bad  # a short vector is refused, not padded with zeros
            self.assertIn("half_extents", str(cm.exception))
            self.assertIsInstance(cm.exception, ValueError)
        self.assertEqual(list(s.half_extents), [0.5, 0.5, 0.5])
        with self.assertRaises(lfem.InvalidArgumentError):
            lfem.ShapeDef(rotation=(1, 0, 0))
        for field, bad in [("density", "400"), ("density", None), ("model", "NEO_HOOKEAN"),
                           ("model", lfem.ShapeType.BOX), ("category_bits", 1.5),
                           ("gravity", ("a", "b", "c")), ("allow_unstable_step", 2),
                           ("user_data", "x")]:
            kind = lfem.WorldDef if field in ("gravity", "allow_unstable_step") else lfem.BodyDef
            with self.assertRaises(TypeError, msg=field) as cm:
                kind(**{field: bad})
            self.assertIn(field, str(cm.exception))
        with self.assertRaises(lfem.InvalidArgumentError):
            lfem.BodyDef(model=7)
        with self.assertRaises(lfem.InvalidArgumentError):
            lfem.BodyDef(mask_bits=-1)
        with self.assertRaises(TypeError) as cm:
            lfem.BodyDef(youngs_modulus=1e5)
        self.assertIn("youngs_modulus", str(cm.exception))
        with self.assertRaises(AttributeError):
            d.youngs_modulus = 1e5  # a typo is not silently a new attribute
        self.assertIn("young_modulus=1000000.0", repr(lfem.BodyDef()))

    def test_version(self):
        self.assertEqual(lfem.version(),
                         (lfem.VERSION_MAJOR, lfem.VERSION_MINOR, lfem.VERSION_PATCH))
        self.assertEqual(lfem.version_string(), "%d.%d.%d" % lfem.version())
        self.assertEqual(lfem.__version__, lfem.version_string())
        self.assertTrue(os.path.isabs(lfem.library_path), lfem.library_path)
        self.assertTrue(lfem.status_string(lfem.Status.INVALID_MESH).startswith("LFEM_INVALID_MESH"))


class Physics(unittest.TestCase):
    def test_profile_counts_the_phases_a_lone_body_runs(self):
        # A lone falling block: one predictor, elastic-force pass and commit per sub-step, no
        # detection and no solve (nothing to touch).
        with lfem.World() as world:
            add_block(world, lfem.Model.PAPER)
            world.step(0.01)
            steps = world.stats.steps
            p = world.profile
            self.assertEqual(p.substeps, steps)
            self.assertEqual(p.predictor.calls, steps)
            self.assertEqual(p.internal_forces.calls, steps)
            self.assertEqual(p.narrow_phase.calls, 0)
            self.assertEqual(p.friction.calls, 0)
            world.reset_profile()
            self.assertEqual(world.profile.predictor.calls, 0)
            self.assertEqual(int(lfem.Status.UNSUPPORTED), 9)

    def test_a_block_held_inside_out_is_reported_once_per_spell(self):
        # A 10 cm cube of one cell: bottom nodes fixed, top ones driven down at 0.5 m/s through
        # the bottom for 0.3 s (to z = -0.05) and held. Every tet then has F = diag(1, 1, -0.5):
        # all inverted, J = -0.5 exactly; after 1 s held it is reported as staying so, once.
        with lfem.World(lfem.WorldDef(gravity=(0, 0, 0))) as world:
            body = world.create_body(lfem.BodyDef(young_modulus=1e4, damping=20))
            mesh = lfem.Mesh.box((0.1, 0.1, 0.1), (1, 1, 1))
            world.add_mesh(body, mesh)
            self.assertEqual(world.inversion(body), (0, 1.0, 0.0))
            bottom = world.find_nodes_in_box(body, (-1, -1, -0.01), (1, 1, 0.01))
            top = world.find_nodes_in_box(body, (-1, -1, 0.09), (1, 1, 0.11))
            world.fix_nodes(body, bottom)
            world.prescribe_node_velocity(body, top, (0, 0, -0.5))
            for _ in range(30):
                world.step(0.01)
            world.fix_nodes(body, top)
            for _ in range(100):
                world.step(0.01)
            count, min_j, since = world.inversion(body)
            self.assertEqual(count, mesh.tet_count)
            self.assertAlmostEqual(min_j, -0.5, delta=1e-12)
            self.assertAlmostEqual(since, 1.1, delta=2e-3)
            self.assertEqual(world.stats.inverted_tets, count)
            stays = world.warning(lfem.WarningKind.STAYS_INVERTED)
            self.assertEqual(stays.count, 1)
            self.assertEqual(stays.last_body, body)
            self.assertEqual(world.warning(lfem.WarningKind.FALLEN_IN).count, 0)
            world.clear_warnings()
            for kind in lfem.WarningKind:
                self.assertEqual(world.warning(kind).count, 0)

    def test_a_bar_hangs_from_a_frame_and_a_resting_block_sleeps(self):
        # A bar held at its top nodes by a frame that never moves carries its weight; a block
        # settling on a plane begins one contact and falls asleep.
        with lfem.World(lfem.WorldDef(enable_sleep=1)) as world:
            mesh = lfem.Mesh.box((0.03, 0.03, 0.3), (1, 1, 10))
            mesh.translate((-0.015, -0.015, 0.2))
            bar = world.create_body(lfem.BodyDef(young_modulus=2e5, damping=10, enable_sleep=0))
            world.add_mesh(bar, mesh)
            top = world.find_nodes_in_box(bar, (-1, -1, 0.4999), (1, 1, 0.5001))
            held = world.attach(bar, top)
            floor = world.create_body(lfem.BodyDef(type=lfem.BodyType.STATIC))
            world.add_shape(floor, lfem.ShapeDef())
            block_mesh = lfem.Mesh.box((0.1, 0.1, 0.1), (2, 2, 2))
            block_mesh.translate((0.3, 0, 0.0005))
            block = world.create_body(lfem.BodyDef(damping=20))
            world.add_mesh(block, block_mesh)
            begins = sleeps = 0
            for _ in range(180):
                world.step(1 / 60)
                for e in world.events():
                    begins += e.type == lfem.EventType.CONTACT_BEGIN
                    sleeps += e.type == lfem.EventType.SLEEP
            self.assertEqual((begins, sleeps), (1, 1))
            self.assertFalse(world.is_awake(block))
            self.assertTrue(world.is_awake(bar))
            m = world.mass(bar)
            self.assertAlmostEqual(world.attachment_force(held)[2], m * G, delta=1e-6 * m * G)
            self.assertEqual(list(world.attachment_frame(held)), [0, 0, 0, 1, 0, 0, 0])
            world.destroy_attachment(held)
            self.assertFalse(world.attachment_is_valid(held))
            # Held instead by a point inside its top on a critically damped spring (k 2000 N/m):
            # 1 s later it carries the weight (to the solve's 1e-3 of it).
            cm = world.center_of_mass(bar)
            top_z = float(world.positions(bar)[:, 2].max())
            k = 2000.0
            spring = world.attach_points(bar, [(cm[0], cm[1], top_z - 0.001)], stiffness=k,
                                         damping=2 * (k * m) ** 0.5)
            for _ in range(60):
                world.step(1 / 60)
            self.assertAlmostEqual(world.attachment_force(spring)[2], m * G, delta=1e-3 * m * G)

    def test_self_contact_is_for_deformable_bodies_only(self):
        with lfem.World() as world:
            self.assertEqual(lfem.BodyDef().self_contact, 0)
            with self.assertRaises(lfem.InvalidArgumentError) as caught:
                world.create_body(lfem.BodyDef(type=lfem.BodyType.STATIC, self_contact=1))
            self.assertIn("self_contact", str(caught.exception))
            world.create_body(lfem.BodyDef(self_contact=1))

    def test_composite_tets_is_a_flag(self):
        with lfem.World() as world:
            self.assertEqual(lfem.BodyDef().composite_tets, 0)
            with self.assertRaises(TypeError) as caught:
                lfem.BodyDef(composite_tets=2)
            self.assertIn("composite_tets", str(caught.exception))
            mesh = lfem.Mesh.box((0.1, 0.1, 0.1), (1, 1, 1))
            mesh.make_quadratic()
            body = world.create_body(lfem.BodyDef(composite_tets=True))
            world.add_mesh(body, mesh)
            self.assertEqual(world.nodes_per_tet(body), 10)

    def test_falling_block_follows_free_fall(self):
        # Uniform gravity on an unstressed body at rest accelerates every node by exactly g: each
        # node follows z0 - g t^2/2 with velocity -g t, the momentum is -m g t and the kinetic
        # energy m (g t)^2/2 with m = rho V. Central differences are exact on a quadratic
        # trajectory; only round-off remains (~1e-16 per sub-step on values of order 1), far
        # below the tolerances (1e-11 absolute, 1e-10 relative).
        mass = DENSITY * SIZE[0] * SIZE[1] * SIZE[2]
        for model in lfem.Model:
            with self.subTest(model=model.name), lfem.World() as world:
                block = add_block(world, model)
                start = world.positions(block).copy()
                self.assertEqual(start.shape, (24, 3))
                self.assertAlmostEqual(world.mass(block), mass, delta=1e-12 * mass)
                x = np.empty_like(start)
                for call in range(1, 51):
                    world.step(0.01)
                    if call % 10:
                        continue
                    stats = world.stats
                    t = stats.time
                    self.assertAlmostEqual(t, 0.01 * call, delta=1e-12)
                    world.positions(block, out=x)
                    v = world.velocities(block)
                    np.testing.assert_allclose(x[:, :2], start[:, :2], rtol=0, atol=1e-11)
                    np.testing.assert_allclose(x[:, 2], start[:, 2] - 0.5 * G * t * t,
                                               rtol=0, atol=1e-11)
                    np.testing.assert_allclose(v[:, 2], -G * t, rtol=0, atol=1e-11)
                    np.testing.assert_allclose(v[:, :2], 0.0, rtol=0, atol=1e-11)
                    self.assertAlmostEqual(stats.linear_momentum[2], -mass * G * t,
                                           delta=1e-10 * mass * G * t)
                    ke = 0.5 * mass * (G * t) ** 2
                    self.assertAlmostEqual(stats.kinetic_energy, ke, delta=1e-10 * ke)
                    self.assertLessEqual(abs(stats.strain_energy), 1e-10 * ke)
                    linear, _ = world.momentum(block)
                    self.assertAlmostEqual(linear[2], -mass * G * t, delta=1e-10 * mass * G * t)
                self.assertEqual(world.stats.body_count, 1)

    def test_sideways_gravity_and_mesh_views(self):
        mesh = lfem.Mesh.box(SIZE, (3, 2, 1))
        self.assertEqual(mesh.node_count, 24)
        self.assertEqual(mesh.tet_count, 36)
        p = mesh.positions
        self.assertTrue(np.all(p >= 0) and np.all(p <= np.array(SIZE)))
        self.assertEqual(mesh.tets.shape, (36, 4))
        self.assertLess(int(mesh.tets.max()), 24)
        with lfem.World() as world:
            block = add_block(world, lfem.Model.COROTATIONAL)
            world.set_gravity((2.0, 0.0, 0.0))
            start = world.positions(block)
            world.step(0.3)
            t = world.stats.time
            x = world.positions(block)
            np.testing.assert_allclose(x[:, 0], start[:, 0] + t * t, rtol=0, atol=1e-11)
            np.testing.assert_allclose(x[:, 2], start[:, 2], rtol=0, atol=1e-11)
            self.assertGreater(world.stable_step, 0.0)
            self.assertTrue(math.isfinite(world.stable_step))


class QuadraticTets(unittest.TestCase):
    def test_ten_node_box_falls_freely_and_shows_its_six_node_faces(self):
        # make_quadratic adds one node per edge: the distinct corner pairs of the tets, counted
        # here with numpy. A body of these tets weighs rho V, falls exactly as z0 - g t^2/2 (the
        # lumped masses are positive, so every node takes g), and its boundary faces have their
        # mid-edge nodes at the middles of their edges.
        mesh = lfem.Mesh.box(SIZE, (3, 2, 1))
        edges = set()
        for t in mesh.tets:
            for i, j in ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)):
                edges.add((min(t[i], t[j]), max(t[i], t[j])))
        mesh.make_quadratic()
        self.assertEqual(mesh.nodes_per_tet, 10)
        self.assertEqual(mesh.tets.shape, (36, 10))
        self.assertEqual(mesh.node_count, 24 + len(edges))
        with self.assertRaises(lfem.InvalidArgumentError):
            mesh.make_quadratic()  # already quadratic
        mesh.translate((0.0, 0.0, 2.0))
        with lfem.World() as world:
            d = lfem.BodyDef(model=lfem.Model.COROTATIONAL, young_modulus=2e5, density=DENSITY)
            body = world.create_body(d)
            world.add_mesh(body, mesh)
            self.assertEqual(world.nodes_per_tet(body), 10)
            mass = DENSITY * SIZE[0] * SIZE[1] * SIZE[2]
            self.assertAlmostEqual(world.mass(body), mass, delta=1e-12 * mass)
            start = world.positions(body).copy()
            world.step(0.3)
            t = world.stats.time
            np.testing.assert_allclose(world.positions(body)[:, 2], start[:, 2] - 0.5 * G * t * t,
                                       rtol=0, atol=1e-11)
            faces = world.boundary_faces(body)
            self.assertEqual(faces.shape[1], 6)
            self.assertEqual(world.boundary_triangles(body).shape[0], 4 * faces.shape[0])
            x = world.positions(body)
            for i in range(3):
                np.testing.assert_allclose(x[faces[:, 3 + i]], 0.5 * (x[faces[:, i]] + x[faces[:, (i + 1) % 3]]),
                                           rtol=0, atol=1e-12)
            # The same tets as arrays: an (m, 10) array makes a quadratic body too.
            other = world.create_body(d)
            world.add_mesh_arrays(other, mesh.positions, mesh.tets)
            self.assertEqual(world.nodes_per_tet(other), 10)
            self.assertEqual(world.tet_count(other), 36)


class Checkpoint(unittest.TestCase):
    def test_checkpoint_continues_bit_for_bit(self):
        # A saved and reloaded world is the same world: the same handles read the same
        # positions, and both go on to bitwise identical states (lfem's checkpoint contract).
        import tempfile
        path = os.path.join(tempfile.gettempdir(), "lfem_py_%d.ckpt" % os.getpid())
        with lfem.World() as world:
            block = add_block(world, lfem.Model.COROTATIONAL)
            world.step(0.05)
            world.save(path)
            with lfem.World.load(path) as loaded:
                self.assertTrue(np.array_equal(world.positions(block), loaded.positions(block)))
                world.step(0.05)
                loaded.step(0.05)
                self.assertTrue(np.array_equal(world.positions(block), loaded.positions(block)))
        os.remove(path)
        with self.assertRaises(lfem.LfemError) as cm:
            lfem.World.load(path)
        self.assertEqual(cm.exception.status, lfem.Status.IO_ERROR)


class Errors(unittest.TestCase):
    def test_bad_arguments_raise_status_and_message(self):
        with lfem.World() as world:
            add_block(world, lfem.Model.PAPER)
            before = bytes(world.stats)
            with self.assertRaises(lfem.LfemError) as cm:
                world.step(-1.0)
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)
            self.assertTrue(cm.exception.message.startswith("lfem_world_step"), cm.exception.message)
            self.assertIn("dt", cm.exception.message)
            self.assertIn("INVALID_ARGUMENT", str(cm.exception))
            self.assertEqual(bytes(world.stats), before, "a failed call changed the world")

            with self.assertRaises(lfem.LfemError) as cm:
                world.step(float("nan"))
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)

            d = lfem.BodyDef.default()
            d.poisson_ratio = 0.5
            with self.assertRaises(lfem.LfemError) as cm:
                world.create_body(d)
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)
            self.assertTrue(cm.exception.message.startswith("lfem_body_create"))

            # An inverted tet, then the same tet correctly oriented.
            body = world.create_body()
            nodes = [(0, 0, 0), (0, 1, 0), (1, 0, 0), (0, 0, 1)]
            with self.assertRaises(lfem.LfemError) as cm:
                world.add_mesh_arrays(body, nodes, [(0, 1, 2, 3)])
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_MESH)
            self.assertTrue(cm.exception.message.startswith("lfem_body_add_mesh"))
            self.assertEqual(world.node_count(body), 0)
            world.add_mesh_arrays(body, nodes, [(0, 2, 1, 3)])
            self.assertEqual((world.node_count(body), world.tet_count(body)), (4, 1))

        bad = lfem.WorldDef.default()
        bad.step_safety = 1.5
        with self.assertRaises(lfem.LfemError) as cm:
            lfem.World(bad)
        self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)
        self.assertIn("step_safety", cm.exception.message)

        with self.assertRaises(lfem.LfemError) as cm:
            lfem.Mesh.load_gmsh("/nonexistent/lfem/mesh.msh")
        self.assertEqual(cm.exception.status, lfem.Status.IO_ERROR)
        with self.assertRaises(lfem.LfemError) as cm:
            lfem.Mesh.box(SIZE, (0, 2, 1))
        self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)

    def test_wrong_types_raise_type_error_naming_the_argument(self):
        # Checked before the call: no ctypes.ArgumentError, no numpy conversion of "0.1".
        with lfem.World() as world:
            block = add_block(world, lfem.Model.PAPER)
            cases = [
                (lambda: world.step("0.1"), "dt"),
                (lambda: world.step(None), "dt"),
                (lambda: world.set_time_step([1e-3]), "time_step"),
                (lambda: world.set_gravity(("0", "0", "-9.81")), "gravity"),
                (lambda: world.positions((block.index, block.generation)), "body"),
                (lambda: world.create_body(lfem.WorldDef()), "definition"),
                (lambda: world.add_mesh(block, "mesh"), "mesh"),
                (lambda: world.fix_nodes(block, [0.5]), "nodes"),
                (lambda: world.positions(block, out=[[0.0] * 3]), "out"),
                (lambda: lfem.Mesh.box((1, 1, 1), (2, 2, "2")), "cells"),
                (lambda: lfem.Mesh.cylinder(0.1, 0.2, 8.0, 2, 2), "segments"),
                (lambda: lfem.Mesh.load_gmsh(3.5), "path"),
            ]
            for call, name in cases:
                with self.assertRaises(TypeError, msg=name) as cm:
                    call()
                self.assertIn(name, str(cm.exception))
            with self.assertRaises(lfem.InvalidArgumentError) as cm:
                world.set_gravity((0, -9.81))
            self.assertIn("gravity", str(cm.exception))
            with self.assertRaises(ValueError):  # InvalidArgumentError is a ValueError too
                world.step(-1.0)

    def test_null_pointers_are_refused(self):
        # Straight through the raw declarations: NULL is answered, never a crash.
        with self.assertRaises(lfem.LfemError) as cm:
            lfem.native.lfem_world_step(None, 0.01)
        self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)
        self.assertEqual(lfem.last_error(), cm.exception.message)
        with self.assertRaises(lfem.LfemError) as cm:
            lfem.native.lfem_world_query_contacts(None, None, 0, None)
        self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)

    def test_destroyed_and_foreign_handles_are_refused(self):
        with lfem.World() as world, lfem.World() as other, lfem.World() as third:
            block = add_block(world, lfem.Model.PAPER)
            copy = lfem.Body(block.index, block.generation)
            self.assertTrue(world.is_valid(block))
            world.destroy_body(block)
            self.assertFalse(world.is_valid(copy))
            # Each error names the call made, not the count asked inside it first.
            for call, name in [(world.positions, "lfem_body_get_positions"),
                               (world.velocities, "lfem_body_get_velocities"),
                               (world.von_mises_stress, "lfem_body_get_von_mises_stress"),
                               (world.boundary_triangles, "lfem_body_get_boundary_triangles")]:
                with self.assertRaises(lfem.LfemError) as cm:
                    call(copy)
                self.assertEqual(cm.exception.status, lfem.Status.INVALID_HANDLE)
                self.assertTrue(cm.exception.message.startswith(name + ":"),
                                cm.exception.message)
            with self.assertRaises(lfem.LfemError) as cm:
                world.destroy_body(copy)
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_HANDLE)
            self.assertEqual(world.stats.body_count, 0)

            fresh = world.create_body()
            self.assertTrue(world.is_valid(fresh))
            self.assertFalse(world.is_valid(copy))
            self.assertNotEqual(fresh, copy)
            with self.assertRaises(lfem.LfemError) as cm:
                world.node_count(lfem.Body())
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_HANDLE)

            foreign = add_block(other, lfem.Model.PAPER)
            with self.assertRaises(lfem.LfemError) as cm:
                third.positions(foreign)
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_HANDLE)

    def test_closed_world_is_refused(self):
        world = lfem.World()
        world.close()
        with self.assertRaises(ValueError):
            world.step(0.01)
        world.close()  # twice is harmless

    def test_short_buffers_are_refused_untouched(self):
        with lfem.World() as world:
            block = add_block(world, lfem.Model.PAPER)
            n = world.node_count(block)
            short = np.full((n - 1, 3), 7.0)
            with self.assertRaises(lfem.LfemError) as cm:
                world.positions(block, out=short)
            self.assertEqual(cm.exception.status, lfem.Status.BUFFER_TOO_SMALL)
            self.assertTrue(np.all(short == 7.0))
            long = np.full((n + 2, 3), 7.0)
            filled = world.positions(block, out=long)
            self.assertEqual(filled.shape, (n, 3))  # the rows written, not the whole buffer
            self.assertTrue(np.shares_memory(filled, long))
            self.assertTrue(np.all(long[n:] == 7.0))
            np.testing.assert_array_equal(long[:n], world.positions(block))
            with self.assertRaises(lfem.LfemError) as cm:
                world.positions(block, out=np.zeros((n, 3), dtype=np.float32))
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)


class Contacts(unittest.TestCase):
    def test_two_bar_impact_matches_the_one_dimensional_wave_solution(self):
        # The paper's Fig. 3: steel bars of L = 0.254 m, sections 0.0254 x 0.0254 and
        # 0.0254 x 0.0224 m, approaching at 5.1359 m/s each across a gap of 2.54e-4 m, nu = 0, no
        # gravity, no friction. 1-D wave solution: the force plateau Z1 Z2/(Z1 + Z2) 2v
        # (Z = rho c A, c = sqrt(E/rho)) over 2L/c gives an impulse of 12.375 N s and final
        # velocities -4.491 and +5.781 m/s. Tolerances as in tests/physics/test_two_bar_impact.cpp:
        # 2 % on the impulse (mesh dispersion, 40 elements per bar), 3 % on the velocities;
        # forces and momentum changes are the same multipliers, equal to round-off.
        L, b, h1, h2, gap = 0.254, 0.0254, 0.0254, 0.0224, 2.54e-4
        v0, rho, E = 5.1359, 7844.0, 206.82e9
        wd = lfem.WorldDef.default()
        wd.gravity[:] = (0.0, 0.0, 0.0)
        with lfem.World(wd) as world:
            def bar(size, offset, v):
                mesh = lfem.Mesh.box(size, (40, 4, 4))
                mesh.translate(offset)
                d = lfem.BodyDef.default()
                d.young_modulus, d.poisson_ratio, d.density, d.friction = E, 0.0, rho, 0.0
                d.linear_velocity[:] = (v, 0.0, 0.0)
                body = world.create_body(d)
                world.add_mesh(body, mesh)
                return body

            bar1 = bar((L, b, h1), (-L - gap / 2, -b / 2, -h1 / 2), v0)
            bar2 = bar((L, b, h2), (gap / 2, -b / 2, -h2 / 2), -v0)
            m1, m2 = world.mass(bar1), world.mass(bar2)
            self.assertAlmostEqual(m1, rho * L * b * h1, delta=1e-12 * m1)
            p10, p20 = world.momentum(bar1)[0][0], world.momentum(bar2)[0][0]
            h = 0.9 * world.stable_step
            impulse, seen = 0.0, 0
            while world.stats.time < 200e-6:
                world.step(h)
                c = world.contacts()
                seen = max(seen, c.size)
                if c.size:
                    self.assertTrue(np.all(c["shape"] == lfem.NO_SHAPE))
                    on_bar2 = c["body_a"]["index"] == bar2.index
                    impulse += h * np.sum(np.where(on_bar2, 1.0, -1.0) * c["force"][:, 0])
            self.assertGreater(seen, 0, "the bars never touched")
            p1, p2 = world.momentum(bar1)[0][0], world.momentum(bar2)[0][0]
            self.assertAlmostEqual(impulse, 12.375, delta=0.02 * 12.375)
            self.assertAlmostEqual(impulse, p2 - p20, delta=1e-9 * 12.375)
            self.assertAlmostEqual(impulse, p10 - p1, delta=1e-9 * 12.375)
            self.assertAlmostEqual(p1 / m1, -4.491, delta=0.03 * 4.491)
            self.assertAlmostEqual(p2 / m2, 5.781, delta=0.03 * 5.781)

    def test_block_on_a_static_plane_touches_the_shape(self):
        # A block released 1 mm above a static plane (z = 0, normal +z): after 0.1 s it has
        # landed; every contact names the floor's shape 0, its normal is +z and its force pushes
        # up (frictionless: along the normal). A buffer one short is refused untouched.
        with lfem.World() as world:
            fd = lfem.BodyDef.default()
            fd.type = lfem.BodyType.STATIC
            floor = world.create_body(fd)
            world.add_shape(floor)
            mesh = lfem.Mesh.box(SIZE, (3, 2, 1))
            mesh.translate((0.0, 0.0, 0.001))
            d = lfem.BodyDef.default()
            d.young_modulus, d.density, d.friction, d.damping = 2e5, DENSITY, 0.0, 5.0
            block = world.create_body(d)
            world.add_mesh(block, mesh)
            world.step(0.1)
            c = world.contacts()
            self.assertGreater(c.size, 0, "the block did not land")
            self.assertEqual(world.contact_count(), c.size)
            self.assertTrue(np.all(c["body_a"]["index"] == block.index))
            self.assertTrue(np.all(c["body_b"]["index"] == floor.index))
            self.assertTrue(np.all(c["shape"] == 0))
            np.testing.assert_allclose(c["normal"], np.tile([0.0, 0.0, 1.0], (c.size, 1)),
                                       rtol=0, atol=1e-12)
            self.assertTrue(np.all(c["force"][:, 2] >= 0))
            np.testing.assert_allclose(c["force"][:, :2], 0.0, rtol=0, atol=1e-9)
            if c.size > 1:
                short = np.zeros(c.size - 1, dtype=lfem.CONTACT_DTYPE)
                short["node"] = 12345
                with self.assertRaises(lfem.LfemError) as cm:
                    world.contacts(out=short)
                self.assertEqual(cm.exception.status, lfem.Status.BUFFER_TOO_SMALL)
                self.assertTrue(np.all(short["node"] == 12345))
            with self.assertRaises(lfem.LfemError) as cm:
                world.add_shape(block)
            self.assertEqual(cm.exception.status, lfem.Status.INVALID_ARGUMENT)
            self.assertTrue(cm.exception.message.startswith("lfem_body_add_shape"))

    def test_contact_query_of_a_single_body_is_empty(self):
        # A lone falling block touches nothing: the query gives a count of 0, an empty structured
        # array, and leaves a caller's buffer alone.
        with lfem.World() as world:
            add_block(world, lfem.Model.NEO_HOOKEAN)
            world.step(0.05)
            self.assertEqual(world.contact_count(), 0)
            c = world.contacts()
            self.assertEqual(c.shape, (0,))
            self.assertEqual(c.dtype, lfem.CONTACT_DTYPE)
            self.assertEqual(c["normal"].shape, (0, 3))
            buf = np.zeros(4, dtype=lfem.CONTACT_DTYPE)
            buf["node"] = 12345
            self.assertEqual(world.contacts(out=buf).shape, (0,))
            self.assertTrue(np.all(buf["node"] == 12345))
            self.assertEqual(world.contacts(out=buf[:0]).shape, (0,))
            self.assertEqual(world.stats.contact_count, 0)
            with self.assertRaises(lfem.LfemError):
                world.contacts(out=np.zeros(4, dtype=np.float64))


if __name__ == "__main__":
    unittest.main()


class SkinsAndQueries(unittest.TestCase):
    def test_a_skin_falls_with_its_block(self):
        # A render mesh (a tetrahedron's surface) inside a falling block: free fall moves every
        # tet by -g t^2 / 2 exactly (up to round-off), so every skin vertex follows p - g t^2 / 2;
        # vertex 0 is the corner of three axis faces of areas 0.01, 0.006 and 0.003 m^2, so its
        # area-weighted normal is -(0.006, 0.012, 0.02) / |.|.
        with lfem.World() as world:
            block = add_block(world, lfem.Model.COROTATIONAL)
            p = np.array([[0.05, 0.05, 2.02], [0.25, 0.05, 2.02], [0.05, 0.15, 2.02],
                          [0.05, 0.05, 2.08]])
            t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
            self.assertEqual(world.add_skin(block, p, t), 0)
            self.assertEqual(world.skin_count(block), 1)
            self.assertEqual(world.skin_sizes(block, 0), (4, 4))
            np.testing.assert_array_equal(world.skin_triangles(block, 0), t)
            world.step(0.1)
            time = world.stats.time
            x, n = world.skin_vertices(block, 0)
            expected = p - [0, 0, 0.5 * G * time * time]
            np.testing.assert_allclose(x, expected, rtol=0, atol=1e-11)
            corner = -np.array([0.006, 0.012, 0.02]) / math.sqrt(0.006**2 + 0.012**2 + 0.02**2)
            np.testing.assert_allclose(n[0], corner, rtol=0, atol=1e-12)
            buffer = np.full((4, 8), -1.0, dtype=np.float32)
            world.skin_vertex_buffer(block, 0, buffer)
            np.testing.assert_array_equal(buffer[:, :3], x.astype(np.float32))
            np.testing.assert_array_equal(buffer[:, 3:6], n.astype(np.float32))
            np.testing.assert_array_equal(buffer[:, 6:], -1.0)
            with self.assertRaises(lfem.LfemError) as cm:
                world.skin_vertex_buffer(block, 0, np.zeros((3, 8), dtype=np.float32))
            self.assertEqual(cm.exception.status, lfem.Status.BUFFER_TOO_SMALL)
            with self.assertRaises(lfem.InvalidArgumentError) as cm:
                world.skin_vertices(block, 1)
            self.assertTrue(cm.exception.message.startswith("lfem_body_get_skin_vertices:"),
                            cm.exception.message)
            with self.assertRaises(lfem.InvalidArgumentError):  # far outside the block
                world.add_skin(block, [[5, 5, 5], [5.1, 5, 5], [5, 5.1, 5]], [[0, 1, 2]])
            self.assertEqual(world.skin_count(block), 1)
            # Settings after creation, and the skin removed.
            world.set_friction(block, 0.2)
            world.set_damping(block, 1.0)
            world.set_sleep_allowed(block, False)
            world.set_material(block, 3e5, 0.25)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.set_material(block, 3e5, 0.5)
            world.set_filter(block, 1, 0xFFFFFFFF)
            world.set_user_data(block, 1234)
            self.assertEqual(world.user_data(block), 1234)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.set_damping(block, -1.0)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.remove_skin(block, 1)
            world.remove_skin(block, 0)
            self.assertEqual(world.skin_count(block), 0)

    def test_a_teleported_block_lands_with_its_approach_speed(self):
        # A soft block put 0.2 m above a plane by its transform (x = X + t) falls and lands at
        # sqrt(2 g H): the begin event's approach speed is within g h / 2 of it (the impact
        # sub-step's predicted mid-step velocity), its normal +z from the plane toward the block.
        with lfem.World() as world:
            floor = world.create_body(lfem.BodyDef(type=lfem.BodyType.STATIC))
            world.add_shape(floor)
            block = world.create_body()
            mesh = lfem.Mesh.box((0.1, 0.1, 0.1), (2, 2, 2))
            world.add_mesh(block, mesh)
            mesh.close()
            pose = world.transform(block)
            pose[2] += 0.2
            world.set_transform(block, pose)
            np.testing.assert_allclose(world.transform(block), pose, rtol=0, atol=1e-12)
            lowest = float(world.positions(block)[:, 2].min())
            self.assertAlmostEqual(lowest, 0.2, delta=1e-12)
            v_impact = math.sqrt(2 * 9.81 * lowest)
            c0 = world.center_of_mass(block)
            landed = False
            for _ in range(30):
                world.step(1 / 60)
                for e in world.events():
                    if e.type != lfem.EventType.CONTACT_BEGIN:
                        continue
                    h = world.stats.step_size
                    self.assertAlmostEqual(e.approach_speed, v_impact, delta=0.5 * 9.81 * h * (1 + 1e-9))
                    self.assertAlmostEqual(e.normal[2], 1.0, delta=1e-12)
                    self.assertLess(abs(e.point[2]), 1e-3 * v_impact * h)
                    landed = True
                if landed:
                    break
            self.assertTrue(landed)
            self.assertLess(world.center_of_mass(block)[2], c0[2])
            # The nearest point of the block's surface to a point 1 m above its centre of mass.
            top = float(world.positions(block)[:, 2].max())
            cm = world.center_of_mass(block)
            q, _, d = world.closest_point(block, (cm[0], cm[1], top + 1.0))
            self.assertAlmostEqual(q[2], top, delta=1e-12)
            self.assertAlmostEqual(d, 1.0, delta=1e-12)
            # An impulse at its centre of mass: its momentum grows by exactly that (round-off).
            p0, _ = world.momentum(block)
            world.apply_impulse(block, world.center_of_mass(block), (0.5, 0.0, 0.2))
            p1, _ = world.momentum(block)
            np.testing.assert_allclose(p1 - p0, [0.5, 0.0, 0.2], rtol=0, atol=1e-12)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.set_transform(floor, pose)

    def test_a_force_acts_for_one_call_and_a_user_id_is_kept(self):
        # Weightless: a force F at the cube's centre for one call of dt gives it F dt of momentum
        # exactly (central differences; round-off of sums over its nodes), the next call nothing.
        with lfem.World(lfem.WorldDef(gravity=(0, 0, 0))) as world:
            cube = world.create_body()
            mesh = lfem.Mesh.box((0.2, 0.2, 0.2), (2, 2, 2))
            world.add_mesh(cube, mesh)
            mesh.close()
            self.assertEqual(world.user_id(cube), 0)
            self.assertEqual(world.body_type(cube), lfem.BodyType.DEFORMABLE)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.set_type(cube, lfem.BodyType.RIGID)
            world.set_user_id(cube, 2**64 - 1)
            self.assertEqual(world.user_id(cube), 2**64 - 1)
            with self.assertRaises(ValueError):
                world.set_user_id(cube, -1)
            dt = 1.0 / 60
            world.apply_force(cube, world.center_of_mass(cube), (3.0, 0.0, -1.0))
            world.step(dt)
            p1, _ = world.momentum(cube)
            np.testing.assert_allclose(p1, [3 * dt, 0.0, -dt], rtol=0, atol=1e-12)
            world.step(dt)
            p2, _ = world.momentum(cube)
            np.testing.assert_allclose(p2, p1, rtol=0, atol=1e-12)

    def test_rays_and_boxes_find_what_is_there(self):
        # A static sphere of radius 0.5 about (2, 0, 0): a ray along +x at height 0.3 meets it at
        # 2 - sqrt(0.25 - 0.09) = 1.6 with normal (p - c) / r; a cube [0, 0.2]^3 is crossed at 1
        # and 1.2 by a ray from x = -1.
        with lfem.World(lfem.WorldDef(gravity=(0, 0, 0))) as world:
            ground = world.create_body(lfem.BodyDef(type=lfem.BodyType.STATIC))
            world.add_shape(ground, lfem.ShapeDef(type=lfem.ShapeType.SPHERE, center=(2, 0, 0),
                                                  radius=0.5))
            cube = world.create_body()
            mesh = lfem.Mesh.box((0.2, 0.2, 0.2), (2, 2, 2))
            world.add_mesh(cube, mesh)
            mesh.close()
            f = lfem.QueryFilter()
            self.assertEqual((f.category_bits, f.mask_bits), (1, 0xFFFFFFFF))
            # A sphere 0.3 above the static sphere's top (radius 0.31) meets it at its top, 0.3
            # away; one of radius 0.06 over the cube's top face (0.05 above) meets it below.
            o = world.overlap_sphere((2, 0, 0.8), 0.31)
            self.assertEqual(len(o), 1)
            self.assertEqual((o[0].body, o[0].shape, o[0].triangle), (ground, 0, lfem.NO_SHAPE))
            self.assertAlmostEqual(o[0].point[2], 0.5, delta=1e-12)
            self.assertAlmostEqual(o[0].distance, 0.3, delta=1e-12)
            o = world.overlap_capsule((0.07, 0.13, 0.25), (0.07, 0.13, 0.25), 0.06)
            self.assertEqual([x.body for x in o], [cube])
            self.assertAlmostEqual(o[0].point[2], 0.2, delta=1e-12)
            self.assertAlmostEqual(o[0].distance, 0.05, delta=1e-12)
            self.assertEqual(world.overlap_sphere((2, 0, 0.8), 0.29), [])
            # A sphere of 0.1 cast along -x from x = 4 at the static sphere: it stops 4 - 2 - 0.5
            # - 0.1 away, touching it at x = 2.5.
            h = world.cast_sphere((4, 0, 0), (-1, 0, 0), 0.1)
            self.assertIsNotNone(h)
            self.assertAlmostEqual(h.distance, 1.4, delta=1e-12)
            self.assertAlmostEqual(h.point[0], 2.5, delta=1e-12)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.overlap_sphere((2, 0, 0.8), -1.0)
            hit = world.cast_ray((0, 0, 0.3), (3, 0, 0))
            self.assertIsNotNone(hit)
            self.assertEqual(hit.body, ground)
            self.assertEqual((hit.shape, hit.triangle), (0, lfem.NO_SHAPE))
            self.assertAlmostEqual(hit.distance, 1.6, delta=1e-12)
            np.testing.assert_allclose(list(hit.normal), [-0.8, 0, 0.6], rtol=0, atol=1e-12)
            hits = world.cast_ray_all((-1, 0.07, 0.03), (1, 0, 0))
            self.assertEqual(len(hits), 4)
            chord = math.sqrt(0.25 - 0.07**2 - 0.03**2)
            np.testing.assert_allclose(hits["distance"], [1.0, 1.2, 3 - chord, 3 + chord],
                                       rtol=0, atol=1e-12)
            self.assertEqual(int(hits[0]["body"]["index"]), cube.index)
            self.assertNotEqual(int(hits[0]["triangle"]), lfem.NO_SHAPE)
            self.assertIsNone(world.cast_ray((-1, 0.07, 0.03), (1, 0, 0), 0.99))
            self.assertIsNone(world.cast_ray((0, 0, 0.3), (1, 0, 0),
                                             filter=lfem.QueryFilter(mask_bits=2)))
            self.assertEqual(world.overlap_box((0.1, 0.1, 0.1), (0.12, 0.12, 0.12)), [cube])
            self.assertEqual(world.overlap_box((-5, -5, -5), (5, 5, 5)), [ground, cube])
            self.assertEqual(world.overlap_box((0.5, 0.5, 0.5), (0.6, 0.6, 0.6)), [])
            with self.assertRaises(lfem.InvalidArgumentError) as cm:
                world.cast_ray((0, 0, 0), (0, 0, 0))
            self.assertIn("direction", cm.exception.message)
            with self.assertRaises(lfem.InvalidArgumentError):
                world.overlap_box((1, 1, 1), (0, 0, 0))
            self.assertGreaterEqual(world.profile.queries, 7)
