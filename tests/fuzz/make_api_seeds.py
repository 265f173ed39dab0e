#!/usr/bin/env python3
"""Writes the seed programs of fuzz_api (tests/fuzz/corpus/api/*.bin): small worlds that use every
shape kind, every joint kind, continuous collision, sensors, queries and snapshot/restore, in the
byte format fuzz_api.cpp reads (op byte, then the op's arguments; numbers as [0, int8(8 v)]).
    python3 tests/fuzz/make_api_seeds.py"""
import os

STEP, BODY, SHAPE, JOINT, PUSH, SET_OR_DESTROY, QUERY, SNAPSHOT = range(8)
STATIC, KINEMATIC, DYNAMIC = range(3)


def num(v):  # number(): kind < 160, then int8 of 8 v
    return [0, int(round(v * 8)) & 0xFF]


def vec(x, y):
    return num(x) + num(y)


def body(kind, x, y, vx=0.0, vy=0.0, spin=0.0, bullet=False, angle=0.0):
    return ([BODY, kind] + vec(x, y) + num(angle) + vec(vx, vy) + num(spin) + [0, 0, 0] +
            [0, int(bullet), 1, 1])  # no damping, gravity scale 1, rotating, bullet?, may sleep, awake


def shape_def(sensor=False):  # density, friction, restitution default; category 1, group 0
    return [0, 0, 0, 0 if sensor else 200, 0, 0, 0, 0, 0, 2]


def circle(b, x, y, r, sensor=False):
    return [SHAPE, b] + shape_def(sensor) + [0] + vec(x, y) + num(r)


def box(b, hx, hy):
    return [SHAPE, b] + shape_def() + [1, 1] + num(hx) + num(hy) + vec(0, 0) + num(0)


def polygon(b, points, radius=0.0):
    out = [SHAPE, b] + shape_def() + [1, 0, len(points) - 3]
    for x, y in points:
        out += vec(x, y)
    return out + ([1] + num(radius) if radius else [0])


def segment(b, x1, y1, x2, y2):
    return [SHAPE, b] + shape_def() + [2] + vec(x1, y1) + vec(x2, y2)


def chain(b, points, loop=False):
    out = [SHAPE, b] + shape_def() + [3, int(loop), len(points) - 2]
    for x, y in points:
        out += vec(x, y)
    return out


def joint(kind, a, b, *fields):
    return [JOINT, a, b, 0, kind] + [x for f in fields for x in f]


def steps(n):
    return [STEP, 1] * n


def world_with_ground():  # body 0: static ground box
    return body(STATIC, 0, -1) + box(0, 10, 1)


seeds = {
    "falling_shapes": world_with_ground() + body(DYNAMIC, 0, 2) + circle(1, 0, 0, 0.5) +
    body(DYNAMIC, 1.5, 3, angle=0.5) + polygon(2, [(-0.5, -0.5), (0.5, -0.5), (0, 0.5)], 0.125) + steps(30),
    "queries_and_snapshot": world_with_ground() + body(DYNAMIC, 0, 1) + box(1, 0.5, 0.5) + steps(10) +
    [QUERY, 0] + vec(-5, 5) + vec(10, -10) + vec(0, 0) + num(0) +
    [QUERY, 1] + vec(-5, 0.5) + vec(10, 0) + vec(0, 0) + num(0) +
    [QUERY, 2] + vec(-1, -1) + vec(1, 2) + vec(0, 0) + num(0) +
    [QUERY, 3] + vec(0, 1) + vec(0, 0) + vec(0, 0) + num(0) +
    [QUERY, 4] + vec(0, 1) + vec(0.5, 0) + vec(0, 0) + num(0) +
    [QUERY, 5] + vec(0, 0) + vec(0, 0) + vec(0, 1) + num(0.5) + [1] + num(0.5) + num(0.5) + vec(0, 0) + num(0) +
    [SNAPSHOT, 0] + steps(5) + [SNAPSHOT, 1] + steps(5),
    "segments_and_chains": body(STATIC, 0, 0) + segment(0, -8, 0, 8, 0) +
    chain(0, [(-8, 4), (-4, 1), (0, 0.5), (4, 1), (8, 4)]) + chain(0, [(-2, 6), (2, 6), (0, 8)], loop=True) +
    body(DYNAMIC, -6, 6) + circle(1, 0, 0, 0.25) + body(DYNAMIC, 6, 6) + box(2, 0.25, 0.25) + steps(40),
    "bullet_ccd": world_with_ground() + body(STATIC, 4, 2) + box(1, 0.125, 2) +
    body(DYNAMIC, -4, 2, vx=15.875, bullet=True) + circle(2, 0, 0, 0.125) +
    body(DYNAMIC, -4, 4, vx=15.875, spin=15.875) + box(3, 0.75, 0.125) +
    [PUSH, 2, 3] + vec(15.875, 0) + vec(-4, 2) + steps(40),
    "sensor_and_forces": world_with_ground() + body(STATIC, 0, 1) + circle(1, 0, 0, 1, sensor=True) +
    body(DYNAMIC, 0, 4) + box(2, 0.5, 0.25) + [PUSH, 2, 2] + vec(5, 0) + vec(0, 0) +
    [PUSH, 2, 3] + vec(1, 2) + vec(0, 4) + [PUSH, 2, 7] + vec(0.5, 0) + vec(1, 5) + steps(30) +
    [SET_OR_DESTROY | 8, 4, 0, 0, 0] + vec(0, 5) + [SET_OR_DESTROY, 0, 2] + steps(5),
}

# One seed per joint kind: ground, two dynamic boxes, the joint between ground and box 1 (and a
# second one between the boxes), then steps.
joint_fields = {
    "revolute": lambda: [vec(0, 4), vec(0, 0.5), num(0), [1], num(-1), num(1), [1], num(2), num(15)],
    "prismatic": lambda: [vec(0, 4), vec(0, 0), vec(1, 0), num(0), [1], num(-1), num(1), [1], num(1), num(15)],
    "distance": lambda: [vec(0, 4), vec(0, 0), num(2), num(1), num(3), num(2), num(0.5)],
    "weld": lambda: [vec(0, 4), vec(0, 0.5), num(0), num(5), num(0.5)],
    "wheel": lambda: [vec(0, 4), vec(0, 0), vec(0, 1), num(4), num(0.75), [1], num(3), num(10)],
    "motor": lambda: [vec(1, 3), num(0.5), num(15), num(15), num(0.25)],
    "mouse": lambda: [vec(2, 4), num(5), num(0.75), num(15)],
}
for kind, (name, fields) in enumerate(joint_fields.items()):
    seeds["joint_" + name] = (world_with_ground() + body(DYNAMIC, 0, 3) + box(1, 0.5, 0.5) +
                              body(DYNAMIC, 1.5, 3) + circle(2, 0, 0, 0.5) + joint(kind, 0, 1, *fields()) +
                              joint(kind, 1, 2, *fields()) + steps(10) + [SET_OR_DESTROY | 8, 6, 0, 0, 0] + num(1) + num(0) +
                              [SET_OR_DESTROY | 8, 7, 0, 0, 0] + vec(1, 2) + [SNAPSHOT, 0] + steps(10) +
                              [SET_OR_DESTROY, 2, 0] + steps(2))

out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "api")
os.makedirs(out, exist_ok=True)
for name, program in seeds.items():
    with open(os.path.join(out, name + ".bin"), "wb") as f:
        f.write(bytes(x & 0xFF for x in program))
print(f"{len(seeds)} seeds in {out}")
