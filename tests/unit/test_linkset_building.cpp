// Adding shapes one at a time places only the new shape and leaves the
// BVH's topology stale until the first reader of tree() rebuilds it, once,
// from any number of threads.  Checked: the placed shapes keep link-major
// order (also when a shape goes to an earlier link), their boxes equal a
// full rebuild's (a copy), the tree holds each exactly once and bounds
// them all, before and after poses, and concurrent first readers agree.
#include "robot/linkset.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace {

using namespace octoprox;

ShapeDef sphere(double radius, double x) {
    ShapeDef def;
    def.kind = ShapeKind::kSphere;
    def.radius = radius;
    def.local.translation = Vec3(x, 0.0, 0.0);
    return def;
}

bool contains(const Aabb &outer, const Aabb &inner) {
    return (outer.lo.array() <= inner.lo.array()).all() && (inner.hi.array() <= outer.hi.array()).all();
}

// Items of the tree's leaves, each counted; every node bounds its leaves.
// Also the layout (aabb_tree.hpp): parents before children, and leaves()
// lists the leaves left to right, as the distance search takes them.
std::vector<int> leaf_counts(const AabbTree &tree, size_t items) {
    std::vector<int> seen(items, 0);
    EXPECT_EQ(tree.leaves().size(), tree.empty() ? 0 : items);
    if (tree.empty()) return seen;
    size_t next_leaf = 0;
    std::vector<int32_t> stack{tree.root()};
    while (!stack.empty()) {
        const int32_t index = stack.back();
        const AabbTreeNode &node = tree.node(index);
        stack.pop_back();
        if (node.is_leaf()) {
            EXPECT_EQ(index, tree.leaves().at(next_leaf++)) << "leaves() out of tree order";
            ++seen.at(static_cast<size_t>(node.item));
            continue;
        }
        for (int32_t child : {node.right, node.left}) {  // left popped first
            EXPECT_GT(child, index) << "a child before its parent";
            const Aabb &box = tree.node(child).box;
            if (!box.empty()) {
                EXPECT_TRUE(contains(node.box, box));
            }
            stack.push_back(child);
        }
    }
    EXPECT_EQ(next_leaf, tree.leaves().size());
    return seen;
}

void expect_tree_holds_every_shape_once(const LinkSet &links) {
    const std::vector<int> seen = leaf_counts(links.tree(), links.placed().size());
    for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "placed shape " << i;
}

// Three links; the last shape goes to link 0 after links 1 and 2 exist.
LinkSet three_links() {
    LinkSet links;
    for (int l = 0; l < 3; ++l) {
        links.add_link("link" + std::to_string(l));
        links.add_shape(static_cast<uint32_t>(l), sphere(0.1, l));
        links.add_shape(static_cast<uint32_t>(l), sphere(0.2, l + 0.5));
    }
    links.add_shape(0, sphere(0.3, -4.0));
    return links;
}

TEST(LinkSetBuilding, PlacedShapesStayLinkMajor) {
    const LinkSet links = three_links();
    const std::vector<std::pair<uint32_t, uint32_t>> expected{{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {2, 0}, {2, 1}};
    ASSERT_EQ(links.placed().size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(links.placed()[i].link, expected[i].first) << i;
        EXPECT_EQ(links.placed()[i].shape, expected[i].second) << i;
    }
    // The late shape of link 0 is placed where its definition says.
    EXPECT_NEAR(links.placed()[2].box.center().x(), -4.0, 1e-12);
    EXPECT_NEAR(links.placed()[2].box.half_extent().x(), 0.3, 1e-12);
}

// The copy constructor places every shape at once, from the definitions.
void expect_same_as_full_rebuild(const LinkSet &links) {
    const LinkSet copy(links);
    ASSERT_EQ(copy.placed().size(), links.placed().size());
    for (size_t i = 0; i < links.placed().size(); ++i) {
        EXPECT_EQ(copy.placed()[i].link, links.placed()[i].link) << i;
        EXPECT_EQ(copy.placed()[i].shape, links.placed()[i].shape) << i;
        EXPECT_EQ(copy.placed()[i].box.lo, links.placed()[i].box.lo) << i;
        EXPECT_EQ(copy.placed()[i].box.hi, links.placed()[i].box.hi) << i;
    }
}

TEST(LinkSetBuilding, BoxesEqualAFullRebuild) {
    LinkSet links = three_links();
    expect_same_as_full_rebuild(links);
    // New poses place each link's shapes again, where the link's entries are.
    std::vector<Pose> poses(links.link_count());
    for (size_t l = 0; l < poses.size(); ++l) poses[l].translation = Vec3(1.0, 2.0 * static_cast<double>(l), 0.0);
    links.set_poses(poses);
    expect_same_as_full_rebuild(links);
    links.set_padding(0.01);
    expect_same_as_full_rebuild(links);
}

TEST(LinkSetBuilding, TreeFollowsEveryChange) {
    LinkSet links = three_links();
    expect_tree_holds_every_shape_once(links);  // before any pose
    links.add_shape(1, sphere(0.1, 7.0));       // to a link that exists, after the tree was read
    expect_tree_holds_every_shape_once(links);
    links.add_link("late");
    links.add_shape(3, sphere(0.1, 9.0));  // after the tree was read
    expect_tree_holds_every_shape_once(links);
    EXPECT_TRUE(contains(links.tree().node(links.tree().root()).box, links.placed().back().box));
    std::vector<Pose> poses(links.link_count());
    for (size_t l = 0; l < poses.size(); ++l) poses[l].translation = Vec3(0.0, 3.0 * static_cast<double>(l), 0.0);
    links.set_poses(poses);
    expect_tree_holds_every_shape_once(links);
    for (const PlacedShape &p : links.placed())
        EXPECT_TRUE(contains(links.tree().node(links.tree().root()).box, p.box));
}

TEST(LinkSetBuilding, ConcurrentFirstReadersAgree) {
    for (int round = 0; round < 20; ++round) {
        LinkSet links;
        for (int l = 0; l < 200; ++l) {
            links.add_link("l");
            links.add_shape(static_cast<uint32_t>(l), sphere(0.05, 0.1 * l));
        }
        const LinkSet &shared = links;
        std::atomic<int> ready{0};
        std::vector<size_t> sizes(4, 0);
        std::vector<std::thread> threads;
        for (size_t t = 0; t < sizes.size(); ++t)
            threads.emplace_back([&, t] {
                ++ready;
                while (ready.load() < static_cast<int>(sizes.size())) {
                }
                sizes[t] = shared.tree().size();
            });
        for (std::thread &thread : threads) thread.join();
        for (size_t size : sizes) EXPECT_EQ(size, 2 * 200 - 1u);
        expect_tree_holds_every_shape_once(links);
    }
}

}  // namespace
