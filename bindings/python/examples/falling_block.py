"""The scene shared by the C, Rust, C# and Python examples: a soft box (0.3 x 0.2 x 0.1 m,
neo-Hookean rubber) dropped from rest with its bottom at z = 2 m, gravity only, stepped 0.5 s in
0.01 s calls; every 0.1 s it prints the time, the lowest node z, the centre-of-mass velocity
along z and the kinetic energy. Run: /usr/bin/python3 bindings/python/examples/falling_block.py
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
import lfem  # noqa: E402

size = (0.3, 0.2, 0.1)  # m
density = 400.0  # kg/m^3
mass = density * (size[0] * size[1] * size[2])

with lfem.World() as world:  # gravity (0, 0, -9.81) m/s^2
    mesh = lfem.Mesh.box(size, (3, 2, 1))
    mesh.translate((0.0, 0.0, 2.0))
    d = lfem.BodyDef.default()
    d.model = lfem.Model.NEO_HOOKEAN
    d.young_modulus = 2e5  # Pa: soft rubber
    d.poisson_ratio = 0.3
    d.density = density
    block = world.create_body(d)
    world.add_mesh(block, mesh)
    mesh.close()

    for call in range(1, 51):
        world.step(0.01)
        if call % 10:
            continue
        lowest = world.positions(block)[:, 2].min()
        stats = world.stats
        print("t = %.6f s  lowest z = %.6f m  com vz = %.6f m/s  kinetic energy = %.6f J"
              % (stats.time, lowest, stats.linear_momentum[2] / mass, stats.kinetic_energy))
