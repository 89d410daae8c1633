#!/usr/bin/env python3
"""edits.py SEED MODE — a random scene script with edits between steps.

The scene (a floor, a table, spheres, boxes, superquadrics and, for half
the seeds, convex polyhedra whose OFF files go under
$TMPDIR/vroc-edits-off) and its edits
(mass, position, velocity, size, delete, new objects, settings, `random`)
depend on SEED alone.  MODE only decides how it is run:
  serial  serially, with the heap
  noheap  serially, without the heap
  udp     with 2 workers over UDP multicast (run it in a private namespace)
  kill    with 3 workers over UDP, one killed mid-run (run.sh sets
          VROC_FAULT_KILL from the seed)
  switch  the heap, the worker count (memq://) and the distribution
          switched at random between steps
  save    serially, with a line `#SAVE` after one of the steps: run.sh
          runs the script to there and `save`s, then a fresh `vroc`
          reads the saved file and the rest (SPEC 11: bit for bit)
Every mode must print the same dump (SPEC 3.2, 5).  tools/fuzz/run.sh
compares them.  Optional developer tool: needs python3, not `make check`.
"""
import math
import os
import random
import sys
import tempfile

seed, mode = int(sys.argv[1]), sys.argv[2]
r = random.Random(seed)                 # the scene and its edits
m = random.Random(seed * 7 + 1)         # mode switches only
s = random.Random(seed * 11 + 3)        # where the save is, only
out = []
P = out.append
names, kinds, count = ["floor", "table"], {"floor": "cube", "table": "cube"}, [0]


def switch():
    if mode != "switch":
        return
    c = m.random()
    if c < 0.3:
        P("heap = %d" % m.randint(0, 1))
    elif c < 0.6:
        P("gps = %d" % m.choice([0, 1, 2, 3]))
    elif c < 0.7:
        P("distribution = %s" % m.choice(["round_robin", "improved"]))


def new_object(z0):
    name = "o%d" % count[0]
    count[0] += 1
    kind = r.choice(["cube", "superquadric", "sphere"])
    names.append(name)
    kinds[name] = kind
    P("%s %s" % (kind, name))
    if kind == "cube":
        P(" size = (%g,%g,%g)" % tuple(r.uniform(0.04, 0.1) for _ in range(3)))
    elif kind == "superquadric":
        P(" a1 = %g\n a2 = %g\n a3 = %g\n exp1 = %g\n exp2 = %g" % (
            r.uniform(.04, .1), r.uniform(.04, .1), r.uniform(.04, .1), r.uniform(.3, 1.5), r.uniform(.3, 1.5)))
    else:
        P(" radius = %g" % r.uniform(0.04, 0.1))
    P(" translate = (%g,%g,%g)" % (r.uniform(-0.9, 0.9), r.uniform(-0.7, 0.7), r.uniform(z0, z0 + 1.2)))
    P(" elasticity = %g" % r.uniform(0, 1))
    if r.random() < 0.5:
        P(" angular_vel = (%g,%g,%g)" % tuple(r.uniform(-3, 3) for _ in range(3)))
    if r.random() < 0.5:
        P(" linear_vel = (%g,%g,%g)" % tuple(r.uniform(-1, 1) for _ in range(3)))


def polyhedra():
    """half the seeds also get 1..2 convex polyhedra (OFF point clouds: a
    prism or an ellipsoid's points) from their own stream, so the rest of
    the scene is drawn as before; they join the objects the edits pick"""
    q = random.Random(seed * 13 + 9)
    if q.random() < 0.5:
        return
    where = os.path.join(tempfile.gettempdir(), "vroc-edits-off")
    os.makedirs(where, exist_ok=True)
    for i in range(q.randint(1, 2)):
        if q.random() < 0.5:
            k, rad, h = q.randint(3, 6), q.uniform(.04, .08), q.uniform(.03, .08)
            pts = [(rad * math.cos(2 * math.pi * j / k), rad * math.sin(2 * math.pi * j / k), z) for z in (-h, h) for j in range(k)]
        else:
            pts = [tuple(q.uniform(-.07, .07) for _ in range(3)) for _ in range(q.randint(6, 12))]
        path = os.path.join(where, "e%d_%d.off" % (seed, i))
        with open(path, "w") as f:
            f.write("OFF\n%d 0 0\n" % len(pts) + "".join("%.17g %.17g %.17g\n" % v for v in pts))
        name = "h%d" % i
        names.append(name)
        kinds[name] = "polyhedron"
        P("polyhedron %s\n file = %s" % (name, path))
        P(" translate = (%g,%g,%g)" % (q.uniform(-0.9, 0.9), q.uniform(-0.7, 0.7), q.uniform(1.0, 2.0)))
        P(" elasticity = %g" % q.uniform(0, 1))
        if q.random() < 0.5:
            P(" angular_vel = (%g,%g,%g)" % tuple(q.uniform(-3, 3) for _ in range(3)))


def edit():
    c, name = r.random(), r.choice(names)
    kind, obj = kinds[name], name.startswith(("o", "h"))
    if c < 0.12 and obj:
        P("%s %s\n mass = %g" % (kind, name, r.choice([-1, 1, 2, 0.5])))
    elif c < 0.22 and obj:
        P("%s %s\n translate = (%g,%g,%g)" % (kind, name, r.uniform(-.8, .8), r.uniform(-.5, .5), r.uniform(1.2, 2.5)))
    elif c < 0.32 and obj:
        P("%s %s\n linear_vel = (%g,%g,%g)" % ((kind, name) + tuple(r.uniform(-1, 1) for _ in range(3))))
    elif c < 0.4 and kind == "cube" and obj:
        P("cube %s\n size = (%g,%g,%g)" % ((name,) + tuple(r.uniform(0.03, 0.1) for _ in range(3))))
    elif c < 0.47 and obj:
        P("delete %s" % name)
        names.remove(name)
    elif c < 0.55:
        new_object(1.3)
    elif c < 0.6:
        P("time_step = %g" % r.choice([0.01, 0.02, 0.05]))
    elif c < 0.65:
        P("collision_dist = %g" % r.choice([0.005, 0.01, 0.02]))
    elif c < 0.7:
        P("max_angular = %g" % r.choice([4, 20, 100]))
    elif c < 0.75:
        P("max_linear = %g" % r.choice([2, 8, 16]))
    elif c < 0.8:
        P("internal_step = %g" % r.choice([0, 0, 0.005]))
    elif c < 0.85:
        P("%s %s\n elasticity = %g" % (kind, name, r.uniform(0, 1)))
    elif c < 0.9:
        P("force = (%g,%g,-1) %g" % (r.uniform(-.3, .3), r.uniform(-.3, .3), r.uniform(0, 12)))
    elif c < 0.93:
        P("cube table\n translate = (0, 0, %g)" % r.choice([0.5, 0.45, 0.4]))
    elif c < 0.95 and "table" in names:
        P("delete table")
        names.remove("table")
    elif c < 0.97:
        P("seed = %d\nroom = 0\nrandom %d" % (r.randint(1, 99), r.randint(1, 3)))
    elif c < 0.99 and kind == "superquadric":
        P("superquadric %s\n exp1 = %g\n exp2 = %g" % (name, r.uniform(.2, 2), r.uniform(.2, 2)))
    else:
        P("cube table\n mass = %g" % r.choice([-1, 0.5, 3]))


P({"serial": "", "noheap": "heap = 0", "udp": "gps = 2", "kill": "gps = 3", "switch": "lcm_url = memq://",
   "save": ""}[mode])
P("time_step = %g\ncollision_dist = %g\nmax_frames = 0\ngravity" % (r.choice([0.02, 0.05]), r.choice([0.005, 0.01])))
P("cube floor\n size = (3, 3, 0.1)\n translate = (0, 0, -0.1)\n mass = -1")
P("cube table\n size = (1, 0.8, 0.05)\n translate = (0, 0, 0.5)\n mass = -1\n elasticity = 0.3")
for _ in range(r.randint(3, 7)):
    new_object(0.8)
polyhedra()
switch()
P("step %d" % r.randint(1, 10))
steps = [len(out)]
for _ in range(r.randint(3, 10)):
    edit()
    switch()
    P("step %d" % r.randint(1, 25))
    steps.append(len(out))
if mode == "save":
    out.insert(s.choice(steps), "#SAVE")
P("dump")
print("\n".join(out))
