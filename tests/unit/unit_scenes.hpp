// Box sets for the broad-phase unit tests: random boxes, the paper's
// synthetic scene and the geb079 map, each as the cells a context binds.
#pragma once

#include "octree/cell_boxes.hpp"
#include "octree/sensor_octree.hpp"
#include "robot/shape.hpp"

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace unit {

// $OPX_DATA_DIR, else the compile-time default (tests/CMakeLists.txt).
std::string data_dir();
bool file_exists(const std::string &path);
// Whether OPX_REQUIRE_DATA=1 (CI sets it): a test then fails, not skips,
// when the shared data is absent (UNIT_SKIP_WITHOUT_DATA).
bool data_required();

}  // namespace unit

// Skips the running gtest for absent shared data, or fails it when the
// data is required.
#define UNIT_SKIP_WITHOUT_DATA(message)                                  \
    do {                                                                 \
        if (unit::data_required()) FAIL() << (message) << " (OPX_REQUIRE_DATA=1)"; \
        GTEST_SKIP() << (message);                                       \
    } while (0)

namespace unit {

// n boxes with centres uniform in [-extent, extent]^3 and edges in
// (0, max_edge].
std::vector<octoprox::Aabb> random_boxes(size_t n, double extent, double max_edge, std::mt19937_64 &rng);

// A random triangle soup: `vertices` points uniform in [-0.3, 0.3]^3
// moved by `offset`, `triangles` triangles over them, its tree built.
octoprox::ShapeDef random_mesh(std::mt19937_64 &rng, int vertices, int triangles,
                               const octoprox::Vec3 &offset = octoprox::Vec3::Zero());

// An empty octree of `resolution` metres, default parameters otherwise.
std::unique_ptr<octoprox::SensorOctree> empty_octree(double resolution);

// Paper section V: 7,784 distinct random cells of 0.2 m in [-20, 20]^3, each
// hit once (occupied), in a sensor octree.
std::unique_ptr<octoprox::SensorOctree> synthetic_octree(uint64_t seed);

// Inserts the points (x y z doubles, packed) with `settings`.
void insert_xyz(octoprox::SensorOctree &tree, const std::vector<double> &xyz, const octoprox::InsertSettings &settings);

// The map at `path` (.bt), default parameters (threshold 0.5).
std::unique_ptr<octoprox::SensorOctree> read_octree(const std::string &path);

// The occupied cells (log-odds >= log-odds of the occupancy threshold).
octoprox::CellBoxes occupied_cells(const octoprox::SensorOctree &tree);

}  // namespace unit
