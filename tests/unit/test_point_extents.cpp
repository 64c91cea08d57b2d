// Point extents of occupied leaves (point_extent.hpp): the packing holds
// every point it is given, extents merge over frames while a cell stays
// occupied and start again after it was freed, survive pruning and
// expansion as boxes holding their points, and never appear on cells that
// were occupied without points (a map read from a file).  A random run
// follows the rules on OctoMap's own map of the same frames.
#include "octree/bounded_tree.hpp"
#include "base/error.hpp"
#include "broadphase/morton.hpp"
#include "octree/octomap_io.hpp"
#include "octree/octoprox_map_io.hpp"
#include "octree/octree_cell.hpp"
#include "octree/point_extent.hpp"
#include "octree/point_slots.hpp"
#include "octree/traverse.hpp"
#include "unit_scenes.hpp"

#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>
#include <vector>

namespace {

using octoprox::Aabb;
using octoprox::CellKey;
using octoprox::OctreeView;
using octoprox::SensorOctree;
using octoprox::Vec3;
namespace extent = octoprox::extent;

// As the query engines decode it: padded by thousands of rounding errors,
// which covers a point on a face of a cube whose edges differ by rounding.
Aabb decoded(const Aabb &cube, uint32_t packed) {
    return octoprox::obstacle_box(cube, packed, octoprox::obstacle_box_pad(cube.hi.x() - cube.lo.x()));
}

bool holds(const Aabb &box, const Vec3 &p) { return (box.lo.array() <= p.array()).all() && (p.array() <= box.hi.array()).all(); }

// The leaf holding `p`, its key and its extent (0 when none).
struct LeafAt {
    CellKey key;
    uint32_t packed = 0;
    float log_odds = 0.0f;
    bool found = false;
};

LeafAt leaf_at(const SensorOctree &tree, const Vec3 &p) {
    LeafAt out;
    octoprox::for_each_leaf(tree.view(), [&](OctreeView::NodeRef node, const CellKey &key) {
        if (holds(octoprox::cell_box(key, tree.params().resolution), p) && !out.found) {
            out.key = key, out.packed = tree.view().point_extent(node);
            out.log_odds = tree.view().log_odds(node), out.found = true;
        }
    });
    return out;
}

octoprox::InsertSettings from(const Vec3 &sensor) {
    octoprox::InsertSettings settings;
    settings.sensor_pose.translation = sensor;
    return settings;
}

// Points given in the map frame, inserted from a sensor at `sensor`.
void insert(SensorOctree &tree, const std::vector<Vec3> &points, const Vec3 &sensor) {
    std::vector<double> xyz;
    for (const Vec3 &p : points) xyz.insert(xyz.end(), {p.x() - sensor.x(), p.y() - sensor.y(), p.z() - sensor.z()});
    unit::insert_xyz(tree, xyz, from(sensor));
}

TEST(PointExtents, PackingHoldsEveryPoint) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const double res = std::pow(10.0, -3.0 + 3.0 * unit(rng));
        CellKey key;
        for (int a = 0; a < 3; ++a) key.key[a] = static_cast<uint16_t>(rng() & 0xFFFF);
        key.depth = 16;
        const Aabb cube = octoprox::cell_box(key, res);
        const extent::PointSlots slots(res);
        Vec3 p;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            // Faces and slot boundaries now and then.
            const double t = i % 5 == 0 ? std::floor(unit(rng) * 33) / 32 : unit(rng);
            p[a] = std::min(std::max(cube.lo[a] + t * (cube.hi[a] - cube.lo[a]), cube.lo[a]), cube.hi[a]);
            slots.of(key.key[a], p[a], lo[a], hi[a]);
        }
        const uint32_t packed = extent::pack(lo, hi);
        ASSERT_TRUE(holds(decoded(cube, packed), p)) << "point " << p.transpose() << " resolution " << res;
        // Up the levels of a pruned leaf and down again, the box still holds the point.
        const uint64_t code = octoprox::morton_encode(key.key[0], key.key[1], key.key[2]);
        uint32_t moved = extent::lift(packed, code, 3);
        for (int level = 2; level >= 0; --level) moved = extent::to_child(moved, int((code >> (3 * level)) & 7));
        ASSERT_TRUE(holds(decoded(cube, moved), p));
    }
}

TEST(PointExtents, MergeOverFramesAndStartAgainAfterFreed) {
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    SensorOctree tree(params);
    const Vec3 sensor(0.05, 0.05, 3.05);
    const Vec3 a(0.01, 0.01, 0.01), b(0.02, 0.09, 0.03), c(0.09, 0.09, 0.09);
    insert(tree, {a}, sensor);
    LeafAt leaf = leaf_at(tree, a);
    ASSERT_TRUE(leaf.found && extent::valid(leaf.packed));
    const Aabb cube = octoprox::cell_box(leaf.key, params.resolution);
    EXPECT_TRUE(holds(decoded(cube, leaf.packed), a));
    EXPECT_FALSE(holds(decoded(cube, leaf.packed), c)) << "the extent is the point's, not the cube";
    insert(tree, {b}, sensor);
    leaf = leaf_at(tree, a);
    EXPECT_TRUE(holds(decoded(cube, leaf.packed), a) && holds(decoded(cube, leaf.packed), b)) << "merged";
    // Rays through the cell to a point below it free the cell.
    for (int i = 0; i < 6; ++i) insert(tree, {Vec3(0.05, 0.05, -1.05)}, sensor);
    leaf = leaf_at(tree, a);
    ASSERT_TRUE(leaf.found);
    EXPECT_LT(leaf.log_odds, 0.0f);
    EXPECT_EQ(leaf.packed, 0u) << "a freed cell keeps no extent";
    // Hit again until occupied: the extent is the new points' alone.
    for (int i = 0; i < 8; ++i) insert(tree, {c}, sensor);
    leaf = leaf_at(tree, c);
    ASSERT_GE(leaf.log_odds, 0.0f);
    ASSERT_TRUE(extent::valid(leaf.packed));
    EXPECT_TRUE(holds(decoded(cube, leaf.packed), c));
    EXPECT_FALSE(holds(decoded(cube, leaf.packed), a)) << "points from before the cell was freed";
    EXPECT_EQ(tree.stats().leaves_with_extent, 2u) << "c's cell and the cell of the point below";
}

TEST(PointExtents, MapsFromFilesKeepWholeCells) {
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    SensorOctree tree(params);
    const Vec3 sensor(0.05, 0.05, 3.05), p(0.01, 0.01, 0.01), q(1.01, 0.01, 0.01);
    insert(tree, {p}, sensor);
    const std::string bytes = octoprox::write_map_file_bytes(tree, octoprox::MapFormat::kBinary);
    std::unique_ptr<SensorOctree> loaded = octoprox::read_map_file_bytes(bytes, params);
    EXPECT_EQ(loaded->stats().leaves_with_extent, 0u);
    // New points in a cell occupied without points: still the whole cube.
    insert(*loaded, {Vec3(0.02, 0.02, 0.02)}, sensor);
    EXPECT_EQ(leaf_at(*loaded, p).packed, 0u);
    // In unobserved space they make an extent.
    insert(*loaded, {q}, sensor);
    EXPECT_TRUE(extent::valid(leaf_at(*loaded, q).packed));
}

// Eight clamped cells prune into one leaf; when one of them came from a
// file (no points), the leaf is the whole cube: an extent of the other
// seven would shrink the obstacle and let a robot through the eighth.
TEST(PointExtents, APrunedLeafWithACellFromAFileIsTheWholeCube) {
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    const Vec3 sensor(0.1, 0.1, 3.0), from_file(0.01, 0.01, 0.01);
    SensorOctree first(params);
    insert(first, {from_file}, sensor);
    const std::string bytes = octoprox::write_map_file_bytes(first, octoprox::MapFormat::kBinary);
    std::unique_ptr<SensorOctree> tree = octoprox::read_map_file_bytes(bytes, params);
    std::vector<Vec3> others;  // a point near the far corner of each of the seven other cells
    for (int i = 1; i < 8; ++i)
        others.push_back(Vec3(0.1 * (i & 1), 0.1 * ((i >> 1) & 1), 0.1 * (i >> 2)) + Vec3(0.08, 0.08, 0.08));
    // Ten frames clamp them all (the cell above the file's one starts free:
    // the file's ray crossed it).
    for (int i = 0; i < 10; ++i) insert(*tree, others, sensor);
    const LeafAt leaf = leaf_at(*tree, from_file);
    ASSERT_EQ(leaf.key.depth, 15) << "the eight cells prune";
    EXPECT_EQ(leaf.packed, 0u) << "the leaf keeps no extent: it is the whole cube";
    EXPECT_EQ(tree->stats().leaves_with_extent, 0u);
}

TEST(PointExtents, PrunedAndExpandedLeavesHoldTheirPoints) {
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    SensorOctree tree(params);
    const Vec3 sensor(0.1, 0.1, 3.0);
    // A 2x2x2 block of cells, each with two points, hit until clamped: it
    // prunes into one leaf of 0.2 m.
    std::vector<Vec3> block;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner(0.1 * (i & 1), 0.1 * ((i >> 1) & 1), 0.1 * (i >> 2));
        block.push_back(corner + Vec3(0.03, 0.04, 0.05));
        block.push_back(corner + Vec3(0.06, 0.02, 0.07));
    }
    for (int i = 0; i < 6; ++i) insert(tree, block, sensor);
    LeafAt leaf = leaf_at(tree, block[0]);
    ASSERT_EQ(leaf.key.depth, 15) << "the block prunes";
    ASSERT_TRUE(extent::valid(leaf.packed));
    const Aabb cube = octoprox::cell_box(leaf.key, params.resolution);
    for (const Vec3 &p : block) EXPECT_TRUE(holds(decoded(cube, leaf.packed), p));
    EXPECT_FALSE(holds(decoded(cube, leaf.packed), cube.lo)) << "the corner holds no point";
    // A ray through one of the cells expands the leaf; every cell still occupied holds its points.
    insert(tree, {Vec3(0.05, 0.15, -2.0)}, Vec3(0.05, 0.15, 3.0));
    for (const Vec3 &p : block) {
        const LeafAt cell = leaf_at(tree, p);
        ASSERT_TRUE(cell.found);
        if (cell.log_odds < 0.0f) continue;
        ASSERT_TRUE(extent::valid(cell.packed));
        EXPECT_EQ(cell.key.depth, 16);
        EXPECT_TRUE(holds(decoded(octoprox::cell_box(cell.key, params.resolution), cell.packed), p));
    }
}

// Random frames from moving sensors; after each, every leaf's extent holds
// the points its cells took since they last became occupied, following
// the rules on OctoMap's map of the same frames.
TEST(PointExtents, RandomFramesFollowTheRules) {
    octoprox::OctreeParams params;
    params.resolution = 0.05;
    SensorOctree tree(params);
    octomap::OcTree reference(params.resolution);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    using Key = std::tuple<int, int, int>;
    std::map<Key, Aabb> since_occupied;  // points per finest cell with an extent
    for (int frame = 0; frame < 40; ++frame) {
        const Vec3 sensor(-1.0 + 2.0 * unit(rng), -1.0 + 2.0 * unit(rng), 1.5);
        std::vector<Vec3> points;
        for (int i = 0; i < 300; ++i) points.emplace_back(0.3 * unit(rng), 0.3 * unit(rng), 0.3 * unit(rng));
        std::map<Key, Aabb> frame_boxes;
        std::map<Key, float> before;
        octomap::Pointcloud cloud;
        for (const Vec3 &p : points) {
            const octomap::point3d f(float(p.x()), float(p.y()), float(p.z()));
            cloud.push_back(f - octomap::point3d(float(sensor.x()), float(sensor.y()), float(sensor.z())));
            const octomap::OcTreeKey k = reference.coordToKey(f);
            const Key key(k[0], k[1], k[2]);
            frame_boxes[key].grow(p);
            const octomap::OcTreeNode *node = reference.search(k);
            before[key] = node ? node->getLogOdds() : -1e9f;
        }
        std::map<Key, float> others_before;
        for (const auto &entry : since_occupied) {
            const auto &[x, y, z] = entry.first;
            const octomap::OcTreeNode *node = reference.search(octomap::OcTreeKey(x, y, z));
            others_before[entry.first] = node ? node->getLogOdds() : -1e9f;
        }
        const octomap::point3d origin(float(sensor.x()), float(sensor.y()), float(sensor.z()));
        reference.insertPointCloud(cloud, octomap::point3d(0, 0, 0), octomap::pose6d(origin, octomath::Quaternion()));
        insert(tree, points, sensor);
        // The rules: freed cells forget; hit cells merge, or start when they were not occupied.
        for (auto it = since_occupied.begin(); it != since_occupied.end();) {
            const auto &[x, y, z] = it->first;
            const float after = reference.search(octomap::OcTreeKey(x, y, z))->getLogOdds();
            const bool missed = !frame_boxes.count(it->first) && after < others_before[it->first];
            it = missed && after < 0.0f ? since_occupied.erase(it) : std::next(it);
        }
        for (const auto &[key, box] : frame_boxes) {
            auto kept = since_occupied.find(key);
            if (kept != since_occupied.end()) kept->second.grow(box);
            else if (before[key] < 0.0f) since_occupied[key] = box;
        }
        // Every leaf with an extent holds the points of its cells.
        octoprox::for_each_leaf(tree.view(), [&](OctreeView::NodeRef node, const CellKey &cell) {
            const uint32_t packed = tree.view().point_extent(node);
            if (!extent::valid(packed)) return;
            const Aabb box = decoded(octoprox::cell_box(cell, params.resolution), packed);
            const int width = cell.width_in_cells();
            for (const auto &[key, points_box] : since_occupied) {
                const auto &[x, y, z] = key;
                if (x < cell.key[0] || x >= cell.key[0] + width || y < cell.key[1] || y >= cell.key[1] + width ||
                    z < cell.key[2] || z >= cell.key[2] + width)
                    continue;
                EXPECT_TRUE(holds(box, points_box.lo) && holds(box, points_box.hi))
                    << "frame " << frame << ": a leaf of depth " << cell.depth << " misses its points: key " << x
                    << " " << y << " " << z << " points " << points_box.lo.transpose() << " / "
                    << points_box.hi.transpose() << " extent " << box.lo.transpose() << " / " << box.hi.transpose()
                    << " log-odds " << tree.view().log_odds(node);
            }
        });
    }
    EXPECT_GT(tree.stats().leaves_with_extent, 0u);
}

}  // namespace

namespace {

TEST(PointExtents, OctoProxMapFilesKeepThem) {
    octoprox::OctreeParams params;
    params.resolution = 0.05;
    SensorOctree tree(params);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec3> points;
    for (int i = 0; i < 500; ++i) points.emplace_back(unit(rng), unit(rng), 0.2 * unit(rng));
    insert(tree, points, Vec3(0.5, 0.5, 2.0));
    const std::string bytes = octoprox::write_octoprox_map_bytes(tree);
    ASSERT_TRUE(octoprox::is_octoprox_map(bytes));
    std::unique_ptr<SensorOctree> loaded = octoprox::read_octoprox_map_bytes(bytes, params);
    EXPECT_EQ(loaded->leaf_extents(), tree.leaf_extents());
    EXPECT_GT(loaded->stats().leaves_with_extent, 0u);
    EXPECT_EQ(loaded->stats().leaves_with_extent, tree.stats().leaves_with_extent);
    // Cut anywhere, or with an extent's bits spoiled: corrupt, never a map.
    for (size_t cut : {size_t(0), size_t(10), bytes.size() / 2, bytes.size() - 1})
        EXPECT_THROW(octoprox::read_octoprox_map_bytes(bytes.substr(0, cut), params), octoprox::ApiError) << cut;
    std::string spoiled = bytes;
    spoiled[spoiled.size() - 1] = char(0x40);  // bit 30 of the last extent
    EXPECT_THROW(octoprox::read_octoprox_map_bytes(spoiled, params), octoprox::ApiError);
    EXPECT_THROW(octoprox::read_octoprox_map_bytes(bytes + "xxxx", params), octoprox::ApiError);
}

}  // namespace

namespace {

// A surface sampled every 5 mm makes extents as thin as the samples, not as
// thick as the cells: for an axis-aligned plane one slot (res / 32) across
// the plane, and together the boxes cover the sampled patch.
TEST(PointExtents, ASampledPlaneIsOneSlotThick) {
    octoprox::OctreeParams params;
    params.resolution = 0.02;
    SensorOctree tree(params);
    std::vector<Vec3> plane;
    const double z = 0.3137;
    for (double x = 0.0; x <= 0.5; x += 0.005)
        for (double y = 0.0; y <= 0.4; y += 0.005) plane.emplace_back(x, y, z);
    octoprox::InsertSettings settings;
    settings.raycast = false;
    std::vector<double> xyz;
    for (const Vec3 &p : plane) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    unit::insert_xyz(tree, xyz, settings);
    double area = 0.0;
    size_t leaves = 0;
    octoprox::for_each_leaf(tree.view(), [&](OctreeView::NodeRef node, const CellKey &cell) {
        if (tree.view().log_odds(node) < 0.0f) return;
        ++leaves;
        const uint32_t packed = tree.view().point_extent(node);
        ASSERT_TRUE(extent::valid(packed));
        const Aabb box = decoded(octoprox::cell_box(cell, params.resolution), packed);
        EXPECT_LE(box.hi.z() - box.lo.z(), params.resolution / 32 + 1e-8) << "thicker than a slot and its padding";
        EXPECT_TRUE(box.lo.z() <= z && z <= box.hi.z());
        area += (box.hi.x() - box.lo.x()) * (box.hi.y() - box.lo.y());
    });
    EXPECT_EQ(tree.stats().leaves_with_extent, leaves);
    // The boxes cover the patch but for the gaps between samples at cell
    // borders (less than one spacing, 5 mm of every 20), and overhang by
    // no more than a slot.
    EXPECT_GT(area, 0.5 * 0.4 * (1 - 0.005 / 0.02) * (1 - 0.005 / 0.02));
    EXPECT_LT(area, 0.52 * 0.42);
}

}  // namespace
