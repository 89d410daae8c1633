#!/usr/bin/env python3
"""physics.py VROC FROM TO — random scenes checked against physics.

Each seed makes a closed room (floor, walls, ceiling), thin and rotated
static plates and blocks, and dynamic spheres, boxes and superquadrics of
different masses (half the seeds also 1..3 convex polyhedra: OFF prisms,
point clouds and tetrahedra, their files under $TMPDIR/vroc-physics-off), elasticities, speeds (up to 12 m/s) and spins, under
gravity or none; then steps it in blocks and, after every block, checks
  - nothing interpenetrates: a `start` that runs no frame (max_frames = 0)
    is refused when two objects overlap (SPEC 1.4), so an object that
    tunnelled into a static one or into another object is reported;
  - energy never grows: every response has e <= 1 and the force is
    conservative, so `stats` energy may only fall (allowing the rotation
    integrator's drift, SPEC 3.2, and 5e-3 for push-outs, below);
  - with e = 1 everywhere and no force, energy is kept (speed clamps are
    lifted: max_linear and max_angular above anything reachable);
  - with no force and nothing static (an eighth of the seeds: no room),
    linear momentum is kept to 1e-9, whatever the elasticities, and so is
    angular momentum about the origin when the bodies are boxes and
    spheres (their inertia has a closed form here);
  - nothing tunnels: dumped every frame, no body leaves the room, and no
    centre crosses a thin plate's plane where the plate stands wider around
    it than the body reaches plus how far it moved in the frame;
  - every dumped number is finite;
  - two in five of the other seeds are rough (SPEC 7): every object has
    friction (default_friction, 0.2..1), half of them a stack of boxes and
    all a pile of 6..12 balls and boxes dropped onto each other, under the
    same checks (no overlap, energy never growing, same bits);
  - heap = 0, and workers (memq://, in this process's memory: 2 dealt
    round robin for even seeds, 3 by the improved distribution for odd), print
    the same dumps as heap = 1 serially, to the bit (SPEC 3.2, 5);
  - saved after a random frame and read back by a fresh vroc with the
    rest of the script, the run prints the same dumps (SPEC 11: rest,
    islands, warm starts and all).
Prints the seeds that break one, with the first broken check.  Optional
developer tool (python3), not `make check`; run.sh runs the other fuzzer.
"""
import math
import os
import random
import subprocess
import sys
import tempfile


def scene(seed, mode="heap = 1"):
    r = random.Random(seed)
    out = []
    P = out.append
    conservative = r.random() < 0.25          # e = 1, no force: energy kept
    free = random.Random(seed * 3 + 2).random() < 0.125   # no force, no room: momentum kept
    step, d = r.choice([0.01, 0.02, 0.05]), r.choice([0.005, 0.01, 0.02])
    P("time_step = %g\ncollision_dist = %g\nmax_frames = 0" % (step, d))
    P("max_linear = 1000\nmax_angular = 100000")        # no clamp bites: they remove energy
    if not conservative and not free:
        P("gravity")
    P(mode)
    rough = random.Random(seed * 7 + 1)    # its own stream: the other seeds' scenes stay as they were
    is_rough = not conservative and not free and rough.random() < 0.4
    if is_rough:
        P("default_friction = %g" % rough.uniform(0.2, 1))
    # a 3 m room of 0.1 m walls
    for name, size, at in () if free else (("floor", (1.6, 1.6, 0.1), (0, 0, -0.1)), ("ceil", (1.6, 1.6, 0.1), (0, 0, 3.1)),
                           ("wx0", (0.1, 1.6, 1.6), (-1.6, 0, 1.5)), ("wx1", (0.1, 1.6, 1.6), (1.6, 0, 1.5)),
                           ("wy0", (1.6, 0.1, 1.6), (0, -1.6, 1.5)), ("wy1", (1.6, 0.1, 1.6), (0, 1.6, 1.5))):
        P("cube %s\n size = (%g,%g,%g)\n translate = (%g,%g,%g)\n mass = -1" % ((name,) + size + at))
        P(" elasticity = %g" % (1 if conservative else r.uniform(0.3, 1)))
    # static plates (thin) and blocks, some rotated, kept apart from one another
    statics, plates, reach, mass, inertia = [], [], {}, {}, {}
    for i in range(0 if free else r.randint(0, 3)):
        for _ in range(100):
            c = (r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0.3, 2.2))
            if all(math.dist(c, s) > 0.9 for s in statics):
                break
        else:
            continue
        statics.append(c)
        thin = r.random() < 0.5
        size = (r.uniform(0.2, 0.4), r.uniform(0.2, 0.4), 0.005 if thin else r.uniform(0.05, 0.2))
        P("cube s%d\n size = (%g,%g,%g)\n translate = (%g,%g,%g)\n mass = -1" % ((i,) + size + c))
        axis, angle = (0, 0, 1), 0
        if r.random() < 0.6:
            axis, angle = (r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0.2, 1)), r.uniform(0.1, 1.2)
            P(" rotate = (%g,%g,%g) %g" % (axis + (angle,)))
        plates.append((c, rotation(axis, angle), size))
        P(" elasticity = %g" % (1 if conservative else r.uniform(0, 1)))
    # an eighth of the rooms have a stack of boxes standing on the floor,
    # each within the envelope of the one below (in contact at the start)
    placed, near = [], {}          # near: how far the others keep from a placed centre
    k = random.Random(seed * 5 + 3)
    x, y = k.uniform(-1, 1), k.uniform(-1, 1)
    if not free and k.random() < (0.5 if is_rough else 0.125) and all(math.dist((x, y), s[:2]) > 0.9 for s in statics):
        z = 0.0
        for j in range(k.randint(2, 5)):
            half = tuple(float("%.6g" % v) for v in (k.uniform(0.05, 0.15), k.uniform(0.05, 0.15), k.uniform(0.02, 0.08)))
            z += k.uniform(0, d) + half[2]
            c = (x + k.uniform(-.03, .03), y, z)
            P("cube k%d\n size = (%.17g,%.17g,%.17g)\n translate = (%.17g,%.17g,%.17g)" % ((j,) + half + c))
            P(" mass = %g\n elasticity = %g" % (k.choice([0.2, 1, 5]), 1 if conservative else k.uniform(0, 1)))
            reach["k%d" % j] = math.sqrt(sum(h * h for h in half))
            placed.append(c)
            near[c] = 0.5
            z += half[2]
    # a rough room's pile: a column of balls and boxes 0.25 m apart, a little
    # off one another, dropped onto the floor and onto each other
    px, py = rough.uniform(-1, 1), rough.uniform(-1, 1)
    if is_rough and all(math.dist((px, py), s[:2]) > 0.9 for s in statics) and all(math.dist((px, py), q[:2]) > 0.6 for q in placed):
        for j in range(rough.randint(6, 12)):
            c = (px + rough.uniform(-.04, .04), py + rough.uniform(-.04, .04), 0.12 + 0.25 * j)
            if rough.random() < 0.5:
                P("sphere p%d\n radius = %g" % (j, 0.08))
                reach["p%d" % j] = 0.08
            else:
                P("cube p%d\n size = (0.08,0.08,0.08)" % j)
                reach["p%d" % j] = 0.08 * math.sqrt(3)
            P(" translate = (%.17g,%.17g,%.17g)\n mass = %g\n elasticity = %g" % (c + (rough.choice([0.5, 1, 2]), rough.uniform(0, 0.8))))
            placed.append(c)
            near[c] = 0.45
    # dynamic objects on a loose grid, clear of the statics
    for i in range(r.randint(2, 9)):
        for _ in range(200):
            c = (r.uniform(-1.3, 1.3), r.uniform(-1.3, 1.3), r.uniform(0.2, 2.8))
            if all(math.dist(c, s) > 0.75 for s in statics) and all(math.dist(c, p) > near.get(p, 0.3) for p in placed):
                break
        else:
            continue
        placed.append(c)
        kind = r.choice(["cube", "superquadric", "sphere"])
        P("%s d%d" % (kind, i))
        if kind == "cube":
            half = tuple(float("%g" % r.uniform(0.02, 0.12)) for _ in range(3))
            P(" size = (%g,%g,%g)" % half)
            unit = tuple((sum(h * h for h in half) - half[k] ** 2) / 3 for k in range(3))
        elif kind == "superquadric":
            half = (r.uniform(.03, .12), r.uniform(.03, .12), r.uniform(.03, .12))
            unit = None                    # no closed form here
            P(" a1 = %g\n a2 = %g\n a3 = %g\n exp1 = %g\n exp2 = %g" % (half + (r.uniform(.3, 1.8), r.uniform(.3, 1.8))))
        else:
            half = (float("%g" % r.uniform(0.02, 0.12)),) * 3
            P(" radius = %g" % half[0])
            unit = (0.4 * half[0] ** 2,) * 3
        reach["d%d" % i] = math.sqrt(sum(h * h for h in half))   # beyond any point of it
        P(" translate = (%g,%g,%g)" % c)
        mass["d%d" % i] = r.choice([0.1, 0.5, 1, 3, 10])
        inertia["d%d" % i] = unit and tuple(mass["d%d" % i] * u for u in unit)   # principal, body axes
        P(" mass = %g" % mass["d%d" % i])
        P(" elasticity = %g" % (1 if conservative else r.choice([0, 0.3, 0.8, 1, r.uniform(0, 1)])))
        if r.random() < 0.5:
            P(" rotate = (%g,%g,%g) %g" % (r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1) + 0.01, r.uniform(0, 3)))
        speed = r.choice([0, 1, 4, 12])
        if free:   # toward the middle, so that they meet: momentum is checked through collisions
            aim = (0, 0, 1.5)
            P(" linear_vel = (%g,%g,%g)" % tuple((aim[k] - c[k]) * max(speed, 1) / 1.5 + r.uniform(-speed, speed) / 6
                                                  for k in range(3)))
        else:
            P(" linear_vel = (%g,%g,%g)" % tuple(r.uniform(-speed, speed) / 1.8 for _ in range(3)))
        if r.random() < 0.6:
            P(" angular_vel = (%g,%g,%g)" % tuple(r.uniform(-8, 8) for _ in range(3)))
    polyhedra(seed, P, statics, placed, reach, mass, inertia, free, conservative)
    P("start\nstats")
    blocks = r.randint(3, 8)
    for _ in range(blocks):
        P("step 1\ndump\n" * r.randint(5, 60) + "stats\nstart")
    return "\n".join(out) + "\n", dict(conservative=conservative, free=free, plates=plates, reach=reach, mass=mass,
                                       inertia=inertia)


OFF_DIR = os.path.join(tempfile.gettempdir(), "vroc-physics-off")


def off_path(seed, i):
    return os.path.join(OFF_DIR, "s%d_q%d.off" % (seed, i))


def hull_points(q):
    """an OFF polyhedron's points: a prism of 3..6 sides (parallel edges and
    faces, the near-parallel cases of the canonical features), a cloud of
    5..12 points on an ellipsoid (general hulls), or a tetrahedron"""
    kind = q.choice(["prism", "cloud", "tetra"])
    if kind == "prism":
        k, rad, h, phi = q.randint(3, 6), q.uniform(.03, .06), q.uniform(.02, .06), q.uniform(0, 2 * math.pi)
        return [(rad * math.cos(phi + 2 * math.pi * i / k), rad * math.sin(phi + 2 * math.pi * i / k), z)
                for z in (-h, h) for i in range(k)]
    axes = (q.uniform(.03, .06), q.uniform(.03, .06), q.uniform(.03, .06))
    pts = []
    for _ in range(4 if kind == "tetra" else q.randint(5, 12)):
        v = [q.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v)) or 1
        pts.append(tuple(axes[j] * v[j] / n for j in range(3)))
    return pts


def flat(pts):
    """no four points far enough out of one plane to make a solid"""
    a = pts[0]
    for b in pts[1:]:
        for c in pts[1:]:
            for d in pts[1:]:
                u, v, w = ([x[j] - a[j] for j in range(3)] for x in (b, c, d))
                if abs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                       + u[2] * (v[0] * w[1] - v[1] * w[0])) > 1e-6:
                    return False
    return True


def polyhedra(seed, P, statics, placed, reach, mass, inertia, free, conservative):
    """half the seeds get 1..3 convex polyhedra from OFF point clouds (their
    own stream: the rest of each seed's scene is what it was).  The hull's
    centre of mass is its body origin: no vertex lies further from it than
    twice the points' reach about their mean"""
    q = random.Random(seed * 11 + 7)
    if q.random() < 0.5:
        return
    os.makedirs(OFF_DIR, exist_ok=True)
    for i in range(q.randint(1, 3)):
        for _ in range(200):
            c = (q.uniform(-1.3, 1.3), q.uniform(-1.3, 1.3), q.uniform(0.25, 2.75))
            if all(math.dist(c, s) > 0.75 for s in statics) and all(math.dist(c, p) > 0.4 for p in placed):
                break
        else:
            continue
        pts = hull_points(q)
        if flat(pts):
            continue
        mean = [sum(v[j] for v in pts) / len(pts) for j in range(3)]
        pts = [tuple(v[j] - mean[j] for j in range(3)) for v in pts]
        with open(off_path(seed, i), "w") as f:
            f.write("OFF\n%d 0 0\n" % len(pts) + "".join("%.17g %.17g %.17g\n" % v for v in pts))
        placed.append(c)
        name = "q%d" % i
        reach[name] = 2 * max(math.sqrt(sum(x * x for x in v)) for v in pts)
        mass[name] = q.choice([0.1, 0.5, 1, 3, 10])
        inertia[name] = None                   # no closed form here
        P("polyhedron %s\n file = %s\n translate = (%g,%g,%g)" % ((name, off_path(seed, i)) + c))
        P(" mass = %g\n elasticity = %g" % (mass[name], 1 if conservative else q.choice([0, 0.5, 1, q.uniform(0, 1)])))
        if q.random() < 0.5:
            P(" rotate = (%g,%g,%g) %g" % (q.uniform(-1, 1), q.uniform(-1, 1), q.uniform(-1, 1) + 0.01, q.uniform(0, 3)))
        speed = q.choice([0, 1, 4, 12])
        if free:
            P(" linear_vel = (%g,%g,%g)" % tuple((1.5 * (k == 2) - c[k]) * max(speed, 1) / 1.5 for k in range(3)))
        else:
            P(" linear_vel = (%g,%g,%g)" % tuple(q.uniform(-speed, speed) / 1.8 for _ in range(3)))
        if q.random() < 0.6:
            P(" angular_vel = (%g,%g,%g)" % tuple(q.uniform(-8, 8) for _ in range(3)))


def rotation(axis, angle):
    """the rotation matrix of `rotate = axis angle` (Rodrigues)"""
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s, k = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return ((c + x * x * k, x * y * k - z * s, x * z * k + y * s),
            (y * x * k + z * s, c + y * y * k, y * z * k - x * s),
            (z * x * k - y * s, z * y * k + x * s, c + z * z * k))


def tunnelled(lines, plates, reach, room):
    """the first passage through a wall or a thin plate in per-frame dumps"""
    last = {}
    for line in lines:
        f = line.split(",")
        if f[0] not in reach:
            continue
        name, x = f[0], tuple(float(v) for v in f[2:5])
        if room and (abs(x[0]) > 1.5 or abs(x[1]) > 1.5 or not 0 < x[2] < 3):
            return "%s left the room at t %s: %s" % (name, f[1], x)
        if name in last:
            moved = math.dist(last[name], x)
            for c, R, half in plates:
                if half[2] > 0.01:
                    continue
                a, b = (tuple(sum(R[i][j] * (p[i] - c[i]) for i in range(3)) for j in range(3)) for p in (last[name], x))
                margin = reach[name] + moved
                inside = all(abs(q[k]) < half[k] - margin for q in (a, b) for k in (0, 1))
                if inside and a[2] * b[2] < 0:
                    return "%s went through a plate at t %s" % (name, f[1])
        last[name] = x
    return None


def run(vroc, text):
    with tempfile.NamedTemporaryFile("w", suffix=".cmd", delete=False) as f:
        f.write(text)
        path = f.name
    try:
        return subprocess.run([vroc, "-q", path], capture_output=True, text=True, timeout=600), path
    except subprocess.TimeoutExpired:
        return None, path


def dumps(p):
    return [line for line in p.stdout.splitlines() if not line.startswith("frames=")]


def frames_of(lines, mass):
    """each dump as {name: its numbers (t, x, q, v, omega)}"""
    frames, cur = [], {}
    for line in lines:
        f = line.split(",")
        if f[0].startswith("#"):
            if cur:
                frames.append(cur)
            cur = {}
        elif f[0] in mass:
            cur[f[0]] = [float(v) for v in f[1:15]]
    if cur:
        frames.append(cur)
    return frames


def largest_change(sums):
    """from (total vector, size) per dump: the largest distance of a total
    from the first one, and the largest size it is measured against"""
    first, worst, size = None, 0.0, 0.0
    for total, terms in sums:
        size = max(size, terms)
        if first is None:
            first = total
        worst = max(worst, math.dist(total, first))
    return worst, size


def momentum_drift(lines, mass):
    """the largest change of the total linear momentum between two dumps,
    and the sum of the bodies' momenta it is measured against"""
    def sums(fr):
        p = {name: [mass[name] * v for v in f[8:11]] for name, f in fr.items()}
        return [sum(v[k] for v in p.values()) for k in range(3)], sum(math.hypot(*v) for v in p.values())
    return largest_change(sums(fr) for fr in frames_of(lines, mass))


def rotation_matrix(w, x, y, z):
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
            (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
            (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)))


def angular_drift(lines, mass, inertia):
    """the largest change of the total angular momentum about the origin
    (m x cross v, plus R I R^T omega for each body) between two dumps, and
    the sum of the terms' sizes it is measured against"""
    def sums(fr):
        total, terms = [0.0, 0.0, 0.0], 0.0
        for name, f in fr.items():
            x, q, v, w = f[1:4], f[4:8], f[8:11], f[11:14]
            m, R = mass[name], rotation_matrix(*q)
            body = [sum(R[j][i] * w[j] for j in range(3)) * inertia[name][i] for i in range(3)]
            spin = [sum(R[i][j] * body[j] for j in range(3)) for i in range(3)]
            orbit = [m * (x[(i + 1) % 3] * v[(i + 2) % 3] - x[(i + 2) % 3] * v[(i + 1) % 3]) for i in range(3)]
            for i in range(3):
                total[i] += orbit[i] + spin[i]
            terms += math.hypot(*orbit) + math.hypot(*spin)
        return total, terms
    return largest_change(sums(fr) for fr in frames_of(lines, mass))


def check(vroc, seed):
    text, info = scene(seed)
    conservative, plates, reach = info["conservative"], info["plates"], info["reach"]
    p, path = run(vroc, text)
    if p is None:
        return "hang", path
    if p.returncode > 1 or "Sanitizer" in p.stderr or "runtime error" in p.stderr:
        return "crash (exit %d) %s" % (p.returncode, p.stderr.strip()[:200]), path
    if p.stderr.strip():
        return p.stderr.strip().splitlines()[0], path
    problem = tunnelled(dumps(p), plates, reach, not info["free"])
    if problem:
        return problem, path
    if info["free"]:
        drift, size = momentum_drift(dumps(p), info["mass"])
        if drift > 1e-9 * size + 1e-12:
            return "momentum drifted by %.3g (of %.3g)" % (drift, size), path
        if all(info["inertia"].values()):   # boxes and spheres only
            drift, size = angular_drift(dumps(p), info["mass"], info["inertia"])
            if drift > 1e-9 * size + 1e-12:
                return "angular momentum drifted by %.3g (of %.3g)" % (drift, size), path
    energies = []
    for line in p.stdout.splitlines():
        if line.startswith("frames="):
            kv = dict(x.split("=", 1) for x in line.split())
            energies.append((float(kv["time"]), float(kv["energy"])))
        elif not line.startswith("#"):
            if not all(math.isfinite(float(x)) for x in line.split(",")[1:-1]):
                return "non-finite dump: " + line, path
    for (t0, e0), (t1, e1) in zip(energies, energies[1:]):
        scale = max(1.0, abs(e0))
        # the integrator's drift (1e-6/s), and push-outs: an unsupported tip
        # drawn through a surface between grid points is lifted back by its
        # depth (m g h^2 / 2 a step; 4.5e-3 of the energy seen at worst, a
        # push-out to half the envelope gave 3e-2)
        tol = 1e-6 * scale * (t1 - t0 + 1) + (0 if conservative else 5e-3 * scale)
        if e1 > e0 + tol:
            return "energy grew %.9g -> %.9g (t %g -> %g)" % (e0, e1, t0, t1), path
        if conservative and abs(e1 - e0) > tol:
            return "energy not kept %.9g -> %.9g (t %g -> %g)" % (e0, e1, t0, t1), path
    workers = "gps = 2" if seed % 2 == 0 else "distribution = improved\ngps = 3"
    for mode in ("heap = 0", "lcm_url = memq://\n" + workers):
        q, qpath = run(vroc, scene(seed, mode)[0])
        os.unlink(qpath)
        if q is None or dumps(q) != dumps(p):
            return "%s prints other dumps" % mode.replace("\n", ", "), path
    problem = saved_and_read(vroc, seed, text, dumps(p))
    return (problem, path) if problem else (None, path)


def saved_and_read(vroc, seed, text, want):
    """SPEC 11: the run saved after a random frame and the save read by a
    fresh vroc with the rest of the script print the run's dumps"""
    lines = text.split("\n")
    cuts = [i for i, line in enumerate(lines) if line == "dump"][:-1]
    if not cuts:
        return None
    k = random.Random(seed * 13 + 5).choice(cuts)
    fd, saved = tempfile.mkstemp(suffix=".vroc")
    os.close(fd)
    try:
        head, hpath = run(vroc, "\n".join(lines[:k + 1]) + "\nsave %s\n" % saved)
        os.unlink(hpath)
        if head is None or head.returncode > 1:
            return "save: the run to the save failed"
        with open(saved) as f:
            state = f.read()
        tail, tpath = run(vroc, state + "\n".join(lines[k + 1:]))
        os.unlink(tpath)
        if tail is None or tail.returncode > 1 or "Sanitizer" in tail.stderr:
            return "save: the saved run read back failed %s" % (tail and tail.stderr.strip()[:200])
        if dumps(head) + dumps(tail) != want:
            return "save after dump %d of %d, read back, prints other dumps" % (cuts.index(k) + 1, len(cuts) + 1)
    finally:
        os.unlink(saved)
    return None


def main():
    vroc, lo, hi = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    bad = 0
    for seed in range(lo, hi + 1):
        problem, path = check(vroc, seed)
        if problem:
            bad += 1
            print("seed %d: %s  [%s]" % (seed, problem, path), flush=True)
        else:
            os.unlink(path)
            for i in range(3):
                if os.path.exists(off_path(seed, i)):
                    os.unlink(off_path(seed, i))
    print("seeds %d..%d: %d problems" % (lo, hi, bad))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
