/*
 * URDF text a fuzzer or an attacker would write: bytes that are not UTF-8,
 * elements nested very deep, joints that form cycles, kinematic chains
 * hundreds of thousands of links long.  Each is refused with
 * OPX_ERROR_CORRUPT and a message naming the place; nothing crashes, leaks
 * (the ASan build checks) or writes to the process's stderr.
 */
#include "opx_urdf_test.h"

#include <fcntl.h>
#include <sys/stat.h>

#define LOAD_STRING "opx_linkset_load_urdf_string"

static void expect_load_failure(const char *xml, opx_status status, const char *needle) {
    opx_linkset *robot = (opx_linkset *)&robot; /* must be reset to NULL */
    expect_failure(status, LOAD_STRING, needle, opx_linkset_load_urdf_string(xml, NULL, &robot));
    assert_null(robot);
}

/* ---- Generated text ---------------------------------------------------- */

/* A growing string; every append checks the allocation. */
typedef struct text_buffer {
    char *data;
    size_t size, capacity;
} text_buffer;

static void append(text_buffer *t, const char *s) {
    const size_t n = strlen(s);
    if (t->size + n + 1 > t->capacity) {
        t->capacity = 2 * (t->size + n + 1);
        t->data = realloc(t->data, t->capacity);
        assert_non_null(t->data);
    }
    memcpy(t->data + t->size, s, n + 1);
    t->size += n;
}

/* Links l0..l{n-1} in one chain: joint j{i} (fixed, 1 cm up) has parent
 * l{i} and child l{i+1}, so link l{i} lies i joints below the root. */
static char *chain_urdf(size_t links) {
    text_buffer t = {NULL, 0, 0};
    char item[160];
    append(&t, "<robot name=\"chain\">");
    for (size_t i = 0; i < links; ++i) {
        snprintf(item, sizeof item, "<link name=\"l%zu\"/>", i);
        append(&t, item);
    }
    for (size_t i = 0; i + 1 < links; ++i) {
        snprintf(item, sizeof item,
                 "<joint name=\"j%zu\" type=\"fixed\"><parent link=\"l%zu\"/><child link=\"l%zu\"/>"
                 "<origin xyz=\"0 0 0.01\"/></joint>",
                 i, i, i + 1);
        append(&t, item);
    }
    append(&t, "</robot>");
    return t.data;
}

/* One link holding `depth` nested <x> elements: robot and link add 2. */
static char *nested_urdf(size_t depth) {
    text_buffer t = {NULL, 0, 0};
    append(&t, "<robot name=\"r\"><link name=\"a\">");
    for (size_t i = 0; i < depth; ++i) append(&t, "<x>");
    for (size_t i = 0; i < depth; ++i) append(&t, "</x>");
    append(&t, "</link></robot>");
    return t.data;
}

/* ---- Text that is not UTF-8 ------------------------------------------- */

static void text_ending_inside_a_utf8_sequence_is_corrupt(void **state) {
    (void)state;
    /* F1 announces a 4-byte sequence: only the terminating NUL follows. */
    expect_load_failure("<?xml><r>\xF1", OPX_ERROR_CORRUPT, "xml: byte offset 9 (0xF1) is not valid UTF-8");
    expect_load_failure("<robot name=\"r\"><link name=\"\xE2\x82", OPX_ERROR_CORRUPT, "byte offset 28 (0xE2)");
}

static void invalid_utf8_inside_the_text_is_corrupt(void **state) {
    (void)state;
    /* An overlong '/', a lone continuation byte, a surrogate, a code point
     * above U+10FFFF, U+FFFF, and a byte order mark after the start. */
    expect_load_failure("<robot name=\"r\"><link name=\"a\xC0\xAF\"/></robot>", OPX_ERROR_CORRUPT,
                        "byte offset 29 (0xC0) is not valid UTF-8");
    expect_load_failure("<robot name=\"r\"><link name=\"\x80\"/></robot>", OPX_ERROR_CORRUPT, "byte offset 28 (0x80)");
    expect_load_failure("<robot name=\"r\"><link name=\"\xED\xA0\x80\"/></robot>", OPX_ERROR_CORRUPT,
                        "byte offset 28 (0xED)");
    expect_load_failure("<robot name=\"r\"><link name=\"\xF4\x90\x80\x80\"/></robot>", OPX_ERROR_CORRUPT,
                        "byte offset 28 (0xF4)");
    expect_load_failure("<robot name=\"r\"><link name=\"\xEF\xBF\xBF\"/></robot>", OPX_ERROR_CORRUPT,
                        "byte offset 28 (0xEF) starts U+FEFF, U+FFFE or U+FFFF");
    expect_load_failure("<robot name=\"r\">\xEF\xBB\xBF<link name=\"a\"/></robot>", OPX_ERROR_CORRUPT,
                        "byte offset 16 (0xEF)");
    /* Character references that give a name no UTF-8: a surrogate (read
     * as UTF-8 once declared so), and a single byte E9 (read as one byte
     * without a declaration). */
    expect_load_failure("<?xml version=\"1.0\"?><robot name=\"r\"><link name=\"&#xD800;\"/></robot>",
                        OPX_ERROR_CORRUPT, "a <link> (line 1) has a name that is not valid UTF-8");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><joint name=\"&#xE9;\"/></robot>", OPX_ERROR_CORRUPT,
                        "a <joint> (line 1) has a name that is not valid UTF-8");
}

static void utf8_names_and_a_leading_byte_order_mark_load(void **state) {
    (void)state;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string("\xEF\xBB\xBF<robot name=\"r\"><link name=\"b\xC3\xA4se\"/>"
                                           "<link name=\"&lt;&amp;#x41;&quot;\tx\"/><joint name=\"j\" type=\"fixed\">"
                                           "<parent link=\"b\xC3\xA4se\"/><child link=\"&lt;&amp;#x41;&quot;&#x9;x\"/>"
                                           "</joint></robot>",
                                           NULL, &robot));
    const char *name = NULL;
    assert_ok(opx_linkset_get_link_name(robot, 0, &name));
    assert_string_equal(name, "b\xC3\xA4se");
    assert_ok(opx_linkset_get_link_name(robot, 1, &name));
    assert_string_equal(name, "<&#x41;\"\tx"); /* read back as written, no reference undone twice */
    opx_linkset_destroy(robot);
}

static void a_file_with_a_nul_byte_is_corrupt(void **state) {
    (void)state;
    const scratch_dir d = make_scratch_dir();
    char path[128];
    snprintf(path, sizeof path, "%s/nul.urdf", d.path);
    static const char text[] = "<robot name=\"r\"><link name=\"a\"/>\0</robot>";
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, sizeof text - 1, f), sizeof text - 1);
    fclose(f);
    opx_linkset *robot = NULL;
    expect_failure(OPX_ERROR_CORRUPT, "opx_linkset_load_urdf_file", "byte offset 32 (0x00) is a NUL character",
                   opx_linkset_load_urdf_file(path, NULL, &robot));
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.srdf_path = write_scratch(&d, "bad.srdf", "<robot name=\"test\"><disable_collisions link1=\"\xF1");
    expect_failure(OPX_ERROR_CORRUPT, LOAD_STRING, "options->srdf_path",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    assert_null(robot);
    remove_scratch_dir(&d);
}

/* ---- Depth ------------------------------------------------------------- */

static void deep_element_nesting_is_corrupt(void **state) {
    (void)state;
    char *xml = nested_urdf(98); /* 100 levels: the limit */
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &robot));
    opx_linkset_destroy(robot);
    free(xml);
    xml = nested_urdf(99);
    expect_load_failure(xml, OPX_ERROR_CORRUPT, "xml: its elements nest 101 deep; the limit is 100");
    free(xml);
    xml = nested_urdf(200000);
    expect_load_failure(xml, OPX_ERROR_CORRUPT, "its elements nest 200002 deep");
    free(xml);
}

static void deep_kinematic_chains_are_corrupt(void **state) {
    (void)state;
    char *xml = chain_urdf(1001); /* l1000 is 1000 joints deep: the limit */
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &robot));
    assert_link_at(robot, 1000, frame_of(0, 0, 10.0, rot_z(0)), 1e-9);
    opx_linkset_destroy(robot);
    free(xml);
    xml = chain_urdf(1002);
    expect_load_failure(xml, OPX_ERROR_CORRUPT,
                        "link 'l1001' (below joint 'j1000') is 1001 joints below the root link; the limit is 1000");
    free(xml);
    xml = chain_urdf(200000);
    expect_load_failure(xml, OPX_ERROR_CORRUPT, "link 'l1001' (below joint 'j1000') is 1001 joints below");
    free(xml);
}

/* ---- Cycles ------------------------------------------------------------ */

static void joint_cycles_are_corrupt_and_named(void **state) {
    (void)state;
    for (int i = 0; i < 3; ++i) /* nothing of a refused load may stay allocated */
        expect_load_failure("<robot name=\"r\"><link name=\"a\"/><joint name=\"j\" type=\"fixed\"><parent link=\"a\"/>"
                            "<child link=\"a\"/></joint></robot>",
                            OPX_ERROR_CORRUPT, "xml: joint 'j' has link 'a' as both parent and child");
    /* A root, and two links each the other's parent. */
    expect_load_failure("<robot name=\"r\"><link name=\"r\"/><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"ja\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint>"
                        "<joint name=\"jb\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "joint 'ja' closes a cycle: link 'a' is its own ancestor");
    /* No root at all. */
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"j1\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"
                        "<joint name=\"j2\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "joint 'j2' closes a cycle: link 'a' is its own ancestor");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>"
                        "<joint name=\"j1\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"
                        "<joint name=\"j2\" type=\"fixed\"><parent link=\"c\"/><child link=\"b\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "link 'b' is the child of two joints, 'j1' and 'j2'");
}

/* ---- stderr ------------------------------------------------------------ */

/* Runs `load` with the process's stderr (fd 2) sent to a scratch file;
 * returns how many bytes were written there. */
static long stderr_bytes_during(void (*load)(void)) {
    fflush(stderr);
    FILE *capture = tmpfile();
    assert_non_null(capture);
    const int saved = dup(2);
    assert_true(saved >= 0);
    assert_true(dup2(fileno(capture), 2) >= 0);
    load();
    fflush(stderr);
    assert_true(dup2(saved, 2) >= 0);
    close(saved);
    struct stat info;
    assert_int_equal(fstat(fileno(capture), &info), 0);
    fclose(capture);
    return (long)info.st_size;
}

/* Parts the library does not read may be broken: they are not checked. */
static const char BROKEN_EXTRAS_URDF[] =
    "<robot name=\"r\"><material name=\"m\"/>"
    "<link name=\"a\"><inertial/><visual><geometry><capsule/></geometry><material name=\"none\"/></visual>"
    "<collision><geometry><sphere radius=\"0.1\"/></geometry></collision></link><link name=\"b\"/>"
    "<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/><calibration rising=\"x\"/>"
    "<dynamics damping=\"x\"/><safety_controller/></joint><transmission name=\"t\"/></robot>";

static void load_accepted_and_refused_urdfs(void) {
    opx_linkset *robot = NULL;
    if (opx_linkset_load_urdf_string(TEST_URDF, NULL, &robot) == OPX_OK) opx_linkset_destroy(robot);
    if (opx_linkset_load_urdf_string(BROKEN_EXTRAS_URDF, NULL, &robot) == OPX_OK) opx_linkset_destroy(robot);
    static const char *const refused[] = {
        "<robot><link name=\"a\"/><link name=\"b\"/></robot>",
        "<robot name=\"r\"><link name=\"a\"/><joint name=\"j\" type=\"fixed\"><parent link=\"a\"/>"
        "<child link=\"a\"/></joint></robot>",
        "<robot name=\"r\" version=\"2.0\"><link name=\"a\"/></robot>",
        "<robot name=\"r\"><link name=\"a\"><collision><geometry><capsule/></geometry></collision></link></robot>",
        "<robot name=\"r\"><link name=\"a\"><collision><geometry/></collision></link></robot>",
        "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" type=\"revolute\">"
        "<parent link=\"a\"/><child link=\"b\"/><limit effort=\"1\"/></joint></robot>",
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; ++i)
        assert_int_not_equal(opx_linkset_load_urdf_string(refused[i], NULL, &robot), OPX_OK);
}

static void loading_writes_nothing_to_stderr(void **state) {
    (void)state;
    assert_int_equal(stderr_bytes_during(load_accepted_and_refused_urdfs), 0);
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(BROKEN_EXTRAS_URDF, NULL, &robot));
    uint32_t count = 0;
    assert_ok(opx_linkset_get_link_count(robot, &count));
    assert_int_equal(count, 2);
    assert_ok(opx_linkset_get_shape_count(robot, 0, &count));
    assert_int_equal(count, 1);
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(text_ending_inside_a_utf8_sequence_is_corrupt),
        cmocka_unit_test(invalid_utf8_inside_the_text_is_corrupt),
        cmocka_unit_test(utf8_names_and_a_leading_byte_order_mark_load),
        cmocka_unit_test(a_file_with_a_nul_byte_is_corrupt),
        cmocka_unit_test(deep_element_nesting_is_corrupt),
        cmocka_unit_test(deep_kinematic_chains_are_corrupt),
        cmocka_unit_test(joint_cycles_are_corrupt_and_named),
        cmocka_unit_test(loading_writes_nothing_to_stderr),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
