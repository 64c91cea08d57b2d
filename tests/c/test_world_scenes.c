/*
 * MoveIt planning scenes read into worlds: tests/data/scenes/kitchen.yaml
 * (a moveit_msgs/PlanningScene with every primitive type, a mesh, poses on
 * objects and on shapes, APPEND, MOVE, ADD and REMOVE) and the same scene
 * as .scene text, with and without object poses, and in robowflex's
 * dialect (kitchen_robowflex.yaml: lists for poses, words for types and
 * operations, fixed frames); then malformed scenes,
 * whose messages name the file (or "data"), the line and the field.
 */
#include "opx_query_test.h"

#ifndef OPX_SCENE_DIR
#error "OPX_SCENE_DIR must name tests/data/scenes"
#endif

static opx_world *load(const char *name) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", OPX_SCENE_DIR, name);
    opx_world *world = NULL;
    assert_ok(opx_world_load_scene_file(path, &world));
    assert_non_null(world);
    return world;
}

static uint32_t find(const opx_world *world, const char *name) {
    uint32_t index = UINT32_MAX;
    assert_ok(opx_world_find_object(world, name, &index));
    return index;
}

/* The distance from a small probe sphere at (x, y, z) to the world. */
static opx_distance_result probe(const opx_world *world, double x, double y, double z) {
    opx_query *query = new_query();
    assert_ok(opx_query_set_world(query, world));
    opx_linkset *links = new_sphere_at(0.01, x, y, z);
    const opx_distance_result r = distance_with(query, NULL, links, NULL);
    opx_linkset_destroy(links);
    opx_query_destroy(query);
    return r;
}

static void assert_probe(const opx_world *world, const char *object, double x, double y, double z,
                         double distance) {
    const opx_distance_result r = probe(world, x, y, z);
    assert_int_equal(r.found, 1);
    assert_int_equal(r.object, (int32_t)find(world, object));
    assert_near(r.distance, distance, 1e-9);
}

/* The kitchen as both files describe it, checked by probes in the map frame. */
static void assert_kitchen(const opx_world *world) {
    uint32_t count = 0;
    assert_ok(opx_world_get_object_count(world, &count));
    assert_int_equal(count, 3);  /* the shelf was removed */
    assert_int_equal(find(world, "table"), 0);
    uint32_t shapes = 0;
    assert_ok(opx_world_get_shape_count(world, find(world, "table"), &shapes));
    assert_int_equal(shapes, 3);  /* box, cylinder, and the appended knob */
    /* The top, turned a quarter about z: 0.8 along x, 1.2 along y in the map. */
    assert_probe(world, "table", 1.5, 0.0, 0.725, 0.09);
    assert_probe(world, "table", 1.0, 0.7, 0.725, 0.09);
    /* The leg: height 0.7, radius 0.03, at (0.65, 0.55) in the map. */
    assert_probe(world, "table", 0.75, 0.55, 0.35, 0.06);
    /* The knob, appended in the map frame at (1, 0, 0.8): object frame (0, 0, 0.8). */
    opx_shape knob = OPX_SHAPE_INIT;
    assert_ok(opx_world_get_shape(world, 0, 2, &knob));
    assert_int_equal(knob.kind, OPX_SHAPE_SPHERE);
    assert_center(knob.pose.position, 0.0, 0.0, 0.8);
    assert_probe(world, "table", 1.0, 0.0, 0.95, 0.09);
    /* The ball, moved to (0, 2, 0.5); its one shape sits at its origin. */
    opx_pose pose = OPX_POSE_IDENTITY;
    assert_ok(opx_world_get_object_pose(world, find(world, "ball"), &pose));
    assert_center(pose.position, 0.0, 2.0, 0.5);
    assert_probe(world, "ball", 0.0, 2.3, 0.5, 0.19);
    /* The wedge mesh at (-1, 0, 0): its bottom face is z = 0. */
    assert_probe(world, "wedge", -0.95, 0.05, -0.1, 0.09);
}

static void test_yaml_planning_scene(void **state) {
    (void)state;
    opx_world *world = load("kitchen.yaml");
    assert_kitchen(world);
    opx_world_destroy(world);
}

static void test_yaml_robowflex_dialect(void **state) {
    (void)state;
    opx_world *world = load("kitchen_robowflex.yaml");
    assert_kitchen(world);
    opx_world_destroy(world);
}

#define FRAMED_BALL(frame, pose)                                                               \
    "fixed_frame_transforms:\n"                                                                \
    "  - {child_frame_id: f, transform: {translation: [1, 0, 0], rotation: [0, 0, 0.7071067811865476, 0.7071067811865476]}}\n" \
    "  - {header: {frame_id: f}, child_frame_id: g, transform: {translation: {x: 0, y: 1, z: 0}}}\n" \
    "world:\n  collision_objects:\n    - id: ball\n      header: {frame_id: " frame "}\n"     \
    "      primitives: [{type: sphere, dimensions: [0.1]}]\n" pose

/* An object whose header names a fixed frame is placed by it: f turns a
 * quarter about z at (1, 0, 0); g is 1 m along f's y, at (0, 0, 0). */
static void test_yaml_fixed_frames(void **state) {
    (void)state;
    static const struct {
        const char *text;
        double x, y, z;
    } cases[] = {
        {FRAMED_BALL("f", "      pose: {position: [1, 0, 0], orientation: [0, 0, 0, 1]}\n"), 1.0, 1.0, 0.0},
        {FRAMED_BALL("f", "      primitive_poses: [{position: [0, 2, 0]}]\n"), -1.0, 0.0, 0.0},
        {FRAMED_BALL("g", "      pose: {position: [0, 0, 3]}\n"), 0.0, 0.0, 3.0},
        {FRAMED_BALL("map", "      pose: {position: [0, 0, 3]}\n"), 0.0, 0.0, 3.0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        opx_world *world = NULL;
        assert_ok(opx_world_load_scene_memory(cases[i].text, strlen(cases[i].text), OPX_SCENE_FORMAT_YAML, &world));
        assert_probe(world, "ball", cases[i].x, cases[i].y, cases[i].z + 0.5, 0.39);
        opx_world_destroy(world);
    }
}

static void test_scene_text_with_object_poses(void **state) {
    (void)state;
    opx_world *world = load("kitchen.scene");
    assert_kitchen(world);
    opx_world_destroy(world);
}

static void test_scene_text_without_object_poses(void **state) {
    (void)state;
    opx_world *world = load("kitchen_without_object_poses.scene");
    uint32_t count = 0;
    assert_ok(opx_world_get_object_count(world, &count));
    assert_int_equal(count, 2);
    assert_probe(world, "ball", 0.0, 2.3, 0.5, 0.19);
    assert_probe(world, "wedge", -0.95, 0.05, -0.1, 0.09);
    opx_world_destroy(world);
}

/* A scene in memory that must fail with `status`, its message holding
 * every one of `parts` (NULL-terminated). */
static void expect_scene_failure(int32_t format, const char *text, opx_status status, const char *const *parts) {
    opx_world *world = NULL;
    const opx_status got = opx_world_load_scene_memory(text, strlen(text), format, &world);
    if (got != status)
        fail_msg("got %s, expected %s: \"%s\"\nscene:\n%s", opx_status_name(got), opx_status_name(status),
                 opx_last_error(), text);
    assert_null(world);
    for (const char *const *part = parts; *part != NULL; ++part)
        if (strstr(opx_last_error(), *part) == NULL)
            fail_msg("\"%s\" does not hold \"%s\"", opx_last_error(), *part);
}

#define EXPECT_YAML(text, status, ...)                                               \
    do {                                                                             \
        const char *const parts_[] = {"opx_world_load_scene_memory: data", __VA_ARGS__, NULL}; \
        expect_scene_failure(OPX_SCENE_FORMAT_YAML, (text), (status), parts_);       \
    } while (0)
#define EXPECT_TEXT(text, status, ...)                                               \
    do {                                                                             \
        const char *const parts_[] = {"opx_world_load_scene_memory: data", __VA_ARGS__, NULL}; \
        expect_scene_failure(OPX_SCENE_FORMAT_TEXT, (text), (status), parts_);       \
    } while (0)

#define OBJECT_HEAD "world:\n  collision_objects:\n    - id: post\n"

static void test_malformed_yaml(void **state) {
    (void)state;
    EXPECT_YAML(OBJECT_HEAD "      primitives:\n        - type: 3\n          dimensions: [0.7]\n", OPX_ERROR_CORRUPT,
                "line 6", "world.collision_objects[0].primitives[0].dimensions", "[height, radius]");
    EXPECT_YAML(OBJECT_HEAD "      primitives:\n        - type: 4\n          dimensions: [0.7, 0.1]\n",
                OPX_ERROR_UNSUPPORTED, "line 5", "primitives[0].type", "CONE");
    EXPECT_YAML(OBJECT_HEAD "      primitives:\n        - type: 1\n          dimensions: [0.1, -0.2, 0.3]\n",
                OPX_ERROR_CORRUPT, "line 6", "dimensions", "-0.2");
    EXPECT_YAML(OBJECT_HEAD "      primitives:\n        - type: 2\n          dimensions: [abc]\n", OPX_ERROR_CORRUPT,
                "line 6", "dimensions[0]", "'abc' is not a number");
    EXPECT_YAML(OBJECT_HEAD "      primitives:\n        - {type: 2, dimensions: [0.1]}\n      pose:\n"
                "        position: {x: .nan, y: 0, z: 0}\n",
                OPX_ERROR_CORRUPT, "line 7", "collision_objects[0].pose", "not finite");
    EXPECT_YAML(OBJECT_HEAD "      primitives: []\n      primitive_poses:\n        - {position: {x: 1}}\n",
                OPX_ERROR_CORRUPT, "primitive_poses", "1 poses for 0 primitives");
    EXPECT_YAML(OBJECT_HEAD "      meshes:\n        - vertices: [{x: 0}, {x: 1}, {y: 1}]\n"
                "          triangles:\n            - vertex_indices: [0, 1, 3]\n",
                OPX_ERROR_CORRUPT, "line 7", "meshes[0].triangles[0].vertex_indices", "vertex 3");
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: 3, dimensions: [1e200, 1e200]}]\n", OPX_ERROR_CORRUPT,
                "line 4", "cylinder radius 1e+200", "at most 1e+06 m");
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: 2, dimensions: [0.1]}]\n      pose: {position: {x: 2e6}}\n",
                OPX_ERROR_CORRUPT, "line 5", "collision_objects[0].pose", "within +-1e+06 m");
    EXPECT_YAML(OBJECT_HEAD "      meshes:\n        - vertices: [{x: 0}, {x: 1}, {y: -1e7}]\n"
                "          triangles:\n            - vertex_indices: [0, 1, 2]\n",
                OPX_ERROR_CORRUPT, "meshes[0]", "vertex 2");
    EXPECT_YAML(OBJECT_HEAD "      planes:\n        - coef: [0, 0, 1, 0]\n", OPX_ERROR_UNSUPPORTED, "line 5", "planes");
    EXPECT_YAML(OBJECT_HEAD "      operation: 3\n", OPX_ERROR_CORRUPT, "line 3", "MOVE", "'post'");
    EXPECT_YAML(OBJECT_HEAD "      operation: 7\n", OPX_ERROR_CORRUPT, "line 4", "operation");
    EXPECT_YAML(OBJECT_HEAD "      operation: 0\n", OPX_ERROR_CORRUPT, "line 3", "no shapes");
    EXPECT_YAML("world:\n  collision_objects:\n    - id: [\n", OPX_ERROR_CORRUPT, "line", "not valid YAML");
    EXPECT_YAML("name: robot only\nrobot_state: {}\n", OPX_ERROR_CORRUPT, "line 1", "world");
    EXPECT_YAML("- 1\n- 2\n", OPX_ERROR_CORRUPT, "line 1", "not a map");
    EXPECT_YAML("", OPX_ERROR_CORRUPT, "no YAML document");
}

/* robowflex's dialect keeps errors naming the line and the field. */
static void test_malformed_robowflex_yaml(void **state) {
    (void)state;
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: torus, dimensions: [0.1]}]\n", OPX_ERROR_CORRUPT, "line 4",
                "primitives[0].type", "'torus' is none of 1 or box");
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: Cone, dimensions: [0.7, 0.1]}]\n", OPX_ERROR_UNSUPPORTED,
                "line 4", "primitives[0].type", "CONE");
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: box, dimensions: [0.1, 0.2, 0.3]}]\n      pose:\n"
                "        orientation: [0, 0, 1]\n",
                OPX_ERROR_CORRUPT, "line 6", "collision_objects[0].pose.orientation", "3 values; a list [x, y, z, w]");
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: box, dimensions: [0.1, 0.2, 0.3]}]\n      pose:\n"
                "        position: [0, 0, up]\n",
                OPX_ERROR_CORRUPT, "line 6", "pose.position[2]", "'up' is not a number");
    EXPECT_YAML(OBJECT_HEAD "      primitives: [{type: sphere, dimensions: [0.1]}]\n      pose: {position: \"0 0 1\"}\n",
                OPX_ERROR_CORRUPT, "line 5", "pose.position", "not a map of x, y, z or a list [x, y, z]");
    EXPECT_YAML(OBJECT_HEAD "      operation: jump\n", OPX_ERROR_CORRUPT, "line 4", "operation",
                "'jump' is none of 0 or add");
    EXPECT_YAML(OBJECT_HEAD "      meshes:\n        - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                "          triangles: [[0, 1]]\n",
                OPX_ERROR_CORRUPT, "line 6", "meshes[0].triangles[0]", "not 3 vertex indices");
    EXPECT_YAML(OBJECT_HEAD "      meshes:\n        - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                "          triangles: [[0, 1, 4]]\n",
                OPX_ERROR_CORRUPT, "line 6", "meshes[0].triangles[0]", "vertex 4");
    EXPECT_YAML(OBJECT_HEAD "      meshes:\n        - {resource: \"package://kitchen/meshes/counter.stl\", dimensions: [1, 1, 1]}\n",
                OPX_ERROR_UNSUPPORTED, "line 5", "meshes[0].resource", "counter.stl", "mesh files are not read");
    EXPECT_YAML("fixed_frame_transforms:\n  - transform: {translation: [0, 0, 0]}\n" OBJECT_HEAD,
                OPX_ERROR_CORRUPT, "line 2", "fixed_frame_transforms[0].child_frame_id", "empty");
    EXPECT_YAML("fixed_frame_transforms:\n  - child_frame_id: f\n    transform: {rotation: [0, 0, 0, .nan]}\n"
                OBJECT_HEAD,
                OPX_ERROR_CORRUPT, "line 3", "fixed_frame_transforms[0].transform", "not finite");
    EXPECT_YAML("fixed_frame_transforms: {child_frame_id: f}\n" OBJECT_HEAD, OPX_ERROR_CORRUPT, "line 1",
                "fixed_frame_transforms", "not a list");
}

static uint32_t yaml_object_count(const char *text) {
    opx_world *world = NULL;
    uint32_t count = 0;
    assert_ok(opx_world_load_scene_memory(text, strlen(text), OPX_SCENE_FORMAT_YAML, &world));
    assert_ok(opx_world_get_object_count(world, &count));
    opx_world_destroy(world);
    return count;
}

#define BALL(id, diff) \
    "world:\n  collision_objects:\n    - id: " id "\n      primitives: [{type: 2, dimensions: [0.1]}]\n" \
    "is_diff: " diff "\n"

/* Messages one after the other, as `ros2 topic echo` prints them. */
static void test_yaml_documents(void **state) {
    (void)state;
    assert_int_equal(yaml_object_count(BALL("a", "false") "---\n"), 1);
    assert_int_equal(yaml_object_count("---\n" BALL("a", "false") "---\n" BALL("b", "true") "---\n"), 2);
    assert_int_equal(yaml_object_count(BALL("a", "true") "...\n---\n" BALL("b", "false")), 1);  /* not a diff: replaces */
    assert_int_equal(yaml_object_count("# a comment\n--- {collision_objects: []}\n"), 0);
    EXPECT_YAML(BALL("a", "true") "---\n" BALL("b", "true") "---\n" OBJECT_HEAD "      operation: 9\n",
                OPX_ERROR_CORRUPT, "line 16", "world.collision_objects[0].operation");
    /* A document starting with ',' (which makes yaml-cpp's LoadAll loop for ever) fails at once. */
    EXPECT_YAML(BALL("a", "true") "---\n,\n", OPX_ERROR_CORRUPT, "line 7", "not a map");
}

#define TEXT_HEAD "scene\n* post\n0 0 0\n0 0 0 1\n1\n"

static void test_malformed_scene_text(void **state) {
    (void)state;
    EXPECT_TEXT(TEXT_HEAD "torus\n0.1 0.2\n", OPX_ERROR_CORRUPT, "line 6", "object 'post' shape 0", "'torus'");
    EXPECT_TEXT(TEXT_HEAD "cone\n0.1 0.2\n", OPX_ERROR_UNSUPPORTED, "line 6", "cone");
    EXPECT_TEXT(TEXT_HEAD "box\n0.1 x 0.3\n", OPX_ERROR_CORRUPT, "line 7", "(box) size", "'x' is not a number");
    EXPECT_TEXT(TEXT_HEAD "cylinder\n0 0.5\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n.\n", OPX_ERROR_CORRUPT, "line 7",
                "cylinder radius 0");
    EXPECT_TEXT(TEXT_HEAD "sphere\n0.1\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n", OPX_ERROR_CORRUPT, "'*' or '.'",
                "ends early");
    EXPECT_TEXT(TEXT_HEAD "mesh\n3 1\n0 0 0\n1 0 0\n0 1 0\n0 1 5\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n.\n",
                OPX_ERROR_CORRUPT, "(mesh)", "vertex 5");
    EXPECT_TEXT(TEXT_HEAD "sphere\n0.1\n0 0 nan\n0 0 0 1\n0 0 0 0\n0\n.\n", OPX_ERROR_CORRUPT, "line 9",
                "shape 0 pose", "not finite");
    EXPECT_TEXT(TEXT_HEAD "sphere\n1e200\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n.\n", OPX_ERROR_CORRUPT, "sphere radius 1e+200",
                "at most 1e+06 m");
    EXPECT_TEXT("scene\n* post\n0 0 -3e6\n0 0 0 1\n1\nsphere\n0.1\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n.\n",
                OPX_ERROR_CORRUPT, "object 'post' pose", "within +-1e+06 m");
    EXPECT_TEXT("scene\n+ post\n", OPX_ERROR_CORRUPT, "line 2", "'+'");
    EXPECT_TEXT("scene\n* post\n0 0 0\n0 0 0 1\n-1\n", OPX_ERROR_CORRUPT, "line 5", "shape count", "'-1'");
}

/* `count` aliases of `anchor` as a flow list: "[*a, *a, ...]". */
static void append_aliases(char *text, size_t size, const char *anchor, int count) {
    strncat(text, "[", size - strlen(text) - 1);
    for (int i = 0; i < count; ++i) {
        strncat(text, i > 0 ? ", *" : "*", size - strlen(text) - 1);
        strncat(text, anchor, size - strlen(text) - 1);
    }
    strncat(text, "]\n", size - strlen(text) - 1);
}

/* Aliases may repeat nodes, not multiply a scene far beyond its text. */
static void test_yaml_aliases(void **state) {
    (void)state;
    assert_int_equal(yaml_object_count("world:\n  collision_objects:\n"
                                       "    - {id: a, pose: &p {position: {x: 1}}, primitives: [&s {type: 2, dimensions: [0.1]}]}\n"
                                       "    - {id: b, pose: *p, primitives: [*s, *s]}\n"),
                     2);
    /* 20 appends of 20 meshes of 23 vertices and 20 triangles, from about 700 bytes. */
    char text[4096] = "anchors:\n  - &v {x: 1}\n  - &t {vertex_indices: [0, 1, 2]}\n  - &V ";
    append_aliases(text, sizeof text, "v", 23);
    strncat(text, "  - &T ", sizeof text - strlen(text) - 1);
    append_aliases(text, sizeof text, "t", 20);
    strncat(text, "  - &m {vertices: *V, triangles: *T}\n  - &M ", sizeof text - strlen(text) - 1);
    append_aliases(text, sizeof text, "m", 20);
    strncat(text, "  - &o {id: a, operation: 2, meshes: *M}\nworld:\n  collision_objects: ", sizeof text - strlen(text) - 1);
    append_aliases(text, sizeof text, "o", 20);
    EXPECT_YAML(text, OPX_ERROR_CORRUPT, "aliases (*name) repeat more elements than its size allows");
}

/* Lists nested beyond the YAML reader's limit are refused as such. */
static void test_yaml_nested_too_deep(void **state) {
    (void)state;
    static char text[4096] = OBJECT_HEAD "      primitives: ";
    for (int i = 0; i < 1000; ++i) strcat(text, "[");
    for (int i = 0; i < 1000; ++i) strcat(text, "]");
    strcat(text, "\n");
    EXPECT_YAML(text, OPX_ERROR_CORRUPT, "line 4", "nested 500 levels deep or more");
}

/* Names leave the library as C strings: one holding a NUL byte is refused. */
static void test_names_holding_a_nul_byte(void **state) {
    (void)state;
    EXPECT_YAML("world:\n  collision_objects:\n    - id: \"ball\\0b\"\n      primitives: [{type: 2, dimensions: [0.1]}]\n",
                OPX_ERROR_CORRUPT, "line 3", "NUL byte");
    static const char text[] = "scene\n* ball\0b\n1\nsphere\n0.1\n0 0 0\n0 0 0 1\n0 0 0 0\n.\n";
    opx_world *world = NULL;
    assert_int_equal(opx_world_load_scene_memory(text, sizeof text - 1, OPX_SCENE_FORMAT_TEXT, &world),
                     OPX_ERROR_CORRUPT);
    assert_null(world);
    assert_non_null(strstr(opx_last_error(), "line 2"));
    assert_non_null(strstr(opx_last_error(), "NUL byte"));
}

static void test_malformed_files_name_the_file(void **state) {
    (void)state;
    opx_world *world = NULL;
    char path[1024];
    snprintf(path, sizeof path, "%s/cylinder_missing_radius.yaml", OPX_SCENE_DIR);
    expect_failure(OPX_ERROR_CORRUPT, "opx_world_load_scene_file", "cylinder_missing_radius.yaml: line 9: "
                   "world.collision_objects[0].primitives[0].dimensions",
                   opx_world_load_scene_file(path, &world));
    snprintf(path, sizeof path, "%s/box_position_too_short.yaml", OPX_SCENE_DIR);
    expect_failure(OPX_ERROR_CORRUPT, "opx_world_load_scene_file", "box_position_too_short.yaml: line 10: "
                   "world.collision_objects[0].primitive_poses[0].position: 2 values",
                   opx_world_load_scene_file(path, &world));
    snprintf(path, sizeof path, "%s/unknown_shape.scene", OPX_SCENE_DIR);
    expect_failure(OPX_ERROR_CORRUPT, "opx_world_load_scene_file", "unknown_shape.scene: line 6: object 'post' shape 0",
                   opx_world_load_scene_file(path, &world));
    assert_null(world);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_yaml_planning_scene),
        cmocka_unit_test(test_yaml_robowflex_dialect),
        cmocka_unit_test(test_yaml_fixed_frames),
        cmocka_unit_test(test_scene_text_with_object_poses),
        cmocka_unit_test(test_scene_text_without_object_poses),
        cmocka_unit_test(test_malformed_yaml),
        cmocka_unit_test(test_malformed_robowflex_yaml),
        cmocka_unit_test(test_yaml_documents),
        cmocka_unit_test(test_yaml_aliases),
        cmocka_unit_test(test_yaml_nested_too_deep),
        cmocka_unit_test(test_malformed_scene_text),
        cmocka_unit_test(test_names_holding_a_nul_byte),
        cmocka_unit_test(test_malformed_files_name_the_file),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
