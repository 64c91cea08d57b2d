/*
 * Attached objects (linkset.h, world.h): what the getters give back (name,
 * link, pose in the link frame, shapes in the object frame, touch links),
 * detaching and renumbering, copies made by opx_linkset_clone, a world
 * object attached where it stands, batches and paths with an attached
 * object (equal to single calls, 1 to 3 threads), and bad input: NULL,
 * bad link, object and shape indices, NaN poses, bad shapes, unknown touch
 * link names, each naming the argument and changing nothing.
 */
#include "opx_batch_test.h"

static uint32_t attached_count(const opx_linkset *links) {
    uint32_t count = UINT32_MAX;
    assert_ok(opx_linkset_get_attached_count(links, &count));
    return count;
}

/* Two links 1 m apart, each a small sphere. */
static opx_linkset *two_links(void) {
    opx_linkset *links = new_linkset();
    add_shape(links, add_link(links, "a"), sphere_shape(0.01));
    add_shape(links, add_link(links, "b"), sphere_shape(0.01));
    const opx_pose poses[2] = {pose_at(0, 0, 0), pose_at(1, 0, 0)};
    assert_ok(opx_linkset_set_poses(links, poses, 2, 0));
    return links;
}

static void getters_give_back_what_was_attached(void **state) {
    (void)state;
    opx_linkset *links = two_links();
    opx_shape shapes[2] = {box_shape(0.1, 0.2, 0.3), sphere_shape(0.05)};
    shapes[1].pose = pose_at(0.0, 0.0, 0.2);
    opx_pose pose = pose_at(0.1, 0.0, 0.0);
    pose.orientation[2] = sin(0.25), pose.orientation[3] = cos(0.25);
    const char *touch[3] = {"b", "a", "b"};
    uint32_t object = UINT32_MAX;
    assert_ok(opx_linkset_attach_object(links, 0, "cup", shapes, 2, &pose, touch, 3, &object));
    assert_int_equal(object, 0);
    const char *name = NULL;
    assert_ok(opx_linkset_get_attached_name(links, 0, &name));
    assert_string_equal(name, "cup");
    uint32_t link = 9, count = 0;
    assert_ok(opx_linkset_get_attached_link(links, 0, &link));
    assert_int_equal(link, 0);
    opx_pose back;
    assert_ok(opx_linkset_get_attached_pose(links, 0, &back));
    assert_center(back.position, 0.1, 0.0, 0.0);
    assert_near(back.orientation[2], sin(0.25), 1e-12);
    assert_ok(opx_linkset_get_attached_shape_count(links, 0, &count));
    assert_int_equal(count, 2);
    opx_shape shape = OPX_SHAPE_INIT;
    assert_ok(opx_linkset_get_attached_shape(links, 0, 1, &shape));
    assert_int_equal(shape.kind, OPX_SHAPE_SPHERE);
    assert_center(shape.pose.position, 0.0, 0.0, 0.2); /* the object frame, as given */
    uint32_t touching[2] = {0, 0};
    size_t touch_count = 0;
    assert_ok(opx_linkset_get_attached_touch_links(links, 0, touching, 2, &touch_count));
    assert_int_equal(touch_count, 1); /* "b" once; "a" is its own link */
    assert_int_equal(touching[0], 1);
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_linkset_get_attached_touch_links", "capacity",
                   opx_linkset_get_attached_touch_links(links, 0, NULL, 0, &touch_count));
    /* The link's own shapes are unchanged. */
    assert_ok(opx_linkset_get_shape_count(links, 0, &count));
    assert_int_equal(count, 1);

    /* A second object, detaching the first renumbers it; a clone keeps both. */
    assert_ok(opx_linkset_attach_object(links, 1, "lid", shapes, 1, NULL, NULL, 0, &object));
    assert_int_equal(object, 1);
    opx_linkset *copy = NULL;
    assert_ok(opx_linkset_clone(links, &copy));
    assert_int_equal(attached_count(copy), 2);
    assert_ok(opx_linkset_find_attached(links, "lid", &object));
    assert_int_equal(object, 1);
    assert_ok(opx_linkset_detach_object(links, 0));
    assert_int_equal(attached_count(links), 1);
    assert_ok(opx_linkset_find_attached(links, "lid", &object));
    assert_int_equal(object, 0);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_find_attached", "cup",
                   opx_linkset_find_attached(links, "cup", &object));
    assert_ok(opx_linkset_find_attached(copy, "cup", &object));
    assert_int_equal(object, 0);
    opx_linkset_destroy(copy);
    opx_linkset_destroy(links);
}

static void bad_input_names_the_argument_and_changes_nothing(void **state) {
    (void)state;
    opx_linkset *links = two_links();
    const opx_shape ball = sphere_shape(0.1);
    const opx_shape shapes[2] = {ball, sphere_shape(-1.0)};
    const char *touch[1] = {"c"};
    const char *null_name[1] = {NULL};
    opx_pose nan_pose = pose_at(NAN, 0, 0);
    opx_pose zero_quaternion = pose_at(0, 0, 0);
    zero_quaternion.orientation[3] = 0.0;
    uint32_t out = 0;
    const char *f = "opx_linkset_attach_object";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "links", opx_linkset_attach_object(NULL, 0, "x", &ball, 1, NULL, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "link 2", opx_linkset_attach_object(links, 2, "x", &ball, 1, NULL, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "name", opx_linkset_attach_object(links, 0, NULL, &ball, 1, NULL, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "shape_count", opx_linkset_attach_object(links, 0, "x", &ball, 0, NULL, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "shapes", opx_linkset_attach_object(links, 0, "x", NULL, 1, NULL, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "shapes[1]", opx_linkset_attach_object(links, 0, "x", shapes, 2, NULL, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "pose", opx_linkset_attach_object(links, 0, "x", &ball, 1, &nan_pose, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "pose", opx_linkset_attach_object(links, 0, "x", &ball, 1, &zero_quaternion, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "touch_links[0] \"c\"", opx_linkset_attach_object(links, 0, "x", &ball, 1, NULL, touch, 1, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "touch_links[0]", opx_linkset_attach_object(links, 0, "x", &ball, 1, NULL, null_name, 1, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, f, "touch_links", opx_linkset_attach_object(links, 0, "x", &ball, 1, NULL, NULL, 1, &out));
    opx_shape unversioned = ball;
    unversioned.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, f, "shapes[0]", opx_linkset_attach_object(links, 0, "x", &unversioned, 1, NULL, NULL, 0, &out));
    assert_int_equal(attached_count(links), 0);

    assert_ok(opx_linkset_attach_object(links, 0, "x", &ball, 1, NULL, NULL, 0, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_detach_object", "object 1", opx_linkset_detach_object(links, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_detach_object", "links", opx_linkset_detach_object(NULL, 0));
    opx_shape shape = OPX_SHAPE_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_attached_shape", "shape 1",
                   opx_linkset_get_attached_shape(links, 0, 1, &shape));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_attached_link", "out_link",
                   opx_linkset_get_attached_link(links, 0, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_attached_pose", "object 3",
                   opx_linkset_get_attached_pose(links, 3, &nan_pose));
    assert_int_equal(attached_count(links), 1);

    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    assert_ok(opx_world_add_object(world, "empty", NULL, NULL));
    const char *g = "opx_linkset_attach_world_object";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, g, "no shapes", opx_linkset_attach_world_object(links, 0, world, 0, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, g, "object 1", opx_linkset_attach_world_object(links, 0, world, 1, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, g, "world", opx_linkset_attach_world_object(links, 0, NULL, 0, NULL, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, g, "link 5", opx_linkset_attach_world_object(links, 5, world, 0, NULL, 0, &out));
    assert_int_equal(attached_count(links), 1);
    opx_world_destroy(world);
    opx_linkset_destroy(links);
}

/* A world object attached where it stands: in the link frame at the pose
 * that keeps it in place; it then moves with the link. */
static void world_object_attached_where_it_stands(void **state) {
    (void)state;
    opx_linkset *links = two_links();
    opx_pose turned = pose_at(1, 0, 0);
    turned.orientation[2] = sin(0.5), turned.orientation[3] = cos(0.5); /* 1 rad about z */
    assert_ok(opx_linkset_set_poses(links, (opx_pose[]){pose_at(0, 0, 0), turned}, 2, 0));
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    const opx_pose at = pose_at(1.0, 0.5, 0.0);
    assert_ok(opx_world_add_object(world, "can", &at, NULL));
    const opx_shape can = cylinder_shape(0.04, 0.12);
    assert_ok(opx_world_add_shape(world, 0, &can, NULL));
    uint32_t object = UINT32_MAX;
    assert_ok(opx_linkset_attach_world_object(links, 1, world, 0, NULL, 0, &object));
    const char *name = NULL;
    assert_ok(opx_linkset_get_attached_name(links, object, &name));
    assert_string_equal(name, "can");
    opx_pose in_link;
    assert_ok(opx_linkset_get_attached_pose(links, object, &in_link));
    assert_center(in_link.position, 0.5 * sin(1.0), 0.5 * cos(1.0), 0.0);
    uint32_t count = 0;
    assert_ok(opx_world_get_object_count(world, &count));
    assert_int_equal(count, 1); /* the world is unchanged */

    /* Where it stands it touches its original; disabled there, nothing. */
    opx_query *query = new_query();
    assert_ok(opx_query_set_world(query, world));
    assert_int_equal(collide_with(query, NULL, links, 1).collided, 1);
    assert_ok(opx_world_set_object_enabled(world, 0, 0));
    assert_int_equal(collide_with(query, NULL, links, 1).collided, 0);
    /* Moving link b by 0.5 along y carries the can 0.5 further. */
    assert_ok(opx_world_set_object_enabled(world, 0, 1));
    turned.position[1] = -0.5;
    assert_ok(opx_linkset_set_poses(links, (opx_pose[]){pose_at(0, 0, 0), turned}, 2, 0));
    const opx_distance_result d = distance_with(query, NULL, links, NULL);
    assert_near(d.distance, 0.5 - 0.08, 1e-7);
    assert_int_equal(d.attached, 0);
    opx_query_destroy(query);
    opx_world_destroy(world);
    opx_linkset_destroy(links);
}

/* A box held by the arm: batches (1 to 3 threads) and paths equal single
 * calls, the box moving with FK in both. */
static void batches_and_paths_carry_the_attached_object(void **state) {
    (void)state;
    enum { ROWS = 120 };
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    const opx_shape box = box_shape(0.3, 0.3, 0.3);
    const opx_pose ahead = pose_at(0.0, 0.0, 0.5);
    const char *fingers[3] = {"finger_l", "finger_r", "tool"};
    assert_ok(opx_linkset_attach_object(arm, 7, "crate", &box, 1, &ahead, fingers, 3, NULL));
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(ROWS, 23);
    opx_query *single = new_query();
    uint8_t collided[ROWS];
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        opx_query *query = new_query_with(threads == 2 ? OPX_ENGINE_AMORTIZED : OPX_ENGINE_DIRECT);
        opx_batch_request request = OPX_BATCH_REQUEST_INIT;
        request.max_threads = threads;
        request.self_collision = 1;
        assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, &request,
                                                 collided, NULL, ROWS));
        for (size_t i = 0; i < ROWS; ++i)
            assert_int_equal(collided[i], single_collides_or_self(single, tree, arm, rows + i * ARM_JOINTS, NULL));
        opx_query_destroy(query);
    }
    /* Without the crate, some configurations do not collide that did. */
    uint8_t bare[ROWS];
    opx_linkset *without = NULL;
    assert_ok(opx_linkset_clone(arm, &without));
    assert_ok(opx_linkset_detach_object(without, 0));
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.self_collision = 1;
    assert_ok(opx_query_check_configurations(single, tree, without, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, &request,
                                             bare, NULL, ROWS));
    int more = 0;
    for (size_t i = 0; i < ROWS; ++i) more += collided[i] > bare[i];
    assert_true(more > 0);

    /* A path over the rows' link poses: the first colliding waypoint. */
    opx_pose *poses = malloc(ROWS * ARM_LINKS * sizeof *poses);
    assert_non_null(poses);
    int64_t first = -1;
    for (size_t w = 0; w < ROWS; ++w) {
        if (first < 0 && single_collides(single, tree, arm, rows + w * ARM_JOINTS, NULL)) first = (int64_t)w;
        arm_poses(arm, poses + w * ARM_LINKS);
    }
    opx_path_result path = OPX_PATH_RESULT_INIT;
    assert_ok(opx_query_path(single, tree, arm, poses, ROWS, 0, 0, NULL, &path));
    assert_int_equal(path.first_colliding_waypoint, first);
    free(poses);
    opx_linkset_destroy(without);
    opx_query_destroy(single);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(getters_give_back_what_was_attached),
        cmocka_unit_test(bad_input_names_the_argument_and_changes_nothing),
        cmocka_unit_test(world_object_attached_where_it_stands),
        cmocka_unit_test(batches_and_paths_carry_the_attached_object),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
