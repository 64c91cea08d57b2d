// Where both engines put what a collision query finds: the exact test of a
// shape against an obstacle cell, the contacts kept (up to max_contacts),
// and when the obstacle answer is settled.  The engines keep their own
// traversals and call offer() for every obstacle cell a shape may touch.
#pragma once

#include "geometry/aabb.hpp"
#include "narrowphase/narrow_phase.hpp"
#include "query/cell_description.hpp"
#include "query/collision_types.hpp"

#include <vector>

namespace octoprox {

class ContactSink {
public:
    // Clears `contacts`; the outcome collects collided, truncated and the
    // narrow-phase test count.
    ContactSink(const CollisionSettings &settings, std::vector<Contact> &contacts, CollisionOutcome &outcome)
        : settings_(settings), contacts_(contacts), outcome_(outcome) {
        contacts.clear();
    }

    // An obstacle cell (its box) that `shape` may touch: when the padded
    // shape does touch it, the query has collided and the contact is kept
    // unless max_contacts are already (then the list is truncated, if any
    // were wanted).  `describe()` gives the cell's CellSummary, asked only
    // for a contact kept.  Returns true once the obstacle answer is settled:
    // the list is full, or the first contact answers a query of at most one.
    template <class Describe>
    bool offer(const PlacedShape &shape, const Aabb &cell, Describe &&describe) {
        if (settled_) return true;
        if (!shape_touches_cell(shape, cell.center(), cell.half_extent(), outcome_.narrow_tests)) return false;
        outcome_.collided = true;
        if (contacts_.size() >= settings_.max_contacts) {
            outcome_.truncated = settings_.max_contacts > 0;
            return settled_ = true;
        }
        keep(shape, cell, describe());
        return settled_ = contacts_.size() >= settings_.max_contacts && settings_.max_contacts <= 1;
    }
    bool settled() const { return settled_; }

private:
    void keep(const PlacedShape &shape, const Aabb &cell, const CellSummary &summary);

    const CollisionSettings &settings_;
    std::vector<Contact> &contacts_;
    CollisionOutcome &outcome_;
    bool settled_ = false;
};

// A contact's depth, normal and position (midway between the two witness
// points) from the shape's penetration into the cell.
void set_contact_penetration(const PlacedShape &shape, const Aabb &cell, Contact &contact);

}  // namespace octoprox
