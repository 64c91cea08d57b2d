// Signed sphere distances (query/spheres/sphere_distance.hpp) against a
// brute force over every obstacle box of the map: outside, the nearest of
// all boxes; inside, the nearest free part of the arrangement the boxes'
// faces cut around the centre (each elementary box either in some
// obstacle box or free).  Random maps with pruned blocks, both obstacle
// models, centres on cell faces, edges and corners, gradients against
// central differences, truncation, and the geb079 map.
#include "octree/octree_cell.hpp"
#include "octree/point_extent.hpp"
#include "octree/traverse.hpp"
#include "query/spheres/sphere_distance.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using octoprox::Aabb;
using octoprox::CellKey;
using octoprox::OctreeView;
using octoprox::SensorOctree;
using octoprox::SphereDistance;
using octoprox::Vec3;

constexpr double kExact = 1e-9;
constexpr double kInf = std::numeric_limits<double>::infinity();

octoprox::InsertSettings from_origin() { return octoprox::InsertSettings{}; }

// Planes of points and solid 8-cell blocks (pruned into coarse leaves).
std::unique_ptr<SensorOctree> random_map(uint64_t seed, double res) {
    auto tree = unit::empty_octree(res);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> xyz;
    for (int plane = 0; plane < 3; ++plane) {
        const Vec3 origin(1.5 + 0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng));
        const Vec3 a = 0.4 * Vec3(u(rng), u(rng), u(rng)), b = 0.4 * Vec3(u(rng), u(rng), u(rng));
        for (int i = 0; i < 1500; ++i) {
            const Vec3 p = origin + a * u(rng) + b * u(rng);
            xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
        }
    }
    for (int block = 0; block < 2; ++block) {
        const Vec3 corner(res * 8 * std::floor(3.0 + 2 * u(rng)), res * 8 * std::floor(2 * u(rng)),
                          res * 8 * std::floor(2 * u(rng)));
        for (int x = 0; x < 8; ++x)
            for (int y = 0; y < 8; ++y)
                for (int z = 0; z < 8; ++z) {
                    const Vec3 p = corner + res * Vec3(x + 0.5, y + 0.5, z + 0.5);
                    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
                }
    }
    for (int f = 0; f < 5; ++f) unit::insert_xyz(*tree, xyz, from_origin());
    return tree;
}

// Every obstacle box, decoded from the map independently of the search.
std::vector<Aabb> obstacle_boxes(const SensorOctree &tree, const octoprox::SphereSettings &s) {
    std::vector<Aabb> boxes;
    const OctreeView view = tree.view();
    octoprox::for_each_leaf(view, [&](OctreeView::NodeRef node, const CellKey &key) {
        if (view.log_odds(node) < s.threshold_log_odds) return;
        const Aabb cube = octoprox::cell_box(key, view.resolution());
        Aabb box = cube;
        const uint32_t packed = s.point_extents ? view.point_extent(node) : 0;
        if (packed != 0) {
            const double slot = (cube.hi.x() - cube.lo.x()) / 32.0;
            for (int a = 0; a < 3; ++a) {
                const int lo = octoprox::extent::lo(packed, a), hi = octoprox::extent::hi(packed, a);
                if (lo > 0) box.lo[a] = cube.lo[a] + slot * lo;
                if (hi < 31) box.hi[a] = cube.lo[a] + slot * (hi + 1);
            }
        }
        boxes.push_back(box);
    });
    return boxes;
}

double point_box(const Vec3 &p, const Aabb &b) {
    return (b.lo - p).cwiseMax(p - b.hi).cwiseMax(0.0).norm();
}

double nearest_box(const std::vector<Aabb> &boxes, const Vec3 &p) {
    double best = kInf;
    for (const Aabb &b : boxes) best = std::min(best, point_box(p, b));
    return best;
}

// The distance from p to the closure of the boxes' complement, found in
// the arrangement of the faces within `reach` of p; +infinity when the
// nearest free point is farther than reach.
double depth_in(const std::vector<Aabb> &boxes, const Vec3 &p, double reach) {
    const Aabb region{p - Vec3::Constant(reach), p + Vec3::Constant(reach)};
    std::vector<const Aabb *> near;
    std::vector<double> cut[3];
    for (int a = 0; a < 3; ++a) cut[a] = {region.lo[a], region.hi[a]};
    for (const Aabb &b : boxes) {
        if (!b.overlaps(region)) continue;
        near.push_back(&b);
        for (int a = 0; a < 3; ++a)
            for (double v : {b.lo[a], b.hi[a]})
                if (v > region.lo[a] && v < region.hi[a]) cut[a].push_back(v);
    }
    for (auto &c : cut) {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
    }
    const size_t nx = cut[0].size() - 1, ny = cut[1].size() - 1, nz = cut[2].size() - 1;
    std::vector<char> covered(nx * ny * nz, 0);
    auto range = [&](int a, double lo, double hi, size_t &first, size_t &last) {
        first = std::lower_bound(cut[a].begin(), cut[a].end(), lo) - cut[a].begin();
        last = std::lower_bound(cut[a].begin(), cut[a].end(), hi) - cut[a].begin();  // exclusive
    };
    for (const Aabb *b : near) {
        size_t f[3], l[3];
        for (int a = 0; a < 3; ++a) range(a, std::max(b->lo[a], region.lo[a]), std::min(b->hi[a], region.hi[a]), f[a], l[a]);
        for (size_t z = f[2]; z < l[2]; ++z)
            for (size_t y = f[1]; y < l[1]; ++y)
                for (size_t x = f[0]; x < l[0]; ++x) covered[(z * ny + y) * nx + x] = 1;
    }
    double best = kInf;
    for (size_t z = 0; z < nz; ++z)
        for (size_t y = 0; y < ny; ++y)
            for (size_t x = 0; x < nx; ++x) {
                if (covered[(z * ny + y) * nx + x]) continue;
                const Aabb e{Vec3(cut[0][x], cut[1][y], cut[2][z]), Vec3(cut[0][x + 1], cut[1][y + 1], cut[2][z + 1])};
                best = std::min(best, point_box(p, e));
            }
    return best < reach ? best : kInf;
}

// The brute force's signed distance field at p.
double brute_sdf(const std::vector<Aabb> &boxes, const Vec3 &p, double reach) {
    const double out = nearest_box(boxes, p);
    return out > 0.0 ? out : -depth_in(boxes, p, reach);
}

octoprox::SphereDistanceSettings settings_for(const SensorOctree &tree, bool extents, double max_distance) {
    octoprox::SphereDistanceSettings s;
    s.map.threshold_log_odds = tree.view().bounds_threshold();
    s.map.point_extents = extents;
    s.max_distance = max_distance;
    return s;
}

SphereDistance ask(const SensorOctree &tree, const octoprox::ObstacleGrid *grid, const Vec3 &c, double r,
                   const octoprox::SphereDistanceSettings &s) {
    octoprox::SphereDistanceScratch scratch;
    return octoprox::sphere_distance(&tree, grid, nullptr, c, r, s, scratch);
}

// One sphere against the brute force: distance, witness and gradient.
// Returns false when the brute force could not decide (deeper than reach).
bool check(const SensorOctree &tree, const octoprox::ObstacleGrid *grid, const std::vector<Aabb> &boxes,
           const Vec3 &c, double r, const octoprox::SphereDistanceSettings &s, double reach) {
    const double sdf = brute_sdf(boxes, c, reach);
    if (sdf == -kInf) return false;
    const SphereDistance got = ask(tree, grid, c, r, s);
    const double expected = std::min(sdf - r, s.max_distance);
    EXPECT_NEAR(got.distance, expected, kExact) << "centre " << c.transpose() << " r " << r;
    if (sdf - r >= s.max_distance + kExact) {
        EXPECT_EQ(got.distance, s.max_distance);
        EXPECT_TRUE(got.gradient.isZero());
        EXPECT_TRUE(std::isnan(got.witness.x()));
        return true;
    }
    if (!(sdf - r < s.max_distance - kExact)) return true;  // at the limit within rounding
    EXPECT_NEAR(got.gradient.norm(), 1.0, 1e-12);
    EXPECT_NEAR((got.witness - c).norm(), std::abs(sdf), kExact) << "centre " << c.transpose();
    if (sdf > 0.0) {
        EXPECT_NEAR(nearest_box(boxes, got.witness), 0.0, kExact);  // on an obstacle
        if (sdf > 1e-6) {
            EXPECT_LT((got.gradient - (c - got.witness) / sdf).norm(), 1e-9);
        }
    } else {
        // The witness is a free point: no depth.
        EXPECT_NEAR(depth_in(boxes, got.witness, reach), 0.0, kExact) << "centre " << c.transpose();
        if (sdf < -1e-6) {
            EXPECT_LT((got.gradient - (got.witness - c) / -sdf).norm(), 1e-9);
        }
    }
    return true;
}

Vec3 corner_of(const CellKey &key, double res) {
    return octoprox::cell_box(key, res).lo;
}

// Centres uniform near the obstacles, and on the faces, edges and corners
// of obstacle cells (and just off them).
std::vector<Vec3> centres_for(const SensorOctree &tree, uint64_t seed, size_t uniform, size_t on_cells) {
    std::vector<Vec3> out;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Aabb bounds;
    std::vector<CellKey> keys;
    const OctreeView view = tree.view();
    octoprox::for_each_leaf(view, [&](OctreeView::NodeRef node, const CellKey &key) {
        if (view.log_odds(node) < view.bounds_threshold()) return;
        bounds.grow(octoprox::cell_box(key, view.resolution()));
        keys.push_back(key);
    });
    bounds.inflate(0.2);
    for (size_t i = 0; i < uniform; ++i)
        out.push_back(bounds.lo + (bounds.hi - bounds.lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng))));
    const double res = view.resolution();
    for (size_t i = 0; i < on_cells && !keys.empty(); ++i) {
        const CellKey &key = keys[rng() % keys.size()];
        const double w = key.width_in_cells() * res;
        Vec3 p = corner_of(key, res);
        const int kind = int(i % 4);  // 0 corner, 1 edge, 2 face, 3 just off a face
        for (int a = 0; a < 3; ++a) {
            const double t = a < 3 - kind ? double(rng() % 2) : u(rng);
            p[a] += w * t;
        }
        if (kind == 3) p[rng() % 3] += (rng() % 2 ? 1 : -1) * 1e-7;
        out.push_back(p);
    }
    return out;
}

TEST(SphereDistance, MatchesBruteForceOnRandomMaps) {
    for (uint64_t seed = 1; seed <= 2; ++seed) {
        const double res = seed == 1 ? 0.05 : 0.1;
        const auto tree = random_map(seed, res);
        for (bool extents : {false, true}) {
            const auto s = settings_for(*tree, extents, 0.3);
            const auto boxes = obstacle_boxes(*tree, s.map);
            const auto grid = tree->obstacle_grid(s.map.threshold_log_odds);
            size_t decided = 0, inside = 0, total = 0;
            for (const Vec3 &c : centres_for(*tree, seed, 150, 150)) {
                for (double r : {0.0, 0.03}) {
                    const bool ok = check(*tree, grid.get(), boxes, c, r, s, 4 * res);
                    decided += ok;
                    ++total;
                    if (ok && nearest_box(boxes, c) == 0.0) ++inside;
                }
            }
            EXPECT_GT(decided, total * 9 / 10) << "seed " << seed;
            // Point extents leave fewer centres inside.
            EXPECT_GT(inside, total / 40) << "seed " << seed << " extents " << extents;
        }
    }
}

// The grid's searches give the octree's distances bit for bit, and the
// same gradients where the nearest point is unique.
TEST(SphereDistance, GridAnswersAsTheOctree) {
    const auto tree = random_map(3, 0.05);
    const auto s = settings_for(*tree, false, 0.1);
    const auto grid = tree->obstacle_grid(s.map.threshold_log_odds);
    ASSERT_NE(grid, nullptr);
    size_t inside = 0;
    for (const Vec3 &c : centres_for(*tree, 3, 2000, 400)) {
        const SphereDistance a = ask(*tree, grid.get(), c, 0.02, s), b = ask(*tree, nullptr, c, 0.02, s);
        EXPECT_EQ(a.distance, b.distance) << "centre " << c.transpose();
        inside += a.distance < -0.02;
        if (std::abs(a.distance + 0.02) > 1e-6) {
            EXPECT_LT((a.gradient - b.gradient).norm(), 1e-12) << c.transpose();
        }
    }
    EXPECT_GT(inside, 50u);
}

// Where the gradient field is continuous around a centre, the distance is
// differentiable there and its central differences match the gradient.
TEST(SphereDistance, GradientsMatchCentralDifferences) {
    const auto tree = random_map(4, 0.05);
    for (bool extents : {false, true}) {
        const auto s = settings_for(*tree, extents, 0.5);
        size_t compared = 0, total = 0;
        const double h = 1e-6;
        for (const Vec3 &c : centres_for(*tree, 4, 400, 0)) {
            const SphereDistance at = ask(*tree, nullptr, c, 0.02, s);
            if (at.gradient.isZero()) continue;
            ++total;
            Vec3 fd;
            bool smooth = true;
            for (int a = 0; a < 3; ++a) {
                Vec3 step = Vec3::Zero();
                step[a] = h;
                const SphereDistance plus = ask(*tree, nullptr, c + step, 0.02, s);
                const SphereDistance minus = ask(*tree, nullptr, c - step, 0.02, s);
                smooth = smooth && (plus.gradient - at.gradient).norm() < 1e-3 &&
                         (minus.gradient - at.gradient).norm() < 1e-3;
                fd[a] = (plus.distance - minus.distance) / (2 * h);
            }
            if (!smooth) continue;
            ++compared;
            EXPECT_LT((fd - at.gradient).norm(), 1e-6) << "centre " << c.transpose() << " fd " << fd.transpose()
                                                      << " gradient " << at.gradient.transpose();
        }
        EXPECT_GT(compared, total * 8 / 10);
    }
}

// Truncation is exact: on a binary-exact map, a sphere exactly at
// max_distance from a face is truncated, one a step nearer is not.
TEST(SphereDistance, TruncationIsExactAtMaxDistance) {
    auto tree = unit::empty_octree(0.125);
    unit::insert_xyz(*tree, {0.0625, 0.0625, 0.0625}, octoprox::InsertSettings{});  // the cell [0, 0.125]^3
    const auto s = settings_for(*tree, false, 0.25);
    const auto grid = tree->obstacle_grid(s.map.threshold_log_odds);
    for (const auto *g : {grid.get(), static_cast<const octoprox::ObstacleGrid *>(nullptr)}) {
        const SphereDistance at = ask(*tree, g, Vec3(0.125 + 0.25 + 0.5, 0.0625, 0.0625), 0.5, s);
        EXPECT_EQ(at.distance, 0.25);
        EXPECT_TRUE(at.gradient.isZero());
        const SphereDistance in = ask(*tree, g, Vec3(0.125 + 0.25 + 0.5 - 1.0 / 1024, 0.0625, 0.0625), 0.5, s);
        EXPECT_EQ(in.distance, 0.25 - 1.0 / 1024);
        EXPECT_EQ(in.gradient, Vec3::UnitX());
        EXPECT_EQ(in.witness, Vec3(0.125, 0.0625, 0.0625));
        // Inside: the depth to the nearest face; on a face, the face's normal.
        const SphereDistance deep = ask(*tree, g, Vec3(0.03125, 0.0625, 0.0625), 0.0, s);
        EXPECT_EQ(deep.distance, -0.03125);
        EXPECT_EQ(deep.gradient, -Vec3::UnitX());
        const SphereDistance face = ask(*tree, g, Vec3(0.125, 0.0625, 0.0625), 0.0, s);
        EXPECT_EQ(face.distance, 0.0);
        EXPECT_EQ(face.gradient, Vec3::UnitX());
        const SphereDistance corner = ask(*tree, g, Vec3(0.0, 0.125, 0.0), 0.0, s);
        EXPECT_EQ(corner.distance, 0.0);
        // At a corner: the faces between the cell and the free piece met
        // first, pointing away from the cell.
        EXPECT_NEAR(corner.gradient.norm(), 1.0, 1e-15);
        EXPECT_GT(corner.gradient.dot(Vec3(0.0, 0.125, 0.0) - Vec3::Constant(0.0625)), 0.0);
    }
}

TEST(SphereDistance, MatchesBruteForceOnGeb079) {
    const std::string path = unit::data_dir() + "/maps/geb079.bt";
    if (!unit::file_exists(path)) UNIT_SKIP_WITHOUT_DATA("geb079.bt not found");
    const auto tree = unit::read_octree(path);
    const auto s = settings_for(*tree, false, 0.5);
    const auto boxes = obstacle_boxes(*tree, s.map);
    const auto grid = tree->obstacle_grid(s.map.threshold_log_odds);
    size_t decided = 0, total = 0;
    for (const Vec3 &c : centres_for(*tree, 9, 20, 40)) {
        decided += check(*tree, grid.get(), boxes, c, 0.05, s, 0.5);
        ++total;
    }
    EXPECT_GT(decided, total * 9 / 10);
}

}  // namespace
