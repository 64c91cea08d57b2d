#include "query/contact_sink.hpp"

#include "narrowphase/shape_penetration.hpp"

namespace octoprox {

void ContactSink::keep(const PlacedShape &shape, const Aabb &cell, const CellSummary &summary) {
    Contact c;
    c.link = shape.link, c.shape = shape.shape, c.attached = shape.attached;
    set_cell(c, summary);
    if (settings_.penetration) set_contact_penetration(shape, cell, c);
    contacts_.push_back(c);
}

void set_contact_penetration(const PlacedShape &shape, const Aabb &cell, Contact &contact) {
    const ShapePenetration p = shape_penetration(shape, cell.center(), cell.half_extent());
    contact.depth = p.depth;
    const Vec3 middle = 0.5 * (p.on_link + p.on_cell);
    for (int axis = 0; axis < 3; ++axis) contact.normal[axis] = p.normal[axis], contact.position[axis] = middle[axis];
}

}  // namespace octoprox
