#include "expected_map.hpp"

#include "real_support.hpp"

#include <cmath>
#include <cstring>

namespace filter_oracle {
namespace {

constexpr double kFaceTolerance = 1e-6;  // metres from a cut point

octomap::point3d to_float(const Vec3 &p) {
    return octomap::point3d(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
}

void insert_keys(const octomap::KeyRay &ray, octomap::KeySet &to) { to.insert(ray.begin(), ray.end()); }

// Every cell within kFaceTolerance of `c` (per axis), when that is more
// than its own cell.
void tolerate_around(const octomap::OcTree &tree, const octomap::point3d &c, std::unordered_set<uint64_t> &tolerated,
                     size_t &count) {
    octomap::OcTreeKey centre, key;
    if (!tree.coordToKeyChecked(c, centre)) return;
    bool near_face = false;
    for (int corner = 0; corner < 8; ++corner) {
        const octomap::point3d shifted(c.x() + static_cast<float>((corner & 1 ? 1 : -1) * kFaceTolerance),
                                       c.y() + static_cast<float>((corner & 2 ? 1 : -1) * kFaceTolerance),
                                       c.z() + static_cast<float>((corner & 4 ? 1 : -1) * kFaceTolerance));
        if (!tree.coordToKeyChecked(shifted, key) || key == centre) continue;
        near_face = true;
        tolerated.insert(packed(key));
    }
    if (!near_face) return;
    tolerated.insert(packed(centre));
    ++count;
}

// Every cell an ambiguous ray may touch: its whole ray and its end.
void tolerate_ray(const octomap::OcTree &tree, const octomap::point3d &origin, const octomap::point3d &end,
                  std::unordered_set<uint64_t> &tolerated) {
    octomap::KeyRay ray;
    octomap::OcTreeKey key;
    if (tree.computeRayKeys(origin, end, ray))
        for (const octomap::OcTreeKey &k : ray) tolerated.insert(packed(k));
    if (tree.coordToKeyChecked(end, key)) tolerated.insert(packed(key));
}

}  // namespace

Vec3 as_double(const octomap::point3d &p) { return Vec3(p.x(), p.y(), p.z()); }

std::vector<Vec3> as_doubles(const std::vector<octomap::point3d> &points) {
    std::vector<Vec3> out;
    out.reserve(points.size());
    for (const octomap::point3d &p : points) out.push_back(as_double(p));
    return out;
}

uint64_t packed(const octomap::OcTreeKey &key) {
    return uint64_t{key[0]} | (uint64_t{key[1]} << 16) | (uint64_t{key[2]} << 32);
}

opx_insert_report insert_frame(opx_octree *tree, const MapFrame &frame, opx_insert_options options) {
    const Vec3 origin = as_double(frame.origin);
    std::vector<double> xyz;
    xyz.reserve(3 * frame.points.size());
    for (const octomap::point3d &p : frame.points)
        for (int a = 0; a < 3; ++a) xyz.push_back(double{p(a)} - origin[a]);
    const opx_pose identity = OPX_POSE_IDENTITY;
    options.sensor_pose = identity;
    for (int a = 0; a < 3; ++a) options.sensor_pose.position[a] = origin[a];
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    real::check_ok(opx_octree_insert_points(tree, xyz.data(), frame.points.size(), 0, OPX_SCALAR_FLOAT64, &options,
                                            &report),
                   "opx_octree_insert_points");
    return report;
}

Expected expected_map(double resolution, const MapFrame &frame, const std::vector<Verdict> &verdicts) {
    Expected out;
    out.tree = std::make_unique<octomap::OcTree>(resolution);
    octomap::OcTree &tree = *out.tree;
    octomap::KeySet free_cells, occupied_cells;
    octomap::KeyRay ray;
    octomap::OcTreeKey key;
    const Vec3 origin = as_double(frame.origin);
    for (size_t i = 0; i < frame.points.size(); ++i) {
        const octomap::point3d &end = frame.points[i];
        const Verdict &v = verdicts[i];
        if (v.ambiguous) {
            tolerate_ray(tree, frame.origin, end, out.tolerated);
            ++out.ambiguous_rays;
            continue;
        }
        if (v.kind == Verdict::kKept) {
            if (tree.computeRayKeys(frame.origin, end, ray)) insert_keys(ray, free_cells);
            if (!v.range_cut && tree.coordToKeyChecked(end, key)) occupied_cells.insert(key);
            continue;
        }
        // As the library rounds its cut point: in double, then to float.
        const octomap::point3d cut = to_float(origin + v.t * (as_double(end) - origin));
        if (tree.computeRayKeys(frame.origin, cut, ray)) insert_keys(ray, free_cells);
        tolerate_around(tree, cut, out.tolerated, out.cuts_near_a_face);
    }
    for (const octomap::OcTreeKey &k : free_cells)
        if (occupied_cells.find(k) == occupied_cells.end()) tree.updateNode(k, false, false);
    for (const octomap::OcTreeKey &k : occupied_cells) tree.updateNode(k, true, false);
    return out;
}

MapDifference compare_maps(const opx_octree *ours, const Expected &expected) {
    const real::FineCells a = real::expand_octoprox(ours), b = real::expand_octomap(*expected.tree);
    MapDifference d;
    const auto note = [&](uint64_t key) {
        (expected.tolerated.count(key) ? d.tolerated_differing : d.differing) += 1;
    };
    for (const auto &cell : a) {
        const auto other = b.find(cell.first);
        ++d.cells;
        if (other == b.end() || std::memcmp(&other->second, &cell.second, sizeof(float)) != 0) note(cell.first);
    }
    for (const auto &cell : b)
        if (a.find(cell.first) == a.end()) ++d.cells, note(cell.first);
    return d;
}

}  // namespace filter_oracle
