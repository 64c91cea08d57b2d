#include "fcl_distance.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>

namespace paper_tables {
namespace {

fcl::DistanceRequestd distance_request(double distance_tolerance = kFclDefaultTolerance) {
    fcl::DistanceRequestd request;
    request.enable_nearest_points = true;
    request.distance_tolerance = distance_tolerance;
    request.gjk_solver_type = fcl::GST_LIBCCD;  // FCL's default, stated
    return request;
}

// The callback's state: the request, and the minimum over the pairs seen.
struct MinimumDistance {
    explicit MinimumDistance(double distance_tolerance = kFclDefaultTolerance)
        : request(distance_request(distance_tolerance)) {}
    fcl::DistanceRequestd request;
    double minimum = std::numeric_limits<double>::infinity();
};

// fcl::distance on the pair; `dist` tells the broad phase the minimum so
// far (it prunes node pairs farther than that); true stops the traversal.
bool keep_minimum(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data, double &dist) {
    auto *state = static_cast<MinimumDistance *>(data);
    fcl::DistanceResultd result;
    fcl::distance(a, b, state->request, result);
    state->minimum = std::min(state->minimum, std::max(0.0, result.min_distance));
    dist = state->minimum;
    return state->minimum <= 0.0;
}

}  // namespace

double fcl_managers_distance(const FclManager &robot, FclManager &map, double distance_tolerance) {
    MinimumDistance state(distance_tolerance);
    robot.distance(&map, &state, keep_minimum);
    return state.minimum;
}

double fcl_octree_distance(const FclManager &robot, fcl::CollisionObjectd &octree) {
    MinimumDistance state;
    robot.distance(&octree, &state, keep_minimum);
    return state.minimum;
}

double fcl_pair_distance(const fcl::CollisionObjectd &a, const fcl::CollisionObjectd &b) {
    static const fcl::DistanceRequestd request = distance_request();
    fcl::DistanceResultd result;
    fcl::distance(&a, &b, request, result);
    return std::max(0.0, result.min_distance);
}

FclObjectPtr make_fcl_sphere(double radius) {
    return std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(radius));
}

std::shared_ptr<octomap::OcTree> read_octomap_binary(const std::string &path) {
    auto tree = std::make_shared<octomap::OcTree>(0.1);  // the file sets the resolution
    if (!tree->readBinary(path)) throw std::runtime_error("octomap readBinary failed on " + path);
    return tree;
}

}  // namespace paper_tables
