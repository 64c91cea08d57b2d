/*
 * Helpers shared by the CMocka tests of link sets and queries: shapes and
 * poses built in one line, a map of one occupied cell, a three-link robot
 * with every shape kind, and link-set snapshots that prove a failing call
 * changed nothing (link count, shape counts, names, poses, and the answers
 * of a collision and a per-link distance query).
 */
#ifndef OPX_QUERY_TEST_H
#define OPX_QUERY_TEST_H

#include "opx_test.h"

/* ---- Poses and shapes -------------------------------------------------- */

static inline opx_pose pose_at(double x, double y, double z) {
    opx_pose pose = OPX_POSE_IDENTITY;
    pose.position[0] = x;
    pose.position[1] = y;
    pose.position[2] = z;
    return pose;
}

static inline opx_shape sphere_shape(double radius) {
    opx_shape s = OPX_SHAPE_INIT;
    s.kind = OPX_SHAPE_SPHERE;
    s.radius = radius;
    return s;
}

static inline opx_shape box_shape(double x, double y, double z) {
    opx_shape s = OPX_SHAPE_INIT;
    s.kind = OPX_SHAPE_BOX;
    s.size[0] = x;
    s.size[1] = y;
    s.size[2] = z;
    return s;
}

static inline opx_shape cylinder_shape(double radius, double length) {
    opx_shape s = OPX_SHAPE_INIT;
    s.kind = OPX_SHAPE_CYLINDER;
    s.radius = radius;
    s.length = length;
    return s;
}

static inline opx_shape capsule_shape(double radius, double length) {
    opx_shape s = cylinder_shape(radius, length);
    s.kind = OPX_SHAPE_CAPSULE;
    return s;
}

/* A tetrahedron: the origin and 0.1 m along each axis (shape frame). */
static const double TETRA[12] = {0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.1};
static const uint32_t TETRA_FACES[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static inline opx_shape convex_shape(const double *vertices, size_t count, size_t stride) {
    opx_shape s = OPX_SHAPE_INIT;
    s.kind = OPX_SHAPE_CONVEX;
    s.vertices = vertices;
    s.vertex_count = count;
    s.vertex_stride = stride;
    return s;
}

static inline opx_shape mesh_shape(const double *vertices, size_t count, size_t stride,
                                   const uint32_t *indices, size_t triangles) {
    opx_shape s = convex_shape(vertices, count, stride);
    s.kind = OPX_SHAPE_MESH;
    s.indices = indices;
    s.triangle_count = triangles;
    return s;
}

/* ---- Link sets --------------------------------------------------------- */

static inline opx_linkset *new_linkset(void) {
    opx_linkset *links = NULL;
    assert_ok(opx_linkset_create(&links));
    assert_non_null(links);
    return links;
}

static inline uint32_t add_link(opx_linkset *links, const char *name) {
    uint32_t index = UINT32_MAX;
    assert_ok(opx_linkset_add_link(links, name, &index));
    return index;
}

static inline uint32_t add_shape(opx_linkset *links, uint32_t link, opx_shape shape) {
    uint32_t index = UINT32_MAX;
    assert_ok(opx_linkset_add_shape(links, link, &shape, &index));
    return index;
}

static inline uint32_t link_count(const opx_linkset *links) {
    uint32_t count = UINT32_MAX;
    assert_ok(opx_linkset_get_link_count(links, &count));
    return count;
}

static inline opx_pose get_pose(const opx_linkset *links, uint32_t link) {
    opx_pose pose;
    memset(&pose, 0, sizeof pose);
    assert_ok(opx_linkset_get_pose(links, link, &pose));
    return pose;
}

/* One link holding one sphere of `radius` centred at (x, y, z), map frame. */
static inline opx_linkset *new_sphere_at(double radius, double x, double y, double z) {
    opx_linkset *links = new_linkset();
    const uint32_t link = add_link(links, "ball");
    add_shape(links, link, sphere_shape(radius));
    const opx_pose pose = pose_at(x, y, z);
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    return links;
}

/*
 * The robot of the failure tests, against new_one_cell_map():
 *   link 0 "base": sphere r 0.1 at (0.35, C0, C0), touching the cell face x = 0.25
 *   link 1 "arm":  box 0.1^3 and capsule r 0.05 length 0.2 along z, at (C0, C0, 1):
 *                  0.6 from the cell (the capsule reaches down to z = 0.85)
 *   link 2 "tool": cylinder r 0.05 length 0.2, the tetrahedron and its
 *                  surface mesh, at (C0, 1, C0): 0.7 from the cell
 */
static inline opx_linkset *new_robot(void) {
    opx_linkset *links = new_linkset();
    assert_int_equal(add_link(links, "base"), 0);
    assert_int_equal(add_link(links, "arm"), 1);
    assert_int_equal(add_link(links, "tool"), 2);
    assert_int_equal(add_shape(links, 0, sphere_shape(0.1)), 0);
    assert_int_equal(add_shape(links, 1, box_shape(0.1, 0.1, 0.1)), 0);
    assert_int_equal(add_shape(links, 1, capsule_shape(0.05, 0.2)), 1);
    assert_int_equal(add_shape(links, 2, cylinder_shape(0.05, 0.2)), 0);
    assert_int_equal(add_shape(links, 2, convex_shape(TETRA, 4, 0)), 1);
    assert_int_equal(add_shape(links, 2, mesh_shape(TETRA, 4, 0, TETRA_FACES, 4)), 2);
    const opx_pose poses[3] = {pose_at(0.35, C0, C0), pose_at(C0, C0, 1.0), pose_at(C0, 1.0, C0)};
    assert_ok(opx_linkset_set_poses(links, poses, 3, 0));
    return links;
}

/* ---- Maps -------------------------------------------------------------- */

/* One occupied cell, [0, RES]^3 (centre C0, probability 0.7); the rest unknown. */
static inline opx_octree *new_one_cell_map(void) {
    opx_octree *tree = new_tree(RES);
    const double xyz[3] = {C0, C0, C0};
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 1, &options);
    const opx_octree_stats stats = stats_of(tree);
    assert_int_equal(stats.leaves_occupied, 1);
    assert_int_equal(stats.leaves_free + stats.leaves_uncertain, 0);
    return tree;
}

static inline opx_query *new_query(void) {
    opx_query *query = NULL;
    assert_ok(opx_query_create(NULL, &query));
    assert_non_null(query);
    return query;
}

/* Collides with the defaults but max_contacts; returns the result. */
static inline opx_collision_result collide_with(opx_query *query, const opx_octree *tree,
                                                const opx_linkset *links, uint32_t max_contacts) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = max_contacts;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &result));
    return result;
}

/* Does `links` collide with `tree` (default request)? */
static inline int collides(const opx_linkset *links, const opx_octree *tree) {
    opx_query *query = new_query();
    const opx_collision_result r = collide_with(query, tree, links, 1);
    opx_query_destroy(query);
    return r.collided;
}

static inline opx_contact get_contact(const opx_query *query, size_t index) {
    opx_contact contact = OPX_CONTACT_INIT;
    assert_ok(opx_query_get_contact(query, index, &contact));
    return contact;
}

static inline opx_distance_result distance_with(opx_query *query, const opx_octree *tree,
                                                const opx_linkset *links,
                                                const opx_distance_request *request) {
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    assert_ok(opx_query_distance(query, tree, links, request, &result));
    return result;
}

/* ---- Snapshots: proof that a failed call left the link set alone ------- */

#define SNAP_MAX_LINKS 8
#define SNAP_MAX_CONTACTS 32

typedef struct linkset_snapshot {
    uint32_t links;
    uint32_t shapes[SNAP_MAX_LINKS];
    char names[SNAP_MAX_LINKS][32];
    opx_pose poses[SNAP_MAX_LINKS];
    /* All contacts with the one-cell map, and each link's distance to it. */
    int32_t collided;
    uint64_t contacts;
    uint32_t contact_link[SNAP_MAX_CONTACTS], contact_shape[SNAP_MAX_CONTACTS];
    double distance;
    double link_distance[SNAP_MAX_LINKS];
} linkset_snapshot;

static inline linkset_snapshot take_linkset_snapshot(const opx_linkset *links) {
    linkset_snapshot s;
    memset(&s, 0, sizeof s);
    s.links = link_count(links);
    assert_true(s.links <= SNAP_MAX_LINKS);
    for (uint32_t i = 0; i < s.links; ++i) {
        assert_ok(opx_linkset_get_shape_count(links, i, &s.shapes[i]));
        const char *name = NULL;
        assert_ok(opx_linkset_get_link_name(links, i, &name));
        assert_non_null(name);
        assert_true(strlen(name) < sizeof s.names[i]);
        strcpy(s.names[i], name);
        s.poses[i] = get_pose(links, i);
    }
    opx_octree *tree = new_one_cell_map();
    opx_query *query = new_query();
    const opx_collision_result c = collide_with(query, tree, links, SNAP_MAX_CONTACTS);
    s.collided = c.collided;
    s.contacts = c.contact_count;
    for (uint64_t i = 0; i < c.contact_count; ++i) {
        const opx_contact contact = get_contact(query, (size_t)i);
        s.contact_link[i] = contact.link;
        s.contact_shape[i] = contact.shape;
    }
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    s.distance = distance_with(query, tree, links, &request).distance;
    size_t count = 0;
    assert_ok(opx_query_get_link_distances(query, s.link_distance, SNAP_MAX_LINKS, &count));
    assert_int_equal(count, s.links);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    return s;
}

static inline void assert_same_linkset(const linkset_snapshot *a, const linkset_snapshot *b) {
    assert_int_equal(a->links, b->links);
    for (uint32_t i = 0; i < a->links; ++i) {
        assert_int_equal(a->shapes[i], b->shapes[i]);
        assert_string_equal(a->names[i], b->names[i]);
        assert_memory_equal(&a->poses[i], &b->poses[i], sizeof(opx_pose));
        assert_true(a->link_distance[i] == b->link_distance[i]);
    }
    assert_int_equal(a->collided, b->collided);
    assert_int_equal(a->contacts, b->contacts);
    for (uint64_t i = 0; i < a->contacts; ++i) {
        assert_int_equal(a->contact_link[i], b->contact_link[i]);
        assert_int_equal(a->contact_shape[i], b->contact_shape[i]);
    }
    assert_true(a->distance == b->distance);
}

/* The link set answers as it did when `before` was taken. */
static inline void assert_linkset_unchanged(const opx_linkset *links,
                                            const linkset_snapshot *before) {
    const linkset_snapshot now = take_linkset_snapshot(links);
    assert_same_linkset(&now, before);
}

/* The robot's snapshot, checked against the hand-computed layout, so a
 * snapshot that compared nothing would fail here. */
static inline linkset_snapshot robot_snapshot(const opx_linkset *robot) {
    const linkset_snapshot s = take_linkset_snapshot(robot);
    assert_int_equal(s.links, 3);
    assert_int_equal(s.shapes[0] + s.shapes[1] + s.shapes[2], 6);
    assert_int_equal(s.collided, 1);
    assert_int_equal(s.contacts, 1);
    assert_near(s.link_distance[0], 0.0, 1e-9);
    assert_near(s.link_distance[1], 0.6, 1e-9);
    assert_near(s.link_distance[2], 0.7, 1e-9);
    return s;
}

#endif /* OPX_QUERY_TEST_H */
