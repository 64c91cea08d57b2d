#include "oracle_cost.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oracle {
namespace {

// Larger than the ambiguity bands: a cell farther than this from a shape's
// bounds is certainly not touched.
constexpr double kMargin = 1e-4;

AlignedBox empty_box() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {Vec3::Constant(inf), Vec3::Constant(-inf)};
}

void grow(AlignedBox &box, const Vec3 &low, const Vec3 &high) {
    box.lo = box.lo.cwiseMin(low);
    box.hi = box.hi.cwiseMax(high);
}

// The padded shape's axis-aligned bounds, from its description: sphere
// centre +-(r + pad); box |R| half + pad; cylinder per axis
// hl |a_i| + r sqrt(1 - a_i^2) + pad; capsule ends +-(r + pad); hull
// vertices +-pad; mesh vertices used by a triangle +-pad.
AlignedBox shape_bounds(const ShapeSpec &spec, const Eigen::Isometry3d &link_pose, double pad) {
    const Eigen::Isometry3d frame = link_pose * isometry_of(spec.pose);
    const Vec3 c = frame.translation();
    const Mat3 R = frame.linear();
    Vec3 reach = Vec3::Zero();
    AlignedBox box = empty_box();
    switch (spec.kind) {
    case OPX_SHAPE_SPHERE: reach = Vec3::Constant(spec.radius); break;
    case OPX_SHAPE_BOX: reach = R.cwiseAbs() * (0.5 * spec.size); break;
    case OPX_SHAPE_CYLINDER:
        for (int i = 0; i < 3; ++i) {
            const double a = R(i, 2);
            reach[i] = 0.5 * spec.length * std::abs(a) + spec.radius * std::sqrt(std::max(0.0, 1.0 - a * a));
        }
        break;
    case OPX_SHAPE_CAPSULE: {
        const Vec3 half_axis = R.col(2) * (0.5 * spec.length);
        for (const Vec3 &end : {Vec3(c - half_axis), Vec3(c + half_axis)})
            grow(box, end - Vec3::Constant(spec.radius + pad), end + Vec3::Constant(spec.radius + pad));
        return box;
    }
    case OPX_SHAPE_MESH:  // a mesh is its triangles: only the vertices they use
        for (const auto &t : spec.triangles)
            for (uint32_t k : t)
                grow(box, frame * spec.vertices[k] - Vec3::Constant(pad), frame * spec.vertices[k] + Vec3::Constant(pad));
        return box;
    default:  // convex: every vertex
        for (const Vec3 &v : spec.vertices) grow(box, frame * v - Vec3::Constant(pad), frame * v + Vec3::Constant(pad));
        return box;
    }
    grow(box, c - reach - Vec3::Constant(pad), c + reach + Vec3::Constant(pad));
    return box;
}

// The part of the cell that counts, or false when none does.  `flat`: an
// unknown cube that only touches the region (within rounding: the oracle's
// and the library's cell faces may differ in the last bit), whether it
// counts (as a box of volume ~0) is not decided.
bool cost_region(const MapCell &cell, const CostSettings &s, AlignedBox &region, double &p, int32_t &cell_class,
                 bool &flat) {
    flat = false;
    if (cell.unknown()) {
        if (s.unknown_occupied) return false;
        bool empty = false;
        region = intersect(aligned_box_of(cell.cell), s.region, empty);
        const double rounding = 1e-9 * cell.size;
        const Vec3 extent = region.hi - region.lo;
        if (extent.minCoeff() < -rounding) return false;
        flat = extent.minCoeff() <= rounding;
        region.hi = region.hi.cwiseMax(region.lo);
        p = s.unknown_probability, cell_class = OPX_CELL_UNKNOWN;
        return true;
    }
    if (cell.log_odds >= s.threshold_log_odds || cell.log_odds < s.free_log_odds) return false;
    region = aligned_box_of(cell.cell);
    p = cell.probability, cell_class = OPX_CELL_UNCERTAIN;
    return true;
}

double gap(const AlignedBox &a, const Vec3 &low, const Vec3 &high) {
    return (a.lo - high).cwiseMax(low - a.hi).cwiseMax(0.0).norm();
}

}  // namespace

std::vector<AlignedBox> link_bounds(const RobotSpec &robot) {
    std::vector<AlignedBox> out(robot.links.size(), empty_box());
    for (size_t i = 0; i < robot.links.size(); ++i) {
        const LinkSpec &link = robot.links[i];
        if (!link.enabled) continue;
        for (const ShapeSpec &spec : link.shapes) {
            const AlignedBox b = shape_bounds(spec, isometry_of(link.pose), link.padding + robot.global_padding);
            grow(out[i], b.lo, b.hi);
        }
    }
    return out;
}

AlignedBox known_bounds(const std::vector<opx_leaf> &leaves, bool &empty) {
    AlignedBox box = empty_box();
    for (const opx_leaf &leaf : leaves) {
        const Vec3 center(leaf.center[0], leaf.center[1], leaf.center[2]);
        grow(box, center - Vec3::Constant(0.5 * leaf.size), center + Vec3::Constant(0.5 * leaf.size));
    }
    empty = leaves.empty();
    return box;
}

CostAnswer oracle_cost(const RobotSpec &robot, const std::vector<PlacedShape> &placed, const CellIndex &cells,
                       const CostSettings &settings) {
    CostAnswer answer;
    const std::vector<AlignedBox> bounds = link_bounds(robot);
    std::vector<uint32_t> near;
    for (const PlacedShape &shape : placed) {
        const Vec3 low = shape.bounds_min - Vec3::Constant(kMargin), high = shape.bounds_max + Vec3::Constant(kMargin);
        cells.candidates(low, high, near);
        for (uint32_t index : near) {
            const MapCell &cell = cells.cells()[index];
            const LinkCell key{shape.link, cell.key};
            if (answer.pairs.count(key)) continue;  // already certain
            AlignedBox region;
            double p = 0.0;
            int32_t cell_class = 0;
            bool flat = false;
            if (!cost_region(cell, settings, region, p, cell_class, flat) || gap(region, low, high) > 0.0) continue;
            const Verdict verdict = judge(shape, shape_aligned_distance(shape, region));
            if (verdict == Verdict::kClear) continue;
            bool unused = false;
            CostPair pair{shape.link, &cell, intersect(region, bounds[shape.link], unused), p, 0.0, cell_class};
            pair.cost = p * pair.box.volume();
            (verdict == Verdict::kTouch && !flat ? answer.pairs : answer.ambiguous)[key] = pair;
        }
    }
    for (const auto &entry : answer.pairs) {
        answer.ambiguous.erase(entry.first);
        answer.total += entry.second.cost;
    }
    for (const auto &entry : answer.ambiguous) answer.ambiguous_total += entry.second.cost;
    return answer;
}

}  // namespace oracle
