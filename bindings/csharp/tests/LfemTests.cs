// Tests of the C# bindings, run under mono: struct layouts against the C sizes, real
// simulations against closed forms, error handling, handle invalidation, buffers, contacts.
// No test framework (none ships with Debian's mono-runtime): each public static void Test*
// method is a test; the runner prints "N passed, N failed" and exits non-zero on any failure.
using System;
using System.Collections.Generic;
using System.Reflection;
using System.Runtime.InteropServices;
using Lfem;

public static class LfemTests
{
    const double G = 9.81;

    // ---- tiny assertion helpers ----

    class Failure : Exception
    {
        public Failure(string m) : base(m) { }
    }

    static void Check(bool condition, string what)
    {
        if (!condition) throw new Failure(what);
    }

    static void Equal<T>(T expected, T actual, string what)
    {
        if (!EqualityComparer<T>.Default.Equals(expected, actual))
            throw new Failure(what + ": expected " + expected + ", got " + actual);
    }

    static void Close(double expected, double actual, double tol, string what)
    {
        if (!(Math.Abs(expected - actual) <= tol))
            throw new Failure(what + ": expected " + expected.ToString("R") + ", got " + actual.ToString("R") + " (tolerance " + tol + ")");
    }

    static LfemException Throws(Action call, string what)
    {
        try { call(); }
        catch (LfemException e) { return e; }
        throw new Failure(what + ": no LfemException");
    }

    // ---- the scene: a block of 0.3 x 0.2 x 0.1 m lifted to z = 2 m ----

    static readonly Vec3 Size = new Vec3(0.3, 0.2, 0.1);
    const double Density = 400.0;

    static Body AddBlock(World world, Model model)
    {
        using (Mesh mesh = Mesh.Box(Size, 3, 2, 1))
        {
            mesh.Translate(new Vec3(0, 0, 2));
            BodyDef def = BodyDef.Default;
            def.Model = model;
            def.YoungModulus = 2e5;
            def.Density = Density;
            Body body = world.CreateBody(def);
            world.AddMesh(body, mesh);
            return body;
        }
    }

    // ---- layout ----

    static void Layout<T>(int size, params object[] fieldsAndOffsets)
    {
        Equal(size, Marshal.SizeOf(typeof(T)), "Marshal.SizeOf(" + typeof(T).Name + ")");
        for (int i = 0; i < fieldsAndOffsets.Length; i += 2)
        {
            string field = (string)fieldsAndOffsets[i];
            Equal((int)fieldsAndOffsets[i + 1], (int)Marshal.OffsetOf(typeof(T), field), typeof(T).Name + "." + field + " offset");
        }
        // Blittable: pinning throws ArgumentException for a non-blittable type.
        GCHandle pin = GCHandle.Alloc(Activator.CreateInstance(typeof(T)), GCHandleType.Pinned);
        pin.Free();
    }

    public static void TestStructSizesMatchC()
    {
        // The numbers bindings/abi_layout.c asserts in C (64-bit targets).
        Check(IntPtr.Size == 8, "64-bit process");
        Equal(4, Marshal.SizeOf(Enum.GetUnderlyingType(typeof(Status))), "sizeof(lfem_status)");
        Equal(4, Marshal.SizeOf(Enum.GetUnderlyingType(typeof(BodyType))), "sizeof(lfem_body_type)");
        Equal(4, Marshal.SizeOf(Enum.GetUnderlyingType(typeof(Model))), "sizeof(lfem_model)");
        Layout<Vec3>(24, "Z", 16);
        Layout<Body>(8, "Index", 0, "Generation", 4);
        Layout<WorldDef>(96, "Gravity", 0, "TimeStep", 24, "StepSafety", 32, "ContactIterations", 40,
                         "ThreadCount", 44,
                         "ContactTolerance", 48, "MaxSubsteps", 56, "AllowUnstableStep", 60, "internalValue", 64,
                         "MassScalingStep", 72, "EnableSleep", 61, "SleepVelocity", 80, "SleepTime", 88);
        Layout<Event>(104, "BodyA", 8, "BodyB", 16, "Attachment", 24, "NormalImpulse", 32, "MaxForce", 40,
                      "ApproachSpeed", 48, "Point", 56, "Normal", 80);
        Layout<WorldStats>(184, "Steps", 8, "StepSize", 16, "StableStep", 24, "SubstepsLastCall", 32, "BodyCount", 36,
                           "KineticEnergy", 40, "EnergyError", 72, "LinearMomentum", 80, "AngularMomentum", 104,
                           "ContactCount", 128, "SolverIterations", 132, "SolverResidual", 136, "MaxPenetration", 144,
                           "RotationDrift", 152, "AddedMass", 160, "InvertedTets", 168, "MinJacobian", 176);
        Layout<Warning>(24, "Count", 0, "LastTime", 8, "LastBody", 16);
        Layout<PhaseTime>(16, "Seconds", 0, "Calls", 8);
        Layout<Profile>(240, "Substeps", 0, "InternalForces", 8, "Predictor", 24, "KinematicMotion", 40,
                        "BroadPhase", 56, "NarrowPhase", 72, "ShapeQueries", 88, "ShapeTests", 104, "CcdQueries", 112,
                        "NormalSolve", 120, "Friction", 136, "GlobalRotation", 152, "Commit", 168,
                        "CandidateSearches", 184, "Queries", 192, "QueryBodies", 200, "QueryPrimitives", 208,
                        "QueryRefits", 216, "ContactSweeps", 224, "ConstraintUpdates", 232);
        Layout<QueryFilter>(8, "CategoryBits", 0, "MaskBits", 4);
        Layout<AttachmentDef>(128, "Body", 0, "Target", 8, "Nodes", 16, "NodeCount", 24, "InternalValue", 28,
                              "Frame", 32, "BreakForce", 88, "Points", 96, "PointCount", 104, "Stiffness", 112,
                              "Damping", 120);
        Layout<Overlap>(48, "Body", 0, "Triangle", 8, "Shape", 12, "Point", 16, "Distance", 40);
        Layout<RayHit>(88, "Body", 0, "Triangle", 8, "Shape", 12, "Barycentric1", 16, "Barycentric2", 24, "Point", 32,
                       "Normal", 56, "Distance", 80);
        Layout<BodyDef>(128, "Type", 0, "Model", 4, "YoungModulus", 8, "PoissonRatio", 16, "Density", 24, "Damping", 32,
                        "Friction", 40, "LinearVelocity", 48, "AngularVelocity", 72, "CategoryBits", 96, "MaskBits", 100,
                        "UserData", 104, "internalValue", 112, "EnableSleep", 116, "SelfContact", 117,
                        "CompositeTets", 118, "EdgeContacts", 120);
        Layout<Contact>(168, "BodyA", 0, "BodyB", 8, "Node", 16, "TriangleA", 20, "TriangleC", 28, "Barycentric1", 32,
                        "Barycentric2", 40, "Position", 48, "Normal", 72, "Force", 96, "Sliding", 120, "Kind", 121,
                        "Shape", 124, "WeightsA", 128, "NodesA0", 152, "NodesA2", 160);
        Equal(4, Marshal.SizeOf(Enum.GetUnderlyingType(typeof(ShapeType))), "sizeof(lfem_shape_type)");
        Layout<ShapeDef>(120, "Type", 0, "PointCount", 4, "Center", 8, "RotationW", 32, "RotationZ", 56, "HalfExtents", 64,
                         "Radius", 88, "HalfLength", 96, "Points", 104, "internalValue", 112);
    }

    public static void TestDefaultsComeFromC()
    {
        WorldDef w = WorldDef.Default;
        Equal(new Vec3(0, 0, -9.81), w.Gravity, "gravity");
        Equal(0.0, w.TimeStep, "time step");
        Equal(0.9, w.StepSafety, "step safety");
        Equal(200u, w.ContactIterations, "contact iterations");
        Equal(1u, w.ThreadCount, "thread count");
        Equal(1e-3, w.ContactTolerance, "contact tolerance");
        Equal(1000000u, w.MaxSubsteps, "max substeps");
        Equal((byte)0, w.AllowUnstableStep, "allow unstable step");
        BodyDef b = BodyDef.Default;
        Equal(BodyType.Deformable, b.Type, "type");
        Equal(Model.Paper, b.Model, "model");
        Equal(1e6, b.YoungModulus, "E");
        Equal(0.3, b.PoissonRatio, "nu");
        Equal(1000.0, b.Density, "density");
        Equal(0.5, b.Friction, "friction");
        Equal(1u, b.CategoryBits, "category");
        Equal(0xFFFFFFFFu, b.MaskBits, "mask");
        Equal(IntPtr.Zero, b.UserData, "user data");
        ShapeDef s = ShapeDef.Default;
        Equal(ShapeType.Plane, s.Type, "shape type");
        Equal(new Vec3(0, 0, 0), s.Center, "shape centre");
        Check(s.RotationW == 1 && s.RotationX == 0 && s.RotationY == 0 && s.RotationZ == 0, "identity rotation");
        Equal(new Vec3(0.5, 0.5, 0.5), s.HalfExtents, "half extents");
        Equal(0.5, s.Radius, "radius");
        Equal(0.5, s.HalfLength, "half length");
        Equal(IntPtr.Zero, s.Points, "points");
    }

    public static void TestVersion()
    {
        Equal((uint)((Library.VersionMajor << 16) | (Library.VersionMinor << 8) | Library.VersionPatch), Library.Version, "version");
        Equal(Library.VersionMajor + "." + Library.VersionMinor + "." + Library.VersionPatch, Library.VersionString, "version string");
        Check(Library.StatusString(Status.InvalidMesh).StartsWith("LFEM_INVALID_MESH"), "status string");
    }

    // ---- physics ----

    public static void TestFallingBlockFollowsFreeFall()
    {
        // Uniform gravity on an unstressed body at rest accelerates every node by exactly g: each
        // node follows z0 - g t^2/2 with velocity -g t, momentum -m g t, kinetic energy
        // m (g t)^2/2, m = rho V. Central differences are exact on a quadratic trajectory; only
        // round-off remains (~1e-16 per sub-step on values of order 1), far below 1e-11.
        double mass = Density * (Size.X * Size.Y * Size.Z);
        foreach (Model model in new[] { Model.Paper, Model.Corotational, Model.NeoHookean, Model.Linear })
        {
            using (World world = new World())
            {
                Body block = AddBlock(world, model);
                Vec3[] start = world.GetPositions(block);
                Equal(24, start.Length, "node count");
                Close(mass, world.Mass(block), 1e-12 * mass, model + " mass = rho V");
                for (int call = 1; call <= 50; ++call)
                {
                    world.Step(0.01);
                    if (call % 10 != 0) continue;
                    WorldStats stats = world.Stats;
                    double t = stats.Time;
                    Close(0.01 * call, t, 1e-12, model + " time");
                    Vec3[] x = world.GetPositions(block);
                    Vec3[] v = world.GetVelocities(block);
                    for (int i = 0; i < x.Length; ++i)
                    {
                        Close(start[i].X, x[i].X, 1e-11, model + " x of node " + i);
                        Close(start[i].Y, x[i].Y, 1e-11, model + " y of node " + i);
                        Close(start[i].Z - 0.5 * G * t * t, x[i].Z, 1e-11, model + " z of node " + i);
                        Close(-G * t, v[i].Z, 1e-11, model + " vz of node " + i);
                        Close(0.0, v[i].X, 1e-11, model + " vx of node " + i);
                    }
                    Close(-mass * G * t, stats.LinearMomentum.Z, 1e-10 * mass * G * t, model + " momentum");
                    double ke = 0.5 * mass * (G * t) * (G * t);
                    Close(ke, stats.KineticEnergy, 1e-10 * ke, model + " kinetic energy");
                    Close(0.0, stats.StrainEnergy, 1e-10 * ke, model + " strain energy");
                    Vec3 p, l;
                    world.GetMomentum(block, out p, out l);
                    Close(-mass * G * t, p.Z, 1e-10 * mass * G * t, model + " body momentum");
                }
                Equal(1u, world.Stats.BodyCount, "body count");
            }
        }
    }

    public static void TestTenNodeBoxFallsFreelyAndShowsItsSixNodeFaces()
    {
        // MakeQuadratic adds one node per edge (the distinct corner pairs of the 4-node tets,
        // counted here); the body weighs rho V and falls as z0 - g t^2/2 exactly (every lumped mass
        // is positive, so every node takes g); its 6-node faces have their mid-edge nodes at the
        // middles of their edges, and contact sees 4 flat triangles per face.
        using (Mesh mesh = Mesh.Box(Size, 3, 2, 1))
        {
            uint[] linear = mesh.GetTets();
            var edges = new System.Collections.Generic.HashSet<ulong>();
            int[,] pairs = { { 0, 1 }, { 1, 2 }, { 0, 2 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
            for (int t = 0; t < linear.Length / 4; ++t)
                for (int e = 0; e < 6; ++e)
                {
                    ulong a = linear[4 * t + pairs[e, 0]], b = linear[4 * t + pairs[e, 1]];
                    edges.Add(Math.Min(a, b) << 32 | Math.Max(a, b));
                }
            mesh.MakeQuadratic();
            Equal(10, mesh.NodesPerTet, "nodes per tet");
            Equal(36, mesh.TetCount, "tet count");
            Equal(360, mesh.GetTets().Length, "tet indices");
            Equal(24 + edges.Count, mesh.NodeCount, "a node per edge");
            Equal(Status.InvalidArgument, Throws(() => mesh.MakeQuadratic(), "make quadratic twice").Status, "status");
            mesh.Translate(new Vec3(0, 0, 2));
            using (World world = new World())
            {
                BodyDef def = BodyDef.Default;
                def.Model = Model.Corotational;
                def.YoungModulus = 2e5;
                def.Density = Density;
                Body body = world.CreateBody(def);
                world.AddMesh(body, mesh);
                Equal(10, world.GetNodesPerTet(body), "body nodes per tet");
                double mass = Density * (Size.X * Size.Y * Size.Z);
                Close(mass, world.Mass(body), 1e-12 * mass, "mass = rho V");
                Vec3[] start = world.GetPositions(body);
                world.Step(0.3);
                double time = world.Stats.Time;
                Vec3[] x = world.GetPositions(body);
                for (int i = 0; i < x.Length; ++i)
                    Close(start[i].Z - 0.5 * G * time * time, x[i].Z, 1e-11, "z of node " + i);
                uint[] faces = world.GetBoundaryFaces(body);
                Equal(0, faces.Length % 6, "6 indices a face");
                Equal(4 * (faces.Length / 6), world.GetBoundaryTriangles(body).Length / 3, "4 flat triangles a face");
                for (int f = 0; f < faces.Length / 6; ++f)
                    for (int i = 0; i < 3; ++i)
                    {
                        Vec3 mid = (x[faces[6 * f + i]] + x[faces[6 * f + (i + 1) % 3]]) / 2;
                        Close(0.0, (x[faces[6 * f + 3 + i]] - mid).Length, 1e-12, "mid-edge node of face " + f);
                    }
                Body other = world.CreateBody(def);
                world.AddQuadraticMesh(other, mesh.GetPositions(), mesh.GetTets());
                Equal(36, world.TetCount(other), "tets of the arrays");
            }
        }
    }

    public static void TestProfileCountsThePhasesALoneBodyRuns()
    {
        // A lone falling block: one predictor, elastic-force pass and commit per sub-step, no
        // detection and no solve (nothing to touch).
        using (World world = new World())
        {
            AddBlock(world, Model.Paper);
            world.Step(0.01);
            ulong steps = world.Stats.Steps;
            Profile p = world.Profile;
            Equal(steps, p.Substeps, "profiled sub-steps");
            Equal(steps, p.Predictor.Calls, "predictor calls");
            Equal(steps, p.InternalForces.Calls, "internal force calls");
            Equal(0ul, p.NarrowPhase.Calls, "narrow phase calls");
            Equal(0ul, p.Friction.Calls, "friction calls");
            world.ResetProfile();
            Equal(0ul, world.Profile.Predictor.Calls, "after reset");
            Equal(9, (int)Status.Unsupported, "LFEM_UNSUPPORTED");
        }
    }

    public static void TestCheckpointContinuesBitForBit()
    {
        // A saved and reloaded world is the same world: the same handles read the same
        // positions, and both go on to bitwise identical states (lfem's checkpoint contract).
        string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "lfem_cs_" + System.Diagnostics.Process.GetCurrentProcess().Id + ".ckpt");
        using (World world = new World())
        {
            Body block = AddBlock(world, Model.Corotational);
            world.Step(0.05);
            world.Save(path);
            using (World loaded = World.Load(path))
            {
                Vec3[] a = world.GetPositions(block), b = loaded.GetPositions(block);
                for (int i = 0; i < a.Length; ++i) Check(a[i].Equals(b[i]), "loaded node " + i);
                world.Step(0.05);
                loaded.Step(0.05);
                a = world.GetPositions(block);
                b = loaded.GetPositions(block);
                for (int i = 0; i < a.Length; ++i) Check(a[i].Equals(b[i]), "continued node " + i);
            }
        }
        System.IO.File.Delete(path);
        LfemException e = Throws(() => World.Load(path), "load(missing)");
        Equal(Status.IoError, e.Status, "missing checkpoint");
    }

    public static void TestSidewaysGravityAndMeshViews()
    {
        using (Mesh mesh = Mesh.Box(Size, 3, 2, 1))
        {
            Equal(24, mesh.NodeCount, "mesh nodes");
            Equal(36, mesh.TetCount, "mesh tets");
            foreach (Vec3 p in mesh.GetPositions())
                Check(p.X >= 0 && p.X <= 0.3 && p.Y >= 0 && p.Y <= 0.2 && p.Z >= 0 && p.Z <= 0.1, "box node inside the box");
            foreach (uint i in mesh.GetTets()) Check(i < 24, "tet index in range");
        }
        using (World world = new World())
        {
            Body block = AddBlock(world, Model.Corotational);
            world.SetGravity(new Vec3(2, 0, 0));
            Vec3[] start = world.GetPositions(block);
            world.Step(0.3);
            double t = world.Stats.Time;
            Vec3[] x = world.GetPositions(block);
            for (int i = 0; i < x.Length; ++i)
            {
                Close(start[i].X + t * t, x[i].X, 1e-11, "x = x0 + a t^2/2");
                Close(start[i].Z, x[i].Z, 1e-11, "z unchanged");
            }
            Check(world.StableStep > 0, "stable step > 0");
        }
    }

    // ---- errors ----

    public static void TestBadArgumentsThrowStatusAndMessage()
    {
        using (World world = new World())
        {
            AddBlock(world, Model.Paper);
            WorldStats before = world.Stats;
            LfemException e = Throws(() => world.Step(-1.0), "step(-1)");
            Equal(Status.InvalidArgument, e.Status, "status");
            Check(e.Message.StartsWith("lfem_world_step"), "message names the function: " + e.Message);
            Check(e.Message.Contains("dt"), "message names dt: " + e.Message);
            Equal(before, world.Stats, "a failed call changed the world");

            e = Throws(() => world.Step(double.NaN), "step(NaN)");
            Equal(Status.InvalidArgument, e.Status, "NaN status");

            BodyDef def = BodyDef.Default;
            def.PoissonRatio = 0.5;
            e = Throws(() => world.CreateBody(def), "nu = 0.5");
            Equal(Status.InvalidArgument, e.Status, "nu status");
            Check(e.Message.StartsWith("lfem_body_create"), "message: " + e.Message);

            // An inverted tet, then the same tet correctly oriented.
            Body body = world.CreateBody(BodyDef.Default);
            Vec3[] nodes = { new Vec3(0, 0, 0), new Vec3(0, 1, 0), new Vec3(1, 0, 0), new Vec3(0, 0, 1) };
            e = Throws(() => world.AddMesh(body, nodes, new uint[] { 0, 1, 2, 3 }), "inverted tet");
            Equal(Status.InvalidMesh, e.Status, "inverted status");
            Check(e.Message.StartsWith("lfem_body_add_mesh"), "message: " + e.Message);
            Equal(0, world.NodeCount(body), "nothing added");
            world.AddMesh(body, nodes, new uint[] { 0, 2, 1, 3 });
            Equal(4, world.NodeCount(body), "nodes added");
            Equal(1, world.TetCount(body), "tet added");

            e = Throws(() => world.SetGravity(new Vec3(double.NaN, 0, 0)), "NaN gravity");
            Equal(Status.InvalidArgument, e.Status, "gravity status");
        }
        WorldDef bad = WorldDef.Default;
        bad.StepSafety = 1.5;
        LfemException e2 = Throws(() => new World(bad), "step safety 1.5");
        Equal(Status.InvalidArgument, e2.Status, "step safety status");
        Check(e2.Message.Contains("step_safety"), "message: " + e2.Message);

        LfemException e3 = Throws(() => Mesh.LoadGmsh("/nonexistent/lfem/mesh.msh"), "missing file");
        Equal(Status.IoError, e3.Status, "io status");
        LfemException e4 = Throws(() => Mesh.Box(Size, 0, 2, 1), "zero cells");
        Equal(Status.InvalidArgument, e4.Status, "zero cells status");
    }

    public static void TestBindingArgumentChecksThrowArgumentExceptions()
    {
        using (World world = new World())
        {
            Body body = AddBlock(world, Model.Paper);
            ArgumentException a = ThrowsArgument(() => world.AddMesh(body, new Vec3[4], new uint[] { 0, 1, 2 }), "tets of 3");
            Equal("tets", a.ParamName, "tets param");
            a = ThrowsArgument(() => world.SetNodeForces(body, new uint[] { 0, 1 }, new Vec3[1]), "2 nodes, 1 force");
            Equal("forces", a.ParamName, "forces param");
            Check(ThrowsArgument(() => world.GetPositions(body, null), "null buffer") is ArgumentNullException, "null buffer");
        }
        // ToString shows the status (Exception.ToString alone would not).
        LfemException e = Throws(() => Mesh.Box(Size, 0, 2, 1), "zero cells");
        Check(e.ToString().StartsWith("Lfem.LfemException (InvalidArgument): lfem_mesh_create_box"), "ToString: " + e);
    }

    static ArgumentException ThrowsArgument(Action call, string what)
    {
        try { call(); }
        catch (ArgumentException e) { return e; }
        throw new Failure(what + ": no ArgumentException");
    }

    public static void TestVec3Arithmetic()
    {
        Vec3 a = new Vec3(1, 2, 3), b = new Vec3(-4, 5, 0.5);
        Equal(new Vec3(-3, 7, 3.5), a + b, "a + b");
        Equal(new Vec3(5, -3, 2.5), a - b, "a - b");
        Equal(new Vec3(-1, -2, -3), -a, "-a");
        Equal(new Vec3(2, 4, 6), a * 2, "a * 2");
        Equal(a * 2, 2 * a, "2 * a");
        Equal(new Vec3(0.5, 1, 1.5), a / 2, "a / 2");
        Equal(-4 + 10 + 1.5, Vec3.Dot(a, b), "dot");
        Vec3 c = Vec3.Cross(a, b);
        Equal(new Vec3(2 * 0.5 - 3 * 5, 3 * -4 - 1 * 0.5, 1 * 5 - 2 * -4), c, "cross");
        Equal(0.0, Vec3.Dot(c, a), "cross is orthogonal to a");
        Equal(0.0, Vec3.Dot(c, b), "cross is orthogonal to b");
        Equal(5.0, new Vec3(3, 4, 0).Length, "length");
        Check(a == new Vec3(1, 2, 3) && a != b && Vec3.Zero == new Vec3(), "== and !=");
        Equal("(1, 2.5, -0.1)", new Vec3(1, 2.5, -0.1).ToString(), "ToString");
    }

    public static void TestNullPointersAreRefused()
    {
        // Straight through the raw P/Invoke declarations: NULL is answered, never a crash.
        Equal(Status.InvalidArgument, Native.lfem_world_step(IntPtr.Zero, 0.01), "step(NULL)");
        Check(Library.LastError.StartsWith("lfem_world_step"), "last error: " + Library.LastError);
        Equal(Status.InvalidArgument, Native.lfem_world_create(IntPtr.Zero, IntPtr.Zero), "create(NULL, NULL)");
        uint count;
        Equal(Status.InvalidArgument, Native.lfem_world_query_contacts(IntPtr.Zero, null, 0, out count), "query(NULL)");
    }

    public static void TestDestroyedAndForeignHandlesAreRefused()
    {
        using (World world = new World())
        using (World other = new World())
        {
            Body block = AddBlock(world, Model.Paper);
            Body copy = block;
            Check(world.IsValid(block), "valid before destroy");
            world.DestroyBody(block);
            Check(!world.IsValid(copy), "stale after destroy");
            // Each error names the call made, not the count asked inside it first.
            LfemException e = Throws(() => world.GetPositions(copy), "positions of a destroyed body");
            Equal(Status.InvalidHandle, e.Status, "stale status");
            Check(e.Message.StartsWith("lfem_body_get_positions:"), "message: " + e.Message);
            Check(Throws(() => world.GetVelocities(copy), "velocities").Message.StartsWith("lfem_body_get_velocities:"), "velocities");
            Check(Throws(() => world.GetVonMisesStress(copy), "stress").Message.StartsWith("lfem_body_get_von_mises_stress:"), "stress");
            Check(Throws(() => world.GetBoundaryTriangles(copy), "triangles").Message.StartsWith("lfem_body_get_boundary_triangles:"),
                  "triangles");
            Equal(Status.InvalidHandle, Throws(() => world.DestroyBody(copy), "destroy twice").Status, "destroy twice");
            Equal(0u, world.Stats.BodyCount, "no body left");

            Body fresh = world.CreateBody(BodyDef.Default);
            Check(world.IsValid(fresh) && !world.IsValid(copy) && fresh != copy, "new generation");
            Equal(Status.InvalidHandle, Throws(() => world.NodeCount(Body.Null), "null handle").Status, "null handle");

            Body foreign = AddBlock(other, Model.Paper);
            using (World third = new World())
                Equal(Status.InvalidHandle, Throws(() => third.GetPositions(foreign), "foreign handle").Status, "foreign");
        }
    }

    public static void TestDisposedWorldIsRefused()
    {
        World world = new World();
        world.Dispose();
        Check(world.Handle.IsClosed, "handle closed");
        bool threw = false;
        try { world.Step(0.01); }
        catch (ObjectDisposedException) { threw = true; }
        Check(threw, "a disposed world throws ObjectDisposedException");
        world.Dispose(); // twice is harmless
    }

    public static void TestShortBuffersAreRefusedUntouched()
    {
        using (World world = new World())
        {
            Body block = AddBlock(world, Model.Paper);
            int n = world.NodeCount(block);
            Vec3[] shortBuffer = new Vec3[n - 1];
            for (int i = 0; i < shortBuffer.Length; ++i) shortBuffer[i] = new Vec3(7, 7, 7);
            Equal(Status.BufferTooSmall, Throws(() => world.GetPositions(block, shortBuffer), "short buffer").Status, "short status");
            foreach (Vec3 p in shortBuffer) Equal(new Vec3(7, 7, 7), p, "short buffer untouched");
            Vec3[] longBuffer = new Vec3[n + 2];
            longBuffer[n] = new Vec3(7, 7, 7);
            world.GetPositions(block, longBuffer);
            Equal(new Vec3(7, 7, 7), longBuffer[n], "beyond the nodes untouched");
            Equal(world.GetPositions(block)[n - 1], longBuffer[n - 1], "same positions");
        }
    }

    public static void TestContactQueryOfASingleBodyIsEmpty()
    {
        // A lone falling block touches nothing: the query gives a count of 0, an empty array,
        // and leaves a caller's buffer alone.
        using (World world = new World())
        {
            AddBlock(world, Model.NeoHookean);
            world.Step(0.05);
            Equal(0, world.ContactCount, "contact count");
            Equal(0, world.GetContacts().Length, "contacts");
            Equal(0, world.GetContacts(new Contact[0]), "empty buffer");
            Contact[] buffer = new Contact[4];
            for (int i = 0; i < buffer.Length; ++i) buffer[i].Node = 12345;
            Equal(0, world.GetContacts(buffer), "count into a buffer");
            foreach (Contact c in buffer) Equal(12345u, c.Node, "buffer untouched");
            Equal(0u, world.Stats.ContactCount, "stats contact count");
        }
    }

    public static void TestBlockOnAStaticPlaneTouchesTheShape()
    {
        // A block released 1 mm above a static plane (z = 0, normal +z): after 0.1 s it has
        // landed; every contact names the floor's shape 0, its normal is +z and its force pushes
        // up (frictionless: along the normal).
        using (World world = new World())
        {
            BodyDef floorDef = BodyDef.Default;
            floorDef.Type = BodyType.Static;
            Body floor = world.CreateBody(floorDef);
            world.AddShape(floor, ShapeDef.Default);
            Body block;
            using (Mesh mesh = Mesh.Box(Size, 3, 2, 1))
            {
                mesh.Translate(new Vec3(0, 0, 0.001));
                BodyDef def = BodyDef.Default;
                def.YoungModulus = 2e5;
                def.Density = Density;
                def.Friction = 0;
                def.Damping = 5;
                block = world.CreateBody(def);
                world.AddMesh(block, mesh);
            }
            world.Step(0.1);
            Contact[] contacts = world.GetContacts();
            Check(contacts.Length > 0, "the block landed");
            Equal(contacts.Length, world.ContactCount, "count");
            foreach (Contact c in contacts)
            {
                Equal(block, c.BodyA, "body a");
                Equal(floor, c.BodyB, "body b");
                Check(c.TouchesShape, "touches a shape");
                Equal(0u, c.Shape, "shape index");
                Close(1.0, c.Normal.Z, 1e-12, "normal z");
                Check(c.Force.Z >= 0, "force pushes up");
                Close(0.0, c.Force.X, 1e-9, "no friction force");
            }
            if (contacts.Length > 1)
            {
                Contact[] shortBuffer = new Contact[contacts.Length - 1];
                for (int i = 0; i < shortBuffer.Length; ++i) shortBuffer[i].Node = 12345;
                Equal(Status.BufferTooSmall, Throws(() => world.GetContacts(shortBuffer), "short buffer").Status, "short");
                foreach (Contact c in shortBuffer) Equal(12345u, c.Node, "short buffer untouched");
            }
            LfemException e = Throws(() => world.AddShape(block, ShapeDef.Default), "shape on a deformable body");
            Equal(Status.InvalidArgument, e.Status, "shape status");
            Check(e.Message.StartsWith("lfem_body_add_shape"), "message: " + e.Message);
        }
    }

    // ---- runner ----

    public static void TestABlockHeldInsideOutIsReportedOncePerSpell()
    {
        // A 10 cm cube of one cell: bottom nodes fixed, top ones driven down at 0.5 m/s through
        // the bottom for 0.3 s (to z = -0.05) and held. Every tet then has F = diag(1, 1, -0.5):
        // all inverted, J = -0.5 exactly; after 1 s held it is reported as staying so, once.
        WorldDef def = WorldDef.Default;
        def.Gravity = new Vec3(0, 0, 0);
        using (World world = new World(def))
        using (Mesh mesh = Mesh.Box(new Vec3(0.1, 0.1, 0.1), 1, 1, 1))
        {
            BodyDef d = BodyDef.Default;
            d.YoungModulus = 1e4;
            d.Damping = 20;
            Body body = world.CreateBody(d);
            world.AddMesh(body, mesh);
            Inversion rest = world.GetInversion(body);
            Equal(0u, rest.InvertedTets, "inverted at rest");
            Equal(1.0, rest.MinJacobian, "J at rest");
            uint[] bottom = world.FindNodesInBox(body, new Vec3(-1, -1, -0.01), new Vec3(1, 1, 0.01));
            uint[] top = world.FindNodesInBox(body, new Vec3(-1, -1, 0.09), new Vec3(1, 1, 0.11));
            world.FixNodes(body, bottom);
            world.PrescribeNodeVelocity(body, top, new Vec3(0, 0, -0.5));
            for (int i = 0; i < 30; ++i) world.Step(0.01);
            world.FixNodes(body, top);
            for (int i = 0; i < 100; ++i) world.Step(0.01);
            Inversion held = world.GetInversion(body);
            Equal((uint)mesh.TetCount, held.InvertedTets, "every tet inverted");
            Close(-0.5, held.MinJacobian, 1e-12, "J held");
            Close(1.1, held.InvertedFor, 2e-3, "inverted for");
            Equal(held.InvertedTets, world.Stats.InvertedTets, "stats inverted tets");
            Warning stays = world.GetWarning(WarningKind.StaysInverted);
            Equal(1ul, stays.Count, "stays inverted: once");
            Check(stays.LastBody == body, "stays inverted: the body");
            Equal(0ul, world.GetWarning(WarningKind.FallenIn).Count, "fallen in");
            world.ClearWarnings();
            foreach (WarningKind k in new[] { WarningKind.InvertedTets, WarningKind.StaysInverted, WarningKind.FallenIn,
                                              WarningKind.Unconverged })
                Equal(0ul, world.GetWarning(k).Count, "cleared " + k);
        }
    }

    public static void TestSelfContactIsForDeformableBodiesOnly()
    {
        using (World world = new World())
        {
            BodyDef d = BodyDef.Default;
            Equal((byte)0, d.SelfContact, "self-contact default");
            d.SelfContact = 1;
            d.Type = BodyType.Static;
            try
            {
                world.CreateBody(d);
                Check(false, "a static body with self-contact was accepted");
            }
            catch (LfemException e)
            {
                Equal(Status.InvalidArgument, e.Status, "status");
                Check(e.Message.Contains("self_contact"), "message names the field: " + e.Message);
            }
            d.Type = BodyType.Deformable;
            world.CreateBody(d);
        }
    }

    public static void TestABarHangsFromAFrameAndAResttingBlockSleeps()
    {
        // A bar held at its top nodes by a frame that never moves carries its weight; a block
        // settling on a plane begins one contact, falls asleep, and stepping it asleep moves
        // no node.
        WorldDef def = WorldDef.Default;
        def.EnableSleep = 1;
        using (World world = new World(def))
        using (Mesh mesh = Mesh.Box(new Vec3(0.03, 0.03, 0.3), 1, 1, 10))
        using (Mesh blockMesh = Mesh.Box(new Vec3(0.1, 0.1, 0.1), 2, 2, 2))
        {
            mesh.Translate(new Vec3(-0.015, -0.015, 0.2));
            BodyDef d = BodyDef.Default;
            d.YoungModulus = 2e5;
            d.Damping = 10;
            d.EnableSleep = 0;
            Body bar = world.CreateBody(d);
            world.AddMesh(bar, mesh);
            uint[] top = world.FindNodesInBox(bar, new Vec3(-1, -1, 0.4999), new Vec3(1, 1, 0.5001));
            Attachment held = world.AttachToFrame(bar, top, new double[] { 0, 0, 0, 1, 0, 0, 0 });
            BodyDef fd = BodyDef.Default;
            fd.Type = BodyType.Static;
            Body floor = world.CreateBody(fd);
            world.AddShape(floor, ShapeDef.Default);
            blockMesh.Translate(new Vec3(0.3, 0, 0.0005));
            BodyDef bd = BodyDef.Default;
            bd.Damping = 20;
            Body block = world.CreateBody(bd);
            world.AddMesh(block, blockMesh);
            int begins = 0, sleeps = 0;
            for (int i = 0; i < 180; ++i)
            {
                world.Step(1.0 / 60);
                foreach (Event e in world.GetEvents())
                {
                    if (e.Type == EventType.ContactBegin) ++begins;
                    if (e.Type == EventType.Sleep) { ++sleeps; Check(e.BodyA == block, "the block slept"); }
                }
            }
            Equal(1, begins, "contact begins");
            Equal(1, sleeps, "sleeps");
            Check(!world.IsAwake(block), "block asleep");
            Check(world.IsAwake(bar), "bar awake");
            double m = world.Mass(bar);
            Close(m * G, world.GetAttachmentForce(held).Z, 1e-6 * m * G, "the frame carries the bar's weight");
            Equal(1.0, world.GetAttachmentFrame(held)[3], "the frame as set");
            world.DestroyAttachment(held);
            Check(!world.IsValid(held), "destroyed");
            // Held instead by a point inside its top on a critically damped spring (k 2000 N/m):
            // 1 s later it carries the weight (to the solve's 1e-3 of it).
            Vec3 cm = world.GetCenterOfMass(bar);
            double topZ = double.NegativeInfinity;
            foreach (Vec3 p in world.GetPositions(bar)) topZ = Math.Max(topZ, p.Z);
            const double k = 2000;
            Attachment spring = world.AttachPoints(bar, new Vec3[] { new Vec3(cm.X, cm.Y, topZ - 0.001) }, Body.Null, k,
                                                   2 * Math.Sqrt(k * m));
            for (int i = 0; i < 60; ++i) world.Step(1.0 / 60);
            Close(m * G, world.GetAttachmentForce(spring).Z, 1e-3 * m * G, "the spring carries the bar's weight");
        }
    }

    public static int Main()
    {
        int passed = 0, failed = 0;
        foreach (MethodInfo m in typeof(LfemTests).GetMethods(BindingFlags.Public | BindingFlags.Static))
        {
            if (!m.Name.StartsWith("Test")) continue;
            try
            {
                m.Invoke(null, null);
                ++passed;
                Console.WriteLine("ok      " + m.Name);
            }
            catch (TargetInvocationException e)
            {
                ++failed;
                Console.WriteLine("FAILED  " + m.Name + ": " + e.InnerException);
            }
        }
        Console.WriteLine(passed + " passed, " + failed + " failed");
        return failed == 0 && passed > 0 ? 0 : 1;
    }

    public static void TestASkinFallsWithItsBlock()
    {
        // A render mesh inside a falling block: free fall moves every tet by -g t^2 / 2 exactly
        // (up to round-off), so every skin vertex follows p - g t^2 / 2; the float buffer holds
        // the same numbers rounded to float.
        using (World world = new World())
        {
            Body block = AddBlock(world, Model.Corotational);
            Vec3[] p = { new Vec3(0.05, 0.05, 2.02), new Vec3(0.25, 0.05, 2.02), new Vec3(0.05, 0.15, 2.02),
                         new Vec3(0.05, 0.05, 2.08) };
            uint[] t = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };  // a tetrahedron's faces, outward
            Equal(0u, world.AddSkin(block, p, t), "skin index");
            Equal(1, world.SkinCount(block), "skin count");
            int nv, nt;
            world.GetSkinSizes(block, 0, out nv, out nt);
            Equal(4, nv, "vertices");
            Equal(4, nt, "triangles");
            Equal(string.Join(",", t), string.Join(",", world.GetSkinTriangles(block, 0)), "triangles as given");
            world.Step(0.1);
            double time = world.Stats.Time;
            Vec3[] normals;
            Vec3[] x = world.GetSkinVertices(block, 0, out normals);
            for (int v = 0; v < 4; ++v)
            {
                Close(p[v].X, x[v].X, 1e-11, "x of vertex " + v);
                Close(p[v].Z - 0.5 * G * time * time, x[v].Z, 1e-11, "z of vertex " + v);
                Close(1.0, normals[v].Length, 1e-12, "unit normal " + v);
            }
            // Vertex 0 is the corner of three axis faces of areas 0.01, 0.006 and 0.003 m^2 (z, y, x):
            // its normal is -(0.006, 0.012, 0.02) / |.| (twice the areas).
            double len = Math.Sqrt(0.006 * 0.006 + 0.012 * 0.012 + 0.02 * 0.02);
            Close(-0.006 / len, normals[0].X, 1e-12, "corner normal x");
            Close(-0.012 / len, normals[0].Y, 1e-12, "corner normal y");
            Close(-0.02 / len, normals[0].Z, 1e-12, "corner normal z");
            float[] buffer = new float[4 * 8];
            for (int i = 0; i < buffer.Length; ++i) buffer[i] = -1f;
            world.GetSkinVertexBuffer(block, 0, buffer, 8, true);
            for (int v = 0; v < 4; ++v)
            {
                Equal((float)x[v].Z, buffer[8 * v + 2], "float z " + v);
                Equal((float)normals[v].Y, buffer[8 * v + 4], "float normal y " + v);
                Equal(-1f, buffer[8 * v + 6], "untouched " + v);
            }
            LfemException e = Throws(() => world.GetSkinVertices(block, 3, out normals), "skin 3");
            Equal(Status.InvalidArgument, e.Status, "status");
            Check(e.Message.StartsWith("lfem_body_get_skin_vertices:"), "message names the call: " + e.Message);
            Vec3[] far = { new Vec3(5, 5, 5), new Vec3(5.1, 5, 5), new Vec3(5, 5.1, 5) };
            Equal(Status.InvalidArgument, Throws(() => world.AddSkin(block, far, new uint[] { 0, 1, 2 }), "far").Status, "far");
            Equal(1, world.SkinCount(block), "nothing added");
            // Settings after creation, and the skin removed.
            world.SetFriction(block, 0.2);
            world.SetDamping(block, 1.0);
            world.SetSleepAllowed(block, false);
            world.SetMaterial(block, 3e5, 0.25);
            Equal(Status.InvalidArgument, Throws(() => world.SetMaterial(block, 3e5, 0.5), "nu 0.5").Status, "material");
            world.SetFilter(block, 1, 0xFFFFFFFFu);
            world.SetUserData(block, new IntPtr(1234));
            Equal(new IntPtr(1234), world.GetUserData(block), "user data");
            Equal(Status.InvalidArgument, Throws(() => world.SetDamping(block, -1.0), "negative damping").Status, "damping");
            world.RemoveSkin(block, 0);
            Equal(0, world.SkinCount(block), "skin removed");
        }
    }

    public static void TestATeleportedBlockLandsWithItsApproachSpeed()
    {
        // A soft block put 0.2 m above a plane by its transform (x = X + t) falls and lands at
        // sqrt(2 g H): the begin event's approach speed is within g h / 2 of it (the impact
        // sub-step's predicted mid-step velocity), its normal +z from the plane toward the block.
        using (World world = new World(WorldDef.Default))
        {
            BodyDef sd = BodyDef.Default;
            sd.Type = BodyType.Static;
            Body floor = world.CreateBody(sd);
            world.AddShape(floor, ShapeDef.Default);
            Body block = world.CreateBody(BodyDef.Default);
            using (Mesh mesh = Mesh.Box(new Vec3(0.1, 0.1, 0.1), 2, 2, 2)) world.AddMesh(block, mesh);
            double[] pose = world.GetTransform(block);
            pose[2] += 0.2;
            world.SetTransform(block, pose);
            double[] t = world.GetTransform(block);
            Close(pose[2], t[2], 1e-12, "transform z");
            Close(1.0, t[3], 1e-12, "transform w");
            double lowest = double.PositiveInfinity;
            foreach (Vec3 p in world.GetPositions(block)) lowest = Math.Min(lowest, p.Z);
            Close(0.2, lowest, 1e-12, "lowest node");
            double vImpact = Math.Sqrt(2 * 9.81 * lowest);
            Vec3 c0 = world.GetCenterOfMass(block);
            bool landed = false;
            for (int call = 0; call < 30 && !landed; ++call)
            {
                world.Step(1.0 / 60);
                foreach (Event e in world.GetEvents())
                {
                    if (e.Type != EventType.ContactBegin) continue;
                    double h = world.Stats.StepSize;
                    Close(vImpact, e.ApproachSpeed, 0.5 * 9.81 * h * (1 + 1e-9), "approach speed");
                    Close(1.0, e.Normal.Z, 1e-12, "normal");
                    Check(Math.Abs(e.Point.Z) < 1e-3 * vImpact * h, "point on the plane");
                    landed = true;
                }
            }
            Check(landed, "landed");
            Check(world.GetCenterOfMass(block).Z < c0.Z, "fell");
            // The nearest point of the block's surface to a point 1 m above its centre of mass.
            double top = double.NegativeInfinity;
            foreach (Vec3 p in world.GetPositions(block)) top = Math.Max(top, p.Z);
            Vec3 cm = world.GetCenterOfMass(block);
            uint tri;
            double dist;
            Vec3 q = world.ClosestPoint(block, new Vec3(cm.X, cm.Y, top + 1), out tri, out dist);
            Close(top, q.Z, 1e-12, "closest point on the top");
            Close(1.0, dist, 1e-12, "its distance");
            // An impulse at its centre of mass: its momentum grows by exactly that (round-off).
            Vec3 p0, p1, l;
            world.GetMomentum(block, out p0, out l);
            world.ApplyImpulse(block, world.GetCenterOfMass(block), new Vec3(0.5, 0, 0.2));
            world.GetMomentum(block, out p1, out l);
            Close(0.5, p1.X - p0.X, 1e-12, "impulse x");
            Close(0.2, p1.Z - p0.Z, 1e-12, "impulse z");
            bool refused = false;
            try { world.SetTransform(floor, pose); }
            catch (LfemException e) { refused = e.Status == Status.InvalidArgument; }
            Check(refused, "a static body does not move");
        }
    }

    public static void TestAForceActsForOneCallAndAUserIdIsKept()
    {
        // Weightless: a force F at the cube's centre for one call of dt gives it F dt of momentum
        // exactly (central differences; round-off of sums over its nodes), the next call nothing.
        WorldDef def = WorldDef.Default;
        def.Gravity = Vec3.Zero;
        using (World world = new World(def))
        {
            Body cube = world.CreateBody(BodyDef.Default);
            using (Mesh mesh = Mesh.Box(new Vec3(0.2, 0.2, 0.2), 2, 2, 2)) world.AddMesh(cube, mesh);
            Equal(0ul, world.GetUserId(cube), "user id at creation");
            Equal(BodyType.Deformable, world.GetBodyType(cube), "its type");
            bool refused = false;
            try { world.SetBodyType(cube, BodyType.Rigid); }
            catch (LfemException e) { refused = e.Status == Status.InvalidArgument; }
            Check(refused, "a deformable body keeps its type");
            world.SetUserId(cube, 0xFEDCBA9876543210ul);
            Equal(0xFEDCBA9876543210ul, world.GetUserId(cube), "user id");
            const double dt = 1.0 / 60;
            world.ApplyForce(cube, world.GetCenterOfMass(cube), new Vec3(3, 0, -1));
            world.Step(dt);
            Vec3 p1, p2, l;
            world.GetMomentum(cube, out p1, out l);
            Close(3 * dt, p1.X, 1e-12, "force x dt");
            Close(-dt, p1.Z, 1e-12, "force z dt");
            world.Step(dt);
            world.GetMomentum(cube, out p2, out l);
            Close(p1.X, p2.X, 1e-12, "no force on the next call");
        }
    }

    public static void TestRaysAndBoxesFindWhatIsThere()
    {
        // A static sphere of radius 0.5 about (2, 0, 0): a ray along +x at height 0.3 meets it at
        // 2 - sqrt(0.25 - 0.09) = 1.6 with normal (p - c) / r; a cube [0, 0.2]^3 is crossed at 1
        // and 1.2 by a ray from x = -1.
        WorldDef def = WorldDef.Default;
        def.Gravity = Vec3.Zero;
        using (World world = new World(def))
        {
            BodyDef sd = BodyDef.Default;
            sd.Type = BodyType.Static;
            Body ground = world.CreateBody(sd);
            ShapeDef shape = ShapeDef.Default;
            shape.Type = ShapeType.Sphere;
            shape.Center = new Vec3(2, 0, 0);
            shape.Radius = 0.5;
            world.AddShape(ground, shape);
            Body cube = world.CreateBody(BodyDef.Default);
            using (Mesh mesh = Mesh.Box(new Vec3(0.2, 0.2, 0.2), 2, 2, 2)) world.AddMesh(cube, mesh);
            QueryFilter filter = QueryFilter.Default;
            // A sphere 0.3 above the static sphere's top (radius 0.31) meets it at its top, 0.3
            // away; one of radius 0.06 over the cube's top face (0.05 above) meets it below.
            Overlap[] o = world.OverlapSphere(new Vec3(2, 0, 0.8), 0.31, filter);
            Equal(1, o.Length, "one overlap");
            Equal(ground, o[0].Body, "the sphere's body");
            Equal(0u, o[0].Shape, "its shape");
            Close(0.5, o[0].Point.Z, 1e-12, "its top");
            Close(0.3, o[0].Distance, 1e-12, "0.3 away");
            o = world.OverlapCapsule(new Vec3(0.07, 0.13, 0.25), new Vec3(0.07, 0.13, 0.25), 0.06, filter);
            Equal(1, o.Length, "the cube");
            Equal(cube, o[0].Body, "the cube's body");
            Close(0.2, o[0].Point.Z, 1e-12, "its top face");
            Close(0.05, o[0].Distance, 1e-12, "0.05 away");
            Equal(0, world.OverlapSphere(new Vec3(2, 0, 0.8), 0.29, filter).Length, "out of reach");
            // A sphere of 0.1 cast along -x from x = 4 at the static sphere: it stops 4 - 2 - 0.5
            // - 0.1 away, touching it at x = 2.5.
            RayHit sh;
            Check(world.CastSphere(new Vec3(4, 0, 0), new Vec3(-1, 0, 0), 0.1, double.PositiveInfinity, filter, out sh), "sphere cast hits");
            Close(1.4, sh.Distance, 1e-12, "sphere cast distance");
            Close(2.5, sh.Point.X, 1e-12, "the point touched");
            Equal(1u, filter.CategoryBits, "default category");
            Equal(0xFFFFFFFFu, filter.MaskBits, "default mask");
            RayHit hit;
            Check(world.CastRay(new Vec3(0, 0, 0.3), new Vec3(3, 0, 0), double.PositiveInfinity, filter, out hit), "sphere hit");
            Equal(ground, hit.Body, "body");
            Check(hit.HitsShape, "a shape");
            Close(1.6, hit.Distance, 1e-12, "distance");
            Close(-0.8, hit.Normal.X, 1e-12, "normal x");
            Close(0.6, hit.Normal.Z, 1e-12, "normal z");
            RayHit[] all = world.CastRayAll(new Vec3(-1, 0.07, 0.03), new Vec3(1, 0, 0), double.PositiveInfinity, filter);
            Equal(4, all.Length, "crossings");
            Close(1.0, all[0].Distance, 1e-12, "cube entry");
            Close(1.2, all[1].Distance, 1e-12, "cube exit");
            Equal(cube, all[0].Body, "cube first");
            Check(!all[0].HitsShape && all[0].Triangle != RayHit.None, "a triangle");
            for (int i = 1; i < all.Length; ++i) Check(all[i - 1].Distance <= all[i].Distance, "sorted");
            Check(!world.CastRay(new Vec3(-1, 0.07, 0.03), new Vec3(1, 0, 0), 0.99, filter, out hit), "too short");
            QueryFilter blind = filter;
            blind.MaskBits = 2;
            Check(!world.CastRay(new Vec3(0, 0, 0.3), new Vec3(1, 0, 0), double.PositiveInfinity, blind, out hit), "filtered");
            Body[] inside = world.OverlapBox(new Vec3(0.1, 0.1, 0.1), new Vec3(0.12, 0.12, 0.12), filter);
            Equal(1, inside.Length, "box in the cube");
            Equal(cube, inside[0], "the cube");
            Equal(2, world.OverlapBox(new Vec3(-5, -5, -5), new Vec3(5, 5, 5), filter).Length, "everything");
            Equal(0, world.OverlapBox(new Vec3(0.5, 0.5, 0.5), new Vec3(0.6, 0.6, 0.6), filter).Length, "nothing");
            LfemException e = Throws(() => world.CastRay(Vec3.Zero, Vec3.Zero, 1, filter, out hit), "zero direction");
            Equal(Status.InvalidArgument, e.Status, "status");
            Check(world.Profile.Queries >= 7, "counted");
        }
    }
}
