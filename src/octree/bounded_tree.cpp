#include "octree/bounded_tree.hpp"

#include <algorithm>

namespace octoprox {

// The packed box lives in OcTreeNode's tail padding (Itanium C++ ABI).
static_assert(sizeof(BoundedNode) == sizeof(octomap::OcTreeNode), "the obstacle box must cost no memory");

namespace {

// The threshold of the scope alive on this thread, if any.  Thread-local
// because a map is changed by one thread at a time (the API says so) while
// other threads may change other maps.
thread_local bool t_scope_active = false;
thread_local float t_threshold = 0.0f;

}  // namespace

BoundsScope::BoundsScope(float threshold_log_odds) : was_active_(t_scope_active), previous_(t_threshold) {
    t_scope_active = true;
    t_threshold = threshold_log_odds;
}

BoundsScope::~BoundsScope() {
    t_scope_active = was_active_;
    t_threshold = previous_;
}

// A child's slot s (of 32 across the child's cube) lies in the parent's
// slot (s + 32 * side) / 2, side = 0 for the lower half: exact, no rounding
// outward is needed, so boxes stay tight however deep the tree.
void BoundedNode::updateOccupancyChildren() {
    setLogOdds(getMaxChildLogOdds());
    if (!t_scope_active) {
        packed_bounds_ = 0;
        return;
    }
    int lo[3] = {bounds::kSlots, bounds::kSlots, bounds::kSlots};
    int hi[3] = {-1, -1, -1};
    for (int i = 0; children != nullptr && i < 8; ++i) {
        const auto *child = static_cast<const BoundedNode *>(children[i]);
        if (child == nullptr || !(child->getLogOdds() >= t_threshold)) continue;  // max below: no obstacle
        uint32_t box = child->children != nullptr ? child->packed_bounds_ : bounds::kFull;
        if ((box & bounds::kValid) == 0) box = bounds::kFull;
        for (int axis = 0; axis < 3; ++axis) {
            const int side = ((i >> axis) & 1) * bounds::kSlots;
            lo[axis] = std::min(lo[axis], (bounds::lo(box, axis) + side) >> 1);
            hi[axis] = std::max(hi[axis], (bounds::hi(box, axis) + side) >> 1);
        }
    }
    // No obstacle below: the engines skip the node by its max log-odds.
    packed_bounds_ = hi[0] < 0 ? bounds::kFull : extent::pack(lo, hi);
}

}  // namespace octoprox
