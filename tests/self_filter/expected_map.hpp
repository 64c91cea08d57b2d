// The map a self-filtered frame must give, built with OctoMap itself from
// the oracle's verdicts: kept points as OctoMap's insertPointCloud inserts
// them (computeRayKeys to the point free, the point's cell occupied, the
// occupied cells taken out of the free set), and each filtered point's ray
// cut at the oracle's cut point as a ray cut at max_range is (its
// computeRayKeys free, no occupied end).  A frame point that is a ray's
// cut at max_range (Verdict::range_cut) frees its ray and occupies
// nothing.  Cells the oracle cannot pin down are tolerated, and counted: those within 1e-6 m of a cut point (the
// library's cut may round to the other side) and every cell of an
// ambiguous ray.
#pragma once

#include "filter_oracle.hpp"

#include <octoprox/octoprox.h>

#include <octomap/OcTree.h>

#include <memory>
#include <unordered_set>
#include <vector>

namespace filter_oracle {

// One frame in the map frame, in float as OctoMap takes it.
struct MapFrame {
    octomap::point3d origin;
    std::vector<octomap::point3d> points;
};

std::vector<Vec3> as_doubles(const std::vector<octomap::point3d> &points);
Vec3 as_double(const octomap::point3d &p);

// The frame into the library's map: the sensor at frame.origin without a
// rotation, the points as float64 offsets from it (exact), so that the
// library's map points are the frame's floats.
opx_insert_report insert_frame(opx_octree *tree, const MapFrame &frame, opx_insert_options options);

// Packed finest key (x | y << 16 | z << 32, as real::FineCells).
uint64_t packed(const octomap::OcTreeKey &key);

struct Expected {
    std::unique_ptr<octomap::OcTree> tree;
    std::unordered_set<uint64_t> tolerated;
    size_t ambiguous_rays = 0, cuts_near_a_face = 0;
};
Expected expected_map(double resolution, const MapFrame &frame, const std::vector<Verdict> &verdicts);

struct MapDifference {
    size_t cells = 0;                // known cells in either map
    size_t differing = 0;            // outside the tolerated cells: must be 0
    size_t tolerated_differing = 0;  // tolerated cells that differ
};
MapDifference compare_maps(const opx_octree *ours, const Expected &expected);

}  // namespace filter_oracle
