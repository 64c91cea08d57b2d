#include "oracle_nearest.hpp"

#include <algorithm>
#include <cmath>

namespace oracle {
namespace {

// Exact distances of one shape, the mesh ones allowed to skip triangles
// farther than `cutoff` (their result is then only known to exceed it).
PairDistance measure(const PlacedShape &shape, const Cell &cell, double cutoff) {
    PairDistance d;
    const uint64_t disagreements = curved_stats().disagreements;
    d.core = std::max(0.0, shape_cell_distance(shape, cell, cutoff));  // cylinders: -1 when deep
    d.doubt = curved_stats().disagreements != disagreements;
    d.padded = std::max(0.0, d.core - shape.inflation);
    return d;
}

double cylinder_point_distance(const Cylinder &c, const Vec3 &p) {
    const Vec3 local = c.axes.transpose() * (p - c.center);
    const double radial = std::hypot(local.x(), local.y()) - c.radius;
    const double axial = std::abs(local.z()) - 0.5 * c.length;
    return Eigen::Vector2d(radial, axial).cwiseMax(0.0).norm();
}

Nearest nearest_for_shape(const PlacedShape &shape, const std::vector<const MapCell *> &obstacles,
                          uint64_t &exact_pairs) {
    Nearest best;
    if (obstacles.empty()) return best;
    std::vector<std::pair<double, const MapCell *>> gaps;
    gaps.reserve(obstacles.size());
    for (const MapCell *cell : obstacles) gaps.push_back({bounds_gap(shape, cell->cell), cell});
    // An upper bound first (the cell of the smallest gap), so that only the
    // cells whose gap is below it are sorted and measured.
    const auto first = std::min_element(gaps.begin(), gaps.end());
    const PairDistance d0 = measure(shape, first->second->cell, kNoDistance);
    ++exact_pairs;
    best = {d0.padded, d0.core, &shape, first->second, false};
    std::vector<std::pair<double, const MapCell *>> near;
    for (const auto &g : gaps)
        if (g.first <= best.distance && g.second != first->second) near.push_back(g);
    std::sort(near.begin(), near.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    std::vector<double> doubtful;  // padded distances of arbitrated cylinder pairs
    if (d0.doubt) doubtful.push_back(d0.padded);
    for (const auto &[gap, cell] : near) {
        if (gap > best.distance || best.distance == 0.0) break;
        const PairDistance d = measure(shape, cell->cell, best.core + 1e-6);
        ++exact_pairs;
        if (d.doubt) doubtful.push_back(d.padded);
        if (d.padded < best.distance) best = {d.padded, d.core, &shape, cell, false};
    }
    for (double value : doubtful) best.doubt |= value <= best.distance + kCurvedAmbiguity;
    return best;
}

}  // namespace

PairDistance pair_distance(const PlacedShape &shape, const Cell &cell) { return measure(shape, cell, kNoDistance); }

double point_core_distance(const PlacedShape &s, const Vec3 &p) {
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: return (p - s.point).norm();
    case OPX_SHAPE_CAPSULE: return (p - closest_point_on_segment(p, s.segment)).norm();
    case OPX_SHAPE_BOX: return point_box_distance(p, s.box);
    case OPX_SHAPE_CYLINDER: return cylinder_point_distance(s.cylinder, p);
    case OPX_SHAPE_CONVEX: {
        const std::vector<Vec3> &v = s.hull.vertices;
        if (v.size() == 1) return (p - v[0]).norm();
        if (v.size() == 2) return (p - closest_point_on_segment(p, {v[0], v[1]})).norm();
        if (v.size() == 3) return point_triangle_distance(p, {v[0], v[1], v[2]});
        return point_polytope_distance(p, s.hull);
    }
    case OPX_SHAPE_MESH: {
        double best = kNoDistance;
        for (const Triangle &t : s.triangles) best = std::min(best, point_triangle_distance(p, t));
        return best;
    }
    }
    return kNoDistance;
}

std::vector<const MapCell *> obstacle_cells(const CellIndex &cells, const ObstacleRule &rule) {
    std::vector<const MapCell *> out;
    for (const MapCell &cell : cells.cells())
        if (rule(cell)) out.push_back(&cell);
    return out;
}

NearestAnswer oracle_nearest(const std::vector<PlacedShape> &placed, size_t link_count,
                             const std::vector<const MapCell *> &obstacles) {
    NearestAnswer answer;
    answer.per_link.resize(link_count);
    for (const PlacedShape &shape : placed) {
        const Nearest n = nearest_for_shape(shape, obstacles, answer.exact_pairs);
        answer.per_shape.push_back(n);
        Nearest &link = answer.per_link.at(shape.link);
        if (n.distance < link.distance) link = n;
        if (n.distance < answer.overall.distance) answer.overall = n;
    }
    // Doubt spreads to the minimum it could have been below.
    for (const Nearest &n : answer.per_shape) {
        if (!n.doubt) continue;
        Nearest &link = answer.per_link.at(n.shape->link);
        link.doubt |= n.distance <= link.distance + kCurvedAmbiguity;
        answer.overall.doubt |= n.distance <= answer.overall.distance + kCurvedAmbiguity;
    }
    return answer;
}

}  // namespace oracle
