// Triangle meshes of the scene's objects and of octree cells, for the
// variant (b) of the tables: the same meshes go to FCL and to OctoProx.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace paper_tables {

// Triangles with outward (counter-clockwise seen from outside) winding.
struct TriangleMesh {
    std::vector<double> vertices;  // x, y, z per vertex, packed
    std::vector<uint32_t> indices;  // 3 vertex indices per triangle, packed

    size_t vertex_count() const { return vertices.size() / 3; }
    size_t triangle_count() const { return indices.size() / 3; }
};

// A UV sphere centred at the origin: `slices` meridians, `stacks` bands
// from pole to pole; its vertices lie on the sphere (it is inscribed).
TriangleMesh make_uv_sphere(double radius, int slices, int stacks);

// A closed cylinder along z, centred at the origin, with `sides` facets;
// full length `length` (URDF and FCL convention).
TriangleMesh make_cylinder(double radius, double length, int sides);

// A box of full edge lengths sx, sy, sz centred at the origin: 12 triangles.
TriangleMesh make_box(double sx, double sy, double sz);

}  // namespace paper_tables
