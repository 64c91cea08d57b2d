// Penetration answers against the depth oracle (oracle_depth.hpp), per
// configuration of a robot in a scene:
//  - every contact of opx_query_collide with compute_penetration = 1: its
//    depth (exact kinds: 1e-9), a unit normal, moving the shape by
//    -(depth + margin) * normal separates it from the cell and by
//    -(depth - margin) * normal does not (margin 1e-7; cylinders 1e-4, their
//    depth is not measured), and its point midway between a point of the
//    padded surface and a point of the cell's surface, depth apart;
//  - opx_query_distance with signed_distance = 1: minus the deepest
//    (shape, cell) depth when something touches, else the exact distance,
//    with witnesses |distance| apart.
#pragma once

#include "oracle_scenes.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

struct DepthCase {
    const Scene *scene = nullptr;
    const RobotSpec *robot = nullptr;
    const std::vector<PlacedShape> *placed = nullptr;
    double threshold = 0.0;  // the request's (0: the octree's)
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
    std::string label;
};

class DepthReport {
public:
    explicit DepthReport(std::string name) : name_(std::move(name)) {}
    // Printed in full: the first few per shape kind (`kind`, 0: none).
    void mismatch(const std::string &message, int32_t kind = 0);
    int finish(double seconds) const;

    uint64_t configurations = 0, contacts = 0, exact_depths = 0, core_overlaps = 0, ball_only = 0;
    uint64_t sphere_centre_inside = 0, cylinder_contacts = 0, by_kind[7] = {};
    uint64_t mesh_contacts = 0, mesh_not_separated = 0;  // a surface: per triangle only
    uint64_t signed_checks = 0, signed_penetrating = 0, signed_with_cylinder = 0, signed_undecided = 0;
    uint64_t mismatches = 0, contact_mismatches[7] = {}, signed_mismatches[7] = {};
    double worst_unit_error = 0.0;

private:
    std::string name_;
    uint64_t printed_[7] = {};
};

// Both checks for one configuration (the link set already holds it).
void check_penetration(opx_query *query, const opx_linkset *links, const DepthCase &c, DepthReport &report);

}  // namespace oracle
