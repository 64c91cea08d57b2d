/*
 * Fuzz target: MoveIt planning scenes (opx_world_load_scene_memory).  Each
 * input is read twice, as planning scene YAML and as .scene text, so the
 * corpus holds plain scene files.  A world that loads is read back (names,
 * poses, shapes), its objects are found by name, and a small robot is
 * checked against it for collision and distance on both engines, which
 * must agree.
 */
#include "fuzz_check.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const opx_pose kIdentity = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};

static int pose_is_finite(const opx_pose *pose) {
    int i, finite = 1;
    for (i = 0; i < 3; ++i) finite &= isfinite(pose->position[i]) != 0;
    for (i = 0; i < 4; ++i) finite &= isfinite(pose->orientation[i]) != 0;
    return finite;
}

/* The readers' bound on every length and coordinate (+-1e6 m), so that
 * every distance is finite and an object is always found.  A shape's pose
 * in its object's frame may compose three bounded poses (an APPEND's
 * object pose, its shape pose and the existing object's). */
#define MAX_METRES 1e6

static void require_bounded_pose(const opx_pose *pose, double bound) {
    int i;
    for (i = 0; i < 3; ++i) FUZZ_REQUIRE(fabs(pose->position[i]) <= bound);
}

static void require_bounded_shape(const opx_shape *shape) {
    size_t i;
    require_bounded_pose(&shape->pose, 3 * MAX_METRES);
    FUZZ_REQUIRE(shape->radius <= MAX_METRES && shape->length <= MAX_METRES);
    for (i = 0; i < 3; ++i) FUZZ_REQUIRE(shape->size[i] <= MAX_METRES);
    for (i = 0; i < 3 * shape->vertex_count; ++i) FUZZ_REQUIRE(fabs(shape->vertices[i]) <= MAX_METRES);
}

/* Reads and checks a shape of an object. */
static void read_shape(const opx_world *world, uint32_t object, uint32_t s) {
    opx_shape shape = OPX_SHAPE_INIT;
    FUZZ_REQUIRE(FUZZ_CALL(opx_world_get_shape, world, object, s, &shape) == OPX_OK);
    FUZZ_REQUIRE(pose_is_finite(&shape.pose));
    switch (shape.kind) {
    case OPX_SHAPE_BOX:
        FUZZ_REQUIRE(shape.size[0] > 0.0 && shape.size[1] > 0.0 && shape.size[2] > 0.0);
        break;
    case OPX_SHAPE_SPHERE: FUZZ_REQUIRE(shape.radius > 0.0); break;
    case OPX_SHAPE_CYLINDER: FUZZ_REQUIRE(shape.radius > 0.0 && shape.length > 0.0); break;
    case OPX_SHAPE_MESH: {
        const uint32_t *indices = (const uint32_t *)shape.indices;
        size_t i;
        FUZZ_REQUIRE(shape.triangle_count > 0 && shape.vertex_count > 0);
        for (i = 0; i < 3 * shape.triangle_count; ++i) FUZZ_REQUIRE(indices[i] < shape.vertex_count);
        break;
    }
    default: FUZZ_REQUIRE(!"a scene shape of a kind the readers do not make");
    }
    require_bounded_shape(&shape);
}

/* Reads every object back. */
static void read_world(const opx_world *world) {
    uint32_t count = 0, o, s;
    FUZZ_REQUIRE(FUZZ_CALL(opx_world_get_object_count, world, &count) == OPX_OK);
    for (o = 0; o < count; ++o) {
        const char *name = NULL;
        uint32_t found = UINT32_MAX, shapes = 0;
        int32_t enabled = 0;
        opx_pose pose;
        FUZZ_REQUIRE(FUZZ_CALL(opx_world_get_object_name, world, o, &name) == OPX_OK && name != NULL);
        /* The first object of that name: this one or an earlier one. */
        FUZZ_REQUIRE(FUZZ_CALL(opx_world_find_object, world, name, &found) == OPX_OK && found <= o);
        FUZZ_REQUIRE(FUZZ_CALL(opx_world_get_object_pose, world, o, &pose) == OPX_OK && pose_is_finite(&pose));
        FUZZ_REQUIRE(FUZZ_CALL(opx_world_get_object_enabled, world, o, &enabled) == OPX_OK && enabled == 1);
        FUZZ_REQUIRE(FUZZ_CALL(opx_world_get_shape_count, world, o, &shapes) == OPX_OK && shapes > 0);
        require_bounded_pose(&pose, MAX_METRES);
        for (s = 0; s < shapes; ++s) read_shape(world, o, s);
    }
}

/* A robot of three links (sphere, box, capsule) near the origin, made once. */
static const opx_linkset *small_robot(void) {
    static opx_linkset *robot = NULL;
    opx_shape sphere = OPX_SHAPE_INIT, box = OPX_SHAPE_INIT, capsule = OPX_SHAPE_INIT;
    opx_pose poses[3];
    uint32_t link;
    if (robot != NULL) return robot;
    sphere.kind = OPX_SHAPE_SPHERE, sphere.radius = 0.2;
    box.kind = OPX_SHAPE_BOX, box.size[0] = 0.4, box.size[1] = 0.3, box.size[2] = 0.2;
    capsule.kind = OPX_SHAPE_CAPSULE, capsule.radius = 0.05, capsule.length = 0.6;
    FUZZ_REQUIRE(opx_linkset_create(&robot) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_link(robot, "ball", &link) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_shape(robot, link, &sphere, NULL) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_link(robot, "block", &link) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_shape(robot, link, &box, NULL) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_link(robot, "rod", &link) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_shape(robot, link, &capsule, NULL) == OPX_OK);
    poses[0] = poses[1] = poses[2] = kIdentity;
    poses[0].position[0] = 1.0, poses[0].position[2] = 0.7;
    poses[1].position[1] = 0.5, poses[1].position[2] = 0.3;
    poses[2].position[0] = 0.5, poses[2].position[2] = 1.0;
    FUZZ_REQUIRE(opx_linkset_set_poses(robot, poses, 3, 0) == OPX_OK);
    return robot;
}

/* Collision and distance against the objects alone, both engines. */
static void query_world(const opx_world *world) {
    static opx_query *queries[2];
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit[2] = {OPX_COLLISION_RESULT_INIT, OPX_COLLISION_RESULT_INIT};
    opx_distance_result near[2] = {OPX_DISTANCE_RESULT_INIT, OPX_DISTANCE_RESULT_INIT};
    uint32_t count = 0;
    int e;
    request.max_contacts = 8;
    request.compute_penetration = 1;
    FUZZ_REQUIRE(opx_world_get_object_count(world, &count) == OPX_OK);
    for (e = 0; e < 2; ++e) {
        if (queries[e] == NULL) {
            opx_query_options options = OPX_QUERY_OPTIONS_INIT;
            options.engine = e == 0 ? OPX_ENGINE_DIRECT : OPX_ENGINE_AMORTIZED;
            FUZZ_REQUIRE(opx_query_create(&options, &queries[e]) == OPX_OK);
        }
        FUZZ_REQUIRE(FUZZ_CALL(opx_query_set_world, queries[e], world) == OPX_OK);
        FUZZ_REQUIRE(FUZZ_CALL(opx_query_collide, queries[e], NULL, small_robot(), &request, &hit[e]) == OPX_OK);
        FUZZ_REQUIRE(FUZZ_CALL(opx_query_distance, queries[e], NULL, small_robot(), NULL, &near[e]) == OPX_OK);
        if (hit[e].contact_count > 0) {
            opx_contact contact = OPX_CONTACT_INIT;
            FUZZ_REQUIRE(FUZZ_CALL(opx_query_get_contact, queries[e], 0, &contact) == OPX_OK);
            FUZZ_REQUIRE(contact.object >= 0 && (uint32_t)contact.object < count);
        }
        FUZZ_REQUIRE(FUZZ_CALL(opx_query_set_world, queries[e], NULL) == OPX_OK);
    }
    FUZZ_REQUIRE(hit[0].collided == hit[1].collided && near[0].found == near[1].found);
    FUZZ_REQUIRE(near[0].found ? count > 0 : count == 0);
    if (near[0].found) {
        FUZZ_REQUIRE(near[0].object >= 0 && (uint32_t)near[0].object < count);
        FUZZ_REQUIRE(near[0].distance == near[1].distance);
        /* Away from touching (cylinders are measured to about 1e-7 m). */
        if (fabs(near[0].distance) > 1e-6) FUZZ_REQUIRE(near[0].collided == hit[0].collided);
    }
}

static void load(const uint8_t *data, size_t size, int32_t format) {
    opx_world *world = (opx_world *)&world; /* must be reset to NULL on failure */
    if (FUZZ_CALL(opx_world_load_scene_memory, data, size, format, &world) != OPX_OK) {
        FUZZ_REQUIRE(world == NULL);
        return;
    }
    FUZZ_REQUIRE(world != NULL);
    read_world(world);
    query_world(world);
    opx_world_destroy(world);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    /* NULL with size 0 is the API's empty scene; libFuzzer passes a pointer. */
    load(data, size, OPX_SCENE_FORMAT_YAML);
    load(data, size, OPX_SCENE_FORMAT_TEXT);
    return 0;
}
