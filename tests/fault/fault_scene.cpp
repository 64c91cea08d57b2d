#include "fault_scene.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fault {

void require_ok(opx_status status, const char *what) {
    if (status == OPX_OK) return;
    std::printf("setup failed: %s: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    std::exit(1);
}

opx_query *new_query(int32_t engine) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.engine = engine;
    opx_query *query = nullptr;
    require_ok(opx_query_create(&options, &query), "opx_query_create");
    return query;
}

double Lcg::uniform(double lo, double hi) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    const double unit = static_cast<double>(state_ >> 11) * (1.0 / 9007199254740992.0);
    return lo + (hi - lo) * unit;
}

const double kSensorPosition[3] = {0.0, 0.0, 1.2};

namespace {

void push_point(std::vector<float> &cloud, double x, double y, double z) {
    // Map frame to sensor frame: the sensor is only translated.
    cloud.push_back(static_cast<float>(x - kSensorPosition[0]));
    cloud.push_back(static_cast<float>(y - kSensorPosition[1]));
    cloud.push_back(static_cast<float>(z - kSensorPosition[2]));
}

// One point of surface `which` (map frame).
void surface_point(std::vector<float> &cloud, int which, Lcg &random) {
    switch (which) {
    case 0:  // floor
        push_point(cloud, random.uniform(0.2, 2.0), random.uniform(-1.2, 1.2), 0.0);
        break;
    case 1:  // wall
        push_point(cloud, 2.0, random.uniform(-1.2, 1.2), random.uniform(0.0, 1.4));
        break;
    case 2:  // top and front of a box on the floor
        if (random.uniform(0.0, 1.0) < 0.5)
            push_point(cloud, random.uniform(0.9, 1.3), random.uniform(-0.1, 0.3), 0.5);
        else
            push_point(cloud, 0.9, random.uniform(-0.1, 0.3), random.uniform(0.0, 0.5));
        break;
    default: {  // a ball, the side facing the sensor
        const double theta = random.uniform(1.6, 4.7), z = random.uniform(-0.2, 0.2);
        const double r = std::sqrt(0.04 - z * z);
        push_point(cloud, 1.0 + r * std::cos(theta), -0.6 + r * std::sin(theta), 0.8 + z);
    }
    }
}

}  // namespace

std::vector<float> room_cloud(size_t count, uint64_t seed) {
    Lcg random(seed);
    std::vector<float> cloud;
    cloud.reserve(3 * count);
    for (size_t i = 0; i < count; ++i) surface_point(cloud, static_cast<int>(i % 4), random);
    return cloud;
}

opx_insert_options sensor_insert_options(int32_t mode) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = mode;
    for (int axis = 0; axis < 3; ++axis) options.sensor_pose.position[axis] = kSensorPosition[axis];
    return options;
}

opx_octree_options map_options(double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    options.free_threshold = 0.3;
    return options;
}

opx_octree *room_map(double resolution, size_t points, uint64_t seed) {
    const opx_octree_options options = map_options(resolution);
    opx_octree *tree = nullptr;
    require_ok(opx_octree_create(&options, &tree), "opx_octree_create");
    const std::vector<float> cloud = room_cloud(points, seed);
    const opx_insert_options insert = sensor_insert_options(OPX_INSERT_RAYCAST);
    require_ok(opx_octree_insert_points(tree, cloud.data(), points, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
               "opx_octree_insert_points");
    return tree;
}

std::vector<unsigned char> map_image(const opx_octree *tree, int32_t format) {
    size_t size = 0;
    const opx_status sized = opx_octree_save_memory(tree, format, nullptr, 0, &size);
    if (sized != OPX_ERROR_BUFFER_TOO_SMALL) require_ok(sized, "opx_octree_save_memory (size)");
    std::vector<unsigned char> image(size);
    require_ok(opx_octree_save_memory(tree, format, image.data(), image.size(), &size), "opx_octree_save_memory");
    return image;
}

std::vector<double> room_boxes(size_t count, uint64_t seed) {
    Lcg random(seed);
    std::vector<double> boxes;
    for (size_t i = 0; i < count; ++i) {
        const double x = random.uniform(0.2, 2.0), y = random.uniform(-1.2, 1.2), z = random.uniform(0.0, 1.4);
        const double e = random.uniform(0.02, 0.2);
        const double box[6] = {x, y, z, x + e, y + random.uniform(0.02, 0.2), z + e};
        boxes.insert(boxes.end(), box, box + 6);
    }
    return boxes;
}

}  // namespace fault
