/*
 * opx_linkset_*: every invalid argument is rejected, named in the message,
 * and leaves the link set unchanged; names, poses, paddings, enabled flags
 * and deep clones.  Shapes: test_linkset_shapes.c.
 */
#include "opx_query_test.h"

static const uint32_t BAD_LINKS[] = {3, 4, 1000, UINT32_MAX};
#define N_BAD_LINKS (sizeof BAD_LINKS / sizeof BAD_LINKS[0])
static const double BAD_PADDINGS[] = {-1e-9, -0.1, NAN, INFINITY, -INFINITY};
#define N_BAD_PADDINGS (sizeof BAD_PADDINGS / sizeof BAD_PADDINGS[0])

/* "link 7" in a message: the bad index itself is named. */
static const char *link_arg(uint32_t link) {
    static char buffer[32];
    snprintf(buffer, sizeof buffer, "link %u", (unsigned)link);
    return buffer;
}

static void create_and_clone_reject_null(void **state) {
    (void)state;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_create", "out",
                   opx_linkset_create(NULL));
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    opx_linkset *out = (opx_linkset *)robot; /* must be reset to NULL */
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_clone", "links",
                   opx_linkset_clone(NULL, &out));
    assert_null(out);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_clone", "out",
                   opx_linkset_clone(robot, NULL));
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
    opx_linkset_destroy(NULL); /* a no-op */
}

static void add_link_rejects_null(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    uint32_t index = 77;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_add_link", "links",
                   opx_linkset_add_link(NULL, "x", &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_add_link", "name",
                   opx_linkset_add_link(robot, NULL, &index));
    assert_int_equal(index, 77);
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

static void counts_and_names_reject_bad_arguments(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    uint32_t count = 0;
    const char *name = NULL;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_link_count", "links",
                   opx_linkset_get_link_count(NULL, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_link_count", "out_count",
                   opx_linkset_get_link_count(robot, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape_count", "links",
                   opx_linkset_get_shape_count(NULL, 0, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape_count", "out_count",
                   opx_linkset_get_shape_count(robot, 0, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_link_name", "links",
                   opx_linkset_get_link_name(NULL, 0, &name));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_link_name", "out_name",
                   opx_linkset_get_link_name(robot, 0, NULL));
    for (size_t i = 0; i < N_BAD_LINKS; ++i) {
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape_count",
                       link_arg(BAD_LINKS[i]), opx_linkset_get_shape_count(robot, BAD_LINKS[i], &count));
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_link_name", link_arg(BAD_LINKS[i]),
                       opx_linkset_get_link_name(robot, BAD_LINKS[i], &name));
    }
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

static void find_link_rejects_bad_arguments_and_missing_names(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    uint32_t index = 77;
    const char *fn = "opx_linkset_find_link";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "links", opx_linkset_find_link(NULL, "arm", &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "name", opx_linkset_find_link(robot, NULL, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_link", opx_linkset_find_link(robot, "arm", NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "elbow", opx_linkset_find_link(robot, "elbow", &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "name", opx_linkset_find_link(robot, "", &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "name", opx_linkset_find_link(robot, "ar", &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "name", opx_linkset_find_link(robot, "arm ", &index));
    assert_int_equal(index, 77);
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

static void paddings_and_enabled_reject_bad_arguments(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_padding", "links",
                   opx_linkset_set_padding(NULL, 0.1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_link_padding", "links",
                   opx_linkset_set_link_padding(NULL, 0, 0.1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_link_enabled", "links",
                   opx_linkset_set_link_enabled(NULL, 0, 0));
    for (size_t i = 0; i < N_BAD_PADDINGS; ++i) {
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_padding", "padding",
                       opx_linkset_set_padding(robot, BAD_PADDINGS[i]));
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_link_padding", "padding",
                       opx_linkset_set_link_padding(robot, 1, BAD_PADDINGS[i]));
    }
    for (size_t i = 0; i < N_BAD_LINKS; ++i) {
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_link_padding",
                       link_arg(BAD_LINKS[i]), opx_linkset_set_link_padding(robot, BAD_LINKS[i], 0.1));
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_link_enabled",
                       link_arg(BAD_LINKS[i]), opx_linkset_set_link_enabled(robot, BAD_LINKS[i], 0));
    }
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

/* Poses of the robot shifted by 0.01 m: a valid set to put bad poses in. */
static void shifted_poses(opx_pose out[3]) {
    out[0] = pose_at(0.36, C0, C0);
    out[1] = pose_at(C0, C0, 1.01);
    out[2] = pose_at(C0, 1.01, C0);
}

static void expect_set_poses_fails(opx_linkset *robot, const linkset_snapshot *before,
                                   const opx_pose *poses, size_t count, size_t stride,
                                   const char *argument) {
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_poses", argument,
                   opx_linkset_set_poses(robot, poses, count, stride));
    assert_linkset_unchanged(robot, before);
}

static void set_poses_rejects_bad_arguments(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    opx_pose poses[4];
    shifted_poses(poses);
    poses[3] = pose_at(0, 0, 0);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_set_poses", "links",
                   opx_linkset_set_poses(NULL, poses, 3, 0));
    expect_set_poses_fails(robot, &before, poses, 2, 0, "count");
    expect_set_poses_fails(robot, &before, poses, 4, 0, "count");
    expect_set_poses_fails(robot, &before, poses, 0, 0, "count");
    expect_set_poses_fails(robot, &before, NULL, 3, 0, "poses");
    const size_t bad_strides[] = {1, 8, sizeof(opx_pose) - 1};
    for (size_t i = 0; i < 3; ++i)
        expect_set_poses_fails(robot, &before, poses, 3, bad_strides[i], "stride");
    /* A bad last pose: the valid poses before it are not applied either. */
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t b = 0; b < 3; ++b) {
        for (int axis = 0; axis < 3; ++axis) {
            shifted_poses(poses);
            poses[2].position[axis] = bad[b];
            expect_set_poses_fails(robot, &before, poses, 3, 0, "poses[2]");
        }
        for (int c = 0; c < 4; ++c) {
            shifted_poses(poses);
            poses[2].orientation[c] = bad[b];
            expect_set_poses_fails(robot, &before, poses, 3, 0, "poses[2]");
        }
    }
    shifted_poses(poses);
    poses[1].orientation[3] = 0.0; /* all four zero */
    expect_set_poses_fails(robot, &before, poses, 3, 0, "poses[1]");
    opx_linkset_destroy(robot);
}

static void get_pose_rejects_bad_arguments(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    opx_pose pose;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_pose", "links",
                   opx_linkset_get_pose(NULL, 0, &pose));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_pose", "out_pose",
                   opx_linkset_get_pose(robot, 0, NULL));
    for (size_t i = 0; i < N_BAD_LINKS; ++i)
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_pose", link_arg(BAD_LINKS[i]),
                       opx_linkset_get_pose(robot, BAD_LINKS[i], &pose));
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

/* ---- Positive behaviour ------------------------------------------------- */

static void names_are_copied_and_found(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    assert_int_equal(link_count(links), 0);
    char name[16];
    strcpy(name, "wrist");
    assert_int_equal(add_link(links, name), 0);
    strcpy(name, "XXXXX"); /* the library kept its own copy */
    assert_int_equal(add_link(links, "elbow"), 1);
    assert_int_equal(add_link(links, "wrist"), 2); /* a duplicate */
    assert_int_equal(link_count(links), 3);
    const char *got = NULL;
    assert_ok(opx_linkset_get_link_name(links, 0, &got));
    assert_string_equal(got, "wrist");
    assert_ok(opx_linkset_get_link_name(links, 1, &got));
    assert_string_equal(got, "elbow");
    uint32_t index = 77;
    assert_ok(opx_linkset_find_link(links, "wrist", &index));
    assert_int_equal(index, 0); /* the first of two */
    assert_ok(opx_linkset_find_link(links, "elbow", &index));
    assert_int_equal(index, 1);
    uint32_t shapes = 77;
    assert_ok(opx_linkset_get_shape_count(links, 2, &shapes));
    assert_int_equal(shapes, 0);
    /* New links start at the identity. */
    const opx_pose identity = OPX_POSE_IDENTITY;
    const opx_pose pose = get_pose(links, 1);
    assert_memory_equal(&pose, &identity, sizeof pose);
    opx_linkset_destroy(links);
}

/* get_pose gives the pose set: position exactly, the quaternion
 * normalised, up to sign; a stride skips the caller's extra bytes. */
static void get_pose_returns_the_set_pose(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    add_link(links, "a");
    add_link(links, "b");
    struct {
        opx_pose pose;
        double extra[2];
    } padded[2];
    padded[0].pose = pose_at(1.0, -2.0, 3.5);
    padded[0].pose.orientation[0] = 0.0; /* 90 degrees about z, not normalised: x2 */
    padded[0].pose.orientation[2] = 2.0 * sqrt(0.5);
    padded[0].pose.orientation[3] = 2.0 * sqrt(0.5);
    padded[1].pose = pose_at(0.0, 0.5, 0.0);
    padded[1].pose.orientation[0] = 0.0;
    padded[1].pose.orientation[1] = -1.0; /* 180 degrees about y */
    padded[1].pose.orientation[3] = 0.0;
    assert_ok(opx_linkset_set_poses(links, &padded[0].pose, 2, sizeof padded[0]));
    const double expected[2][4] = {{0.0, 0.0, sqrt(0.5), sqrt(0.5)}, {0.0, -1.0, 0.0, 0.0}};
    for (uint32_t l = 0; l < 2; ++l) {
        const opx_pose got = get_pose(links, l);
        for (int i = 0; i < 3; ++i) assert_true(got.position[i] == padded[l].pose.position[i]);
        double dot = 0.0;
        for (int i = 0; i < 4; ++i) dot += got.orientation[i] * expected[l][i];
        const double sign = dot < 0.0 ? -1.0 : 1.0;
        for (int i = 0; i < 4; ++i) assert_near(sign * got.orientation[i], expected[l][i], 1e-12);
    }
    opx_linkset_destroy(links);
}

/* A sphere r 0.1 at x = 0.45 is 0.1 from the cell: paddings close the gap
 * (global + link), a hair less does not. */
static void padding_closes_a_gap(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_sphere_at(0.1, 0.45, C0, C0);
    assert_false(collides(links, tree));
    assert_ok(opx_linkset_set_link_padding(links, 0, 0.0999));
    assert_false(collides(links, tree));
    assert_ok(opx_linkset_set_link_padding(links, 0, 0.1));
    assert_true(collides(links, tree));
    assert_ok(opx_linkset_set_link_padding(links, 0, 0.05));
    assert_ok(opx_linkset_set_padding(links, 0.0499));
    assert_false(collides(links, tree));
    assert_ok(opx_linkset_set_padding(links, 0.05)); /* 0.05 + 0.05 */
    assert_true(collides(links, tree));
    assert_ok(opx_linkset_set_link_padding(links, 0, 0.0));
    assert_ok(opx_linkset_set_padding(links, 0.1));
    assert_true(collides(links, tree));
    assert_ok(opx_linkset_set_padding(links, 0.0));
    assert_false(collides(links, tree));
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

static void disabled_links_are_ignored(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *robot = new_robot();
    assert_true(collides(robot, tree));
    assert_ok(opx_linkset_set_link_enabled(robot, 0, 0));
    assert_false(collides(robot, tree));
    opx_query *query = new_query();
    const opx_distance_result d = distance_with(query, tree, robot, NULL);
    assert_int_equal(d.found, 1);
    assert_int_equal(d.link, 1); /* base is ignored: arm is nearest */
    assert_near(d.distance, 0.6, 1e-9);
    assert_ok(opx_linkset_set_link_enabled(robot, 0, 7)); /* nonzero: enabled */
    assert_true(collides(robot, tree));
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(tree);
}

/* A clone owns all its state: changing either leaves the other alone. */
static void clone_is_deep(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const linkset_snapshot original = robot_snapshot(robot);
    opx_linkset *clone = NULL;
    assert_ok(opx_linkset_clone(robot, &clone));
    assert_non_null(clone);
    assert_true(clone != robot);
    const linkset_snapshot copied = take_linkset_snapshot(clone);
    assert_same_linkset(&copied, &original);

    add_shape(clone, 2, sphere_shape(0.5));
    add_link(clone, "extra");
    assert_ok(opx_linkset_set_padding(clone, 0.2));
    assert_ok(opx_linkset_set_link_enabled(clone, 0, 0));
    const opx_pose far[4] = {pose_at(5, 5, 5), pose_at(6, 6, 6), pose_at(7, 7, 7), pose_at(8, 8, 8)};
    assert_ok(opx_linkset_set_poses(clone, far, 4, 0));
    assert_linkset_unchanged(robot, &original);
    assert_int_equal(link_count(clone), 4);

    /* And the other way: the original changes, the clone does not. */
    opx_linkset *clone2 = NULL;
    assert_ok(opx_linkset_clone(robot, &clone2));
    opx_linkset_destroy(robot); /* nothing of the original is shared */
    assert_linkset_unchanged(clone2, &original);
    opx_linkset_destroy(clone2);
    opx_linkset_destroy(clone);
}

/* An empty link set is valid everywhere: no collision, nothing found. */
static void empty_link_set_queries(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_linkset();
    assert_ok(opx_linkset_set_poses(links, NULL, 0, 0));
    assert_false(collides(links, tree));
    opx_query *query = new_query();
    const opx_distance_result d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.found, 0);
    assert_true(isinf(d.distance) && d.distance > 0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(create_and_clone_reject_null),
        cmocka_unit_test(add_link_rejects_null),
        cmocka_unit_test(counts_and_names_reject_bad_arguments),
        cmocka_unit_test(find_link_rejects_bad_arguments_and_missing_names),
        cmocka_unit_test(paddings_and_enabled_reject_bad_arguments),
        cmocka_unit_test(set_poses_rejects_bad_arguments),
        cmocka_unit_test(get_pose_rejects_bad_arguments),
        cmocka_unit_test(names_are_copied_and_found),
        cmocka_unit_test(get_pose_returns_the_set_pose),
        cmocka_unit_test(padding_closes_a_gap),
        cmocka_unit_test(disabled_links_are_ignored),
        cmocka_unit_test(clone_is_deep),
        cmocka_unit_test(empty_link_set_queries),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
