#include "narrowphase/shape_pair.hpp"

#include "geometry/obb.hpp"
#include "narrowphase/convex_pair.hpp"
#include "narrowphase/narrow_phase.hpp"
#include "narrowphase/pair_sides.hpp"

#include <limits>

namespace octoprox {
namespace {

// Pairs of nodes (a's, b's) on a stack.  Median-split trees are at most
// 33 levels deep and each split adds one entry: 160 never overflow.
struct NodePair {
    int32_t a, b;
};
constexpr int kPairStack = 160;

// Visits the leaf pairs whose padded boxes are within kTouchTolerance,
// splitting the larger node first; stops when visit(a_leaf, b_leaf)
// returns true, and returns true then.
template <class Visit>
bool walk_close_leaves(const PosedSide &a, const PosedSide &b, Visit &&visit) {
    const RelativeFrame frame(a.rotation(), a.origin(), b.rotation(), b.origin());
    NodePair stack[kPairStack];
    int top = 0;
    stack[top++] = {a.root(), b.root()};
    while (top > 0) {
        const NodePair p = stack[--top];
        if (!boxes_within(a.center(p.a), a.half(p.a), b.center(p.b), b.half(p.b), frame, kTouchTolerance)) continue;
        const bool a_leaf = a.leaf(p.a), b_leaf = b.leaf(p.b);
        if (a_leaf && b_leaf) {
            if (visit(p.a, p.b)) return true;
            continue;
        }
        if (b_leaf || (!a_leaf && a.size(p.a) >= b.size(p.b))) {
            stack[top++] = {a.right(p.a), p.b};
            stack[top++] = {a.left(p.a), p.b};
        } else {
            stack[top++] = {p.a, b.right(p.b)};
            stack[top++] = {p.a, b.left(p.b)};
        }
    }
    return false;
}

}  // namespace

// A mesh: its shape frame, where its tree lives.  A box, cylinder or
// capsule: its own frame, its box there tight.  A sphere, or a hull: the
// map's axes around the padded box.
PosedSide::PosedSide(const PlacedShape &shape)
    : shape_(shape), tree_(shape.kind == ShapeKind::kMesh ? &shape.def->mesh_tree : nullptr) {
    const Convex &core = shape.core;
    const double r = shape.inflation;
    switch (shape.kind) {
    case ShapeKind::kMesh: rotation_ = core.axes, origin_ = core.center; break;
    case ShapeKind::kBox:
    case ShapeKind::kCylinder: rotation_ = core.axes, origin_ = core.center, half_ = core.half + Vec3::Constant(r); break;
    case ShapeKind::kCapsule:
        rotation_ = core.axes, origin_ = core.center;
        half_ = Vec3(r, r, 0.5 * (core.v[1] - core.v[0]).norm() + r);
        break;
    default: center_ = shape.box.center(), half_ = shape.box.half_extent(); break;
    }
}

bool shapes_touch(const PlacedShape &a, const PlacedShape &b, uint64_t &narrow_tests) {
    const PosedSide side_a(a), side_b(b);
    const double scale = pair_scale(a, b);
    return walk_close_leaves(side_a, side_b, [&](int32_t na, int32_t nb) {
        ++narrow_tests;
        const Convex pa = side_a.piece(na), pb = side_b.piece(nb);
        return pieces_within({&pa, a.inflation}, {&pb, b.inflation}, kTouchTolerance, scale);
    });
}

ShapePairPenetration shape_pair_penetration(const PlacedShape &a, const PlacedShape &b, uint64_t &narrow_tests) {
    const PosedSide side_a(a), side_b(b);
    const double scale = pair_scale(a, b);
    PiecePairPenetration deepest;
    deepest.depth = -std::numeric_limits<double>::infinity();
    walk_close_leaves(side_a, side_b, [&](int32_t na, int32_t nb) {
        ++narrow_tests;
        const Convex pa = side_a.piece(na), pb = side_b.piece(nb);
        const PiecePairPenetration p = piece_pair_penetration({&pa, a.inflation}, {&pb, b.inflation}, scale);
        if (p.depth > deepest.depth) deepest = p;
        return false;
    });
    ShapePairPenetration out;
    out.depth = std::max(0.0, deepest.depth);  // touching within the tolerance: 0
    out.normal = deepest.normal, out.on_a = deepest.on_a, out.on_b = deepest.on_b;
    return out;
}

}  // namespace octoprox
