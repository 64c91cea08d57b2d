/* OctoProx public API: include this one header. */
#ifndef OCTOPROX_OCTOPROX_H
#define OCTOPROX_OCTOPROX_H

#include "common.h"
#include "octree.h"
#include "linkset.h"
#include "robot.h"
#include "query.h"
#include "self_collision.h"
#include "world.h"
#include "batch.h"
#include "spheres.h"
#include "io.h"

#endif /* OCTOPROX_OCTOPROX_H */
