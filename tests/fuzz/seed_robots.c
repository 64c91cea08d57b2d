/* URDF seeds, and call sequences for the API fuzzer (records of
 * fuzz_api_ops.h whose argument bytes follow the operations' readers). */
#include "seeds.h"

#include "fuzz_api_ops.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* Every geometry kind (a mesh that resolves nowhere), every joint kind. */
static const char URDF_FULL[] =
    "<?xml version=\"1.0\"?>\n<robot name=\"seed\">\n"
    " <material name=\"grey\"><color rgba=\"0.5 0.5 0.5 1\"/></material>\n"
    " <link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\""
    " iyz=\"0\" izz=\"1\"/></inertial>\n"
    "  <visual><geometry><box size=\"1 1 1\"/></geometry><material name=\"grey\"/></visual>\n"
    "  <collision><origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/><geometry><box size=\"0.4 0.3 0.2\"/></geometry>"
    "</collision></link>\n"
    " <link name=\"arm\"><collision><origin xyz=\"0.25 0 0\" rpy=\"0 1.5707963 0\"/>"
    "<geometry><cylinder radius=\"0.05\" length=\"0.5\"/></geometry></collision>\n"
    "  <collision><origin xyz=\"0.5 0 0\"/><geometry><sphere radius=\"0.07\"/></geometry></collision></link>\n"
    " <link name=\"hand\"><collision><geometry><mesh filename=\"package://robot/meshes/hand.stl\""
    " scale=\"1 1 1\"/></geometry></collision></link>\n"
    " <link name=\"slider\"/><link name=\"wheel\"/><link name=\"finger\"/><link name=\"free\"/>"
    "<link name=\"flat\"/>\n"
    " <joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/>"
    "<origin xyz=\"0 0 0.2\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1\"/>"
    "<limit lower=\"-1\" upper=\"2\" effort=\"10\" velocity=\"1.5\"/></joint>\n"
    " <joint name=\"slide\" type=\"prismatic\"><parent link=\"arm\"/><child link=\"slider\"/>"
    "<origin xyz=\"0.5 0 0\"/><axis xyz=\"1 0 0\"/><limit lower=\"0\" upper=\"0.3\" effort=\"100\""
    " velocity=\"0.2\"/></joint>\n"
    " <joint name=\"wheel\" type=\"continuous\"><parent link=\"base\"/><child link=\"wheel\"/>"
    "<origin xyz=\"0 0.2 0\" rpy=\"1.5707963 0 0\"/><axis xyz=\"0 0 1\"/></joint>\n"
    " <joint name=\"finger\" type=\"prismatic\"><parent link=\"slider\"/><child link=\"finger\"/>"
    "<axis xyz=\"0 1 0\"/><limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
    "<mimic joint=\"slide\" multiplier=\"2\" offset=\"0.01\"/></joint>\n"
    " <joint name=\"hand\" type=\"fixed\"><parent link=\"finger\"/><child link=\"hand\"/></joint>\n"
    " <joint name=\"free\" type=\"floating\"><parent link=\"base\"/><child link=\"free\"/></joint>\n"
    " <joint name=\"flat\" type=\"planar\"><parent link=\"base\"/><child link=\"flat\"/>"
    "<axis xyz=\"0 0 1\"/></joint>\n"
    "</robot>\n";

/* The same without the mesh: it loads. */
static const char URDF_PRIMITIVES[] =
    "<robot name=\"p\"><link name=\"a\"><collision><geometry><box size=\"1 2 3\"/></geometry></collision>"
    "<collision><origin xyz=\"1 0 0\" rpy=\"0.1 0.2 0.3\"/><geometry><cylinder radius=\"0.1\" length=\"1\"/>"
    "</geometry></collision></link><link name=\"b\"><collision><geometry><sphere radius=\"0.5\"/></geometry>"
    "</collision></link><joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
    "<axis xyz=\"0 1 0\"/><limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint></robot>";

void write_urdf_seeds(const char *out_dir) {
    write_text_seed(out_dir, "fuzz_urdf", "full.urdf", URDF_FULL);
    write_text_seed(out_dir, "fuzz_urdf", "primitives.urdf", URDF_PRIMITIVES);
    write_text_seed(out_dir, "fuzz_urdf", "one_link.urdf", "<robot name=\"r\"><link name=\"a\"/></robot>");
    write_text_seed(out_dir, "fuzz_urdf", "relative_mesh.urdf",
                    "<robot name=\"r\"><link name=\"a\"><collision><geometry><mesh filename=\"meshes/a.dae\"/>"
                    "</geometry></collision></link></robot>");
    write_text_seed(out_dir, "fuzz_urdf", "capsule.urdf",
                    "<robot name=\"r\"><link name=\"a\"><collision><geometry><capsule radius=\"1\" length=\"2\"/>"
                    "</geometry></collision></link></robot>");
}

/* ---- Call sequences ---------------------------------------------------- */

typedef struct program {
    unsigned char bytes[4096];
    size_t size;
    uint32_t random; /* a fixed sequence: the seeds are the same every build */
} program;

static unsigned char next_random(program *p) {
    p->random = p->random * 1103515245u + 12345u;
    return (unsigned char)(p->random >> 16);
}

static void emit(program *p, int op, const unsigned char *args, size_t length) {
    if (p->size + 2 + length > sizeof p->bytes) return;
    p->bytes[p->size++] = (unsigned char)op;
    p->bytes[p->size++] = (unsigned char)length;
    memcpy(p->bytes + p->size, args, length);
    p->size += length;
}

#define EMIT(p, op, ...)                                                  \
    do {                                                                  \
        const unsigned char args_[] = {__VA_ARGS__};                      \
        emit(p, op, args_, sizeof args_);                                 \
    } while (0)

/* An operation whose arguments are bytes of the fixed random sequence. */
static void emit_random(program *p, int op, size_t length) {
    unsigned char args[255];
    for (size_t i = 0; i < length; ++i) args[i] = next_random(p);
    emit(p, op, args, length);
}

/* Inserts `count` float32 points (small coordinates) into tree slot 0. */
static void emit_insert(program *p, unsigned char count) {
    unsigned char args[255];
    size_t n = 0;
    args[n++] = 0, args[n++] = count, args[n++] = 0, args[n++] = 0; /* tree 0, count, float32, packed */
    for (int i = 0; i < 3 * count; ++i) args[n++] = 0, args[n++] = (unsigned char)(next_random(p) % 40);
    /* options: size, raycast, pose (small, identity rotation), max_range 0 (capped), no NULLs */
    const unsigned char tail[] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 64, 0, 0, 0};
    memcpy(args + n, tail, sizeof tail);
    emit(p, OP_OCTREE_INSERT, args, n + sizeof tail);
}

/* A shape of `kind` (0 sphere .. 5 mesh) on link 0 of link set 0. */
static void emit_shape(program *p, unsigned char kind) {
    unsigned char args[255];
    size_t n = 0;
    const unsigned char head[] = {0, 0, 0, 0, kind, 0, 10, 0, 0, 0, 0, 0, 64, 0, 20, 0, 30, 0, 10, 0, 10, 0, 10};
    memcpy(args, head, sizeof head);
    n = sizeof head;
    if (kind >= 4) {
        args[n++] = 8, args[n++] = 0, args[n++] = 200; /* 8 vertices, packed, not flat */
        for (int i = 0; i < 24; ++i) args[n++] = 0, args[n++] = (unsigned char)(next_random(p) % 20);
        args[n++] = 0; /* vertices given */
    }
    if (kind == 5) {
        args[n++] = 4; /* triangles */
        for (int i = 0; i < 12; ++i) args[n++] = 0, args[n++] = (unsigned char)(i % 8);
        args[n++] = 0;
    }
    emit(p, OP_LINKSET_ADD_SHAPE, args, n);
}

static void emit_scene(program *p, unsigned char engine) {
    EMIT(p, OP_OCTREE_CREATE, 0, 0, 0, 0);
    emit_insert(p, 24);
    emit_insert(p, 8);
    EMIT(p, OP_LINKSET_CREATE, 1, 0);
    EMIT(p, OP_LINKSET_ADD_LINK, 0, 1, 0, 0);
    EMIT(p, OP_LINKSET_ADD_LINK, 0, 1, 1, 0);
    for (unsigned char kind = 0; kind < 6; ++kind) emit_shape(p, kind);
    EMIT(p, OP_QUERY_CREATE, 0, engine, 1, 9, 0, 0);
}

/* A batch of four rows of the URDF robot in slot 0 (7 joints) against
 * tree 0 on query 0, on two threads, its root near an occupied leaf, then
 * the certified motion from the first row to the last: the arguments
 * op_query_batch reads, in its order. */
static void emit_batch(program *p) {
    unsigned char args[255];
    size_t n = 0;
    const unsigned char head[] = {0, 0, 0, /* query, tree, link set: slot 0 */
                                  0, 0, 0, 1, 0, /* request: size, free, the map's threshold, 2 threads, cells */
                                  0, 0, 3}; /* the robot's joint count; 4 rows */
    for (size_t i = 0; i < sizeof head; ++i) args[n++] = head[i];
    for (int i = 0; i < 4 * 7; ++i) args[n++] = 0, args[n++] = next_random(p); /* small joint positions */
    const unsigned char base[] = {0, 0, 0, 0, 0, 0, 0, 64, /* pose: origin, identity */
                                  0, next_random(p), next_random(p), next_random(p), next_random(p)}; /* near a leaf */
    for (size_t i = 0; i < sizeof base; ++i) args[n++] = base[i];
    const unsigned char motion[] = {1, 3, 0, 0, 0}; /* certified, tolerance 1/64, no self, 1 thread, cells */
    for (size_t i = 0; i < sizeof motion; ++i) args[n++] = motion[i];
    emit(p, OP_QUERY_BATCH, args, n);
}

/* Tail steps besides operations: load the robot of spheres alone
 * (op_robot_load), a batch of the robot in slot 0 (emit_batch). */
enum { LOAD_SPHERE_ROBOT = -1, BATCH_OF_ROBOT = -2 };

void write_api_seeds(const char *out_dir) {
    static const int tail_ops[][6] = {
        {OP_QUERY_COLLIDE, OP_QUERY_DISTANCE, OP_QUERY_READ, OP_QUERY_PATH, OP_OCTREE_IMAGE, OP_QUERY_BOXES},
        {OP_LINKSET_SET_POSES, OP_QUERY_SPHERES, OP_LINKSET_SETTINGS, OP_QUERY_COLLIDE, OP_QUERY_READ,
         OP_OCTREE_EXERCISE},
        {OP_ROBOT_LOAD, OP_ROBOT_JOINTS, OP_QUERY_COLLIDE, OP_QUERY_PATH, OP_LINKSET_READ, OP_QUERY_DISTANCE},
        {OP_OCTREE_READ, OP_LINKSET_CREATE, OP_OCTREE_DESTROY, OP_QUERY_COLLIDE, OP_OCTREE_CLEAR,
         OP_QUERY_DISTANCE},
        {OP_QUERY_SPHERES, OP_OCTREE_EXERCISE, OP_QUERY_SPHERES, OP_OCTREE_CLEAR, OP_QUERY_SPHERES,
         OP_QUERY_COLLIDE},
        {LOAD_SPHERE_ROBOT, BATCH_OF_ROBOT, OP_QUERY_BATCH, BATCH_OF_ROBOT, OP_OCTREE_EXERCISE, BATCH_OF_ROBOT},
        {OP_ROBOT_LOAD, BATCH_OF_ROBOT, OP_OCTREE_CLEAR, BATCH_OF_ROBOT, OP_ROBOT_JOINTS, OP_QUERY_BATCH},
        {OP_QUERY_SPHERE_DISTANCE, OP_OCTREE_EXERCISE, OP_QUERY_SPHERE_DISTANCE, OP_OCTREE_CLEAR,
         OP_QUERY_SPHERE_DISTANCE, OP_QUERY_SPHERES},
        {LOAD_SPHERE_ROBOT, OP_QUERY_TRAJECTORY_COST, OP_OCTREE_EXERCISE, OP_QUERY_TRAJECTORY_COST, OP_ROBOT_JOINTS,
         OP_QUERY_TRAJECTORY_COST},
        {OP_OCTREE_EDIT, OP_QUERY_COLLIDE, OP_OCTREE_EDIT, OP_QUERY_DISTANCE, OP_OCTREE_EDIT, OP_OCTREE_EXERCISE},
    };
    const size_t tails = sizeof tail_ops / sizeof tail_ops[0];
    for (size_t s = 0; s < 2 * tails; ++s) {
        program p = {{0}, 0, (uint32_t)(s + 1)};
        p.bytes[p.size++] = (unsigned char)s; /* the order of the final destruction */
        emit_scene(&p, s % 2 ? 200 : 0);
        const int *ops = tail_ops[s % tails];
        for (int i = 0; i < 6; ++i) {
            if (ops[i] == OP_ROBOT_LOAD) EMIT(&p, OP_ROBOT_LOAD, 0, 0, 0, 0);
            else if (ops[i] == LOAD_SPHERE_ROBOT) EMIT(&p, OP_ROBOT_LOAD, 0, 210, 0, 0);
            else if (ops[i] == BATCH_OF_ROBOT) emit_batch(&p);
            else emit_random(&p, ops[i], 24 + next_random(&p) % 64);
        }
        char name[32];
        snprintf(name, sizeof name, "scene_%zu", s);
        write_seed(out_dir, "fuzz_api", name, p.bytes, p.size);
    }
}
