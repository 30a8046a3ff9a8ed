"""A user's program, run outside the repository against an installed lfem (bindings/outside/):
a 1 kg cube dropped 1 cm onto a static plane comes to rest on it, and the contact forces,
summed over the contacts and averaged over 0.5 s, carry its weight m g. Exits non-zero when
they do not."""
import sys

import lfem

H = 5e-4          # s, a fixed sub-step, about half the stable limit of this mesh
SETTLE = 1000     # steps (0.5 s) to land and come to rest
WINDOW = 1000     # steps (0.5 s) over which the contact forces are averaged

world = lfem.World(lfem.WorldDef(time_step=H))            # gravity (0, 0, -9.81) m/s^2
floor = world.create_body(lfem.BodyDef(type=lfem.BodyType.STATIC))
world.add_shape(floor, lfem.ShapeDef(type=lfem.ShapeType.PLANE))  # z = 0, normal +z

mesh = lfem.Mesh.box((0.1, 0.1, 0.1), (2, 2, 2))          # m, cells
mesh.translate((-0.05, -0.05, 0.01))                      # bottom 1 cm above the plane
# No damping: then gravity is the only force on the cube besides the contacts (below).
cube = world.create_body(lfem.BodyDef(model=lfem.Model.NEO_HOOKEAN, young_modulus=1e6,
                                      density=1000.0, damping=0.0))
world.add_mesh(cube, mesh)
mass = world.mass(cube)                                   # rho V = 1 kg
weight = mass * -lfem.WorldDef().gravity[2]               # N

for _ in range(SETTLE):
    world.step(H)
p0 = world.momentum(cube)[0]
impulse = [0.0, 0.0, 0.0]
for _ in range(WINDOW):
    world.step(H)                                         # one sub-step: H is the fixed step
    force = world.contacts()["force"].sum(axis=0)         # N, summed over the contacts
    impulse = [impulse[i] + force[i] * H for i in range(3)]
p1 = world.momentum(cube)[0]
span = WINDOW * H
mean = [impulse[i] / span for i in range(3)]

print("lfem %s: cube of %.6f kg dropped 0.01 m onto the plane z = 0"
      % (lfem.version_string(), mass))
print("resting from t = %.6f s to t = %.6f s: %d contacts at the end"
      % (world.stats.time - span, world.stats.time, world.contact_count()))
print("mean summed contact force z: %.6f N (x, y below 1e-6 m g)" % mean[2])
print("weight m g: %.6f N, ratio %.6f" % (weight, mean[2] / weight))

failures = []
# Newton's second law over the window: the momentum lfem reports changes in each sub-step by H times
# the total force on the cube, the weight plus the contact forces (no damping; the tets' elastic
# forces sum to zero), as long as the cube keeps touching the plane (a sub-step in which it lands or
# lifts off entirely is off by m g H / 2, the half step of the synchronized velocities). So the
# contact impulses equal the change of momentum plus the weight's impulse, up to rounding (about
# 1e-15 of m g per step), and this fails if the cube bounces.
balance = mean[2] - weight - (p1[2] - p0[2]) / span
if abs(balance) > 1e-9 * weight:
    failures.append("contact impulses %.3e N off the momentum balance" % balance)
# At rest the plane carries the weight. What is left of the drop is elastic vibration, whose
# momentum is at most sqrt(2 m E_kin) (Cauchy-Schwarz over the lumped masses): about 0.017
# kg m/s here (E_kin ~ 1.5e-4 J), so the mean over 0.5 s may differ from m g by up to
# 2 * 0.017 / 0.5 = 0.07 N, 0.7 %; 1 % allows for that.
if abs(mean[2] / weight - 1) > 0.01:
    failures.append("mean contact force %.6f N is not the weight %.6f N" % (mean[2], weight))
# The scene is symmetric about x and y: the lateral (friction) forces cancel but for rounding.
if max(abs(mean[0]), abs(mean[1])) > 1e-6 * weight:
    failures.append("lateral contact force (%.3e, %.3e) N" % (mean[0], mean[1]))
if world.contact_count() == 0:
    failures.append("the cube does not touch the plane")
world.close()
for failure in failures:
    print("FAIL: " + failure)
if failures:
    sys.exit(1)
print("OK: the plane carries the cube's weight and the contact impulses balance its momentum")
