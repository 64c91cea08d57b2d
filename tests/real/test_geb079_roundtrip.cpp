// real_geb079_roundtrip: the real OctoMap map geb079.bt (0.08 m) through
// load, statistics, and .bt/.ot round trips in files and memory.
#include "real_support.hpp"

#include <cmath>
#include <cstring>

namespace {

constexpr double kResolution = 0.08;
std::string g_map_path;

opx_octree *load_map() {
    opx_octree *tree = nullptr;
    real::check_ok(opx_octree_load_file(g_map_path.c_str(), nullptr, &tree), "opx_octree_load_file");
    return tree;
}

opx_octree *load_bytes(const std::vector<unsigned char> &bytes) {
    opx_octree *tree = nullptr;
    real::check_ok(opx_octree_load_memory(bytes.data(), bytes.size(), nullptr, &tree), "opx_octree_load_memory");
    return tree;
}

std::vector<unsigned char> save_to_memory(const opx_octree *tree, int32_t format) {
    size_t size = 0;
    assert_int_equal(opx_octree_save_memory(tree, format, nullptr, 0, &size), OPX_ERROR_BUFFER_TOO_SMALL);
    std::vector<unsigned char> bytes(size);
    size_t written = 0;
    real::check_ok(opx_octree_save_memory(tree, format, bytes.data(), bytes.size(), &written), "opx_octree_save_memory");
    assert_int_equal(written, size);
    return bytes;
}

// Same leaves: centres, sizes, depths, classes; probabilities when asked.
void assert_same_leaves(const opx_octree *a, const opx_octree *b, bool compare_probability) {
    std::vector<opx_leaf> la = real::get_leaves(a), lb = real::get_leaves(b);
    assert_int_equal(la.size(), lb.size());
    real::sort_leaves(la);
    real::sort_leaves(lb);
    for (size_t i = 0; i < la.size(); ++i) {
        const opx_leaf &x = la[i], &y = lb[i];
        if (std::memcmp(x.center, y.center, sizeof x.center) != 0 || x.size != y.size || x.depth != y.depth ||
            x.cell_class != y.cell_class || (compare_probability && x.probability != y.probability))
            fail_msg("leaf %zu differs: (%g %g %g) size %g class %d p %.17g vs (%g %g %g) size %g class %d p %.17g", i,
                     x.center[0], x.center[1], x.center[2], x.size, x.cell_class, x.probability, y.center[0],
                     y.center[1], y.center[2], y.size, y.cell_class, y.probability);
    }
}

void assert_multiple_of_resolution(double value, double expected) {
    const double cells = value / kResolution;
    if (std::fabs(value - expected) > 1e-9 || std::fabs(cells - std::round(cells)) * kResolution > 1e-9)
        fail_msg("bound %.12f: expected %.2f, a multiple of %.2f within 1e-9", value, expected, kResolution);
}

void test_counts_and_bounds(void **) {
    opx_octree *tree = load_map();
    const opx_octree_stats s = real::get_stats(tree);
    assert_true(std::fabs(s.resolution - kResolution) < 1e-12);
    assert_int_equal(s.leaves_occupied, 143729);
    assert_int_equal(s.leaves_free, 284415);
    assert_int_equal(s.leaves_uncertain, 0);
    assert_int_equal(s.inner_nodes, 104422);
    assert_int_equal(s.has_occupied, 1);
    const double lo[3] = {-8.00, -7.52, -0.32}, hi[3] = {30.96, 7.44, 2.80};
    for (int axis = 0; axis < 3; ++axis) {
        assert_multiple_of_resolution(s.occupied_min[axis], lo[axis]);
        assert_multiple_of_resolution(s.occupied_max[axis], hi[axis]);
    }
    print_message("geb079: %llu occupied, %llu free leaves, %llu inner nodes, %llu bytes\n",
                  (unsigned long long)s.leaves_occupied, (unsigned long long)s.leaves_free,
                  (unsigned long long)s.inner_nodes, (unsigned long long)s.memory_bytes);
    opx_octree_destroy(tree);
}

// OctoMap's own reader must see the very same leaves, log-odds included.
void test_leaves_match_octomap_reader(void **) {
    octomap::OcTree reference(0.1);
    assert_true(reference.readBinary(g_map_path));
    opx_octree *tree = load_map();
    const std::vector<real::LeafKey> ours = real::leaf_keys_octoprox(tree), theirs = real::leaf_keys_octomap(reference);
    assert_int_equal(ours.size(), theirs.size());
    for (size_t i = 0; i < ours.size(); ++i) {
        if (ours[i].depth != theirs[i].depth || ours[i].min_key != theirs[i].min_key ||
            ours[i].log_odds != theirs[i].log_odds)
            fail_msg("leaf %zu: depth %u key %llx log-odds %.9g vs OctoMap depth %u key %llx log-odds %.9g", i,
                     ours[i].depth, (unsigned long long)ours[i].min_key, ours[i].log_odds, theirs[i].depth,
                     (unsigned long long)theirs[i].min_key, theirs[i].log_odds);
    }
    opx_octree_destroy(tree);
}

void test_load_memory_equals_load_file(void **) {
    opx_octree *from_file = load_map();
    opx_octree *from_memory = load_bytes(real::read_file_bytes(g_map_path));
    assert_same_leaves(from_file, from_memory, true);
    opx_octree_destroy(from_memory);
    opx_octree_destroy(from_file);
}

// The body after "data\n": what OctoMap's writeBinary would write too.
std::vector<unsigned char> bt_body(const std::vector<unsigned char> &bytes) {
    static const char marker[] = "\ndata\n";
    for (size_t i = 0; i + 6 <= bytes.size(); ++i)
        if (std::memcmp(&bytes[i], marker, 6) == 0) return std::vector<unsigned char>(bytes.begin() + i + 6, bytes.end());
    fail_msg("no data line in a .bt image");
    return {};
}

void test_bt_memory_round_trip(void **) {
    opx_octree *original = load_map();
    const std::vector<unsigned char> bytes = save_to_memory(original, OPX_FORMAT_BT);
    // The tree is unchanged by load + save, so the bit stream is too.
    assert_true(bt_body(bytes) == bt_body(real::read_file_bytes(g_map_path)));
    opx_octree *again = load_bytes(bytes);
    assert_same_leaves(original, again, true);
    opx_octree_destroy(again);
    opx_octree_destroy(original);
}

// Saves with OPX_FORMAT_AUTO (picked by the extension), loads the file back.
void round_trip_file(const char *name, int32_t expected_format) {
    const std::string dir = real::make_temp_dir();
    const std::string path = dir + "/" + name;
    opx_octree *original = load_map();
    real::check_ok(opx_octree_save_file(original, path.c_str(), OPX_FORMAT_AUTO), "opx_octree_save_file");
    opx_octree *again = nullptr;
    real::check_ok(opx_octree_load_file(path.c_str(), nullptr, &again), "opx_octree_load_file (saved)");
    assert_same_leaves(original, again, true);
    // The file holds the same bytes as a memory image in the expected format.
    assert_true(real::read_file_bytes(path) == save_to_memory(original, expected_format));
    opx_octree_destroy(again);
    opx_octree_destroy(original);
    real::remove_dir(dir);
}

void test_bt_file_round_trip(void **) { round_trip_file("geb079-copy.bt", OPX_FORMAT_BT); }
void test_ot_file_round_trip(void **) { round_trip_file("geb079-copy.ot", OPX_FORMAT_OT); }

void test_ot_memory_round_trip(void **) {
    opx_octree *original = load_map();
    const std::vector<unsigned char> bytes = save_to_memory(original, OPX_FORMAT_OT);
    opx_octree *again = load_bytes(bytes);  // OPX_FORMAT_AUTO reads the header
    assert_same_leaves(original, again, true);
    // Saving the reloaded map gives the same bytes again.
    assert_true(save_to_memory(again, OPX_FORMAT_OT) == bytes);
    opx_octree_destroy(again);
    opx_octree_destroy(original);
}

}  // namespace

int main() {
    g_map_path = real::require_data_file("maps/geb079.bt");
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counts_and_bounds),
        cmocka_unit_test(test_leaves_match_octomap_reader),
        cmocka_unit_test(test_load_memory_equals_load_file),
        cmocka_unit_test(test_bt_memory_round_trip),
        cmocka_unit_test(test_bt_file_round_trip),
        cmocka_unit_test(test_ot_file_round_trip),
        cmocka_unit_test(test_ot_memory_round_trip),
    };
    return cmocka_run_group_tests_name("real_geb079_roundtrip", tests, nullptr, nullptr);
}
