// Penetration of a placed shape (padding included) into a cell it touches.
#pragma once

#include "robot/shape.hpp"

namespace octoprox {

struct ShapePenetration {
    double depth = 0.0;            // >= 0, padding included
    Vec3 normal = Vec3::UnitX();   // the direction the shape went into the cell
    Vec3 on_link = Vec3::Zero();   // the padded shape's point deepest in the cell
    Vec3 on_cell = Vec3::Zero();   // on_link - depth * normal, on the cell's surface
};

// For a shape touching the cell; for a mesh, its deepest triangle.
ShapePenetration shape_penetration(const PlacedShape &shape, const Vec3 &cell_center, const Vec3 &cell_half);

}  // namespace octoprox
