/*
 * opx_octree_save_file and _load_file: format by extension, files equal to
 * the memory images, arguments, missing and unwritable paths.  Files are
 * written in the working directory (ctest: the build directory).
 */
#define _POSIX_C_SOURCE 200809L /* setrlimit, SIGXFSZ, mkdir */
#include "opx_test.h"

#include <dirent.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#define NOT_NULL_SENTINEL ((opx_octree *)(uintptr_t)0x10)
#define MISSING_DIR "/nonexistent-octoprox-test-dir"

static void write_whole_file(const char *path, const unsigned char *data, size_t size) {
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, size, f), size);
    assert_int_equal(fclose(f), 0);
}

/* Files of the working directory whose name starts with prefix. */
static int files_starting(const char *prefix) {
    struct dirent *entry;
    int count = 0;
    DIR *dir = opendir(".");
    assert_non_null(dir);
    while ((entry = readdir(dir)) != NULL)
        if (strncmp(entry->d_name, prefix, strlen(prefix)) == 0) ++count;
    closedir(dir);
    return count;
}

static int file_exists(const char *path) {
    FILE *f = fopen(path, "rb");
    if (f != NULL) fclose(f);
    return f != NULL;
}

/* Saves the sample map to path, checks the file holds the same bytes as
 * save_memory in `expected_format`, and loads it back. */
static void check_file_round_trip(const char *path, int32_t format, int32_t expected_format) {
    opx_octree *tree = new_sample_map();
    assert_ok(opx_octree_save_file(tree, path, format));
    byte_buffer file = read_whole_file(path);
    byte_buffer memory = save_to_memory(tree, expected_format);
    assert_int_equal(file.size, memory.size);
    assert_memory_equal(file.data, memory.data, memory.size);

    opx_octree *loaded = NULL;
    assert_ok(opx_octree_load_file(path, NULL, &loaded));
    assert_non_null(loaded);
    const opx_octree_stats a = stats_of(loaded), b = stats_of(tree);
    assert_int_equal(a.leaves_occupied, b.leaves_occupied);
    assert_int_equal(a.leaves_free, b.leaves_free);
    assert_memory_equal(a.known_max, b.known_max, sizeof a.known_max);
    assert_true(a.resolution == RES);
    opx_octree_destroy(loaded);
    opx_octree_destroy(tree);
    free(file.data);
    free(memory.data);
    remove(path);
}

static void save_auto_picks_format_by_extension(void **state) {
    (void)state;
    check_file_round_trip("c_octree_files_auto.bt", OPX_FORMAT_AUTO, OPX_FORMAT_BT);
    check_file_round_trip("c_octree_files_auto.ot", OPX_FORMAT_AUTO, OPX_FORMAT_OT);
}

static void explicit_format_wins_over_extension(void **state) {
    (void)state;
    check_file_round_trip("c_octree_files_full.map", OPX_FORMAT_OT, OPX_FORMAT_OT);
    check_file_round_trip("c_octree_files_binary.ot", OPX_FORMAT_BT, OPX_FORMAT_BT);
}

static void ot_file_keeps_probabilities(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    const char *path = "c_octree_files_prob.ot";
    assert_ok(opx_octree_save_file(tree, path, OPX_FORMAT_AUTO));
    opx_octree *loaded = NULL;
    assert_ok(opx_octree_load_file(path, NULL, &loaded));
    assert_same_known_leaves(loaded, tree);
    opx_octree_destroy(loaded);
    opx_octree_destroy(tree);
    remove(path);
}

/* .opx keeps every log-odds and the occupied cells' point extents; the
 * same map as .ot keeps the log-odds only. */
static void opx_file_keeps_point_extents(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    opx_octree_stats before = OPX_OCTREE_STATS_INIT, opx = OPX_OCTREE_STATS_INIT, ot = OPX_OCTREE_STATS_INIT;
    assert_ok(opx_octree_get_stats(tree, &before));
    assert_true(before.leaves_with_extent > 0);
    assert_ok(opx_octree_save_file(tree, "c_octree_files_extents.opx", OPX_FORMAT_AUTO));
    assert_ok(opx_octree_save_file(tree, "c_octree_files_extents.ot", OPX_FORMAT_AUTO));
    opx_octree *from_opx = NULL, *from_ot = NULL;
    assert_ok(opx_octree_load_file("c_octree_files_extents.opx", NULL, &from_opx));
    assert_ok(opx_octree_load_file("c_octree_files_extents.ot", NULL, &from_ot));
    assert_ok(opx_octree_get_stats(from_opx, &opx));
    assert_ok(opx_octree_get_stats(from_ot, &ot));
    assert_int_equal(opx.leaves_with_extent, before.leaves_with_extent);
    assert_int_equal(ot.leaves_with_extent, 0);
    assert_same_known_leaves(from_opx, tree);
    opx_octree_destroy(from_opx);
    opx_octree_destroy(from_ot);
    opx_octree_destroy(tree);
    remove("c_octree_files_extents.opx");
    remove("c_octree_files_extents.ot");
}

static void save_file_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    const char *fn = "opx_octree_save_file";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree",
                   opx_octree_save_file(NULL, "c_octree_files_x.bt", OPX_FORMAT_AUTO));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "path",
                   opx_octree_save_file(tree, NULL, OPX_FORMAT_BT));
    const int32_t bad[] = {-1, 4, 42};
    for (size_t i = 0; i < 3; ++i)
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "format",
                       opx_octree_save_file(tree, "c_octree_files_x.bt", bad[i]));
    assert_false(file_exists("c_octree_files_x.bt"));
    /* AUTO cannot pick a format for an unknown extension. */
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "path",
                   opx_octree_save_file(tree, "c_octree_files_x.txt", OPX_FORMAT_AUTO));
    assert_false(file_exists("c_octree_files_x.txt"));
    opx_octree_destroy(tree);
}

static void save_file_into_missing_directory_is_io_error(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    expect_failure(OPX_ERROR_IO, "opx_octree_save_file", MISSING_DIR,
                   opx_octree_save_file(tree, MISSING_DIR "/map.bt", OPX_FORMAT_AUTO));
    opx_octree_destroy(tree);
}

static void expect_load_file_fails(const char *path, const opx_octree_options *options,
                                   opx_status expected, const char *argument) {
    opx_octree *out = NOT_NULL_SENTINEL;
    expect_failure(expected, "opx_octree_load_file", argument,
                   opx_octree_load_file(path, options, &out));
    assert_null(out);
}

static void load_missing_file_is_io_error(void **state) {
    (void)state;
    expect_load_file_fails(MISSING_DIR "/map.bt", NULL, OPX_ERROR_IO, MISSING_DIR);
    expect_load_file_fails("c_octree_files_does_not_exist.ot", NULL, OPX_ERROR_IO,
                           "c_octree_files_does_not_exist.ot");
}

static void load_file_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    const char *path = "c_octree_files_args.bt";
    assert_ok(opx_octree_save_file(tree, path, OPX_FORMAT_AUTO));
    expect_load_file_fails(NULL, NULL, OPX_ERROR_INVALID_ARGUMENT, "path");
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_load_file", "out",
                   opx_octree_load_file(path, NULL, NULL));
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.struct_size = 0;
    expect_load_file_fails(path, &options, OPX_ERROR_VERSION, "struct_size");
    options = (opx_octree_options)OPX_OCTREE_OPTIONS_INIT;
    options.free_threshold = 0.9;
    expect_load_file_fails(path, &options, OPX_ERROR_INVALID_ARGUMENT, "free_threshold");
    opx_octree_destroy(tree);
    remove(path);
}

/* A file cut in the middle of its data is corrupt, not an I/O error. */
static void load_truncated_file_is_corrupt(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer ot = save_to_memory(tree, OPX_FORMAT_OT);
    const char *path = "c_octree_files_truncated.ot";
    write_whole_file(path, ot.data, ot.size - 3);
    expect_load_file_fails(path, NULL, OPX_ERROR_CORRUPT, NULL);
    write_whole_file(path, ot.data, 0);
    expect_load_file_fails(path, NULL, OPX_ERROR_CORRUPT, NULL);
    remove(path);
    free(ot.data);
    opx_octree_destroy(tree);
}

static void load_directory_is_io_error(void **state) {
    (void)state;
    const char *dir = "c_octree_files_dir.bt";
    mkdir(dir, 0700);
    expect_load_file_fails(dir, NULL, OPX_ERROR_IO, "directory");
    rmdir(dir);
}

/* A save that cannot be written whole (here: past the process's file-size
 * limit) fails with an I/O error and leaves no temporary file behind; the
 * map saved before at the path is kept as it was. */
static void failed_save_leaves_no_temporary_file(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map(), *empty = new_tree(RES);
    const char *path = "c_octree_files_limited.bt";
    assert_ok(opx_octree_save_file(empty, path, OPX_FORMAT_AUTO));
    struct rlimit saved;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &saved), 0);
    void (*previous)(int) = signal(SIGXFSZ, SIG_IGN);
    struct rlimit tiny = saved;
    tiny.rlim_cur = 16;
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &tiny), 0);
    const opx_status status = opx_octree_save_file(tree, path, OPX_FORMAT_AUTO);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &saved), 0);
    signal(SIGXFSZ, previous);
    assert_status(status, OPX_ERROR_IO);
    assert_non_null(strstr(opx_last_error(), "opx_octree_save_file"));
    byte_buffer kept = read_whole_file(path), expected = save_to_memory(empty, OPX_FORMAT_BT);
    assert_int_equal(kept.size, expected.size);
    assert_memory_equal(kept.data, expected.data, expected.size);
    assert_int_equal(files_starting(".c_octree_files_limited.bt."), 0);
    free(kept.data), free(expected.data);
    remove(path);
    opx_octree_destroy(empty);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(save_auto_picks_format_by_extension),
        cmocka_unit_test(explicit_format_wins_over_extension),
        cmocka_unit_test(ot_file_keeps_probabilities),
        cmocka_unit_test(opx_file_keeps_point_extents),
        cmocka_unit_test(save_file_rejects_bad_arguments),
        cmocka_unit_test(save_file_into_missing_directory_is_io_error),
        cmocka_unit_test(load_missing_file_is_io_error),
        cmocka_unit_test(load_file_rejects_bad_arguments),
        cmocka_unit_test(load_truncated_file_is_corrupt),
        cmocka_unit_test(load_directory_is_io_error),
        cmocka_unit_test(failed_save_leaves_no_temporary_file),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
