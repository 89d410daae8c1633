/* brute_distance.h — a reference distance between two convex polyhedra by
 * brute force over all feature pairs, for the tests that check the walk and
 * the canonical distance (test_closest.c, test_contact.c).  Not library
 * code: it shares no geometry with the walk, so that an error in the walk's
 * formulas cannot hide behind the same error here. */
#ifndef VROC_BRUTE_DISTANCE_H
#define VROC_BRUTE_DISTANCE_H

#include "feature.h"

/* 0 when the polyhedra touch or overlap */
double vrClosest_BruteForce(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb);

#endif
