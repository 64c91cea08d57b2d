// Forgetting: every known cell's log-odds moves toward 0 (the prior,
// p = 0.5) by a fixed amount, so that what the sensor no longer sees fades
// out of the map.
#pragma once

namespace octoprox {

class BoundedOcTree;

// Each leaf's log-odds v becomes v - amount when positive, v + amount when
// negative, computed in double and rounded to float; a leaf whose value
// reaches or crosses 0 (one at 0 included) is removed (unknown space), and
// a node whose children all go goes too.  A leaf that ends below
// `occupied_log_odds` loses its point extent.  Nodes on the way up are
// pruned or have their occupancy and obstacle box recomputed.  amount > 0;
// call inside a BoundsScope.  Allocates nothing.  Returns whether a leaf
// was removed.
bool decay_cells(BoundedOcTree &tree, double amount, float occupied_log_odds);

// One leaf value after decay; removed when the result is 0.
inline float decayed_log_odds(float value, double amount) {
    if (value > 0.0f) {
        const float next = static_cast<float>(static_cast<double>(value) - amount);
        return next > 0.0f ? next : 0.0f;
    }
    if (value < 0.0f) {
        const float next = static_cast<float>(static_cast<double>(value) + amount);
        return next < 0.0f ? next : 0.0f;
    }
    return 0.0f;
}

}  // namespace octoprox
