/*
 * Self-collision through the C ABI: the case a MoveIt user knows (two
 * links 1 cm apart, padding, the pair disabled), contacts and their
 * limits, penetration, signed distance, the SRDF's pairs, clones, the
 * pair-sampling helper, and every invalid argument named in the message.
 */
#include "opx_urdf_test.h"

static const char *const COLLIDE = "opx_query_self_collide";
static const char *const DISTANCE = "opx_query_self_distance";

/* Two links holding a 0.1 m cube each, centres `gap` + 0.1 apart along x. */
static opx_linkset *two_cubes(double gap) {
    opx_linkset *links = new_linkset();
    add_shape(links, add_link(links, "left"), box_shape(0.1, 0.1, 0.1));
    add_shape(links, add_link(links, "right"), box_shape(0.1, 0.1, 0.1));
    const opx_pose poses[2] = {pose_at(0, 0, 0), pose_at(0.1 + gap, 0, 0)};
    assert_ok(opx_linkset_set_poses(links, poses, 2, 0));
    return links;
}

static opx_self_collision_result self_collide(opx_query *query, const opx_linkset *links, uint32_t max_contacts) {
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    request.max_contacts = max_contacts;
    request.compute_penetration = 1;
    opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
    assert_ok(opx_query_self_collide(query, links, &request, &result));
    return result;
}

static opx_self_distance_result self_distance(opx_query *query, const opx_linkset *links, int32_t signed_distance) {
    opx_self_distance_request request = OPX_SELF_DISTANCE_REQUEST_INIT;
    request.signed_distance = signed_distance;
    opx_self_distance_result result = OPX_SELF_DISTANCE_RESULT_INIT;
    assert_ok(opx_query_self_distance(query, links, &request, &result));
    return result;
}

static int32_t pair_enabled(const opx_linkset *links, uint32_t a, uint32_t b) {
    int32_t enabled = -1;
    assert_ok(opx_linkset_get_pair_enabled(links, a, b, &enabled));
    return enabled;
}

/* 1 cm apart: reported at 1 cm; a padding of 0.5 cm on each closes the
 * gap (touching collides); disabling the pair removes it from both calls. */
static void links_one_centimetre_apart(void **state) {
    (void)state;
    opx_linkset *links = two_cubes(0.01);
    opx_query *query = new_query();
    assert_int_equal(self_collide(query, links, 1).collided, 0);
    opx_self_distance_result d = self_distance(query, links, 0);
    assert_int_equal(d.found, 1);
    assert_int_equal(d.collided, 0);
    assert_near(d.distance, 0.01, 1e-12);
    assert_int_equal(d.link_a, 0);
    assert_int_equal(d.link_b, 1);
    assert_near(d.point_on_a[0], 0.05, 1e-12);
    assert_near(d.point_on_b[0], 0.06, 1e-12);

    assert_ok(opx_linkset_set_padding(links, 0.005));
    const opx_self_collision_result padded = self_collide(query, links, 1);
    assert_int_equal(padded.collided, 1);
    assert_int_equal(padded.contact_count, 1);
    d = self_distance(query, links, 0);
    assert_int_equal(d.collided, 1);
    assert_near(d.distance, 0.0, 1e-12);

    assert_ok(opx_linkset_set_pair_enabled(links, 1, 0, 0));
    assert_int_equal(pair_enabled(links, 0, 1), 0);
    assert_int_equal(self_collide(query, links, 1).collided, 0);
    d = self_distance(query, links, 0);
    assert_int_equal(d.found, 0);
    assert_true(isinf(d.distance));
    assert_ok(opx_linkset_set_pair_enabled(links, 0, 1, 1));
    assert_int_equal(self_collide(query, links, 1).collided, 1);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

/* Cubes 0.02 m deep into each other: the contact names both links and
 * shapes, its depth and normal; signed distance is minus the depth. */
static void contacts_and_penetration(void **state) {
    (void)state;
    opx_linkset *links = two_cubes(-0.02);
    opx_query *query = new_query();
    const opx_self_collision_result r = self_collide(query, links, UINT32_MAX);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 1);
    assert_int_equal(r.truncated, 0);
    assert_true(r.link_pairs == 1 && r.narrow_tests >= 1);
    opx_self_contact c = OPX_SELF_CONTACT_INIT;
    assert_ok(opx_query_get_self_contact(query, 0, &c));
    assert_int_equal(c.link_a, 0);
    assert_int_equal(c.shape_a, 0);
    assert_int_equal(c.link_b, 1);
    assert_int_equal(c.shape_b, 0);
    assert_near(c.depth, 0.02, 1e-12);
    assert_near(c.normal[0], 1.0, 1e-12);
    assert_near(c.position[0], 0.04, 1e-12);
    const opx_self_distance_result d = self_distance(query, links, 1);
    assert_near(d.distance, -0.02, 1e-12);
    assert_near(d.point_on_a[0] - d.point_on_b[0], 0.02, 1e-12);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

/* Three spheres in a row touch pairwise (0-1, 1-2): yes/no, one, all. */
static void contact_limits(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    for (int i = 0; i < 3; ++i) add_shape(links, add_link(links, "ball"), sphere_shape(0.1));
    const opx_pose poses[3] = {pose_at(0, 0, 0), pose_at(0.15, 0, 0), pose_at(0.3, 0, 0)};
    assert_ok(opx_linkset_set_poses(links, poses, 3, 0));
    opx_query *query = new_query();
    opx_self_collision_result r = self_collide(query, links, 0);
    assert_true(r.collided == 1 && r.contact_count == 0 && r.truncated == 0);
    r = self_collide(query, links, 1);
    assert_true(r.collided == 1 && r.contact_count == 1 && r.truncated == 0);
    r = self_collide(query, links, 2);
    assert_true(r.contact_count == 2 && r.truncated == 0);
    assert_ok(opx_linkset_set_link_enabled(links, 1, 0));
    r = self_collide(query, links, UINT32_MAX);
    assert_int_equal(r.collided, 0);
    assert_int_equal(r.contact_count, 0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

static const char TEST_SRDF_PAIRS[] =
    "<robot name=\"test\"><disable_collisions link1=\"arm\" link2=\"base\" reason=\"Adjacent\"/></robot>";

/* Whether the last self-collision query has a contact of links a < b. */
static int has_contact(const opx_query *query, uint64_t count, uint32_t a, uint32_t b) {
    for (uint64_t i = 0; i < count; ++i) {
        opx_self_contact c = OPX_SELF_CONTACT_INIT;
        assert_ok(opx_query_get_self_contact(query, i, &c));
        assert_true(c.link_a < c.link_b);
        if (c.link_a == a && c.link_b == b) return 1;
    }
    return 0;
}

/* The SRDF's pair starts disabled and clones keep the pairs; the arm lies
 * on the base, a contact only while the pair is enabled. */
static void srdf_pairs_start_disabled(void **state) {
    (void)state;
    scratch_dir dir = make_scratch_dir();
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.srdf_path = write_scratch(&dir, "test.srdf", TEST_SRDF_PAIRS);
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    assert_int_equal(pair_enabled(robot, L_BASE, L_ARM), 0);
    assert_int_equal(pair_enabled(robot, L_ARM, L_TOOL), 1);
    opx_query *query = new_query();
    opx_self_collision_result r = self_collide(query, robot, UINT32_MAX);
    assert_false(has_contact(query, r.contact_count, L_BASE, L_ARM));
    opx_linkset *copy = NULL;
    assert_ok(opx_linkset_clone(robot, &copy));
    assert_int_equal(pair_enabled(copy, L_ARM, L_BASE), 0);
    assert_ok(opx_linkset_set_pair_enabled(copy, L_BASE, L_ARM, 1));
    r = self_collide(query, copy, UINT32_MAX);
    assert_int_equal(r.collided, 1);
    assert_true(has_contact(query, r.contact_count, L_BASE, L_ARM));
    assert_int_equal(pair_enabled(robot, L_BASE, L_ARM), 0);
    opx_query_destroy(query);
    opx_linkset_destroy(copy);
    opx_linkset_destroy(robot);
    remove_scratch_dir(&dir);
}

/* The arm always lies on the base; the tool (z >= 0.32) never meets the
 * wheel (z <= 0.13).  The helper leaves poses and joints alone and is
 * repeatable. */
static void sampling_disables_never_and_always(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    opx_linkset *again = NULL, *now = NULL;
    assert_ok(opx_linkset_clone(robot, &again));
    assert_ok(opx_linkset_clone(robot, &now));
    const opx_pose before = get_pose(robot, L_TOOL);
    opx_pair_sampling_options options = OPX_PAIR_SAMPLING_OPTIONS_INIT;
    opx_pair_sampling_result result = OPX_PAIR_SAMPLING_RESULT_INIT;
    options.samples = 300;
    assert_ok(opx_linkset_disable_never_colliding_pairs(robot, &options, &result));
    const uint32_t never = result.never;
    assert_int_equal(result.always, 0);
    assert_int_equal(result.now, 0);
    assert_true(never >= 1);
    assert_int_equal(pair_enabled(robot, L_BASE, L_ARM), 1);
    assert_int_equal(pair_enabled(robot, L_TOOL, L_WHEEL), 0);
    assert_int_equal(pair_enabled(robot, L_SLIDER, L_FINGER), 1); /* no shapes: left alone */
    const opx_pose after = get_pose(robot, L_TOOL);
    assert_memory_equal(&before, &after, sizeof before);

    options.also_always_colliding = 1;
    assert_ok(opx_linkset_disable_never_colliding_pairs(again, &options, &result));
    assert_int_equal(result.never, never);
    assert_true(result.always >= 1);
    assert_int_equal(pair_enabled(again, L_BASE, L_ARM), 0);
    for (uint32_t a = 0; a < TEST_LINKS; ++a)  /* the same seed: the same never-colliding pairs */
        for (uint32_t b = a + 1; b < TEST_LINKS; ++b)
            if (!pair_enabled(robot, a, b)) assert_int_equal(pair_enabled(again, a, b), 0);

    /* Colliding now (the arm on the base, at the zero configuration): first. */
    options.also_always_colliding = 0, options.also_colliding_now = 1;
    assert_ok(opx_linkset_disable_never_colliding_pairs(now, &options, NULL));
    assert_int_equal(pair_enabled(now, L_BASE, L_ARM), 0);
    opx_query *query = new_query();
    assert_int_equal(self_collide(query, now, 1).collided, 0);
    opx_query_destroy(query);
    opx_linkset_destroy(now);
    opx_linkset_destroy(again);
    opx_linkset_destroy(robot);
}

static void collide_rejects_bad_arguments(void **state) {
    (void)state;
    opx_linkset *links = two_cubes(0.01);
    opx_query *query = new_query();
    opx_self_collision_result r = OPX_SELF_COLLISION_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, COLLIDE, "query", opx_query_self_collide(NULL, links, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, COLLIDE, "links", opx_query_self_collide(query, NULL, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, COLLIDE, "out_result",
                   opx_query_self_collide(query, links, NULL, NULL));
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    request.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, COLLIDE, "request", opx_query_self_collide(query, links, &request, &r));
    r.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, COLLIDE, "out_result", opx_query_self_collide(query, links, NULL, &r));
    opx_self_contact c = OPX_SELF_CONTACT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_self_contact", "index 0",
                   opx_query_get_self_contact(query, 0, &c));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_self_contact", "query",
                   opx_query_get_self_contact(NULL, 0, &c));
    c.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_query_get_self_contact", "out_contact",
                   opx_query_get_self_contact(query, 0, &c));
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

static void distance_rejects_bad_arguments(void **state) {
    (void)state;
    opx_linkset *links = two_cubes(0.01);
    opx_query *query = new_query();
    opx_self_distance_result r = OPX_SELF_DISTANCE_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, DISTANCE, "query", opx_query_self_distance(NULL, links, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, DISTANCE, "links", opx_query_self_distance(query, NULL, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, DISTANCE, "out_result",
                   opx_query_self_distance(query, links, NULL, NULL));
    opx_self_distance_request request = OPX_SELF_DISTANCE_REQUEST_INIT;
    request.cutoff = -1.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, DISTANCE, "request->cutoff",
                   opx_query_self_distance(query, links, &request, &r));
    request.cutoff = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, DISTANCE, "request->cutoff",
                   opx_query_self_distance(query, links, &request, &r));
    request.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, DISTANCE, "request", opx_query_self_distance(query, links, &request, &r));
    /* A cutoff below the gap: not found, the distance is the cutoff. */
    request = (opx_self_distance_request)OPX_SELF_DISTANCE_REQUEST_INIT;
    request.cutoff = 0.005;
    assert_ok(opx_query_self_distance(query, links, &request, &r));
    assert_int_equal(r.found, 0);
    assert_near(r.distance, 0.005, 0.0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

static void pairs_reject_bad_links(void **state) {
    (void)state;
    opx_linkset *links = two_cubes(0.01);
    const char *set = "opx_linkset_set_pair_enabled", *get = "opx_linkset_get_pair_enabled";
    int32_t enabled = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, set, "links", opx_linkset_set_pair_enabled(NULL, 0, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, set, "a: link 2", opx_linkset_set_pair_enabled(links, 2, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, set, "b: link 7", opx_linkset_set_pair_enabled(links, 0, 7, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, set, "both link 1", opx_linkset_set_pair_enabled(links, 1, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, get, "out_enabled", opx_linkset_get_pair_enabled(links, 0, 1, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, get, "b: link 9",
                   opx_linkset_get_pair_enabled(links, 0, 9, &enabled));
    assert_int_equal(pair_enabled(links, 0, 1), 1); /* nothing changed */
    const char *sample = "opx_linkset_disable_never_colliding_pairs";
    expect_failure(OPX_ERROR_UNSUPPORTED, sample, "joints",
                   opx_linkset_disable_never_colliding_pairs(links, NULL, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, sample, "links",
                   opx_linkset_disable_never_colliding_pairs(NULL, NULL, NULL));
    opx_pair_sampling_options options = OPX_PAIR_SAMPLING_OPTIONS_INIT;
    options.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, sample, "options",
                   opx_linkset_disable_never_colliding_pairs(links, &options, NULL));
    opx_pair_sampling_result result = OPX_PAIR_SAMPLING_RESULT_INIT;
    result.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, sample, "out_result",
                   opx_linkset_disable_never_colliding_pairs(links, NULL, &result));
    opx_linkset_destroy(links);
}

/* The _init functions fill defaults up to the size given. */
static void init_functions_fill_defaults(void **state) {
    (void)state;
    opx_self_collision_request request;
    memset(&request, 0xff, sizeof request);
    assert_ok(opx_self_collision_request_init(&request, sizeof request));
    assert_int_equal(request.max_contacts, 1);
    opx_self_distance_result result;
    assert_ok(opx_self_distance_result_init(&result, sizeof result));
    assert_int_equal(result.struct_size, sizeof result);
    opx_pair_sampling_options options;
    assert_ok(opx_pair_sampling_options_init(&options, sizeof options));
    assert_int_equal(options.samples, 10000);
    opx_self_contact contact;
    expect_failure(OPX_ERROR_VERSION, "opx_self_contact_init", "size", opx_self_contact_init(&contact, 2));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(links_one_centimetre_apart),
        cmocka_unit_test(contacts_and_penetration),
        cmocka_unit_test(contact_limits),
        cmocka_unit_test(srdf_pairs_start_disabled),
        cmocka_unit_test(sampling_disables_never_and_always),
        cmocka_unit_test(collide_rejects_bad_arguments),
        cmocka_unit_test(distance_rejects_bad_arguments),
        cmocka_unit_test(pairs_reject_bad_links),
        cmocka_unit_test(init_functions_fill_defaults),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
