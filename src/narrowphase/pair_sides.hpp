// A shape of a pair seen as a tree of convex pieces: a mesh is its triangle
// tree, any other shape one leaf (its core).  The shape-pair tests
// (shape_pair.cpp, shape_pair_distance.cpp) walk two such trees at once.
// Two views: PosedSide reads a mesh's tree in the mesh's own frame (boxes
// there; collision tests need no placed mesh, see geometry/obb.hpp),
// PlacedSide reads the placed mesh (map-frame boxes; distance searches).
#pragma once

#include "robot/shape.hpp"

namespace octoprox {

class PosedSide {
public:
    explicit PosedSide(const PlacedShape &shape);

    const PlacedShape &shape() const { return shape_; }
    int32_t root() const { return 0; }
    bool leaf(int32_t node) const { return tree_ == nullptr || tree_->node(node).is_leaf(); }
    int32_t left(int32_t node) const { return tree_->node(node).left; }
    int32_t right(int32_t node) const { return tree_->node(node).right; }
    // The side's own frame in the map (p_map = rotation * p + origin).
    const Eigen::Matrix3d &rotation() const { return rotation_; }
    const Vec3 &origin() const { return origin_; }
    // The node's box in that frame, grown by the shape's padding: it holds
    // the padded pieces below the node.
    Vec3 center(int32_t node) const { return tree_ == nullptr ? center_ : tree_->node(node).box.center(); }
    Vec3 half(int32_t node) const {
        return tree_ == nullptr ? half_ : Vec3(tree_->node(node).box.half_extent().array() + shape_.inflation);
    }
    // A leaf's piece, in the map frame.
    Convex piece(int32_t node) const {
        return tree_ == nullptr ? shape_.core : shape_.posed_triangle(tree_->node(node).item);
    }
    // How large the node is (to pick which side to split).
    double size(int32_t node) const { return half(node).squaredNorm(); }

private:
    const PlacedShape &shape_;
    const AabbTree *tree_;
    Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
    Vec3 origin_ = Vec3::Zero();
    Vec3 center_ = Vec3::Zero(), half_ = Vec3::Zero();  // a single piece's box
};

class PlacedSide {
public:
    // Places a mesh (once per pose; thread-safe).
    explicit PlacedSide(const PlacedShape &shape)
        : shape_(shape), tree_(shape.kind == ShapeKind::kMesh ? &shape.mesh_tree : nullptr) {
        if (tree_ != nullptr) shape.place_mesh();
    }

    const PlacedShape &shape() const { return shape_; }
    int32_t root() const { return 0; }
    bool leaf(int32_t node) const { return tree_ == nullptr || tree_->node(node).is_leaf(); }
    int32_t left(int32_t node) const { return tree_->node(node).left; }
    int32_t right(int32_t node) const { return tree_->node(node).right; }
    // The node's map-frame box grown by the padding (the shape's own box
    // for a single piece).
    Aabb bounds(int32_t node) const {
        if (tree_ == nullptr) return shape_.box;
        Aabb box = tree_->node(node).box;
        box.inflate(shape_.inflation);
        return box;
    }
    Convex piece(int32_t node) const {
        return tree_ == nullptr ? shape_.core : shape_.triangle(tree_->node(node).item);
    }
    double size(int32_t node) const { return bounds(node).half_extent().squaredNorm(); }

private:
    const PlacedShape &shape_;
    const AabbTree *tree_;
};

// About the pair's size, for GJK's rounding floor (GjkPairQuery::scale).
inline double pair_scale(const PlacedShape &a, const PlacedShape &b) {
    return std::max(a.box.half_extent().norm(), b.box.half_extent().norm());
}

}  // namespace octoprox
