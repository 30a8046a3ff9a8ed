// C# bindings of lfem (include_c/lfem.h): P/Invoke into the native library "lfem" (liblfem.so,
// liblfem.dylib, lfem.dll), cdecl. One file, no dependency beyond mscorlib, no unsafe code:
// drop it into a Unity, Godot C# or .NET project next to the native library.
//
// - Structs are blittable and laid out as in C (flags are byte, never bool; arrays of 3 doubles
//   are Vec3). Their sizes are checked by tests/LfemTests.cs against the C sizes.
// - Every failing call of the library throws LfemException carrying the Status and
//   lfem_last_error's message; a failed call changes nothing. Arguments refused by the binding
//   itself (null, arrays of the wrong length) throw the ArgumentException family, as .NET code
//   expects.
// - World, Mesh and VtkSeries own their native object through a SafeHandle: Dispose() (or the
//   finalizer) frees it. Body is a plain value handle; a destroyed body's handle is refused with
//   Status.InvalidHandle.
// - One World must not be used by two threads at once (lfem does no locking).
using System;
using System.Runtime.InteropServices;
using Microsoft.Win32.SafeHandles;

namespace Lfem
{
    public enum Status : int
    {
        Ok = 0,
        InvalidArgument = 1, // a null pointer, a NaN, a number out of its range
        InvalidMesh = 2,     // bad indices, inverted or zero-volume tets, unused nodes
        InvalidHandle = 3,   // a stale, foreign or null body handle
        BufferTooSmall = 4,  // the caller's capacity is below what the answer needs
        Unstable = 5,        // the state blew up; the world was rolled back
        IoError = 6,         // a file could not be read or written, or is malformed
        OutOfMemory = 7,
        InternalError = 8,   // a bug in lfem: please report it with the message
        Unsupported = 9,     // this build leaves the feature out (LFEM_WITH_CCD, LFEM_WITH_IO)
    }

    public enum BodyType : int
    {
        Deformable = 0, // finite elements, moves and deforms
        Static = 1,     // never moves (a floor, a wall)
        Kinematic = 2,  // moves rigidly with a prescribed velocity
        Rigid = 3,      // global translation and rotation alone, moved by forces and contacts
    }

    /// <summary>lfem_warning_kind: what a warning counts.</summary>
    public enum WarningKind : int
    {
        InvertedTets = 0,  // a sub-step ended with inverted tets in a body: once per body and sub-step
        StaysInverted = 1, // a body kept inverted tets for 0.5 s in a row: once per spell
        FallenIn = 2,      // nodes found inside another body (or their own), pushed out
        Unconverged = 3,   // a contact solve used every sweep and ended above its tolerance
    }

    public enum Model : int
    {
        Paper = 0,        // floating frame: one global rotation per body (eq. 2)
        Corotational = 1, // one rotation per tet: large local rotations (bending)
        NeoHookean = 2,   // stable neo-Hookean hyperelasticity: large strains
        Linear = 3,       // small-strain linear elasticity, no rotation at all
    }

    /// <summary>Three doubles, laid out as C's double[3]: a position (m), a velocity (m/s), a
    /// force (N). The usual vector arithmetic; == compares exactly.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3 : IEquatable<Vec3>
    {
        public double X, Y, Z;

        public Vec3(double x, double y, double z) { X = x; Y = y; Z = z; }

        public static readonly Vec3 Zero = new Vec3(0, 0, 0);

        public static Vec3 operator +(Vec3 a, Vec3 b) { return new Vec3(a.X + b.X, a.Y + b.Y, a.Z + b.Z); }
        public static Vec3 operator -(Vec3 a, Vec3 b) { return new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z); }
        public static Vec3 operator -(Vec3 a) { return new Vec3(-a.X, -a.Y, -a.Z); }
        public static Vec3 operator *(Vec3 a, double s) { return new Vec3(a.X * s, a.Y * s, a.Z * s); }
        public static Vec3 operator *(double s, Vec3 a) { return a * s; }
        public static Vec3 operator /(Vec3 a, double s) { return new Vec3(a.X / s, a.Y / s, a.Z / s); }
        public static bool operator ==(Vec3 a, Vec3 b) { return a.Equals(b); }
        public static bool operator !=(Vec3 a, Vec3 b) { return !a.Equals(b); }

        public static double Dot(Vec3 a, Vec3 b) { return a.X * b.X + a.Y * b.Y + a.Z * b.Z; }
        public static Vec3 Cross(Vec3 a, Vec3 b)
        {
            return new Vec3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        }
        public double LengthSquared { get { return Dot(this, this); } }
        public double Length { get { return Math.Sqrt(LengthSquared); } }

        public bool Equals(Vec3 o) { return X == o.X && Y == o.Y && Z == o.Z; }
        public override bool Equals(object o) { return o is Vec3 && Equals((Vec3)o); }
        public override int GetHashCode() { return X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919); }

        /// <summary>"(x, y, z)" with '.' decimals whatever the culture, round-trip precision.</summary>
        public override string ToString()
        {
            System.Globalization.CultureInfo c = System.Globalization.CultureInfo.InvariantCulture;
            return "(" + X.ToString("R", c) + ", " + Y.ToString("R", c) + ", " + Z.ToString("R", c) + ")";
        }
    }

    /// <summary>lfem_world_def. Start from WorldDef.Default and edit.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WorldDef
    {
        public Vec3 Gravity;            // m/s^2, default (0, 0, -9.81)
        public double TimeStep;         // s; 0 (default) = automatic
        public double StepSafety;       // fraction of the stable limit, in (0, 1), default 0.9
        public uint ContactIterations;  // default 200
        public uint ThreadCount;        // 1..64, default 1; results are the same for every count
        public double ContactTolerance; // default 1e-3
        public uint MaxSubsteps;        // default 1000000
        public byte AllowUnstableStep;  // 1 = skip the up-front stability check, default 0
        public byte EnableSleep;        // 1 = bodies at rest fall asleep, default 0
#pragma warning disable 0169, 0649 // set by lfem_world_def_default, never by C#
        private byte padding1, padding2;
        private uint internalValue;
        private uint padding3;
#pragma warning restore 0169, 0649
        public double MassScalingStep;  // s; 0 (default) = off: tets that would need a shorter
                                        // sub-step get added mass (see lfem_world_def)
        public double SleepVelocity;    // m/s, default 0.01
        public double SleepTime;        // s, default 0.5

        /// <summary>The defaults (lfem_world_def_default).</summary>
        public static WorldDef Default { get { return Native.lfem_world_def_default(); } }
    }

    /// <summary>lfem_world_stats.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WorldStats
    {
        public double Time;             // s, simulated time
        public ulong Steps;             // sub-steps since creation
        public double StepSize;         // s, last sub-step
        public double StableStep;       // s
        public uint SubstepsLastCall;
        public uint BodyCount;
        public double KineticEnergy;    // J
        public double StrainEnergy;     // J
        public double ExternalWork;     // J
        public double DissipatedEnergy; // J
        public double EnergyError;      // J
        public Vec3 LinearMomentum;     // kg m/s
        public Vec3 AngularMomentum;    // kg m^2/s, about the origin
        public uint ContactCount;
        public uint SolverIterations;
        public double SolverResidual;   // m
        public double MaxPenetration;   // m
        public double RotationDrift;    // rad
        public double AddedMass;        // kg, by mass scaling
        public uint InvertedTets;       // tets with J = det F <= 0 after the last sub-step
#pragma warning disable 0169 // padding
        private uint padding;
#pragma warning restore 0169
        public double MinJacobian;      // the smallest volume ratio J of the tets (1 without any)
    }

    /// <summary>An attachment handle (lfem_attachment): a value.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Attachment : IEquatable<Attachment>
    {
        public uint Index;
        public uint Generation;
        public bool Equals(Attachment o) { return Index == o.Index && Generation == o.Generation; }
        public override bool Equals(object o) { return o is Attachment && Equals((Attachment)o); }
        public override int GetHashCode() { return (int)(Index * 2654435761u ^ Generation); }
    }

    /// <summary>lfem_attachment_def (what the native call takes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct AttachmentDef
    {
        public Body Body;
        public Body Target;       // Body.Null: the caller's frame
        public IntPtr Nodes;
        public uint NodeCount;
        public uint InternalValue;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 7)] public double[] Frame;
        public double BreakForce;
        public IntPtr Points;     // instead of Nodes: PointCount points (3 doubles each)
        public uint PointCount;
        public double Stiffness;  // N/m per point and axis, 0: rigid
        public double Damping;    // N s/m, with a stiffness
    }

    public enum EventType : int
    {
        ContactBegin = 0, // a pair began to touch during the step
        ContactEnd = 1,   // a pair that touched stopped
        Sleep = 2,        // BodyA fell asleep
        Wake = 3,         // BodyA woke
        AttachmentBroken = 4,
        ContactPersist = 5, // a pair still touching (when either body reports its contacts)
    }

    /// <summary>lfem_event: one event of the last step.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Event
    {
        public EventType Type;
        public uint ContactCount;     // contact events: the pair's active contacts after the step
        public Body BodyA, BodyB;
        public Attachment Attachment;
        public double NormalImpulse;  // N s, a pair's over the step
        public double MaxForce;       // N
        public double ApproachSpeed;  // m/s, contact events: the pair's fastest approach in the step
        public Vec3 Point;            // m, contact events: where it was
        public Vec3 Normal;           // contact events: unit, from BodyA toward BodyB
    }

    /// <summary>lfem_warning: how often, when last, for which body.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Warning
    {
        public ulong Count;      // since creation or World.ClearWarnings
        public double LastTime;  // s, of the last one (0 before any)
        public Body LastBody;    // Body.Null when none is concerned
    }

    /// <summary>A body's inverted tets after the last sub-step (lfem_body_get_inversion).</summary>
    public struct Inversion
    {
        public uint InvertedTets;  // tets with J = det F <= 0
        public double MinJacobian; // the smallest J
        public double InvertedFor; // s, inverted without a break (0 when none)
    }

    /// <summary>lfem_phase_time: wall time (s) and run count of one phase of the step.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PhaseTime
    {
        public double Seconds;
        public ulong Calls;
    }

    /// <summary>lfem_profile: per-phase time and counts of the step, accumulated.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Profile
    {
        public ulong Substeps;
        public PhaseTime InternalForces;
        public PhaseTime Predictor;
        public PhaseTime KinematicMotion;
        public PhaseTime BroadPhase;
        public PhaseTime NarrowPhase;
        public PhaseTime ShapeQueries;
        public ulong ShapeTests;
        public ulong CcdQueries;
        public PhaseTime NormalSolve;
        public PhaseTime Friction;
        public PhaseTime GlobalRotation;
        public PhaseTime Commit;
        public ulong CandidateSearches; // contact's searches for candidate faces anew
        public ulong Queries;           // rays and boxes the queries answered
        public ulong QueryBodies;       // bodies a query reached (box met, filter passed)
        public ulong QueryPrimitives;   // triangles and shapes a query tested exactly
        public ulong QueryRefits;       // moving bodies' trees built or refitted for the queries
        public ulong ContactSweeps;     // contact solve sweeps (slowest group per sub-step), summed
        public ulong ConstraintUpdates; // updates of one constraint in a sweep, summed
    }

    /// <summary>A query's collision filter (lfem_query_filter), as the bodies' own: a body is
    /// seen when (body.CategoryBits &amp; MaskBits) != 0 and (CategoryBits &amp; body.MaskBits) != 0.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct QueryFilter
    {
        public uint CategoryBits;   // default 1
        public uint MaskBits;       // default all bits

        /// <summary>The defaults (lfem_query_filter_default).</summary>
        public static QueryFilter Default { get { return Native.lfem_query_filter_default(); } }
    }

    /// <summary>Where a ray crossed a surface (lfem_ray_hit).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct RayHit
    {
        public Body Body;
        public uint Triangle;         // the body's boundary triangle, or None for a shape
        public uint Shape;            // the body's shape, or None for a triangle
        public double Barycentric1, Barycentric2; // t1, t2: (1 - t1 - t2) a + t2 b + t1 c (0 for a shape)
        public Vec3 Point;            // m, on the ray
        public Vec3 Normal;           // unit, out of the surface hit
        public double Distance;       // m from the origin along the unit ray

        public const uint None = 0xFFFFFFFFu;

        public bool HitsShape { get { return Shape != None; } }
    }

    /// <summary>A body a sphere or capsule overlaps, and where (lfem_overlap).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Overlap
    {
        public Body Body;
        public uint Triangle;         // its boundary triangle nearest the query's core, or None
        public uint Shape;            // its shape nearest the core, or None
        public Vec3 Point;            // m, the point of that triangle or shape nearest the core
        public double Distance;       // m from the core to Point; 0 inside

        public const uint None = 0xFFFFFFFFu;
    }

    /// <summary>A body handle (lfem_body): a value. Body.Null is {0, 0}.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Body : IEquatable<Body>
    {
        public uint Index;
        public uint Generation;

        public static readonly Body Null = new Body();

        public bool Equals(Body o) { return Index == o.Index && Generation == o.Generation; }
        public override bool Equals(object o) { return o is Body && Equals((Body)o); }
        public override int GetHashCode() { return (int)(Index * 2654435761u ^ Generation); }
        public static bool operator ==(Body a, Body b) { return a.Equals(b); }
        public static bool operator !=(Body a, Body b) { return !a.Equals(b); }
        public override string ToString() { return "Body(" + Index + ", " + Generation + ")"; }
    }

    /// <summary>lfem_body_def. Start from BodyDef.Default and edit.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BodyDef
    {
        public BodyType Type;         // default Deformable
        public Model Model;           // default Paper
        public double YoungModulus;   // Pa, > 0, default 1e6
        public double PoissonRatio;   // (-1, 0.5), default 0.3
        public double Density;        // kg/m^3, > 0, default 1000
        public double Damping;        // 1/s, >= 0, default 0
        public double Friction;       // Coulomb coefficient, >= 0, default 0.5
        public Vec3 LinearVelocity;   // m/s, initial (kinematic: constant)
        public Vec3 AngularVelocity;  // rad/s, initial spin about the centre of mass
        public uint CategoryBits;     // collision filter: what this body is, default 1
        public uint MaskBits;         // collision filter: what it collides with, default all
        public IntPtr UserData;       // returned by World.GetUserData
#pragma warning disable 0169, 0649 // set by lfem_body_def_default, never by C#
        private uint internalValue;
#pragma warning restore 0169, 0649
        public byte EnableSleep;      // 1 (default) = may fall asleep when the world allows it
        public byte SelfContact;      // 1 = the surface collides with itself (deformable only), default 0
        public byte CompositeTets;    // 1 = 10-node tets as the composite element, default 0
        public byte ReportContacts;   // 1 = every step reports the pairs that stay in touch, default 0
        public byte EdgeContacts;     // 1 (default) = sharp edges crossing other bodies' are held apart

        /// <summary>The defaults (lfem_body_def_default).</summary>
        public static BodyDef Default { get { return Native.lfem_body_def_default(); } }
    }

    /// <summary>One active node-to-triangle contact of the last step (lfem_contact).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Contact
    {
        public Body BodyA;            // owns the node
        public Body BodyB;            // owns the triangle
        public uint Node;             // node index in BodyA
        public uint TriangleA, TriangleB, TriangleC; // node indices in BodyB
        public double Barycentric1, Barycentric2;    // t1, t2: (1 - t1 - t2) a + t2 b + t1 c
        public Vec3 Position;         // m, on the triangle
        public Vec3 Normal;           // unit, out of BodyB's surface
        public Vec3 Force;            // N, on the node
        public byte Sliding;          // 1 when friction is on the Coulomb cone
        public byte Kind;             // 0 node-face, 1 node-shape, 2 face-shape, 3 edge-edge (lfem_contact_kind)
#pragma warning disable 0169 // C padding
        private byte padding1, padding2;
#pragma warning restore 0169
        public uint Shape;            // index of BodyB's rigid shape, or NoShape for a triangle
        public Vec3 WeightsA;         // BodyA's point: sum of WeightsA[k] x node NodesA[k]
        public uint NodesA0, NodesA1, NodesA2; // node indices in BodyA (NoShape: unused)
#pragma warning disable 0169 // C padding
        private uint padding3;
#pragma warning restore 0169

        public const uint NoShape = 0xFFFFFFFFu;

        public bool IsSliding { get { return Sliding != 0; } }
        public bool TouchesShape { get { return Shape != NoShape; } }
    }

    public enum ShapeType : int
    {
        Plane = 0,      // the half-space below the plane through Center with normal local +z
        Box = 1,        // HalfExtents along the local axes
        Sphere = 2,     // Radius
        Capsule = 3,    // segment -HalfLength..+HalfLength along local z, swept by Radius
        ConvexHull = 4, // convex hull of points (local coordinates), see World.AddShape
    }

    /// <summary>A rigid shape of a static or kinematic body (lfem_shape_def). Start from
    /// ShapeDef.Default; convex hull points are passed to World.AddShape.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ShapeDef
    {
        public ShapeType Type;       // default Plane
        public uint PointCount;      // set by World.AddShape from its points
        public Vec3 Center;          // m, world position of the local origin, default 0
        public double RotationW, RotationX, RotationY, RotationZ; // unit quaternion, default identity
        public Vec3 HalfExtents;     // m, box, default 0.5
        public double Radius;        // m, sphere and capsule, default 0.5
        public double HalfLength;    // m, capsule, default 0.5
        public IntPtr Points;        // set by World.AddShape (3 * PointCount doubles)
#pragma warning disable 0169, 0649 // set by lfem_shape_def_default, never by C#
        private uint internalValue;
        private uint padding;
#pragma warning restore 0169, 0649

        /// <summary>The defaults (lfem_shape_def_default).</summary>
        public static ShapeDef Default { get { return Native.lfem_shape_def_default(); } }
    }

    /// <summary>A failed lfem call: its status and lfem_last_error's message.</summary>
    public class LfemException : Exception
    {
        public Status Status { get; private set; }

        public LfemException(Status status, string message) : base(message) { Status = status; }

        /// <summary>The exception for a call that just returned status on this thread.</summary>
        internal static LfemException FromLastError(Status status)
        {
            return new LfemException(status, Library.PtrToString(Native.lfem_last_error()));
        }

        internal static void Check(Status status)
        {
            if (status != Status.Ok) throw FromLastError(status);
        }

        /// <summary>The same error naming the call the user made (outer, e.g.
        /// lfem_body_get_positions) in place of the helper call that failed first inside it
        /// (inner, a count).</summary>
        internal LfemException Renamed(string inner, string outer)
        {
            if (!Message.StartsWith(inner + ":", StringComparison.Ordinal)) return this;
            return new LfemException(Status, outer + Message.Substring(inner.Length));
        }

        /// <summary>The type, the status and the message (Exception.ToString() would leave the
        /// status out), then the stack trace.</summary>
        public override string ToString()
        {
            string s = GetType().FullName + " (" + Status + "): " + Message;
            return StackTrace == null ? s : s + Environment.NewLine + StackTrace;
        }
    }

    /// <summary>Version and status names of the loaded library.</summary>
    public static class Library
    {
        public const int VersionMajor = 0, VersionMinor = 5, VersionPatch = 0;

        /// <summary>(major &lt;&lt; 16) | (minor &lt;&lt; 8) | patch of the library loaded.</summary>
        public static uint Version { get { return Native.lfem_version(); } }
        public static string VersionString { get { return PtrToString(Native.lfem_version_string()); } }

        /// <summary>e.g. "LFEM_INVALID_MESH: invalid mesh".</summary>
        public static string StatusString(Status status) { return PtrToString(Native.lfem_status_string(status)); }

        /// <summary>The message of this thread's last failed call ("" before any).</summary>
        public static string LastError { get { return PtrToString(Native.lfem_last_error()); } }

        internal static string PtrToString(IntPtr p)
        {
            if (p == IntPtr.Zero) return "";
            int n = 0;
            while (Marshal.ReadByte(p, n) != 0) ++n;
            byte[] bytes = new byte[n];
            Marshal.Copy(p, bytes, 0, n);
            return System.Text.Encoding.UTF8.GetString(bytes);
        }

        internal static byte[] ToCString(string s)
        {
            if (s == null) throw new ArgumentNullException("s");
            byte[] utf8 = System.Text.Encoding.UTF8.GetBytes(s);
            byte[] z = new byte[utf8.Length + 1];
            Array.Copy(utf8, z, utf8.Length);
            return z;
        }
    }

    public sealed class WorldHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        private WorldHandle() : base(true) { }
        protected override bool ReleaseHandle() { Native.lfem_world_destroy(handle); return true; }
    }

    public sealed class MeshHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        private MeshHandle() : base(true) { }
        protected override bool ReleaseHandle() { Native.lfem_mesh_destroy(handle); return true; }
    }

    public sealed class VtkSeriesHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        private VtkSeriesHandle() : base(true) { }
        protected override bool ReleaseHandle() { Native.lfem_vtk_series_destroy(handle); return true; }
    }

    /// <summary>A simulation world; Dispose() destroys it and all its bodies.</summary>
    public sealed class World : IDisposable
    {
        private readonly WorldHandle handle;

        public World() : this(WorldDef.Default) { }

        public World(WorldDef def)
        {
            WorldHandle h;
            LfemException.Check(Native.lfem_world_create(ref def, out h));
            handle = h;
        }

        private World(WorldHandle h) { handle = h; }

        /// <summary>A new world from a checkpoint written by Save; stepping it continues the
        /// saved run bit for bit. Body handles of the saved world are valid in it.</summary>
        public static World Load(string path)
        {
            WorldHandle h;
            Status s = Native.lfem_world_load(Library.ToCString(path), out h);
            if (s != Status.Ok)
            {
                LfemException e = LfemException.FromLastError(s);
                if (h != null) h.Dispose();
                throw e;
            }
            return new World(h);
        }

        /// <summary>Write a checkpoint of the whole world (replaces path only once complete).</summary>
        public void Save(string path) { LfemException.Check(Native.lfem_world_save(handle, Library.ToCString(path))); }

        public WorldHandle Handle { get { return handle; } }

        public void Dispose() { handle.Dispose(); }

        /// <summary>Advance by dt seconds (split into stable sub-steps).</summary>
        public void Step(double dt) { LfemException.Check(Native.lfem_world_step(handle, dt)); }

        public void SetGravity(Vec3 gravity) { LfemException.Check(Native.lfem_world_set_gravity(handle, ref gravity)); }

        /// <summary>Fixed sub-step (s), 0 = automatic.</summary>
        public void SetTimeStep(double timeStep) { LfemException.Check(Native.lfem_world_set_time_step(handle, timeStep)); }

        /// <summary>The stable limit of the step (s); infinity without deformable bodies.</summary>
        public double StableStep
        {
            get { double s; LfemException.Check(Native.lfem_world_get_stable_step(handle, out s)); return s; }
        }

        public WorldStats Stats
        {
            get { WorldStats s; LfemException.Check(Native.lfem_world_get_stats(handle, out s)); return s; }
        }

        /// <summary>Per-phase time and counts since creation or ResetProfile.</summary>
        public Profile Profile
        {
            get { Profile p; LfemException.Check(Native.lfem_world_get_profile(handle, out p)); return p; }
        }

        public void ResetProfile() { LfemException.Check(Native.lfem_world_reset_profile(handle)); }

        /// <summary>Hold nodes of a deformable body at their offsets in a target body's frame
        /// (rigid, kinematic or static).</summary>
        public Attachment Attach(Body body, uint[] nodes, Body target, double breakForce = 0)
        {
            return CreateAttachment(body, nodes, target, new double[] { 0, 0, 0, 1, 0, 0, 0 }, breakForce);
        }

        /// <summary>Hold nodes at their offsets in a frame the caller moves (centre, quaternion
        /// w x y z at creation).</summary>
        public Attachment AttachToFrame(Body body, uint[] nodes, double[] frame, double breakForce = 0)
        {
            if (frame == null || frame.Length != 7) throw new ArgumentException("frame must hold 7 numbers", "frame");
            return CreateAttachment(body, nodes, Body.Null, frame, breakForce);
        }

        Attachment CreateAttachment(Body body, uint[] nodes, Body target, double[] frame, double breakForce)
        {
            if (nodes == null) throw new ArgumentNullException("nodes");
            AttachmentDef d = Native.lfem_attachment_def_default();
            d.Body = body;
            d.Target = target;
            d.NodeCount = (uint)nodes.Length;
            d.Frame = (double[])frame.Clone();
            d.BreakForce = breakForce;
            return CreatePinned(d, nodes, true);
        }

        /// <summary>Hold points (m) of a deformable body where they are (each bound once to the tet
        /// around it) at their offsets in the frame of target (Body.Null: the identity frame the
        /// caller moves), or at the same material points of a deformable target; rigidly
        /// (stiffness 0) or by a spring (N/m) with a damper (N s/m).</summary>
        public Attachment AttachPoints(Body body, Vec3[] points, Body target, double stiffness = 0, double damping = 0,
                                       double breakForce = 0)
        {
            if (points == null) throw new ArgumentNullException("points");
            AttachmentDef d = Native.lfem_attachment_def_default();
            d.Body = body;
            d.Target = target;
            d.PointCount = (uint)points.Length;
            d.Stiffness = stiffness;
            d.Damping = damping;
            d.BreakForce = breakForce;
            return CreatePinned(d, points, false);
        }

        // The native call with the nodes or the points pinned for its duration.
        Attachment CreatePinned(AttachmentDef d, object held, bool nodes)
        {
            GCHandle pin = GCHandle.Alloc(held, GCHandleType.Pinned);
            try
            {
                if (nodes) d.Nodes = pin.AddrOfPinnedObject();
                else d.Points = pin.AddrOfPinnedObject();
                Attachment a;
                LfemException.Check(Native.lfem_attachment_create(handle, ref d, out a));
                return a;
            }
            finally { pin.Free(); }
        }

        public void DestroyAttachment(Attachment a) { LfemException.Check(Native.lfem_attachment_destroy(handle, a)); }
        public bool IsValid(Attachment a) { return Native.lfem_attachment_is_valid(handle, a) == 1; }

        /// <summary>Where the caller's frame is to be at the end of the next step.</summary>
        public void SetAttachmentFrame(Attachment a, double[] frame)
        {
            if (frame == null || frame.Length != 7) throw new ArgumentException("frame must hold 7 numbers", "frame");
            LfemException.Check(Native.lfem_attachment_set_frame(handle, a, frame));
        }

        /// <summary>The total force (N) on the attachment's nodes at the last sub-step.</summary>
        public Vec3 GetAttachmentForce(Attachment a)
        {
            Vec3 f; LfemException.Check(Native.lfem_attachment_get_force(handle, a, out f)); return f;
        }

        public void Wake(Body body) { LfemException.Check(Native.lfem_body_wake(handle, body)); }

        /// <summary>Whether a body is awake (LfemException for a bad handle).</summary>
        public bool IsAwake(Body body)
        {
            int r = Native.lfem_body_is_awake(handle, body);
            if (r < 0) throw new LfemException(Status.InvalidHandle, "body handle is stale or of another world");
            return r == 1;
        }

        /// <summary>The events of the last step.</summary>
        public Event[] GetEvents()
        {
            uint n;
            Native.lfem_world_get_events(handle, null, 0, out n);
            Event[] e = new Event[n];
            LfemException.Check(Native.lfem_world_get_events(handle, e, n, out n));
            return e;
        }

        /// <summary>One warning counter (lfem_world_get_warning).</summary>
        public Warning GetWarning(WarningKind kind)
        {
            Warning w; LfemException.Check(Native.lfem_world_get_warning(handle, kind, out w)); return w;
        }

        public void ClearWarnings() { LfemException.Check(Native.lfem_world_clear_warnings(handle)); }

        // ---- bodies ----

        public Body CreateBody(BodyDef def)
        {
            Body b;
            LfemException.Check(Native.lfem_body_create(handle, ref def, out b));
            return b;
        }

        public void DestroyBody(Body body) { LfemException.Check(Native.lfem_body_destroy(handle, body)); }

        public bool IsValid(Body body) { return Native.lfem_body_is_valid(handle, body) != 0; }

        /// <summary>Add the tets of a mesh (copied): 4-node tets, or 10-node ones
        /// (Mesh.MakeQuadratic, a Gmsh file of type 11) through lfem_body_add_quadratic_mesh.</summary>
        public void AddMesh(Body body, Mesh mesh)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            if (mesh.NodesPerTet == 10)
                LfemException.Check(Native.lfem_body_add_quadratic_mesh(handle, body, Native.lfem_mesh_get_positions(mesh.Handle),
                    Native.lfem_mesh_get_node_count(mesh.Handle), Native.lfem_mesh_get_tets(mesh.Handle),
                    Native.lfem_mesh_get_tet_count(mesh.Handle)));
            else
                LfemException.Check(Native.lfem_body_add_mesh(handle, body, Native.lfem_mesh_get_positions(mesh.Handle),
                    Native.lfem_mesh_get_node_count(mesh.Handle), Native.lfem_mesh_get_tets(mesh.Handle),
                    Native.lfem_mesh_get_tet_count(mesh.Handle)));
            GC.KeepAlive(mesh);
        }

        /// <summary>Add nodes (m) and tets (4 node indices each, flat) to a body.</summary>
        public void AddMesh(Body body, Vec3[] positions, uint[] tets)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            if (tets == null) throw new ArgumentNullException("tets");
            if (tets.Length % 4 != 0)
                throw new ArgumentException("Lfem: tets.Length " + tets.Length + " is not a multiple of 4", "tets");
            LfemException.Check(Native.lfem_body_add_mesh(handle, body, positions, (uint)positions.Length, tets, (uint)(tets.Length / 4)));
        }

        /// <summary>Add nodes (m) and 10-node tets (10 node indices each, flat: the corners, then
        /// the mid-edge nodes of the edges 01, 12, 02, 03, 13, 23) to a body.</summary>
        public void AddQuadraticMesh(Body body, Vec3[] positions, uint[] tets)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            if (tets == null) throw new ArgumentNullException("tets");
            if (tets.Length % 10 != 0)
                throw new ArgumentException("Lfem: tets.Length " + tets.Length + " is not a multiple of 10", "tets");
            LfemException.Check(Native.lfem_body_add_quadratic_mesh(handle, body, positions, (uint)positions.Length, tets,
                                                                    (uint)(tets.Length / 10)));
        }

        /// <summary>Nodes per tet of a body: 4, 10 for quadratic tets, 0 without tets.</summary>
        public int GetNodesPerTet(Body body)
        {
            uint n;
            LfemException.Check(Native.lfem_body_get_nodes_per_tet(handle, body, out n));
            return (int)n;
        }

        /// <summary>Give a static or kinematic body a rigid shape; points: the convex hull's
        /// points (local coordinates, m), null for the other shapes. Returns the shape's index
        /// on the body (the Shape of the contacts that touch it).</summary>
        public uint AddShape(Body body, ShapeDef def, Vec3[] points = null)
        {
            GCHandle pin = default(GCHandle);
            try
            {
                if (points != null && points.Length > 0)
                {
                    pin = GCHandle.Alloc(points, GCHandleType.Pinned);
                    def.Points = pin.AddrOfPinnedObject();
                    def.PointCount = (uint)points.Length;
                }
                else
                {
                    def.Points = IntPtr.Zero;
                    def.PointCount = 0;
                }
                uint index;
                LfemException.Check(Native.lfem_body_add_shape(handle, body, ref def, out index));
                return index;
            }
            finally
            {
                if (pin.IsAllocated) pin.Free();
            }
        }

        /// <summary>Total mass (kg) of a body: the sum of its lumped node masses, rho V, and what
        /// mass scaling added.</summary>
        public double Mass(Body body)
        {
            double m; LfemException.Check(Native.lfem_body_get_mass(handle, body, out m)); return m;
        }

        /// <summary>The mass (kg) mass scaling added to a body (WorldDef.MassScalingStep).</summary>
        public double AddedMass(Body body)
        {
            double m; LfemException.Check(Native.lfem_body_get_added_mass(handle, body, out m)); return m;
        }

        /// <summary>The body's inverted tets, smallest volume ratio and time inverted.</summary>
        public Inversion GetInversion(Body body)
        {
            Inversion r;
            LfemException.Check(Native.lfem_body_get_inversion(handle, body, out r.InvertedTets, out r.MinJacobian,
                                                               out r.InvertedFor));
            return r;
        }

        /// <summary>Linear momentum (kg m/s) and angular momentum about the origin (kg m^2/s).</summary>
        public void GetMomentum(Body body, out Vec3 linear, out Vec3 angular)
        {
            LfemException.Check(Native.lfem_body_get_momentum(handle, body, out linear, out angular));
        }

        private delegate Status CountFunction(WorldHandle world, Body body, out uint count);

        /// <summary>A count asked before the call the user made; an error names that call.</summary>
        private int CountFor(CountFunction count, string countName, Body body, string call)
        {
            uint n;
            Status s = count(handle, body, out n);
            if (s != Status.Ok) throw LfemException.FromLastError(s).Renamed(countName, call);
            return checked((int)n);
        }

        public int NodeCount(Body body)
        {
            uint n; LfemException.Check(Native.lfem_body_get_node_count(handle, body, out n)); return (int)n;
        }

        public int TetCount(Body body)
        {
            uint n; LfemException.Check(Native.lfem_body_get_tet_count(handle, body, out n)); return (int)n;
        }

        public IntPtr GetUserData(Body body)
        {
            IntPtr p; LfemException.Check(Native.lfem_body_get_user_data(handle, body, out p)); return p;
        }

        /// <summary>Node positions (m) into buffer (one per node, or more). Status.BufferTooSmall
        /// (nothing written) when it is shorter.</summary>
        public void GetPositions(Body body, Vec3[] buffer)
        {
            if (buffer == null) throw new ArgumentNullException("buffer");
            LfemException.Check(Native.lfem_body_get_positions(handle, body, buffer, (uint)buffer.Length));
        }

        public Vec3[] GetPositions(Body body)
        {
            Vec3[] x = new Vec3[CountFor(Native.lfem_body_get_node_count, "lfem_body_get_node_count", body, "lfem_body_get_positions")];
            GetPositions(body, x);
            return x;
        }

        /// <summary>Node velocities (m/s) into buffer (see GetPositions).</summary>
        public void GetVelocities(Body body, Vec3[] buffer)
        {
            if (buffer == null) throw new ArgumentNullException("buffer");
            LfemException.Check(Native.lfem_body_get_velocities(handle, body, buffer, (uint)buffer.Length));
        }

        public Vec3[] GetVelocities(Body body)
        {
            Vec3[] v = new Vec3[CountFor(Native.lfem_body_get_node_count, "lfem_body_get_node_count", body, "lfem_body_get_velocities")];
            GetVelocities(body, v);
            return v;
        }

        public void SetVelocities(Body body, Vec3[] velocities)
        {
            if (velocities == null) throw new ArgumentNullException("velocities");
            LfemException.Check(Native.lfem_body_set_velocities(handle, body, velocities, (uint)velocities.Length));
        }

        /// <summary>Boundary triangles, 3 node indices each (flat), counter-clockwise from outside.</summary>
        public uint[] GetBoundaryTriangles(Body body)
        {
            int n = CountFor(Native.lfem_body_get_boundary_triangle_count, "lfem_body_get_boundary_triangle_count", body,
                             "lfem_body_get_boundary_triangles");
            uint[] t = new uint[3 * n];
            LfemException.Check(Native.lfem_body_get_boundary_triangles(handle, body, t, (uint)n));
            return t;
        }

        /// <summary>The boundary as faces (flat): 6 node indices per face for a body of 10-node
        /// tets (corners a, b, c counter-clockwise from outside, then the mid-edge nodes of ab,
        /// bc, ca), 3 (the boundary triangles) for any other body.</summary>
        public uint[] GetBoundaryFaces(Body body)
        {
            int n = CountFor(Native.lfem_body_get_boundary_face_count, "lfem_body_get_boundary_face_count", body,
                             "lfem_body_get_boundary_faces");
            int width = CountFor(Native.lfem_body_get_nodes_per_tet, "lfem_body_get_nodes_per_tet", body,
                                 "lfem_body_get_boundary_faces") == 10 ? 6 : 3;
            uint[] f = new uint[width * n];
            LfemException.Check(Native.lfem_body_get_boundary_faces(handle, body, f, (uint)n));
            return f;
        }

        /// <summary>Von Mises stress (Pa), one per tet.</summary>
        public double[] GetVonMisesStress(Body body)
        {
            double[] s = new double[CountFor(Native.lfem_body_get_tet_count, "lfem_body_get_tet_count", body, "lfem_body_get_von_mises_stress")];
            LfemException.Check(Native.lfem_body_get_von_mises_stress(handle, body, s, (uint)s.Length));
            return s;
        }

        /// <summary>The paper model's global rotation, row-major 3x3 (identity otherwise).</summary>
        public double[] GetRotation(Body body)
        {
            double[] r = new double[9];
            LfemException.Check(Native.lfem_body_get_rotation(handle, body, r));
            return r;
        }

        /// <summary>Teleport a deformable body's nodes (m, one per node): velocities kept, the change
        /// of strain energy booked as work, its pairs end.</summary>
        public void SetPositions(Body body, Vec3[] positions)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            LfemException.Check(Native.lfem_body_set_positions(handle, body, positions, (uint)positions.Length));
        }

        /// <summary>A one-shot impulse (N s) at a world point (m): a deformable body's tet around the
        /// point takes it by its shape functions, a rigid body as a whole.</summary>
        public void ApplyImpulse(Body body, Vec3 point, Vec3 impulse)
        {
            LfemException.Check(Native.lfem_body_apply_impulse(handle, body, ref point, ref impulse));
        }

        /// <summary>A force (N) at a world point (m) for the next Step call only: bound to the body
        /// where it is now (the tet around the point) and moved with it; the body gains force * dt.</summary>
        public void ApplyForce(Body body, Vec3 point, Vec3 force)
        {
            LfemException.Check(Native.lfem_body_apply_force(handle, body, ref point, ref force));
        }

        /// <summary>The point of the body's surface nearest to point, its boundary triangle and the
        /// distance (m).</summary>
        public Vec3 ClosestPoint(Body body, Vec3 point, out uint triangle, out double distance)
        {
            Vec3 q;
            LfemException.Check(Native.lfem_body_closest_point(handle, body, ref point, out q, out triangle, out distance));
            return q;
        }

        /// <summary>The body's pose x = R X + t: t, then R as a quaternion w x y z (7 numbers; a
        /// deformable body's best fit).</summary>
        public double[] GetTransform(Body body)
        {
            double[] t = new double[7];
            LfemException.Check(Native.lfem_body_get_transform(handle, body, t));
            return t;
        }

        /// <summary>Teleport a body rigidly to the pose (t, then a quaternion w x y z): velocities
        /// kept, no work.</summary>
        public void SetTransform(Body body, double[] transform)
        {
            if (transform == null || transform.Length != 7) throw new ArgumentException("transform must hold 7 numbers", "transform");
            LfemException.Check(Native.lfem_body_set_transform(handle, body, transform));
        }

        /// <summary>The centre of mass where the nodes are now (m).</summary>
        public Vec3 GetCenterOfMass(Body body)
        {
            Vec3 c;
            LfemException.Check(Native.lfem_body_get_center_of_mass(handle, body, out c));
            return c;
        }

        /// <summary>The nodes whose current position lies in the box [lo, hi] (m).</summary>
        public uint[] FindNodesInBox(Body body, Vec3 lo, Vec3 hi)
        {
            uint count;
            Status s = Native.lfem_body_find_nodes_in_box(handle, body, ref lo, ref hi, null, 0, out count);
            if (s != Status.BufferTooSmall) LfemException.Check(s);
            uint[] nodes = new uint[count];
            if (count > 0)
                LfemException.Check(Native.lfem_body_find_nodes_in_box(handle, body, ref lo, ref hi, nodes, count, out count));
            return nodes;
        }

        // ---- loads and supports ----

        public void FixNodes(Body body, uint[] nodes)
        {
            if (nodes == null) throw new ArgumentNullException("nodes");
            LfemException.Check(Native.lfem_body_fix_nodes(handle, body, nodes, (uint)nodes.Length));
        }

        public void PrescribeNodeVelocity(Body body, uint[] nodes, Vec3 velocity)
        {
            if (nodes == null) throw new ArgumentNullException("nodes");
            LfemException.Check(Native.lfem_body_prescribe_node_velocity(handle, body, nodes, (uint)nodes.Length, ref velocity));
        }

        public void ReleaseNodes(Body body, uint[] nodes)
        {
            if (nodes == null) throw new ArgumentNullException("nodes");
            LfemException.Check(Native.lfem_body_release_nodes(handle, body, nodes, (uint)nodes.Length));
        }

        /// <summary>Constant external forces (N), forces[i] on nodes[i], from now on.</summary>
        public void SetNodeForces(Body body, uint[] nodes, Vec3[] forces)
        {
            if (nodes == null) throw new ArgumentNullException("nodes");
            if (forces == null) throw new ArgumentNullException("forces");
            if (nodes.Length != forces.Length)
                throw new ArgumentException("Lfem: " + nodes.Length + " nodes but " + forces.Length + " forces", "forces");
            LfemException.Check(Native.lfem_body_set_node_forces(handle, body, nodes, (uint)nodes.Length, forces));
        }

        public void ClearNodeForces(Body body) { LfemException.Check(Native.lfem_body_clear_node_forces(handle, body)); }

        public void SetKinematicVelocity(Body body, Vec3 linear, Vec3 angular)
        {
            LfemException.Check(Native.lfem_body_set_kinematic_velocity(handle, body, ref linear, ref angular));
        }

        // ---- skins ----

        /// <summary>Bind a render mesh (vertices in the body's rest frame, m; triangles: 3
        /// vertex indices each, flat) to the body's tets; returns the skin's index.</summary>
        public uint AddSkin(Body body, Vec3[] positions, uint[] triangles)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            if (triangles == null) throw new ArgumentNullException("triangles");
            if (triangles.Length % 3 != 0)
                throw new ArgumentException("Lfem: triangles.Length " + triangles.Length + " is not a multiple of 3", "triangles");
            uint index;
            LfemException.Check(Native.lfem_body_add_skin(handle, body, positions, (uint)positions.Length, triangles,
                                                          (uint)(triangles.Length / 3), out index));
            return index;
        }

        /// <summary>Remove a skin; the skins after it move down one index.</summary>
        public void RemoveSkin(Body body, uint skin) { LfemException.Check(Native.lfem_body_remove_skin(handle, body, skin)); }
        /// <summary>Change the body's Coulomb friction (>= 0); the body wakes.</summary>
        public void SetFriction(Body body, double friction) { LfemException.Check(Native.lfem_body_set_friction(handle, body, friction)); }
        /// <summary>Change a deformable body's Young's modulus (Pa) and Poisson's ratio; its stable step
        /// follows, the change of strain energy is booked as work (not under mass scaling).</summary>
        public void SetMaterial(Body body, double youngModulus, double poissonRatio) { LfemException.Check(Native.lfem_body_set_material(handle, body, youngModulus, poissonRatio)); }
        /// <summary>Whether the body may fall asleep; false wakes it.</summary>
        public void SetSleepAllowed(Body body, bool allowed) { LfemException.Check(Native.lfem_body_set_sleep_allowed(handle, body, allowed ? 1 : 0)); }
        /// <summary>The caller's frame an attachment holds its nodes to, as last set (7 numbers).</summary>
        public double[] GetAttachmentFrame(Attachment a)
        {
            double[] f = new double[7];
            LfemException.Check(Native.lfem_attachment_get_frame(handle, a, f));
            return f;
        }
        /// <summary>Change the body's mass-proportional damping (>= 0, 1/s); the body wakes.</summary>
        public void SetDamping(Body body, double damping) { LfemException.Check(Native.lfem_body_set_damping(handle, body, damping)); }
        /// <summary>Change the body's collision filter; pairs it now forbids end with the next step's events.</summary>
        public void SetFilter(Body body, uint categoryBits, uint maskBits) { LfemException.Check(Native.lfem_body_set_filter(handle, body, categoryBits, maskBits)); }
        /// <summary>Change the user data World.GetUserData returns.</summary>
        public void SetUserData(Body body, IntPtr userData) { LfemException.Check(Native.lfem_body_set_user_data(handle, body, userData)); }
        /// <summary>Change the body's type between rigid, kinematic and static (the pose carries over;
        /// a deformable body keeps its type).</summary>
        public void SetBodyType(Body body, BodyType type) { LfemException.Check(Native.lfem_body_set_type(handle, body, type)); }
        /// <summary>The body's type.</summary>
        public BodyType GetBodyType(Body body) { BodyType t; LfemException.Check(Native.lfem_body_get_type(handle, body, out t)); return t; }
        /// <summary>An opaque 64-bit number kept on the body (an entity id); checkpoints keep it.</summary>
        public void SetUserId(Body body, ulong userId) { LfemException.Check(Native.lfem_body_set_user_id(handle, body, userId)); }
        /// <summary>The body's user id (0 at creation).</summary>
        public ulong GetUserId(Body body) { ulong id; LfemException.Check(Native.lfem_body_get_user_id(handle, body, out id)); return id; }

        public int SkinCount(Body body)
        {
            uint n; LfemException.Check(Native.lfem_body_get_skin_count(handle, body, out n)); return checked((int)n);
        }

        /// <summary>The vertex and triangle counts of a skin.</summary>
        public void GetSkinSizes(Body body, uint skin, out int vertexCount, out int triangleCount)
        {
            uint v, t;
            LfemException.Check(Native.lfem_body_get_skin_sizes(handle, body, skin, out v, out t));
            vertexCount = checked((int)v);
            triangleCount = checked((int)t);
        }

        private int SkinSize(Body body, uint skin, bool vertices, string call)
        {
            uint v, t;
            Status s = Native.lfem_body_get_skin_sizes(handle, body, skin, out v, out t);
            if (s != Status.Ok) throw LfemException.FromLastError(s).Renamed("lfem_body_get_skin_sizes", call);
            return checked((int)(vertices ? v : t));
        }

        /// <summary>A skin's triangles as given, 3 vertex indices each (flat).</summary>
        public uint[] GetSkinTriangles(Body body, uint skin)
        {
            int n = SkinSize(body, skin, false, "lfem_body_get_skin_triangles");
            uint[] t = new uint[3 * n];
            LfemException.Check(Native.lfem_body_get_skin_triangles(handle, body, skin, t, (uint)n));
            return t;
        }

        /// <summary>A skin's deformed vertices (m) and unit smooth normals into the buffers
        /// (normals may be null); Status.BufferTooSmall when a buffer is too short.</summary>
        public void GetSkinVertices(Body body, uint skin, Vec3[] positions, Vec3[] normals)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            if (normals != null && normals.Length < positions.Length)
                throw new ArgumentException("Lfem: normals is shorter than positions", "normals");
            LfemException.Check(Native.lfem_body_get_skin_vertices(handle, body, skin, positions, normals, (uint)positions.Length));
        }

        public Vec3[] GetSkinVertices(Body body, uint skin, out Vec3[] normals)
        {
            int n = SkinSize(body, skin, true, "lfem_body_get_skin_vertices");
            Vec3[] p = new Vec3[n];
            normals = new Vec3[n];
            GetSkinVertices(body, skin, p, normals);
            return p;
        }

        /// <summary>A skin's vertices into an interleaved float vertex buffer of stride floats
        /// per vertex: the position at buffer[i * stride + 0..2] and, with normals, the unit
        /// normal right after it (buffer[i * stride + 3..5]); the other floats are left alone.
        /// stride >= 3 (6 with normals).</summary>
        public void GetSkinVertexBuffer(Body body, uint skin, float[] buffer, int stride, bool normals)
        {
            if (buffer == null) throw new ArgumentNullException("buffer");
            int width = normals ? 6 : 3;
            if (stride < width)
                throw new ArgumentException("Lfem: stride " + stride + " is below the " + width + " floats of a vertex", "stride");
            int n = SkinSize(body, skin, true, "lfem_body_get_skin_vertices_f32");
            if (n > 0 && buffer.Length < (long)(n - 1) * stride + width)
                throw new ArgumentException("Lfem: a buffer of " + buffer.Length + " floats is below the " +
                                            ((long)(n - 1) * stride + width) + " that " + n + " vertices need", "buffer");
            GCHandle pin = GCHandle.Alloc(buffer, GCHandleType.Pinned);
            try
            {
                IntPtr p = pin.AddrOfPinnedObject();
                LfemException.Check(Native.lfem_body_get_skin_vertices_f32(handle, body, skin, p, (uint)stride,
                                                                           normals ? p + 3 * sizeof(float) : IntPtr.Zero,
                                                                           (uint)stride, (uint)n));
            }
            finally
            {
                pin.Free();
            }
        }

        // ---- queries ----

        /// <summary>The nearest crossing of the ray origin + t direction / |direction|, t in
        /// [0, maxDistance] (m; double.PositiveInfinity for no limit), with the surface of a body
        /// the filter sees; false when it meets nothing (hit then default).</summary>
        /// <summary>A sphere of radius swept along the ray: where it first touches a surface the
        /// filter sees (Distance its centre's travel, Point the point touched, Normal from it
        /// towards the centre).</summary>
        public bool CastSphere(Vec3 origin, Vec3 direction, double radius, double maxDistance, QueryFilter filter, out RayHit hit)
        {
            int found;
            RayHit h = default(RayHit);
            LfemException.Check(Native.lfem_world_cast_sphere(handle, ref origin, ref direction, radius, maxDistance, filter, ref h, out found));
            hit = h;
            return found == 1;
        }

        public bool CastRay(Vec3 origin, Vec3 direction, double maxDistance, QueryFilter filter, out RayHit hit)
        {
            int found;
            RayHit h = default(RayHit);
            LfemException.Check(Native.lfem_world_cast_ray(handle, ref origin, ref direction, maxDistance, filter, ref h, out found));
            hit = h;
            return found == 1;
        }

        /// <summary>Every crossing along the ray, nearest first.</summary>
        public RayHit[] CastRayAll(Vec3 origin, Vec3 direction, double maxDistance, QueryFilter filter)
        {
            uint count;
            Status s = Native.lfem_world_cast_ray_all(handle, ref origin, ref direction, maxDistance, filter, null, 0, out count);
            if (s != Status.BufferTooSmall) LfemException.Check(s);
            RayHit[] hits = new RayHit[count];
            if (count > 0)
                LfemException.Check(Native.lfem_world_cast_ray_all(handle, ref origin, ref direction, maxDistance, filter, hits,
                                                                   count, out count));
            return hits;
        }

        /// <summary>The bodies the filter sees that the solid sphere overlaps (touching counts), in
        /// body order, each with its triangle or shape nearest the centre and the point of it.</summary>
        public Overlap[] OverlapSphere(Vec3 center, double radius, QueryFilter filter)
        {
            return OverlapCapsule(center, center, radius, filter);
        }

        /// <summary>The same for the capsule of the segment a-b swept by radius.</summary>
        public Overlap[] OverlapCapsule(Vec3 a, Vec3 b, double radius, QueryFilter filter)
        {
            uint count;
            Status s = Native.lfem_world_overlap_capsule(handle, ref a, ref b, radius, filter, null, 0, out count);
            if (s != Status.BufferTooSmall) LfemException.Check(s);
            Overlap[] found = new Overlap[count];
            if (count > 0)
                LfemException.Check(Native.lfem_world_overlap_capsule(handle, ref a, ref b, radius, filter, found, count, out count));
            return found;
        }

        /// <summary>The bodies the filter sees whose current geometry overlaps the box [lo, hi]
        /// (m), in body order.</summary>
        public Body[] OverlapBox(Vec3 lo, Vec3 hi, QueryFilter filter)
        {
            uint count;
            Status s = Native.lfem_world_overlap_box(handle, ref lo, ref hi, filter, null, 0, out count);
            if (s != Status.BufferTooSmall) LfemException.Check(s);
            Body[] bodies = new Body[count];
            if (count > 0)
                LfemException.Check(Native.lfem_world_overlap_box(handle, ref lo, ref hi, filter, bodies, count, out count));
            return bodies;
        }

        // ---- contacts ----

        /// <summary>The number of active contacts of the last step.</summary>
        public int ContactCount
        {
            get
            {
                uint count;
                Status s = Native.lfem_world_query_contacts(handle, null, 0, out count);
                if (s != Status.BufferTooSmall) LfemException.Check(s);
                return checked((int)count);
            }
        }

        /// <summary>Copy the active contacts into buffer; returns how many. Status.BufferTooSmall
        /// (nothing copied) when buffer is too short.</summary>
        public int GetContacts(Contact[] buffer)
        {
            if (buffer == null) throw new ArgumentNullException("buffer");
            uint count;
            LfemException.Check(Native.lfem_world_query_contacts(handle, buffer, (uint)buffer.Length, out count));
            return checked((int)count);
        }

        public Contact[] GetContacts()
        {
            Contact[] c = new Contact[ContactCount];
            int n = GetContacts(c);
            if (n != c.Length) Array.Resize(ref c, n);
            return c;
        }
    }

    /// <summary>A tetrahedral mesh owned by C#; Dispose() frees it.</summary>
    public sealed class Mesh : IDisposable
    {
        private readonly MeshHandle handle;

        private Mesh(Status status, MeshHandle h)
        {
            if (status != Status.Ok)
            {
                LfemException e = LfemException.FromLastError(status);
                if (h != null) h.Dispose();
                throw e;
            }
            handle = h;
        }

        public MeshHandle Handle { get { return handle; } }

        public void Dispose() { handle.Dispose(); }

        /// <summary>A box [0, size] (m) of cells hexahedra, 6 tets each.</summary>
        public static Mesh Box(Vec3 size, uint cellsX, uint cellsY, uint cellsZ)
        {
            uint[] cells = { cellsX, cellsY, cellsZ };
            MeshHandle h;
            Status s = Native.lfem_mesh_create_box(ref size, cells, out h);
            return new Mesh(s, h);
        }

        public static Mesh Cylinder(double radius, double height, uint segments, uint rings, uint layers)
        {
            MeshHandle h;
            Status s = Native.lfem_mesh_create_cylinder(radius, height, segments, rings, layers, out h);
            return new Mesh(s, h);
        }

        public static Mesh Cup(double outerRadius, double height, double wall, double bottom, uint segments, uint layers)
        {
            MeshHandle h;
            Status s = Native.lfem_mesh_create_cup(outerRadius, height, wall, bottom, segments, layers, out h);
            return new Mesh(s, h);
        }

        public static Mesh Hammer(double handleLength, double handleWidth, double headLength, double headWidth, double cellSize)
        {
            MeshHandle h;
            Status s = Native.lfem_mesh_create_hammer(handleLength, handleWidth, headLength, headWidth, cellSize, out h);
            return new Mesh(s, h);
        }

        /// <summary>The tetrahedra of a Gmsh .msh file (ASCII 2.2 or 4.1): 4-node ones, or
        /// 10-node ones (type 11).</summary>
        public static Mesh LoadGmsh(string path)
        {
            MeshHandle h;
            Status s = Native.lfem_mesh_load_gmsh(Library.ToCString(path), out h);
            return new Mesh(s, h);
        }

        public int NodeCount { get { return (int)Native.lfem_mesh_get_node_count(handle); } }
        public int TetCount { get { return (int)Native.lfem_mesh_get_tet_count(handle); } }
        /// <summary>4, or 10 for quadratic tets.</summary>
        public int NodesPerTet { get { return (int)Native.lfem_mesh_get_nodes_per_tet(handle); } }

        /// <summary>Turn the 4-node tets into 10-node ones: a node at the middle of every edge,
        /// numbered after the corners (see lfem_mesh_make_quadratic).</summary>
        public void MakeQuadratic() { LfemException.Check(Native.lfem_mesh_make_quadratic(handle)); }

        /// <summary>A copy of the node positions (m).</summary>
        public Vec3[] GetPositions()
        {
            int n = NodeCount;
            double[] flat = new double[3 * n];
            if (n > 0) Marshal.Copy(Native.lfem_mesh_get_positions(handle), flat, 0, flat.Length);
            Vec3[] x = new Vec3[n];
            for (int i = 0; i < n; ++i) x[i] = new Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
            return x;
        }

        /// <summary>A copy of the tets, NodesPerTet node indices each (flat).</summary>
        public uint[] GetTets()
        {
            int n = NodesPerTet * TetCount;
            int[] raw = new int[n];
            if (n > 0) Marshal.Copy(Native.lfem_mesh_get_tets(handle), raw, 0, n);
            uint[] t = new uint[n];
            Buffer.BlockCopy(raw, 0, t, 0, 4 * n);
            return t;
        }

        public void Translate(Vec3 offset) { LfemException.Check(Native.lfem_mesh_translate(handle, ref offset)); }

        /// <summary>Rotate about the origin by angle (rad) around axis.</summary>
        public void Rotate(Vec3 axis, double angle) { LfemException.Check(Native.lfem_mesh_rotate(handle, ref axis, angle)); }
    }

    /// <summary>A ParaView time series (.pvd plus one .vtu per frame); Dispose() closes it.</summary>
    public sealed class VtkSeries : IDisposable
    {
        private readonly VtkSeriesHandle handle;

        public VtkSeries(string pvdPath)
        {
            VtkSeriesHandle h;
            Status s = Native.lfem_vtk_series_create(Library.ToCString(pvdPath), out h);
            if (s != Status.Ok)
            {
                LfemException e = LfemException.FromLastError(s);
                if (h != null) h.Dispose();
                throw e;
            }
            handle = h;
        }

        public void WriteFrame(World world)
        {
            if (world == null) throw new ArgumentNullException("world");
            LfemException.Check(Native.lfem_vtk_series_write_frame(handle, world.Handle));
        }

        public void Dispose() { handle.Dispose(); }
    }

    /// <summary>The raw C functions, one DllImport each (cdecl). Public for advanced use.</summary>
    public static class Native
    {
        public const string Lib = "lfem";
        private const CallingConvention Cdecl = CallingConvention.Cdecl;

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern IntPtr lfem_status_string(Status status);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern IntPtr lfem_last_error();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern uint lfem_version();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern IntPtr lfem_version_string();

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern WorldDef lfem_world_def_default();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_create(ref WorldDef def, out WorldHandle world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_create(IntPtr def, IntPtr world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern void lfem_world_destroy(IntPtr world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_step(WorldHandle world, double dt);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_step(IntPtr world, double dt);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_save(WorldHandle world, [In] byte[] path);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_save(IntPtr world, [In] byte[] path);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_load([In] byte[] path, out WorldHandle world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_load([In] byte[] path, IntPtr world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_set_gravity(WorldHandle world, ref Vec3 gravity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_set_time_step(WorldHandle world, double timeStep);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_get_stable_step(WorldHandle world, out double stableStep);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_get_stats(WorldHandle world, out WorldStats stats);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_get_profile(WorldHandle world, out Profile profile);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_reset_profile(WorldHandle world);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern BodyDef lfem_body_def_default();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_create(WorldHandle world, ref BodyDef def, out Body body);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_destroy(WorldHandle world, Body body);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern int lfem_body_is_valid(WorldHandle world, Body body);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_add_mesh(WorldHandle world, Body body, IntPtr positions, uint nodeCount, IntPtr tets, uint tetCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_add_mesh(WorldHandle world, Body body, [In] Vec3[] positions, uint nodeCount, [In] uint[] tets, uint tetCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_add_quadratic_mesh(WorldHandle world, Body body, IntPtr positions, uint nodeCount, IntPtr tets, uint tetCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_add_quadratic_mesh(WorldHandle world, Body body, [In] Vec3[] positions, uint nodeCount, [In] uint[] tets, uint tetCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_nodes_per_tet(WorldHandle world, Body body, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_node_count(WorldHandle world, Body body, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_tet_count(WorldHandle world, Body body, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_user_data(WorldHandle world, Body body, out IntPtr userData);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_mass(WorldHandle world, Body body, out double mass);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_added_mass(WorldHandle world, Body body, out double mass);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_inversion(WorldHandle world, Body body, out uint invertedTets, out double minJacobian, out double invertedFor);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_get_warning(WorldHandle world, WarningKind kind, out Warning warning);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_clear_warnings(WorldHandle world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_wake(WorldHandle world, Body body);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern int lfem_body_is_awake(WorldHandle world, Body body);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern AttachmentDef lfem_attachment_def_default();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_attachment_create(WorldHandle world, ref AttachmentDef def, out Attachment attachment);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_attachment_destroy(WorldHandle world, Attachment attachment);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern int lfem_attachment_is_valid(WorldHandle world, Attachment attachment);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_attachment_set_frame(WorldHandle world, Attachment attachment, double[] frame);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_attachment_get_force(WorldHandle world, Attachment attachment, out Vec3 force);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_get_events(WorldHandle world, [Out] Event[] events, uint capacity, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_momentum(WorldHandle world, Body body, out Vec3 linear, out Vec3 angular);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_positions(WorldHandle world, Body body, [Out] Vec3[] positions, uint nodeCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_velocities(WorldHandle world, Body body, [Out] Vec3[] velocities, uint nodeCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_velocities(WorldHandle world, Body body, [In] Vec3[] velocities, uint nodeCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_boundary_triangle_count(WorldHandle world, Body body, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_boundary_triangles(WorldHandle world, Body body, [Out] uint[] triangles, uint triangleCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_boundary_face_count(WorldHandle world, Body body, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_boundary_faces(WorldHandle world, Body body, [Out] uint[] faces, uint faceCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_von_mises_stress(WorldHandle world, Body body, [Out] double[] stress, uint tetCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_rotation(WorldHandle world, Body body, [Out] double[] rotation);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_positions(WorldHandle world, Body body, [In] Vec3[] positions, uint nodeCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_remove_skin(WorldHandle world, Body body, uint skin);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_friction(WorldHandle world, Body body, double friction);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_material(WorldHandle world, Body body, double youngModulus, double poissonRatio);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_sleep_allowed(WorldHandle world, Body body, int allowed);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_attachment_get_frame(WorldHandle world, Attachment attachment, [Out] double[] frame);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_damping(WorldHandle world, Body body, double damping);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_filter(WorldHandle world, Body body, uint categoryBits, uint maskBits);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_user_data(WorldHandle world, Body body, IntPtr userData);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_apply_impulse(WorldHandle world, Body body, ref Vec3 point, ref Vec3 impulse);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_apply_force(WorldHandle world, Body body, ref Vec3 point, ref Vec3 force);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_type(WorldHandle world, Body body, BodyType type);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_type(WorldHandle world, Body body, out BodyType type);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_user_id(WorldHandle world, Body body, ulong userId);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_user_id(WorldHandle world, Body body, out ulong userId);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_closest_point(WorldHandle world, Body body, ref Vec3 point, out Vec3 outPoint, out uint triangle, out double distance);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_transform(WorldHandle world, Body body, [Out] double[] transform);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_transform(WorldHandle world, Body body, [In] double[] transform);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_center_of_mass(WorldHandle world, Body body, out Vec3 center);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_find_nodes_in_box(WorldHandle world, Body body, ref Vec3 lo, ref Vec3 hi, [Out] uint[] nodes, uint capacity, out uint count);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_fix_nodes(WorldHandle world, Body body, [In] uint[] nodes, uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_prescribe_node_velocity(WorldHandle world, Body body, [In] uint[] nodes, uint count, ref Vec3 velocity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_release_nodes(WorldHandle world, Body body, [In] uint[] nodes, uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_node_forces(WorldHandle world, Body body, [In] uint[] nodes, uint count, [In] Vec3[] forces);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_clear_node_forces(WorldHandle world, Body body);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_set_kinematic_velocity(WorldHandle world, Body body, ref Vec3 linear, ref Vec3 angular);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern ShapeDef lfem_shape_def_default();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_add_shape(WorldHandle world, Body body, ref ShapeDef def, out uint index);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_query_contacts(WorldHandle world, [Out] Contact[] contacts, uint capacity, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_query_contacts(IntPtr world, [Out] Contact[] contacts, uint capacity, out uint count);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_add_skin(WorldHandle world, Body body, [In] Vec3[] positions, uint vertexCount, [In] uint[] triangles, uint triangleCount, out uint skinIndex);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_skin_count(WorldHandle world, Body body, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_skin_sizes(WorldHandle world, Body body, uint skin, out uint vertexCount, out uint triangleCount);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_skin_triangles(WorldHandle world, Body body, uint skin, [Out] uint[] triangles, uint triangleCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_skin_vertices(WorldHandle world, Body body, uint skin, [Out] Vec3[] positions, [Out] Vec3[] normals, uint vertexCapacity);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_body_get_skin_vertices_f32(WorldHandle world, Body body, uint skin, IntPtr positions, uint positionStride, IntPtr normals, uint normalStride, uint vertexCapacity);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern QueryFilter lfem_query_filter_default();
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_cast_sphere(WorldHandle world, ref Vec3 origin, ref Vec3 direction, double radius, double maxDistance, QueryFilter filter, ref RayHit hit, out int found);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_cast_ray(WorldHandle world, ref Vec3 origin, ref Vec3 direction, double maxDistance, QueryFilter filter, ref RayHit hit, out int found);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_cast_ray_all(WorldHandle world, ref Vec3 origin, ref Vec3 direction, double maxDistance, QueryFilter filter, [Out] RayHit[] hits, uint capacity, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_overlap_capsule(WorldHandle world, ref Vec3 a, ref Vec3 b, double radius, QueryFilter filter, [Out] Overlap[] found, uint capacity, out uint count);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_world_overlap_box(WorldHandle world, ref Vec3 lo, ref Vec3 hi, QueryFilter filter, [Out] Body[] bodies, uint capacity, out uint count);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_create_box(ref Vec3 size, [In] uint[] cells, out MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_create_cylinder(double radius, double height, uint segments, uint rings, uint layers, out MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_create_cup(double outerRadius, double height, double wall, double bottom, uint segments, uint layers, out MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_create_hammer(double handleLength, double handleWidth, double headLength, double headWidth, double cellSize, out MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_load_gmsh([In] byte[] path, out MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern void lfem_mesh_destroy(IntPtr mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern uint lfem_mesh_get_node_count(MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern uint lfem_mesh_get_tet_count(MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern uint lfem_mesh_get_nodes_per_tet(MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_make_quadratic(MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern IntPtr lfem_mesh_get_positions(MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern IntPtr lfem_mesh_get_tets(MeshHandle mesh);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_translate(MeshHandle mesh, ref Vec3 offset);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_mesh_rotate(MeshHandle mesh, ref Vec3 axis, double angle);

        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_vtk_series_create([In] byte[] pvdPath, out VtkSeriesHandle series);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern Status lfem_vtk_series_write_frame(VtkSeriesHandle series, WorldHandle world);
        [DllImport(Lib, CallingConvention = Cdecl)] public static extern void lfem_vtk_series_destroy(IntPtr series);
    }
}
