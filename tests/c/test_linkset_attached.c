/*
 * Objects attached to links (opx_linkset_attach_object and friends): an
 * attached object moves with its link (poses and forward kinematics), is
 * checked against the octree and world objects as the link's own shapes
 * (contacts and distances name it), and against the robot without its
 * own link and its touch links: a box grasped between the arm's fingers
 * collides with them unless they are touch links.  Detaching, cloning,
 * attaching a world object where it stands, batches and paths, and bad
 * input (NULL, bad indices, NaN poses, unknown touch link names).
 */
#include "opx_batch_test.h"

#define L7 7
#define FINGER_L 8
#define FINGER_R 9

/* The arm straight up, its fingers 3 cm apart from the centre. */
static void open_hand(opx_linkset *arm, double *q) {
    for (int j = 0; j < ARM_JOINTS; ++j) q[j] = 0.0;
    q[7] = 0.03;
    assert_ok(opx_linkset_set_joint_positions(arm, q, ARM_JOINTS, NULL));
}

/* A box 2 x 4.2 x 3 cm between the fingers (their inner faces 4 cm
 * apart, l7 frame z 0.27 to 0.33): 1 mm into each finger. */
static uint32_t grasp_box(opx_linkset *arm, const char *const *touch, size_t touch_count) {
    const opx_shape box = box_shape(0.02, 0.042, 0.03);
    const opx_pose in_hand = pose_at(0.0, 0.0, 0.30);
    uint32_t object = UINT32_MAX;
    assert_ok(opx_linkset_attach_object(arm, L7, "part", &box, 1, &in_hand, touch, touch_count, &object));
    return object;
}

static opx_self_collision_result self_collide_all(opx_query *query, const opx_linkset *arm) {
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    request.max_contacts = UINT32_MAX;
    opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
    assert_ok(opx_query_self_collide(query, arm, &request, &result));
    return result;
}

static void grasped_box_touches_its_fingers_only_when_not_touch_links(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    double q[ARM_JOINTS];
    open_hand(arm, q);
    opx_query *query = new_query();
    assert_int_equal(self_collide_all(query, arm).collided, 0);

    /* Not touch links: the box collides with both fingers (never with l7). */
    grasp_box(arm, NULL, 0);
    opx_self_collision_result r = self_collide_all(query, arm);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 2);
    for (size_t i = 0; i < 2; ++i) {
        opx_self_contact c = OPX_SELF_CONTACT_INIT;
        assert_ok(opx_query_get_self_contact(query, i, &c));
        assert_int_equal(c.link_a, L7);
        assert_int_equal(c.attached_a, 0);
        assert_int_equal(c.shape_a, 0);
        assert_true(c.link_b == FINGER_L || c.link_b == FINGER_R);
        assert_int_equal(c.attached_b, -1);
    }
    opx_self_distance_request signed_request = OPX_SELF_DISTANCE_REQUEST_INIT;
    signed_request.signed_distance = 1;
    opx_self_distance_result d = OPX_SELF_DISTANCE_RESULT_INIT;
    assert_ok(opx_query_self_distance(query, arm, &signed_request, &d));
    assert_near(d.distance, -0.001, 1e-9);
    assert_int_equal(d.attached_a, 0);
    assert_int_equal(d.attached_b, -1);

    /* The fingers as touch links (MoveIt's grasp): no collision. */
    assert_ok(opx_linkset_detach_object(arm, 0));
    const char *fingers[2] = {"finger_l", "finger_r"};
    grasp_box(arm, fingers, 2);
    assert_int_equal(self_collide_all(query, arm).collided, 0);
    uint32_t touching[4] = {0, 0, 0, 0};
    size_t count = 0;
    assert_ok(opx_linkset_get_attached_touch_links(arm, 0, touching, 4, &count));
    assert_int_equal(count, 2);
    assert_int_equal(touching[0], FINGER_L);
    assert_int_equal(touching[1], FINGER_R);

    /* One finger only: the other still collides. */
    assert_ok(opx_linkset_detach_object(arm, 0));
    grasp_box(arm, fingers, 1);
    r = self_collide_all(query, arm);
    assert_int_equal(r.contact_count, 1);
    opx_self_contact c = OPX_SELF_CONTACT_INIT;
    assert_ok(opx_query_get_self_contact(query, 0, &c));
    assert_int_equal(c.link_b, FINGER_R);
    opx_query_destroy(query);
    opx_linkset_destroy(arm);
}

/* Two objects on one link never collide; on two links they do. */
static void attached_objects_among_themselves(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    const uint32_t a = add_link(links, "a"), b = add_link(links, "b");
    add_shape(links, a, sphere_shape(0.01));
    add_shape(links, b, sphere_shape(0.01));
    const opx_pose poses[2] = {pose_at(0, 0, 0), pose_at(1, 0, 0)};
    assert_ok(opx_linkset_set_poses(links, poses, 2, 0));
    const opx_shape ball = sphere_shape(0.3);
    const opx_pose right = pose_at(0.5, 0, 0), left = pose_at(-0.45, 0, 0);
    assert_ok(opx_linkset_attach_object(links, a, "one", &ball, 1, &right, NULL, 0, NULL));
    assert_ok(opx_linkset_attach_object(links, a, "two", &ball, 1, &right, NULL, 0, NULL));
    opx_query *query = new_query();
    assert_int_equal(self_collide_all(query, links).collided, 0); /* same link; link b 0.2 away */
    assert_ok(opx_linkset_attach_object(links, b, "three", &ball, 1, &left, NULL, 0, NULL));
    opx_self_collision_result r = self_collide_all(query, links);
    assert_int_equal(r.contact_count, 2); /* one and two with three */
    int objects_pairs = 0;
    for (size_t i = 0; i < r.contact_count; ++i) {
        opx_self_contact c = OPX_SELF_CONTACT_INIT;
        assert_ok(opx_query_get_self_contact(query, i, &c));
        assert_int_equal(c.link_a, a);
        assert_int_equal(c.link_b, b);
        objects_pairs += c.attached_a >= 0 && c.attached_b == 2;
    }
    assert_int_equal(objects_pairs, 2);
    /* Disabling link b takes its object out too. */
    assert_ok(opx_linkset_set_link_enabled(links, b, 0));
    assert_int_equal(self_collide_all(query, links).collided, 0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

/* The attached object moves with FK and meets the octree and world
 * objects as the link's shapes do, the answers naming it. */
static void attached_object_meets_octree_and_world(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    double q[ARM_JOINTS];
    open_hand(arm, q);
    const opx_shape plate = box_shape(0.5, 0.5, 0.02);
    const opx_pose above = pose_at(0.0, 0.0, 0.5);
    uint32_t object = 0;
    assert_ok(opx_linkset_attach_object(arm, L7, "plate", &plate, 1, &above, NULL, 0, &object));
    /* A ball resting on the plate, 0.5 m above l7 (the arm straight up). */
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    const opx_pose l7 = get_pose(arm, L7);
    const opx_pose at_plate = pose_at(l7.position[0], l7.position[1], l7.position[2] + 0.5 + 0.01 + 0.05);
    uint32_t ball = 0;
    assert_ok(opx_world_add_object(world, "ball", &at_plate, &ball));
    const opx_shape sphere = sphere_shape(0.05);
    assert_ok(opx_world_add_shape(world, ball, &sphere, NULL));
    opx_query *query = new_query();
    assert_ok(opx_query_set_world(query, world));
    opx_collision_result r = collide_with(query, NULL, arm, UINT32_MAX);
    assert_int_equal(r.collided, 1); /* the ball rests on the plate */
    const opx_contact c = get_contact(query, 0);
    assert_int_equal(c.link, L7);
    assert_int_equal(c.attached, 0);
    assert_int_equal(c.shape, 0);
    assert_int_equal(c.object, 0);
    opx_distance_result d = distance_with(query, NULL, arm, NULL);
    assert_near(d.distance, 0.0, 1e-9);
    assert_int_equal(d.attached, 0);

    /* FK moves it: the hand turned by j7 keeps the plate under the ball;
     * bending j6 swings it away. */
    q[6] = 1.0;
    assert_ok(opx_linkset_set_joint_positions(arm, q, ARM_JOINTS, NULL));
    assert_int_equal(collide_with(query, NULL, arm, 1).collided, 1);
    q[5] = 1.0;
    assert_ok(opx_linkset_set_joint_positions(arm, q, ARM_JOINTS, NULL));
    assert_int_equal(collide_with(query, NULL, arm, 1).collided, 0);
    d = distance_with(query, NULL, arm, NULL);
    assert_true(d.distance > 0.05);

    /* Against the octree: the one-cell map [0, 0.25]^3, the plate 1 mm
     * into its top face (the arm moved by a base pose). */
    assert_ok(opx_query_set_world(query, NULL));
    opx_octree *tree = new_one_cell_map();
    q[5] = 0.0;
    const opx_pose base = pose_at(C0, C0, 0.25 - 0.001 - (l7.position[2] + 0.49));
    assert_ok(opx_linkset_set_joint_positions(arm, q, ARM_JOINTS, &base));
    const opx_contact none = OPX_CONTACT_INIT;
    assert_int_equal(none.attached, -1);
    r = collide_with(query, tree, arm, UINT32_MAX);
    assert_int_equal(r.collided, 1);
    int plate_contacts = 0;
    for (size_t i = 0; i < r.contact_count; ++i) plate_contacts += get_contact(query, i).attached == 0;
    assert_true(plate_contacts >= 1);
    opx_octree_destroy(tree);
    opx_query_destroy(query);
    opx_world_destroy(world);
    opx_linkset_destroy(arm);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grasped_box_touches_its_fingers_only_when_not_touch_links),
        cmocka_unit_test(attached_objects_among_themselves),
        cmocka_unit_test(attached_object_meets_octree_and_world),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
