/*
 * Saves and loads on hostile paths: a save is written to a fresh
 * temporary and renamed (never through a link planted where a temporary
 * might be, never leaving one behind), saves of one path running at once
 * leave one whole map, and a load reads no more than the header allows
 * (endless devices and pipes are refused at once).  Files go to a folder
 * of the working directory (ctest: the build directory).
 */
#define _POSIX_C_SOURCE 200809L /* fork, mkfifo, symlink, clock_gettime */
#include "opx_test.h"

#include "atomic_file.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define DIR_NAME "c_octree_file_safety.d"
#define ROUNDS 8
#define SAVES_PER_ROUND 4

/* DIR_NAME/name, in one of 4 buffers used in turn. */
static const char *in_dir(const char *name) {
    static char paths[4][512];
    static int slot = 0;
    char *path = paths[slot++ % 4];
    mkdir(DIR_NAME, 0700);
    snprintf(path, sizeof paths[0], DIR_NAME "/%s", name);
    return path;
}

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static int same_bytes(const byte_buffer *a, const byte_buffer *b) {
    return a->size == b->size && memcmp(a->data, b->data, a->size) == 0;
}

/* Entries of DIR_NAME whose name starts with ".NAME." (the temporaries of
 * NAME), or with "NAME." when hidden is 0. */
static int files_starting(const char *name, int hidden) {
    char prefix[256];
    struct dirent *entry;
    int count = 0;
    DIR *dir = opendir(DIR_NAME);
    assert_non_null(dir);
    snprintf(prefix, sizeof prefix, "%s%s.", hidden ? "." : "", name);
    while ((entry = readdir(dir)) != NULL)
        if (strncmp(entry->d_name, prefix, strlen(prefix)) == 0) ++count;
    closedir(dir);
    return count;
}

/* A second map, unlike new_sample_map()'s. */
static opx_octree *other_map(void) {
    opx_octree *tree = new_sample_map();
    insert_one_ray(tree, -3.0, 2.0, 1.0);
    return tree;
}

/* A link planted where a predictable temporary would be is neither
 * followed nor touched, nor is any other file beside the map. */
static void save_never_writes_through_a_planted_link(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    const char *victim = in_dir("victim.txt");
    const char *map = in_dir("planted.bt");
    char link_path[512];
    write_text(victim, "keep me\n");
    snprintf(link_path, sizeof link_path, "%s.tmp", map);
    unlink(link_path);
    assert_int_equal(symlink("victim.txt", link_path), 0);
    assert_ok(opx_octree_save_file(tree, map, OPX_FORMAT_AUTO));
    byte_buffer kept = read_whole_file(victim);
    assert_int_equal(kept.size, 8);
    assert_memory_equal(kept.data, "keep me\n", 8);
    struct stat status;
    assert_int_equal(lstat(link_path, &status), 0);
    assert_true(S_ISLNK(status.st_mode));
    opx_octree *loaded = NULL;
    assert_ok(opx_octree_load_file(map, NULL, &loaded));
    assert_int_equal(files_starting("planted.bt", 1), 0);
    free(kept.data);
    opx_octree_destroy(loaded);
    opx_octree_destroy(tree);
}

/* The helper refuses to create its temporary through a link, dangling or
 * not: the file the link names is neither made nor changed. */
static void exclusive_create_refuses_links(void **state) {
    (void)state;
    char victim[512], link_path[512], dangling[512], made[512];
    snprintf(victim, sizeof victim, "%s", in_dir("victim2.txt"));
    snprintf(link_path, sizeof link_path, "%s", in_dir("link_to_victim"));
    snprintf(dangling, sizeof dangling, "%s", in_dir("dangling_link"));
    snprintf(made, sizeof made, "%s", in_dir("made_by_link"));
    write_text(victim, "keep me\n");
    unlink(link_path), unlink(dangling), unlink(made);
    assert_int_equal(symlink("victim2.txt", link_path), 0);
    assert_int_equal(symlink("made_by_link", dangling), 0);
    errno = 0;
    assert_int_equal(atomic_file_create_exclusive(link_path), -1);
    assert_int_equal(errno, EEXIST);
    assert_int_equal(atomic_file_create_exclusive(dangling), -1);
    assert_int_equal(access(made, F_OK), -1);
    byte_buffer kept = read_whole_file(victim);
    assert_int_equal(kept.size, 8);
    free(kept.data);
}

/* A map given through a link: the file it points to is replaced, the link
 * stays a link. */
static void save_through_a_link_keeps_the_link(void **state) {
    (void)state;
    opx_octree *first = new_sample_map(), *second = other_map();
    const char *real = in_dir("real.ot");
    const char *link_path = in_dir("alias.ot");
    assert_ok(opx_octree_save_file(first, real, OPX_FORMAT_AUTO));
    unlink(link_path);
    assert_int_equal(symlink("real.ot", link_path), 0);
    assert_ok(opx_octree_save_file(second, link_path, OPX_FORMAT_AUTO));
    struct stat status;
    assert_int_equal(lstat(link_path, &status), 0);
    assert_true(S_ISLNK(status.st_mode));
    byte_buffer saved = read_whole_file(real), expected = save_to_memory(second, OPX_FORMAT_OT);
    assert_true(same_bytes(&saved, &expected));
    assert_int_equal(files_starting("real.ot", 1) + files_starting("alias.ot", 1), 0);
    free(saved.data), free(expected.data);
    opx_octree_destroy(first), opx_octree_destroy(second);
}

static void save_repeatedly(const opx_octree *tree, const char *path) {
    int i;
    for (i = 0; i < SAVES_PER_ROUND; ++i)
        if (opx_octree_save_file(tree, path, OPX_FORMAT_AUTO) != OPX_OK) _exit(1);
    _exit(0);
}

/* Two processes saving one path at once: every round ends with a map that
 * loads and equals one of the two, and no temporary is left. */
static void concurrent_saves_leave_one_whole_map(void **state) {
    (void)state;
    opx_octree *maps[2] = {new_sample_map(), other_map()};
    byte_buffer images[2] = {save_to_memory(maps[0], OPX_FORMAT_BT), save_to_memory(maps[1], OPX_FORMAT_BT)};
    const char *path = in_dir("shared.bt");
    int round, p;
    assert_false(same_bytes(&images[0], &images[1]));
    for (round = 0; round < ROUNDS; ++round) {
        pid_t children[2];
        for (p = 0; p < 2; ++p) {
            children[p] = fork();
            assert_true(children[p] >= 0);
            if (children[p] == 0) save_repeatedly(maps[p], path);
        }
        for (p = 0; p < 2; ++p) {
            int status = 0;
            assert_int_equal(waitpid(children[p], &status, 0), children[p]);
            assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        }
        byte_buffer saved = read_whole_file(path);
        assert_true(same_bytes(&saved, &images[0]) || same_bytes(&saved, &images[1]));
        opx_octree *loaded = NULL;
        assert_ok(opx_octree_load_file(path, NULL, &loaded));
        opx_octree_destroy(loaded);
        free(saved.data);
    }
    assert_int_equal(files_starting("shared.bt", 1), 0);
    free(images[0].data), free(images[1].data);
    opx_octree_destroy(maps[0]), opx_octree_destroy(maps[1]);
}

/* Seconds opx_octree_load_file takes to refuse the device as corrupt. */
static double seconds_to_refuse(const char *device) {
    struct timespec start, end;
    opx_octree *out = NULL;
    clock_gettime(CLOCK_MONOTONIC, &start);
    expect_failure(OPX_ERROR_CORRUPT, "opx_octree_load_file", NULL, opx_octree_load_file(device, NULL, &out));
    clock_gettime(CLOCK_MONOTONIC, &end);
    assert_null(out);
    return (double)(end.tv_sec - start.tv_sec) + 1e-9 * (double)(end.tv_nsec - start.tv_nsec);
}

/* Devices that never end are refused from their first bytes. */
static void endless_devices_are_refused_at_once(void **state) {
    (void)state;
    assert_true(seconds_to_refuse("/dev/zero") < 1.0);
    assert_true(seconds_to_refuse("/dev/urandom") < 1.0);
}

/* A regular file longer than its header's node count allows is refused
 * before its body is read. */
static void a_body_longer_than_the_header_allows_is_refused(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer bt = save_to_memory(tree, OPX_FORMAT_BT);
    const char *path = in_dir("long.bt");
    FILE *f = fopen(path, "wb");
    opx_octree *out = NULL;
    assert_non_null(f);
    assert_int_equal(fwrite(bt.data, 1, bt.size, f), bt.size);
    assert_int_equal(fseek(f, 1L << 24, SEEK_CUR), 0); /* a 16 MiB hole */
    fputc('x', f);
    assert_int_equal(fclose(f), 0);
    expect_failure(OPX_ERROR_CORRUPT, "opx_octree_load_file", "header allows",
                   opx_octree_load_file(path, NULL, &out));
    assert_null(out);
    free(bt.data);
    opx_octree_destroy(tree);
}

/* A full map of another tree type (a ColorOcTree's nodes are longer than
 * an OcTree's 5 bytes) is unsupported, not taken as too long. */
static void another_tree_type_is_unsupported_whatever_its_length(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map(), *out = NULL;
    byte_buffer ot = save_to_memory(tree, OPX_FORMAT_OT);
    byte_buffer color = replace_header_line(&ot, "id ", "id ColorOcTree");
    const char *path = in_dir("color.ot");
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(color.data, 1, color.size, f), color.size);
    for (size_t i = 0; i < color.size; ++i) fputc(0, f); /* three more bytes a node, and more */
    assert_int_equal(fclose(f), 0);
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_octree_load_file", "ColorOcTree", opx_octree_load_file(path, NULL, &out));
    assert_null(out);
    free(ot.data), free(color.data);
    opx_octree_destroy(tree);
}

/* Writes a map's header and then zeros into the pipe until the reader
 * goes away. */
static void serve_endless_body(const char *fifo, const byte_buffer *map) {
    static const unsigned char zeros[4096];
    const int out = open(fifo, O_WRONLY);
    signal(SIGPIPE, SIG_IGN);
    if (out < 0 || write(out, map->data, body_offset(map)) < 0) _exit(1);
    while (write(out, zeros, sizeof zeros) > 0) {
    }
    _exit(0);
}

/* A pipe with a good header and an endless body: read up to the bound,
 * then refused (the writer is left to see the pipe close). */
static void an_endless_pipe_is_read_up_to_its_bound(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map(), *out = NULL;
    byte_buffer bt = save_to_memory(tree, OPX_FORMAT_BT);
    const char *fifo = in_dir("endless.bt");
    int status = 0;
    pid_t writer;
    unlink(fifo);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    writer = fork();
    assert_true(writer >= 0);
    if (writer == 0) serve_endless_body(fifo, &bt);
    expect_failure(OPX_ERROR_CORRUPT, "opx_octree_load_file", "header allows",
                   opx_octree_load_file(fifo, NULL, &out));
    assert_null(out);
    assert_int_equal(waitpid(writer, &status, 0), writer);
    unlink(fifo);
    free(bt.data);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(save_never_writes_through_a_planted_link),
        cmocka_unit_test(exclusive_create_refuses_links),
        cmocka_unit_test(save_through_a_link_keeps_the_link),
        cmocka_unit_test(concurrent_saves_leave_one_whole_map),
        cmocka_unit_test(endless_devices_are_refused_at_once),
        cmocka_unit_test(a_body_longer_than_the_header_allows_is_refused),
        cmocka_unit_test(an_endless_pipe_is_read_up_to_its_bound),
        cmocka_unit_test(another_tree_type_is_unsupported_whatever_its_length),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
