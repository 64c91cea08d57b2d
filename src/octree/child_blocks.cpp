// The child-block store of BoundedOcTree (declared in bounded_tree.hpp).
//
// A block is OctoMap's child array (8 pointers: every OctoMap algorithm
// reads children through it, unchanged) followed by the 8 child slots.  A
// child exists when its pointer is set, and then points to its slot.  A
// slot without a child holds a placeholder leaf with log-odds -infinity, so
// that a traversal for which absent (unknown) and below-threshold children
// are the same may read a slot without its pointer (OctreeView::
// child_or_absent).  The block is allocated with the node's first child and
// freed with its last, by pruning or clearing, as OctoMap frees its array,
// from and to the map's ChildBlockPool; only the root is allocated on its
// own (OctoMap's `new NODE()`).
//
// OccupancyOcTreeBase<BoundedNode> is abstract and BoundedOcTree is its
// only subclass, so `this` here is always a BoundedOcTree (pool_of).
#include "octree/bounded_tree.hpp"

#include "octree/point_extent.hpp"
#include "octree/update_worker.hpp"

#include <cstddef>
#include <cstring>
#include <limits>
#include <new>

namespace octomap {
namespace {

using octoprox::BoundedNode;

struct ChildBlock {
    AbstractOcTreeNode *pointers[8];
    alignas(alignof(BoundedNode)) unsigned char slots[8][sizeof(BoundedNode)];
};
static_assert(sizeof(ChildBlock) == octoprox::child_block::kBytes &&
                  offsetof(ChildBlock, slots) == octoprox::child_block::kSlotsOffset &&
                  sizeof(BoundedNode) == octoprox::child_block::kSlotBytes &&
                  alignof(ChildBlock) <= octoprox::ChildBlockPool::kAlignment,
              "the layout the pool and the view assume (child_block_pool.hpp)");

BoundedNode *slot_of(AbstractOcTreeNode **pointers, unsigned int child) {
    return reinterpret_cast<BoundedNode *>(reinterpret_cast<ChildBlock *>(pointers)->slots[child]);
}

void place_absent_child(AbstractOcTreeNode **pointers, unsigned int child) {
    BoundedNode *placeholder = new (slot_of(pointers, child)) BoundedNode();
    placeholder->setLogOdds(-std::numeric_limits<float>::infinity());
}


octoprox::ChildBlockPool &pool_of(BoundedTreeBase *tree) {
    return static_cast<octoprox::BoundedOcTree *>(tree)->child_blocks();
}

// Blocks come from and go to the map's pool, or, on a thread working on
// a part of a parallel update, through its worker (update_worker.hpp).
void *take_block(BoundedTreeBase *tree) {
    octoprox::UpdateWorker *worker = octoprox::UpdateWorker::current();
    return worker != nullptr ? worker->allocate() : pool_of(tree).allocate();
}

void give_block(BoundedTreeBase *tree, void *block) {
    octoprox::UpdateWorker *worker = octoprox::UpdateWorker::current();
    if (worker != nullptr) worker->release(block);
    else pool_of(tree).release(block);
}

// The map's node count, or a worker's count of its changes to it.
void count_nodes(size_t &tree_size, bool &size_changed, long delta) {
    octoprox::UpdateWorker *worker = octoprox::UpdateWorker::current();
    if (worker != nullptr) {
        worker->count_nodes(delta);
        return;
    }
    tree_size += delta;
    size_changed = true;
}

// Destroys the subtree below `node` (not `node`) and returns its blocks.
void release_children(BoundedTreeBase *tree, BoundedNode &node) {
    AbstractOcTreeNode **&children = node.child_pointers();
    if (children == nullptr) return;
    for (unsigned int i = 0; i < 8; ++i) {
        BoundedNode *slot = slot_of(children, i);
        if (children[i] != nullptr) release_children(tree, *slot);
        slot->~BoundedNode();
    }
    give_block(tree, children);
    children = nullptr;
}

}  // namespace

template <>
void BoundedTreeBase::allocNodeChildren(BoundedNode *node) {
    auto *block = new (take_block(this)) ChildBlock;
    for (unsigned int i = 0; i < 8; ++i) {
        block->pointers[i] = nullptr;
        place_absent_child(block->pointers, i);
    }
    node->children = block->pointers;
}

template <>
BoundedNode *BoundedTreeBase::createNodeChild(BoundedNode *node, unsigned int child) {
    if (node->children == nullptr) allocNodeChildren(node);
    BoundedNode *slot = slot_of(node->children, child);
    slot->~BoundedNode();
    BoundedNode *created = new (slot) BoundedNode();
    node->children[child] = created;
    count_nodes(tree_size, size_changed, +1);
    return created;
}

// OctoMap deletes only leaves this way; a subtree would leak there, not here.
template <>
void BoundedTreeBase::deleteNodeChild(BoundedNode *node, unsigned int child) {
    BoundedNode *deleted = slot_of(node->children, child);
    release_children(this, *deleted);
    deleted->~BoundedNode();
    place_absent_child(node->children, child);
    node->children[child] = nullptr;
    count_nodes(tree_size, size_changed, -1);
}

// OctoMap's pruneNode, with the block freed instead of the array.  The
// new leaf's point extent holds its children's (none when one of them has
// none: that child is a whole cube).
template <>
bool BoundedTreeBase::pruneNode(BoundedNode *node) {
    if (!isNodeCollapsible(node)) return false;
    node->copyData(*getNodeChild(node, 0));
    uint32_t merged = 0;  // the children's extents in the node's slots
    for (unsigned int i = 0; i < 8; ++i) {
        const uint32_t child = getNodeChild(node, i)->point_extent();
        if (!octoprox::extent::valid(child)) {
            merged = 0;
            break;
        }
        const uint32_t lifted = octoprox::extent::to_parent(child, static_cast<int>(i));
        merged = i == 0 ? lifted : octoprox::extent::merge(merged, lifted);
    }
    node->set_point_extent(merged);
    for (unsigned int i = 0; i < 8; ++i) deleteNodeChild(node, i);
    release_children(this, *node);  // the block, now empty
    return true;
}

// OctoMap's expandNode (eight children holding the leaf's value), each
// child keeping the part of the leaf's point extent inside it.  The node's
// own obstacle box is unknown until its children change (none of ours
// expands a node without changing one).
template <>
void BoundedTreeBase::expandNode(BoundedNode *node) {
    const uint32_t extent = node->point_extent();
    for (unsigned int i = 0; i < 8; ++i) {
        BoundedNode *child = createNodeChild(node, i);
        child->copyData(*node);
        child->set_point_extent(octoprox::extent::valid(extent)
                                    ? octoprox::extent::to_child(extent, static_cast<int>(i))
                                    : 0);
    }
    node->set_point_extent(0);
}

// OctoMap calls this with the root alone (clear()), the one node that is
// not in a block.
template <>
void BoundedTreeBase::deleteNodeRecurs(BoundedNode *node) {
    release_children(this, *node);
    delete node;
}

// OctoMap's own count assumes a pointer array and separate nodes.  Here:
// the tree object, the root and the pool's slabs (blocks in use or free).
template <>
size_t BoundedTreeBase::memoryUsage() const {
    const size_t pool = static_cast<const octoprox::BoundedOcTree *>(this)->child_blocks().bytes_reserved();
    return sizeof(*this) + (root == nullptr ? 0 : sizeof(BoundedNode)) + pool;
}

}  // namespace octomap

namespace octoprox {
namespace {

size_t nodes_below(const BoundedNode &node) {
    if (!node.has_child_array()) return 0;
    const auto *pointers = static_cast<octomap::AbstractOcTreeNode *const *>(node.child_array());
    size_t count = 0;
    for (unsigned int i = 0; i < 8; ++i)
        if (pointers[i] != nullptr) count += 1 + nodes_below(*static_cast<const BoundedNode *>(pointers[i]));
    return count;
}

bool has_any_child(const BoundedNode &node) {
    if (!node.has_child_array()) return false;
    const auto *pointers = static_cast<octomap::AbstractOcTreeNode *const *>(node.child_array());
    for (unsigned int i = 0; i < 8; ++i)
        if (pointers[i] != nullptr) return true;
    return false;
}

// A copy of the block and of every block below it, from `pool`, which has
// them reserved.
octomap::AbstractOcTreeNode **copy_block(ChildBlockPool &pool, octomap::AbstractOcTreeNode **old) {
    auto *fresh = static_cast<octomap::ChildBlock *>(pool.allocate());
    std::memcpy(static_cast<void *>(fresh), static_cast<const void *>(old), sizeof(octomap::ChildBlock));
    for (unsigned int i = 0; i < 8; ++i) {
        if (old[i] == nullptr) continue;
        BoundedNode *slot = octomap::slot_of(fresh->pointers, i);
        fresh->pointers[i] = slot;
        octomap::AbstractOcTreeNode **&below = slot->child_pointers();
        if (below != nullptr) below = copy_block(pool, below);
    }
    return fresh->pointers;
}

}  // namespace

void BoundedOcTree::remove_child(BoundedNode *node, unsigned int child) {
    const size_t below = nodes_below(*getNodeChild(node, child));
    deleteNodeChild(node, child);  // counts the child; its subtree goes with it
    tree_size -= below;
    if (!has_any_child(*node)) octomap::release_children(this, *node);
}

void BoundedOcTree::remove_children(BoundedNode *node) {
    tree_size -= nodes_below(*node);
    size_changed = true;
    octomap::release_children(this, *node);
}

void BoundedOcTree::compact_blocks(ChildBlockPool &fresh) {
    if (root == nullptr || !root->has_child_array()) return;
    root->child_pointers() = copy_block(fresh, root->child_pointers());
    fresh.release_spares();
    child_blocks_.swap(fresh);  // the old slabs go with `fresh`
}

}  // namespace octoprox
