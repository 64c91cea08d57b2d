// OctoMap's occupancy octree, with one more fact in every inner node: the
// part of its cube that holds its obstacle leaves (leaves at or above the
// map's occupancy threshold).  The distance and collision engines bound a
// subtree by that box instead of its whole cube, which prunes most of the
// nodes a nearest-first search would otherwise open.
//
// The box costs no memory: it is packed into the 4 bytes of padding after
// OcTreeNode's float (16 bytes a node either way).  It is kept up to date
// by the same calls that keep OctoMap's inner max log-odds up to date
// (updateOccupancyChildren, along every changed path), so there is no
// per-frame pass over the map.
//
// Packing: per axis, the lowest and highest 1/32nd of the cube that holds
// an obstacle leaf (5 bits each, six fields), and a validity bit.  Leaves
// use the same bytes, packed the same way, for their point extent (the box
// of the sensed points in them, point_extent.hpp); an inner node's box is
// made of its leaves' whole cubes, whatever their extents.  A box
// is only computed inside a BoundsScope (which says the threshold); a node
// updated outside one is marked invalid, and the engines then use its cube.
#pragma once

#include <octomap/OccupancyOcTreeBase.h>
#include <octomap/OcTreeNode.h>

#include "octree/child_block_pool.hpp"
#include "octree/point_extent.hpp"

#include <cstdint>
#include <string>

namespace octoprox {

// The packing of point_extent.hpp: a leaf's extent and an inner node's box
// share it.
namespace bounds {
using extent::hi;
using extent::kSlots;  // a cube's edge is cut into 32 slots
using extent::kValid;
using extent::lo;
constexpr uint32_t kFull = kValid | 0x3FFF8000u;  // lo = 0, hi = 31 on every axis
}  // namespace bounds

class BoundedNode : public octomap::OcTreeNode {
public:
    // OctoMap's templates call these on the node type (they are not
    // virtual): pruning copies a child's data up, expanding copies it down.
    void copyData(const BoundedNode &from) {
        octomap::OcTreeNode::copyData(from);
        packed_bounds_ = from.packed_bounds_;
    }
    // The max log-odds of the children (as OctoMap's) and the obstacle box.
    void updateOccupancyChildren();

    // Meaningful for nodes with children only; 0 when not valid.
    uint32_t packed_bounds() const { return packed_bounds_; }
    // A leaf's use of the same 4 bytes: the box of the sensed points that
    // made it occupied (point_extent.hpp); 0 when it has none.
    uint32_t point_extent() const { return packed_bounds_; }
    void set_point_extent(uint32_t packed) { packed_bounds_ = packed; }
    // Whether the node has children, from the node alone.  OctoMap's
    // nodeHasChildren also scans the child array (another cache line, and
    // the traversals ask it of every child they bound); the array alone
    // decides because every change our maps go through (updates, pruning,
    // expanding, reading files) allocates it with a first child and frees
    // it with the last.  Only OctoMap's deleteNode can leave an empty one,
    // and no map of ours calls it (test unit_obstacle_bounds checks).
    bool has_child_array() const { return children != nullptr; }
    const void *child_array() const { return children; }
    // For the child-block store (child_blocks.cpp) alone.
    octomap::AbstractOcTreeNode **&child_pointers() { return children; }

private:
    uint32_t packed_bounds_ = 0;
};

}  // namespace octoprox

// Each node's children live together in one child block (child_blocks.cpp):
// OctoMap's array of 8 child pointers, then the 8 child nodes themselves,
// 64-byte aligned.  OctoMap allocates every child and its pointer array
// separately, so a traversal that opens a node's children chased pointers
// to up to 9 scattered places; in a block they fill 3 cache lines.  These
// are explicit specializations of the OctoMap members that allocate and
// free nodes, declared here so that every use of the tree sees them.
namespace octomap {
using BoundedTreeBase = OcTreeBaseImpl<octoprox::BoundedNode, AbstractOccupancyOcTree>;
template <> void BoundedTreeBase::allocNodeChildren(octoprox::BoundedNode *node);
template <> octoprox::BoundedNode *BoundedTreeBase::createNodeChild(octoprox::BoundedNode *node, unsigned int child);
template <> void BoundedTreeBase::deleteNodeChild(octoprox::BoundedNode *node, unsigned int child);
template <> bool BoundedTreeBase::pruneNode(octoprox::BoundedNode *node);
template <> void BoundedTreeBase::expandNode(octoprox::BoundedNode *node);
template <> void BoundedTreeBase::deleteNodeRecurs(octoprox::BoundedNode *node);
template <> size_t BoundedTreeBase::memoryUsage() const;
}  // namespace octomap

namespace octoprox {

// While one is alive on this thread, inner-node updates compute obstacle
// boxes for leaves with log-odds >= threshold.  Every change our code makes
// to a map runs inside one (the map's threshold is fixed at creation).
class BoundsScope {
public:
    explicit BoundsScope(float threshold_log_odds);
    ~BoundsScope();
    BoundsScope(const BoundsScope &) = delete;
    BoundsScope &operator=(const BoundsScope &) = delete;

private:
    bool was_active_;
    float previous_;
};

class BoundedOcTree : public octomap::OccupancyOcTreeBase<BoundedNode> {
public:
    explicit BoundedOcTree(double resolution) : octomap::OccupancyOcTreeBase<BoundedNode>(resolution) {}
    // The nodes go back to the pool before the pool goes (OctoMap's own
    // destructor, which runs later, would clear into a destroyed pool).
    ~BoundedOcTree() override { clear(); }
    // OctoMap's copy would allocate the children one by one, outside blocks.
    BoundedOcTree(const BoundedOcTree &) = delete;
    BoundedOcTree &operator=(const BoundedOcTree &) = delete;
    // The same type name as OctoMap's OcTree: the files we write are theirs.
    std::string getTreeType() const override { return "OcTree"; }
    BoundedOcTree *create() const override { return new BoundedOcTree(resolution); }

    // The root an update starts from, made (as OctoMap's updateNode makes
    // it) when the map is empty; `created` says so.
    BoundedNode *root_for_update(bool &created) {
        created = root == nullptr;
        if (created) {
            root = new BoundedNode();
            ++tree_size;
        }
        return root;
    }

    // Counts the nodes workers of a parallel update added (update_worker.hpp).
    void add_worker_nodes(long added) {
        tree_size = static_cast<size_t>(static_cast<long>(tree_size) + added);
        size_changed = true;
    }

    // Removes child `child` of `node` and the subtree below it, counting
    // every node; the node's block goes back to the pool with its last
    // child (child_blocks.cpp).
    void remove_child(BoundedNode *node, unsigned int child);
    // Removes every node below `node`, which becomes a leaf.
    void remove_children(BoundedNode *node);
    // Moves every block into `fresh`, in depth-first order, and gives the
    // old slabs back to the heap (`fresh` then holds them, to be dropped).
    // `fresh` must have reserved every block in use (ChildBlockPool::
    // reserve), so the move allocates nothing and cannot fail.
    void compact_blocks(ChildBlockPool &fresh);

    // The child-block store's memory (child_blocks.cpp).
    ChildBlockPool &child_blocks() { return child_blocks_; }
    const ChildBlockPool &child_blocks() const { return child_blocks_; }

private:
    ChildBlockPool child_blocks_;
};

}  // namespace octoprox
