// The oracle checks itself before it judges the library: hand-computed
// distances, agreement between its independent methods (a box as an
// oriented box and as a polytope), sampling upper bounds, FCL on clear
// polytope cases, and FCL's cylinder distance against inscribed and
// circumscribed prisms and an exact closed form.
#include "oracle_check.hpp"
#include "oracle_fcl.hpp"
#include "oracle_random.hpp"

#include <cmath>
#include <cstdio>
#include <string>

using namespace oracle;

namespace {

int failures = 0;
int checks = 0;
int fcl_indep_wrong = 0;

void expect_near(double got, double want, double tolerance, const std::string &what) {
    ++checks;
    if (std::abs(got - want) <= tolerance) return;
    if (++failures <= 10) std::printf("FAIL %s: got %.17g, want %.17g\n", what.c_str(), got, want);
}

void expect_true(bool ok, const std::string &what) {
    ++checks;
    if (!ok && ++failures <= 10) std::printf("FAIL %s\n", what.c_str());
}

const Cell kUnitCell{Vec3::Zero(), 0.5};

void hand_computed_cases() {
    expect_near(point_cell_distance(Vec3(2, 0, 0), kUnitCell), 1.5, 0, "point face");
    expect_near(point_cell_distance(Vec3(1, 1, 1), kUnitCell), std::sqrt(0.75), 1e-15, "point corner");
    expect_near(point_cell_distance(Vec3(0.1, 0.2, 0.3), kUnitCell), 0, 0, "point inside");
    expect_near(segment_cell_distance({Vec3(-2, 0.1, 0), Vec3(2, 0.1, 0)}, kUnitCell), 0, 0, "segment through");
    expect_near(segment_cell_distance({Vec3(-2, 1, 1), Vec3(2, 1, 1)}, kUnitCell), std::sqrt(0.5), 1e-15,
                "segment parallel to an edge");
    expect_near(segment_cell_distance({Vec3(1, -1, 0.6), Vec3(1, 1, 0.6)}, kUnitCell), std::sqrt(0.26), 1e-15,
                "segment skew");
    // A segment crossing the cell's corner region diagonally: closest to the edge.
    expect_near(segment_cell_distance({Vec3(1.5, 0, 0), Vec3(0, 1.5, 0)}, kUnitCell),
                (1.5 / std::sqrt(2.0)) - std::sqrt(0.5), 1e-15, "segment vs edge");
    expect_near(triangle_cell_distance({Vec3(-5, -5, 1), Vec3(5, -5, 1), Vec3(0, 5, 1)}, kUnitCell), 0.5, 1e-15,
                "triangle above");
    expect_near(triangle_cell_distance({Vec3(-5, -5, 0.5), Vec3(5, -5, 0.5), Vec3(0, 5, 0.5)}, kUnitCell), 0, 0,
                "triangle flush with a face");
    expect_near(triangle_cell_distance({Vec3(-5, -5, 0), Vec3(5, -5, 0), Vec3(0, 5, 0)}, kUnitCell), 0, 0,
                "triangle through, no vertex inside");
    // A big triangle whose plane cuts near the corner (1,1,1)/2 but misses it.
    const double offset = 1.5 + 0.1 * std::sqrt(3.0);  // plane x+y+z = offset
    expect_near(triangle_cell_distance({Vec3(offset, 0, 0) + Vec3(10, -5, -5), Vec3(offset, 0, 0) + Vec3(-5, 10, -5),
                                        Vec3(offset, 0, 0) + Vec3(-5, -5, 10)}, kUnitCell),
                0.1, 1e-14, "triangle facing a corner");
    OrientedBox box{Vec3(2, 0, 0), Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix(),
                    Vec3::Constant(0.5)};
    expect_near(box_cell_distance(box, kUnitCell), 2 - std::sqrt(0.5) - 0.5, 1e-15, "rotated box");
    box.center = Vec3(1.2, 0, 0);
    expect_near(box_cell_distance(box, kUnitCell), 0, 0, "rotated box overlapping");
    Polytope tetra{{Vec3(0.4, 0.4, 0.4), Vec3(3, 0, 0), Vec3(0, 3, 0), Vec3(0, 0, 3)},
                   {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};
    expect_near(polytope_cell_distance(tetra, kUnitCell), 0, 0, "hull vertex inside the cell");
    // The cell inside a big hull: solid, so 0 although no face is near.
    Polytope big{{Vec3(-10, -10, -10), Vec3(30, -10, -10), Vec3(-10, 30, -10), Vec3(-10, -10, 30)},
                 {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};
    expect_near(polytope_cell_distance(big, kUnitCell), 0, 0, "cell inside the hull");
    expect_near(segment_segment_distance({Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0.5, 1, -1), Vec3(0.5, 1, 1)}), 1,
                1e-15, "segments crossing");
    expect_near(segment_segment_distance({Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(2, 1, 0), Vec3(3, 1, 0)}),
                std::sqrt(2.0), 1e-15, "parallel segments apart");
}

Polytope box_as_polytope(const OrientedBox &box) {
    Polytope hull;
    for (const Vec3 &c : box_corners(box)) hull.vertices.push_back(c);
    // Two triangles per face; corner index bits are x, y, z.
    const int quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto &q : quads) hull.faces.push_back({q[0], q[1], q[2]}), hull.faces.push_back({q[0], q[2], q[3]});
    return hull;
}

OrientedBox random_box(Rng &rng) {
    return {rng.point(Vec3::Constant(-2), Vec3::Constant(2)), random_rotation(rng).toRotationMatrix(),
            Vec3(rng.uniform(0.01, 1), rng.uniform(0.01, 1), rng.uniform(0.01, 1))};
}

Cell random_cell(Rng &rng) { return {rng.point(Vec3::Constant(-1), Vec3::Constant(1)), rng.uniform(0.05, 0.5)}; }

// Points of the box sampled on its surface and inside: each gives an upper
// bound of the true distance.
double sampled_box_distance(Rng &rng, const OrientedBox &box, const Cell &cell) {
    double best = 1e300;
    for (int i = 0; i < 200; ++i) {
        Vec3 local = rng.point(-box.half, box.half);
        const int axis = i % 4;  // a point on a face, or (axis 3) inside
        if (axis < 3) local[axis] = rng.chance(0.5) ? box.half[axis] : -box.half[axis];
        best = std::min(best, point_cell_distance(box.center + box.axes * local, cell));
    }
    return best;
}

void random_polytope_cases(Rng &rng) {
    for (int i = 0; i < 3000; ++i) {
        const OrientedBox box = random_box(rng);
        const Cell cell = random_cell(rng);
        const double exact = box_cell_distance(box, cell);
        const std::string what = "random box " + std::to_string(i);
        expect_near(polytope_cell_distance(box_as_polytope(box), cell), exact, 1e-12, what + ": as a polytope");
        expect_true(exact <= sampled_box_distance(rng, box, cell) + 1e-12, what + ": above a sampled point");
        // FCL's libccd solver agrees; its GST_INDEP solver is sometimes off by
        // millimetres on box pairs (counted, printed: an FCL defect).
        if (exact > 1e-3) expect_near(fcl_box_cell_distance(box, cell, true), exact, 1e-6, what + ": FCL libccd");
        if (exact == 0.0) expect_near(fcl_box_cell_distance(box, cell, true), 0.0, 1e-9, what + ": FCL intersecting");
        if (exact > 1e-3 && std::abs(fcl_box_cell_distance(box, cell, false) - exact) > 1e-6) ++fcl_indep_wrong;
        // A disjoint closed hull and its surface are at the same distance.
        const ShapeSpec hull = random_convex(rng, 2.0);
        if (hull.hull_faces.empty()) continue;  // a point, segment or triangle
        Polytope solid{std::vector<Vec3>(hull.vertices.begin(), hull.vertices.begin() + hull.hull_vertex_count),
                       hull.hull_faces};
        double surface = 1e300;
        for (const auto &f : solid.faces)
            surface = std::min(surface, triangle_cell_distance({solid.vertices[f[0]], solid.vertices[f[1]],
                                                                solid.vertices[f[2]]}, cell));
        const double solid_distance = polytope_cell_distance(solid, cell);
        if (solid_distance > 0.0) expect_near(solid_distance, surface, 1e-12, what + ": hull vs its surface");
        else expect_true(surface == 0.0 || point_polytope_distance(cell.center, solid) == 0.0,
                         what + ": a hull touching the cell touches it with a face or holds it");
    }
}

void cylinder_cases(Rng &rng) {
    constexpr int kSides = 128;
    for (int i = 0; i < 1500; ++i) {
        const Cylinder c{rng.point(Vec3::Constant(-2), Vec3::Constant(2)), random_rotation(rng).toRotationMatrix(),
                         rng.uniform(0.01, 0.8), rng.uniform(0.01, 1.5)};
        const Cell cell = random_cell(rng);
        const double d = std::max(0.0, cylinder_cell_distance(c, cell));
        const double inner = polytope_cell_distance(cylinder_prism(c, kSides, c.radius), cell);
        const double outer = polytope_cell_distance(cylinder_prism(c, kSides, c.radius / std::cos(M_PI / kSides)), cell);
        expect_true(d >= outer - 1e-9 && d <= inner + 1e-9,
                    "cylinder " + std::to_string(i) + ": FCL " + std::to_string(d) + " outside the prisms [" +
                        std::to_string(outer) + ", " + std::to_string(inner) + "]");
    }
    // Axis along z, the cell level with it: distance = (xy distance) - radius.
    double worst = 0.0;
    for (int i = 0; i < 1500; ++i) {
        const Cell cell = random_cell(rng);
        const Vec3 center(rng.uniform(-2, 2), rng.uniform(-2, 2), cell.center.z());
        const Cylinder c{center, Mat3::Identity(), rng.uniform(0.01, 0.8), rng.uniform(0.01, 1.5)};
        const Vec3 flat = ((c.center - cell.center).cwiseAbs() - Vec3::Constant(cell.half)).cwiseMax(0.0);
        const double exact = std::max(0.0, Vec3(flat.x(), flat.y(), 0).norm() - c.radius);
        const double d = std::max(0.0, cylinder_cell_distance(c, cell));
        worst = std::max(worst, std::abs(d - exact));
        expect_near(d, exact, 1e-7, "upright cylinder " + std::to_string(i));
    }
    std::printf("FCL upright-cylinder distance: worst error %.3g m\n", worst);
    const CurvedStats stats = curved_stats();
    std::printf("cylinder pairs measured %llu, FCL solvers disagreed on %llu (decided by prisms), unresolved %llu\n",
                (unsigned long long)stats.measured, (unsigned long long)stats.disagreements,
                (unsigned long long)stats.unresolved);
}

}  // namespace

int main() {
    const double start = elapsed_seconds();
    hand_computed_cases();
    Rng rng(env_number("OPX_ORACLE_SEED", 7));
    random_polytope_cases(rng);
    cylinder_cases(rng);
    std::printf("FCL GST_INDEP box-box distance off by > 1e-6 m on %d of 3000 random pairs (not a failure)\n",
                fcl_indep_wrong);
    std::printf("SUMMARY oracle_geometry: checks %d, failures %d, ambiguous 0; %.1f s\n", checks, failures,
                elapsed_seconds() - start);
    return failures == 0 ? 0 : 1;
}
