#include "geometry/epa.hpp"

#include <cmath>
#include <limits>

namespace octoprox {
namespace {

// A polytope of V vertices has at most 2V - 4 faces; dead faces are
// compacted away after every expansion, so these bounds hold.
constexpr int kMaxVertices = 256;
constexpr int kMaxFaces = 2 * kMaxVertices;
constexpr int kMaxIterations = kMaxVertices - 8;
// Polytopes end exactly (no gain); curved cores (cylinders) stop when the
// next support gains less than this fraction of the depth.
constexpr double kRelativeTolerance = 1e-10;

struct Vertex {
    Vec3 w, s, c;  // difference point, and the shape and cell points behind it
};

struct Face {
    int v[3];
    Vec3 normal;     // outward unit normal
    double offset;   // distance of the face plane from the origin
    bool alive;
};

struct Edge {
    int a, b;
};

class Polytope {
public:
    bool add_face(int a, int b, int c);
    int closest_face() const;
    void expand(int vertex);  // replaces the faces the vertex sees

    Vertex vertices[kMaxVertices];
    int vertex_count = 0;
    Face faces[kMaxFaces];
    int face_count = 0;

private:
    void add_horizon_edge(Edge *edges, int &count, int a, int b) const;
};

bool Polytope::add_face(int a, int b, int c) {
    if (face_count >= kMaxFaces) return false;
    const Vec3 &wa = vertices[a].w;
    Vec3 n = (vertices[b].w - wa).cross(vertices[c].w - wa);
    const double length = n.norm();
    if (!(length > 0.0)) return false;  // a degenerate face
    n /= length;
    faces[face_count++] = Face{{a, b, c}, n, n.dot(wa), true};
    return true;
}

int Polytope::closest_face() const {
    int best = -1;
    for (int i = 0; i < face_count; ++i)
        if (faces[i].alive && (best < 0 || faces[i].offset < faces[best].offset)) best = i;
    return best;
}

// An edge shared by two removed faces is interior: the two directions cancel.
void Polytope::add_horizon_edge(Edge *edges, int &count, int a, int b) const {
    for (int i = 0; i < count; ++i) {
        if (edges[i].a == b && edges[i].b == a) {
            edges[i] = edges[--count];
            return;
        }
    }
    edges[count++] = Edge{a, b};
}

void Polytope::expand(int vertex) {
    Edge edges[3 * kMaxFaces];
    int edge_count = 0;
    const Vec3 &w = vertices[vertex].w;
    for (int i = 0; i < face_count; ++i) {
        Face &f = faces[i];
        // Faces the new point sees only by rounding stay: removing a face
        // that is not truly visible would make the polytope non-convex.
        if (!f.alive || f.normal.dot(w - vertices[f.v[0]].w) <= 1e-12 * (1.0 + w.norm())) continue;
        f.alive = false;
        for (int k = 0; k < 3; ++k) add_horizon_edge(edges, edge_count, f.v[k], f.v[(k + 1) % 3]);
    }
    int kept = 0;
    for (int i = 0; i < face_count; ++i)
        if (faces[i].alive) faces[kept++] = faces[i];
    face_count = kept;
    for (int i = 0; i < edge_count; ++i) add_face(edges[i].a, edges[i].b, vertex);
}


// Witness points from the barycentric coordinates of the origin's
// projection onto the final face.
Penetration from_face(const Polytope &p, const Face &f) {
    const Vertex &a = p.vertices[f.v[0]], &b = p.vertices[f.v[1]], &c = p.vertices[f.v[2]];
    const Vec3 q = f.normal * f.offset;
    const Vec3 n = (b.w - a.w).cross(c.w - a.w);
    const double area = n.squaredNorm();
    const double u = (c.w - b.w).cross(q - b.w).dot(n) / area;
    const double v = (a.w - c.w).cross(q - c.w).dot(n) / area;
    const double t = 1.0 - u - v;
    Penetration r;
    r.depth = f.offset;
    r.normal = f.normal;
    r.on_shape = u * a.s + v * b.s + t * c.s;
    r.on_cell = u * a.c + v * b.c + t * c.c;
    return r;
}

// Grows a simplex whose hull holds the origin on its boundary (GJK stopped
// with v = 0) into a tetrahedron, adding supports off its affine hull.
// `support(d)`: the difference's vertex furthest along d; `eps`: the
// length below which two difference points are one.
template <class Support>
int blow_up(const Support &support, double eps, Vertex *v, int size) {
    auto add_if_new = [&](const Vec3 &d, auto off_hull) {
        for (const Vec3 &dir : {d, Vec3(-d)}) {
            const Vertex w = support(dir);
            if (off_hull(w.w)) {
                v[size++] = w;
                return true;
            }
        }
        return false;
    };
    if (size == 1) {
        for (int axis = 0; axis < 3 && size == 1; ++axis)
            add_if_new(Vec3::Unit(axis), [&](const Vec3 &w) { return (w - v[0].w).norm() > eps; });
    }
    if (size == 2) {
        const Vec3 u = (v[1].w - v[0].w).normalized();
        for (int axis = 0; axis < 3 && size == 2; ++axis) {
            const Vec3 d = u.cross(Vec3::Unit(axis));
            if (d.norm() < 0.1) continue;
            add_if_new(d, [&](const Vec3 &w) { return (w - v[0].w).cross(u).norm() > eps; });
        }
    }
    if (size == 3) {
        const Vec3 n = (v[1].w - v[0].w).cross(v[2].w - v[0].w).normalized();
        add_if_new(n, [&](const Vec3 &w) { return std::fabs((w - v[0].w).dot(n)) > eps; });
    }
    return size;
}

// EPA from GJK's simplex; `touching` is the answer when the two only touch.
template <class Support>
Penetration epa_run(const Support &support, double eps, const Simplex &start, const Penetration &touching) {
    Polytope p;
    for (int i = 0; i < start.size; ++i) p.vertices[i] = Vertex{start.w[i], start.s[i], start.c[i]};
    p.vertex_count = start.size == 0 ? 0 : blow_up(support, eps, p.vertices, start.size);
    if (p.vertex_count < 4) return touching;  // flat: they only touch
    // Orient each face away from the vertex it does not hold.
    static const int kFaces[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    for (const auto &f : kFaces) {
        const Vec3 n = (p.vertices[f[1]].w - p.vertices[f[0]].w).cross(p.vertices[f[2]].w - p.vertices[f[0]].w);
        const bool outward = n.dot(p.vertices[f[3]].w - p.vertices[f[0]].w) < 0.0;
        if (!(outward ? p.add_face(f[0], f[1], f[2]) : p.add_face(f[0], f[2], f[1]))) return touching;
    }
    int best = p.closest_face();
    for (int iteration = 0; iteration < kMaxIterations && best >= 0; ++iteration) {
        const Face &f = p.faces[best];
        const Vertex next = support(f.normal);
        const double gain = next.w.dot(f.normal) - f.offset;
        if (gain <= kRelativeTolerance * std::max(1.0, std::fabs(f.offset)) || p.vertex_count >= kMaxVertices) break;
        p.vertices[p.vertex_count] = next;
        p.expand(p.vertex_count++);
        const int candidate = p.closest_face();
        if (candidate < 0) break;
        best = candidate;
    }
    return best >= 0 ? from_face(p, p.faces[best]) : touching;
}

}  // namespace

Penetration epa_cell_penetration(const Vec3 &cell_center, const Vec3 &cell_half, const Convex &core,
                                 const Simplex &start) {
    Penetration touching;
    touching.on_shape = touching.on_cell = start.size > 0 ? start.c[0] : cell_center;
    const auto support = [&](const Vec3 &d) {
        const Vec3 s = core.support(d);
        const Vec3 c = box_support(cell_center, cell_half, -d);
        return Vertex{s - c, s, c};
    };
    return epa_run(support, 1e-12 * (1.0 + cell_half.norm()), start, touching);
}

Penetration epa_pair_penetration(const Convex &a, const Convex &b, double scale, const Simplex &start) {
    Penetration touching;
    touching.on_shape = touching.on_cell = start.size > 0 ? start.c[0] : b.support(Vec3::UnitX());
    const auto support = [&](const Vec3 &d) {
        const Vec3 s = a.support(d);
        const Vec3 c = b.support(-d);
        return Vertex{s - c, s, c};
    };
    return epa_run(support, 1e-12 * (1.0 + scale), start, touching);
}

}  // namespace octoprox
