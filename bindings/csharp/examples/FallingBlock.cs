// The scene shared by the C, Rust, C# and Python examples: a soft box (0.3 x 0.2 x 0.1 m,
// neo-Hookean rubber) dropped from rest with its bottom at z = 2 m, gravity only, stepped 0.5 s
// in 0.01 s calls; every 0.1 s it prints the time, the lowest node z, the centre-of-mass
// velocity along z and the kinetic energy.
// Build and run: mcs -out:FallingBlock.exe ../Lfem.cs FallingBlock.cs && LD_LIBRARY_PATH=<build> mono FallingBlock.exe
using System;
using System.Globalization;
using Lfem;

public static class FallingBlock
{
    static string F(double x) { return x.ToString("F6", CultureInfo.InvariantCulture); }

    public static int Main()
    {
        Vec3 size = new Vec3(0.3, 0.2, 0.1); // m
        double density = 400.0;               // kg/m^3
        double mass = density * (size.X * size.Y * size.Z);

        try
        {
            using (World world = new World(WorldDef.Default)) // gravity (0, 0, -9.81) m/s^2
            {
                Body block;
                using (Mesh mesh = Mesh.Box(size, 3, 2, 1))
                {
                    mesh.Translate(new Vec3(0, 0, 2));
                    BodyDef def = BodyDef.Default;
                    def.Model = Model.NeoHookean;
                    def.YoungModulus = 2e5; // Pa: soft rubber
                    def.PoissonRatio = 0.3;
                    def.Density = density;
                    block = world.CreateBody(def);
                    world.AddMesh(block, mesh);
                }

                for (int call = 1; call <= 50; ++call)
                {
                    world.Step(0.01);
                    if (call % 10 != 0) continue;
                    double lowest = double.PositiveInfinity;
                    foreach (Vec3 p in world.GetPositions(block)) lowest = Math.Min(lowest, p.Z);
                    WorldStats stats = world.Stats;
                    Console.WriteLine("t = " + F(stats.Time) + " s  lowest z = " + F(lowest) + " m  com vz = " +
                                      F(stats.LinearMomentum.Z / mass) + " m/s  kinetic energy = " +
                                      F(stats.KineticEnergy) + " J");
                }
            }
        }
        catch (LfemException e)
        {
            Console.Error.WriteLine(e.Status + ": " + e.Message);
            return 1;
        }
        return 0;
    }
}
