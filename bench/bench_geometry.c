/* bench_geometry.c — distance queries per second (make bench).
 *
 * The closest-feature walk alone (vrClosest_Walk), coherent (a smooth
 * periodic motion: about 0.17 degree and 1 mm per query) and cold (random
 * poses, random caches); vrContact_Distance (walk + canonical features)
 * coherent; and libccd's intersection tests on the same poses for scale
 * (they answer only "overlapping?", with a brute-force support function).
 * A box resting flat on a table (parallel faces: the degenerate case the
 * canonical rule exists for) adds vrContact_Region with d = 1 cm.
 * Prints a table and `csv,` lines; asserts nothing.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <ccd/ccd.h>

#include "contact.h"
#include "primitives.h"

#define NPOSE 4096
#define TRIALS 9
#define TRIAL_SECONDS 0.05

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static unsigned long long bench_seed = 88172645463325252ull;
static double bench_rand(void)
{
    bench_seed ^= bench_seed << 13;
    bench_seed ^= bench_seed >> 7;
    bench_seed ^= bench_seed << 17;
    return (double)(bench_seed >> 11) / 9007199254740992.0;
}
static vec3 bench_dir(void)
{
    double z = 2 * bench_rand() - 1, a = 2 * VR_PI * bench_rand(), s = sqrt(1 - z * z);
    return vec3_make(s * cos(a), s * sin(a), z);
}

typedef struct Case {
    const char *name;
    int resting;           /* b slides and turns flat on a, 2..4 mm above it */
    vrShape a, b;
    vrPose pa;
    vrPose coherent[NPOSE], cold[NPOSE];
    vrWalkCache cold_cache[NPOSE];
} Case;

/* b circles a at 1.15 times the summed outer radii, spinning twice per lap */
static void make_poses(Case *c)
{
    double R = 1.15 * (c->a.poly->r_out + c->b.poly->r_out);
    vec3 axis = vec3_normalize(vec3_make(0.3, -1, 0.5));
    int i;
    c->pa = vrPose_make(vec3_zero(), quat_identity());
    for (i = 0; i < NPOSE; i++) {
        double t = 2 * VR_PI * i / NPOSE;
        vec3 p = vec3_scale(vec3_make(cos(t), sin(t), 0.3 * sin(2 * t)), R);
        const vrPolyhedron *pb = c->b.poly;
        c->coherent[i] = vrPose_make(p, quat_from_axis_angle(axis, 2 * t));
        if (c->resting)
            c->coherent[i] = vrPose_make(vec3_make(0.3 * cos(t), 0.2 * sin(t), 0.025 + 0.25 + 0.003 + 0.001 * sin(3 * t)),
                                         quat_from_axis_angle(vec3_make(0, 0, 1), 0.3 * sin(t)));
        c->cold[i] = vrPose_make(vec3_scale(bench_dir(), R * (0.9 + 0.5 * bench_rand())),
                                 quat_from_axis_angle(bench_dir(), VR_PI * bench_rand()));
        memset(&c->cold_cache[i], 0, sizeof c->cold_cache[i]);
        c->cold_cache[i].a.type = (int)(3 * bench_rand());
        c->cold_cache[i].a.index = (int)(bench_rand() * (c->cold_cache[i].a.type == 0 ? c->a.poly->nv
                                                         : c->cold_cache[i].a.type == 1 ? c->a.poly->ne : c->a.poly->nf));
        c->cold_cache[i].b.type = (int)(3 * bench_rand());
        c->cold_cache[i].b.index = (int)(bench_rand() * (c->cold_cache[i].b.type == 0 ? pb->nv
                                                         : c->cold_cache[i].b.type == 1 ? pb->ne : pb->nf));
        c->cold_cache[i].valid = 1;
    }
}

/* ---- what is timed ----------------------------------------------------- */

enum { WALK_COHERENT, WALK_COLD, CONTACT_COHERENT, CCD_GJK, CCD_MPR, REGION_COHERENT, NMODES };
static const char *mode_name[NMODES] = {"walk coherent", "walk cold", "contact coherent", "ccdGJKIntersect",
                                        "ccdMPRIntersect", "region coherent"};

typedef struct CcdBody { const vrPolyhedron *p; const vrPose *pose; } CcdBody;

static void ccd_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const CcdBody *o = obj;
    vec3 d = mat33_tmulv(&o->pose->R, vec3_make(dir->v[0], dir->v[1], dir->v[2])), w;
    int i, best = 0;
    for (i = 1; i < o->p->nv; i++)
        if (vec3_dot(d, o->p->vert[i]) > vec3_dot(d, o->p->vert[best])) best = i;
    w = vrPose_apply(o->pose, o->p->vert[best]);
    ccdVec3Set(out, w.x, w.y, w.z);
}

static void ccd_centre(const void *obj, ccd_vec3_t *out)
{
    vec3 p = ((const CcdBody *)obj)->pose->p;
    ccdVec3Set(out, p.x, p.y, p.z);
}

/* one pass over the NPOSE poses; returns feature steps (walk modes) */
static long run_pass(Case *c, int mode, vrWalkCache *warm, long *sink)
{
    long steps = 0;
    int i, s, pen;
    vec3 ca, cb;
    vrContact out;
    ccd_t ccd;
    CcdBody oa, ob;
    CCD_INIT(&ccd);
    ccd.support1 = ccd.support2 = ccd_support;
    ccd.center1 = ccd.center2 = ccd_centre;
    oa.p = c->a.poly, oa.pose = &c->pa, ob.p = c->b.poly;
    for (i = 0; i < NPOSE; i++) {
        switch (mode) {
        case WALK_COHERENT:
            *sink += vrClosest_Walk(c->a.poly, &c->pa, c->b.poly, &c->coherent[i], warm, &ca, &cb, &s, &pen) > 0;
            steps += s;
            break;
        case WALK_COLD: {
            vrWalkCache w = c->cold_cache[i];
            *sink += vrClosest_Walk(c->a.poly, &c->pa, c->b.poly, &c->cold[i], &w, &ca, &cb, &s, &pen) > 0;
            steps += s;
            break;
        }
        case CONTACT_COHERENT:
            vrContact_Distance(&c->a, &c->pa, &c->b, &c->coherent[i], warm, &out);
            *sink += out.dist > 0;
            steps += out.walk_steps;
            break;
        case REGION_COHERENT:
            vrContact_Region(&c->a, &c->pa, &c->b, &c->coherent[i], 0.01, warm, &out);
            *sink += out.npoints;
            steps += out.walk_steps;
            break;
        default:
            ob.pose = &c->coherent[i];
            *sink += mode == CCD_GJK ? ccdGJKIntersect(&oa, &ob, &ccd) : ccdMPRIntersect(&oa, &ob, &ccd);
        }
    }
    return steps;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}

/* TRIALS timed trials of at least TRIAL_SECONDS: the best and the median
 * (the machine is shared and virtual: the best is the code, the median the
 * day) */
static void run(Case *c, int mode, long *sink)
{
    double ns[TRIALS];
    vrWalkCache warm;
    long steps = 0, total = 0;
    int k;
    memset(&warm, 0, sizeof warm);
    run_pass(c, mode, &warm, sink); /* warm up the walk cache and the memory caches */
    for (k = 0; k < TRIALS; k++) {
        long n = 0;
        double t0 = now(), t;
        do {
            steps += run_pass(c, mode, &warm, sink);
            n += NPOSE;
        } while ((t = now() - t0) < TRIAL_SECONDS);
        ns[k] = 1e9 * t / n;
        total += n;
    }
    qsort(ns, TRIALS, sizeof ns[0], cmp_double);
    printf("%-14s %-17s %9.1f %9.1f %12.0f %8.3f\n", c->name, mode_name[mode], ns[0], ns[TRIALS / 2], 1e9 / ns[0],
           (double)steps / total);
    printf("csv,geometry,%s,%s,%.1f,%.1f,%.0f,%.3f\n", c->name, mode_name[mode], ns[0], ns[TRIALS / 2], 1e9 / ns[0],
           (double)steps / total);
}

static int make_case(Case *c, const char *name, vrPolyhedron *a, vrPolyhedron *b, int resting)
{
    memset(&c->a, 0, sizeof c->a);
    c->name = name;
    c->resting = resting;
    c->a.kind = VR_SHAPE_POLY;
    c->a.poly = a;
    c->b = c->a;
    c->b.poly = b;
    make_poses(c);
    return 0;
}

int main(void)
{
    static Case cases[4];
    vrPolyhedron *cube, *mesh, *sq, *table;
    char err[256];
    long sink = 0;
    int i, m;
    if (vrPolyhedron_Cube(vec3_make(0.25, 0.25, 0.25), &cube, err, sizeof err)
        || vrPolyhedron_Sphere(0.3, 10, 10, &mesh, err, sizeof err)
        || vrPolyhedron_Superquadric(0.5, 0.5, vec3_make(0.3, 0.25, 0.2), 20, 20, &sq, err, sizeof err)
        || vrPolyhedron_Cube(vec3_make(1, 0.5, 0.025), &table, err, sizeof err)) {
        fprintf(stderr, "bench_geometry: %s\n", err);
        return 1;
    }
    make_case(&cases[0], "cube-cube", cube, cube, 0);
    make_case(&cases[1], "mesh10-mesh10", mesh, mesh, 0);
    make_case(&cases[2], "sq20-sq20", sq, sq, 0);
    make_case(&cases[3], "table-box", table, cube, 1);
    printf("# shapes: cube 8 v; 10x10 sphere mesh %d v %d e %d f; 20x20 superquadric (0.5, 0.5) %d v %d e %d f\n",
           mesh->nv, mesh->ne, mesh->nf, sq->nv, sq->ne, sq->nf);
    printf("%-14s %-17s %9s %9s %12s %8s\n", "pair", "query", "best ns", "median ns", "best q/s", "steps");
    printf("csv,bench,pair,query,best_ns_per_query,median_ns_per_query,best_queries_per_s,mean_steps\n");
    for (i = 0; i < 3; i++)
        for (m = 0; m < REGION_COHERENT; m++) run(&cases[i], m, &sink);
    for (m = WALK_COHERENT; m < NMODES; m++)
        if (m != WALK_COLD) run(&cases[3], m, &sink);
    vrPolyhedron_Free(table);
    vrPolyhedron_Free(cube);
    vrPolyhedron_Free(mesh);
    vrPolyhedron_Free(sq);
    return sink < 0;
}
