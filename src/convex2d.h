/* convex2d.h — 2-D convex geometry in the contact plane (convex2d.c): points,
 * hulls, their intersection, and the contact region's tolerances. */
#ifndef VROC_CONVEX2D_H
#define VROC_CONVEX2D_H

#include "vec.h"

/* The region's tolerances (m): within VR_REGION_SLACK a point is on a line
 * or in a polygon (also the slab slack of region.c); points closer than
 * VR_REGION_DEDUP are one. */
#define VR_REGION_SLACK 1e-9
#define VR_REGION_DEDUP 1e-12

typedef struct P2 { double x, y; } P2;

static inline P2 p2(double x, double y) { P2 r; r.x = x; r.y = y; return r; }
static inline P2 p2_sub(P2 a, P2 b) { return p2(a.x - b.x, a.y - b.y); }
static inline P2 p2_lerp(P2 a, P2 b, double t) { return p2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)); }
static inline double p2_cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
static inline double p2_dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
static inline double p2_len(P2 a) { return sqrt(p2_dot(a, a)); }

static inline int p2_less(P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
/* twice the signed area of o, a, b: > 0 when they turn left */
static inline double p2_turn(P2 o, P2 a, P2 b) { return p2_cross(p2_sub(a, o), p2_sub(b, o)); }

/* Andrew's monotone chain over points sorted by p2_less: the lower, then the
 * upper hull into h (room for 2n), counter-clockwise without collinear
 * points, the first point again at the end; returns its length */
int vrP2_Chain(const P2 *p, int n, P2 *h);
/* the counter-clockwise hull of p[0..n) without collinear points, in place
 * (tmp: room for 2n); a point or a segment when degenerate */
int vrP2_Hull(P2 *p, int n, P2 *tmp);
/* Intersection of two convex sets given as hulls (1 point, 2 = a segment,
 * >= 3 = a counter-clockwise polygon), within VR_REGION_SLACK; buf holds
 * np + nq + 2 points. */
int vrP2_IntersectHulls(P2 *p, int np, P2 *q, int nq, P2 *out, P2 *buf);

#endif
