#include "meshes.hpp"

#include <cmath>

namespace paper_tables {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;
constexpr double kPi = 0.5 * kTwoPi;

uint32_t add_vertex(TriangleMesh &mesh, double x, double y, double z) {
    mesh.vertices.insert(mesh.vertices.end(), {x, y, z});
    return static_cast<uint32_t>(mesh.vertex_count() - 1);
}

void add_triangle(TriangleMesh &mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// Two triangles over the quad a-b-c-d (counter-clockwise).
void add_quad(TriangleMesh &mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    add_triangle(mesh, a, b, c);
    add_triangle(mesh, a, c, d);
}

// A ring of `sides` vertices at height z; returns the index of the first.
uint32_t add_ring(TriangleMesh &mesh, double radius, double z, int sides) {
    const uint32_t first = static_cast<uint32_t>(mesh.vertex_count());
    for (int i = 0; i < sides; ++i) {
        const double angle = kTwoPi * i / sides;
        add_vertex(mesh, radius * std::cos(angle), radius * std::sin(angle), z);
    }
    return first;
}

// The quads between two rings of equal size, `lower` below `upper`.
void join_rings(TriangleMesh &mesh, uint32_t lower, uint32_t upper, int sides) {
    for (int i = 0; i < sides; ++i) {
        const uint32_t next = static_cast<uint32_t>((i + 1) % sides);
        add_quad(mesh, lower + i, lower + next, upper + next, upper + i);
    }
}

// A fan from `apex` to a ring; `upward` when the fan faces +z.
void add_fan(TriangleMesh &mesh, uint32_t apex, uint32_t ring, int sides, bool upward) {
    for (int i = 0; i < sides; ++i) {
        const uint32_t next = static_cast<uint32_t>((i + 1) % sides);
        if (upward)
            add_triangle(mesh, apex, ring + i, ring + next);
        else
            add_triangle(mesh, apex, ring + next, ring + i);
    }
}

}  // namespace

TriangleMesh make_uv_sphere(double radius, int slices, int stacks) {
    TriangleMesh mesh;
    const uint32_t south = add_vertex(mesh, 0.0, 0.0, -radius);
    uint32_t previous = 0;
    for (int band = 1; band < stacks; ++band) {
        const double polar = kPi * band / stacks;  // from the south pole
        const uint32_t ring = add_ring(mesh, radius * std::sin(polar), -radius * std::cos(polar), slices);
        if (band == 1)
            add_fan(mesh, south, ring, slices, false);
        else
            join_rings(mesh, previous, ring, slices);
        previous = ring;
    }
    const uint32_t north = add_vertex(mesh, 0.0, 0.0, radius);
    add_fan(mesh, north, previous, slices, true);
    return mesh;
}

TriangleMesh make_cylinder(double radius, double length, int sides) {
    TriangleMesh mesh;
    const double half = 0.5 * length;
    const uint32_t bottom = add_ring(mesh, radius, -half, sides);
    const uint32_t top = add_ring(mesh, radius, half, sides);
    join_rings(mesh, bottom, top, sides);
    add_fan(mesh, add_vertex(mesh, 0.0, 0.0, -half), bottom, sides, false);
    add_fan(mesh, add_vertex(mesh, 0.0, 0.0, half), top, sides, true);
    return mesh;
}

TriangleMesh make_box(double sx, double sy, double sz) {
    TriangleMesh mesh;
    const double hx = 0.5 * sx, hy = 0.5 * sy, hz = 0.5 * sz;
    // Vertex i has the sign pattern of its bits: bit 0 x, bit 1 y, bit 2 z.
    for (int i = 0; i < 8; ++i)
        add_vertex(mesh, (i & 1) ? hx : -hx, (i & 2) ? hy : -hy, (i & 4) ? hz : -hz);
    add_quad(mesh, 0, 2, 3, 1);  // -z
    add_quad(mesh, 4, 5, 7, 6);  // +z
    add_quad(mesh, 0, 1, 5, 4);  // -y
    add_quad(mesh, 2, 6, 7, 3);  // +y
    add_quad(mesh, 0, 4, 6, 2);  // -x
    add_quad(mesh, 1, 3, 7, 5);  // +x
    return mesh;
}

}  // namespace paper_tables
