#!/usr/bin/env python3
"""Writes the seed inputs of fuzz_api (tests/fuzz/corpus/api): small programs in the byte
encoding of fuzz_input.h, so that the fuzzer starts from scenes that collide, not from noise.
Run it again after changing the call table of fuzz_api.cpp."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


class Program:
    def __init__(self):
        self.b = bytearray()

    def u32(self, v):
        self.b += struct.pack('<I', v & 0xFFFFFFFF)

    def below(self, v):  # in.below(n) reads a u32 and takes it modulo n
        self.u32(v)

    def number(self, lo, hi, v):  # a plain value: kind byte < 200, then a fraction
        self.b.append(0)
        self.u32(round((v - lo) / (hi - lo) * 4294967295.0))

    def byte(self, v):
        self.b.append(v)

    def header(self, max_substeps=40, iterations=30, safety=0.9):
        self.below(max_substeps - 1)
        self.below(iterations - 1)
        self.number(0.05, 0.99, safety)

    def body(self, kind, model=0, young=1e5):
        self.below(0)
        self.below(kind)
        self.below(model)
        self.number(1e3, 1e8, young)
        self.number(-0.2, 0.5, 0.3)
        self.number(10, 2e4, 1000)
        self.number(0, 10, 0)
        self.number(0, 1, 0.5)
        for _ in range(3):
            self.number(-10, 10, 0)
        for _ in range(3):
            self.number(-5, 5, 0)
        self.byte(0)  # mask: all

    def box(self, body_index, size, cells, offset):  # cells (1, 1, 1): 10-node tets
        self.below(1)
        for s in size:
            self.number(0.01, 1, s)
        for c in cells:
            self.below(c - 1)
        for o, (lo, hi) in zip(offset, [(-1, 1), (-1, 1), (-0.2, 1)]):
            self.number(lo, hi, o)
        self.byte(0)
        self.below(body_index)

    def step(self, dt):
        self.below(4)
        self.byte(0)
        self.number(1e-5, 0.02, dt)

    def query(self, capacity):
        self.below(5)
        self.below(capacity)


def write(name, program):
    with open(os.path.join(HERE, 'corpus', 'api', name), 'wb') as f:
        f.write(program.b)


# A soft block dropped on a static floor, stepped and queried.
p = Program()
p.header()
p.body(1)                     # static floor
p.box(0, (0.6, 0.6, 0.1), (2, 2, 1), (-0.3, -0.3, -0.1))
p.body(0, model=2)            # soft neo-Hookean block
p.box(1, (0.1, 0.1, 0.1), (2, 2, 2), (-0.05, -0.05, 0.005))
for _ in range(6):
    p.step(0.005)
p.query(10)
p.query(0)
write('block_on_floor', p)

# Two soft bodies of different models, a checkpoint in between.
p = Program()
p.header()
p.body(1)
p.box(0, (0.6, 0.6, 0.1), (2, 2, 1), (-0.3, -0.3, -0.1))
p.body(0, model=1)
p.box(1, (0.1, 0.1, 0.1), (2, 2, 2), (-0.05, -0.05, 0.0))
p.body(0, model=0)
p.box(2, (0.08, 0.08, 0.08), (1, 1, 1), (-0.02, -0.04, 0.12))
p.step(0.01)
p.below(14)                   # save and load
p.step(0.01)
p.query(3)
write('two_bodies_checkpoint', p)

# A rigid box and a sphere shape, node constraints and a destroy.
p = Program()
p.header()
p.body(1)
p.below(11)                   # shape: sphere on the static body
p.below(2)
for v in (0, 0, -0.5):
    p.number(-1, 1, v)
for v in (1, 0, 0, 0):
    p.number(-1, 1, v)
for _ in range(3):
    p.number(0, 0.5, 0.1)
p.number(0, 0.5, 0.5)
p.number(0, 0.5, 0.1)
p.below(0)                    # no hull points
p.byte(0)
p.below(0)
p.body(3)                     # rigid
p.box(1, (0.1, 0.1, 0.1), (1, 1, 1), (-0.05, -0.05, 0.0))
p.step(0.005)
p.below(7)                    # fix nodes 0 and 1 of body 1
p.below(2)
p.below(0)
p.below(1)
p.byte(0)
p.below(1)
p.step(0.005)
p.below(10)                   # destroy body 1, then step
p.byte(0)
p.below(1)
p.step(0.005)
write('rigid_shape_destroy', p)

# A skin in a soft block, read back, and rays and boxes across it and a floor.
p = Program()
p.header()
p.body(1)
p.box(0, (0.6, 0.6, 0.1), (2, 2, 1), (-0.3, -0.3, -0.1))
p.body(0, model=1)
p.box(1, (0.1, 0.1, 0.1), (2, 2, 2), (-0.05, -0.05, 0.0))
p.below(15)                   # add a skin of 4 vertices and 2 triangles to body 1
p.below(4)
p.below(2)
for v in (-0.02, -0.02, 0.02, 0.02, -0.02, 0.02, -0.02, 0.02, 0.02, 0.02, 0.02, 0.08):
    p.number(-0.5, 1, v)
for i in (0, 1, 2, 1, 3, 2):
    p.below(i)
p.byte(0)
p.below(1)
p.step(0.005)
p.below(16)                   # read its vertices and normals
p.byte(0)
p.below(1)
p.below(0)
p.below(4)
p.below(3)
p.below(3)
p.below(0)
p.byte(1)
p.below(17)                   # all hits of a ray down through the block and the floor
for v in (0.001, 0.002, 1.0, 0.0, 0.0, -1.0):
    p.number(-2, 2, v)
p.byte(255)
p.below(6)
p.below(1)
p.number(0, 5, 4.0)
p.below(17)                   # a box about the block
for v in (-0.1, -0.1, -0.1, 0.1, 0.1, 0.1):
    p.number(-2, 2, v)
p.byte(255)
p.below(4)
p.below(2)
write('skin_and_rays', p)
