// A user's program, run outside the repository against an installed lfem (bindings/outside/):
// a 1 kg cube dropped 1 cm onto a static plane comes to rest on it, and the contact forces,
// summed over the contacts and averaged over 0.5 s, carry its weight m g. Exits non-zero when
// they do not.
using System;
using System.Collections.Generic;
using System.Globalization;
using Lfem;

public static class DropCube
{
    const double H = 5e-4;   // s, a fixed sub-step, about half the stable limit of this mesh
    const int Settle = 1000; // steps (0.5 s) to land and come to rest
    const int Window = 1000; // steps (0.5 s) over which the contact forces are averaged

    static string F6(double x) { return x.ToString("F6", CultureInfo.InvariantCulture); }

    public static int Main()
    {
        WorldDef worldDef = WorldDef.Default; // gravity (0, 0, -9.81) m/s^2
        worldDef.TimeStep = H;
        using (World world = new World(worldDef))
        {
            BodyDef floorDef = BodyDef.Default;
            floorDef.Type = BodyType.Static;
            Body floor = world.CreateBody(floorDef);
            ShapeDef plane = ShapeDef.Default;
            plane.Type = ShapeType.Plane; // z = 0, normal +z
            world.AddShape(floor, plane);

            BodyDef def = BodyDef.Default;
            def.Model = Model.NeoHookean;
            def.YoungModulus = 1e6;
            def.Density = 1000;
            def.Damping = 0; // then gravity is the only force on the cube besides the contacts
            Body cube = world.CreateBody(def);
            using (Mesh mesh = Mesh.Box(new Vec3(0.1, 0.1, 0.1), 2, 2, 2)) // m, cells
            {
                mesh.Translate(new Vec3(-0.05, -0.05, 0.01)); // bottom 1 cm above the plane
                world.AddMesh(cube, mesh);
            }
            double mass = world.Mass(cube); // rho V = 1 kg
            double weight = mass * -worldDef.Gravity.Z;

            for (int i = 0; i < Settle; ++i) world.Step(H);
            Vec3 p0, p1, angular;
            world.GetMomentum(cube, out p0, out angular);
            Vec3 impulse = Vec3.Zero;
            for (int i = 0; i < Window; ++i)
            {
                world.Step(H); // one sub-step: H is the fixed step
                foreach (Contact c in world.GetContacts()) impulse += c.Force * H; // N s
            }
            world.GetMomentum(cube, out p1, out angular);
            double span = Window * H;
            Vec3 mean = impulse / span;
            double end = world.Stats.Time;
            int contacts = world.ContactCount;

            Console.WriteLine("lfem " + Library.VersionString + ": cube of " + F6(mass) + " kg dropped 0.01 m onto the plane z = 0");
            Console.WriteLine("resting from t = " + F6(end - span) + " s to t = " + F6(end) + " s: " + contacts + " contacts at the end");
            Console.WriteLine("mean summed contact force z: " + F6(mean.Z) + " N (x, y below 1e-6 m g)");
            Console.WriteLine("weight m g: " + F6(weight) + " N, ratio " + F6(mean.Z / weight));

            List<string> failures = new List<string>();
            // Newton's second law over the window: the momentum lfem reports changes in each sub-
            // step by H times the total force on the cube, the weight plus the contact forces (no
            // damping; the tets' elastic forces sum to zero), as long as the cube keeps touching
            // the plane (a sub-step in which it lands or lifts off entirely is off by m g H / 2,
            // the half step of the synchronized velocities). So the contact impulses equal the
            // change of momentum plus the weight's impulse, up to rounding (about 1e-15 of m g per
            // step), and this fails if the cube bounces.
            double balance = mean.Z - weight - (p1.Z - p0.Z) / span;
            if (Math.Abs(balance) > 1e-9 * weight)
                failures.Add("contact impulses " + balance.ToString("E3", CultureInfo.InvariantCulture) + " N off the momentum balance");
            // At rest the plane carries the weight. What is left of the drop is elastic vibration,
            // whose momentum is at most sqrt(2 m E_kin) (Cauchy-Schwarz over the lumped masses):
            // about 0.017 kg m/s here (E_kin ~ 1.5e-4 J), so the mean over 0.5 s may differ from m g
            // by up to 2 * 0.017 / 0.5 = 0.07 N, 0.7 %; 1 % allows for that.
            if (Math.Abs(mean.Z / weight - 1) > 0.01)
                failures.Add("mean contact force " + F6(mean.Z) + " N is not the weight " + F6(weight) + " N");
            // The scene is symmetric about x and y: the lateral (friction) forces cancel but for
            // rounding.
            if (Math.Max(Math.Abs(mean.X), Math.Abs(mean.Y)) > 1e-6 * weight)
                failures.Add("lateral contact force " + mean + " N");
            if (contacts == 0) failures.Add("the cube does not touch the plane");
            foreach (string failure in failures) Console.WriteLine("FAIL: " + failure);
            if (failures.Count > 0) return 1;
            Console.WriteLine("OK: the plane carries the cube's weight and the contact impulses balance its momentum");
            return 0;
        }
    }
}
