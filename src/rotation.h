/* rotation.h — a body's orientation in free flight (rotation.c) */
#ifndef VROC_ROTATION_H
#define VROC_ROTATION_H

#include "body.h"

/* the orientation at tau >= 0 after b's anchor (body to world); an
 * asymmetric body advances its cache of integrator states */
quat vrRotation_Orientation(vrBody *b, double tau);

#endif
