// A map kept as a window around a moving sensor: each frame goes in, the
// map is cropped to the window and decayed.  The process's heap (every
// operator new, counted by bench/heap_meter.cpp) stays flat however far the
// sensor goes, where the same frames without the crop grow it.
#include "heap_meter.hpp"
#include "octree/sensor_octree.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

namespace {

using namespace octoprox;

// Points on a corridor's floor, walls and clutter around x (sensor frame
// = map frame shifted by x).
std::vector<double> corridor_frame(std::mt19937_64 &rng) {
    std::uniform_real_distribution<double> along(-2.0, 2.0), across(-1.5, 1.5), up(0.0, 2.5);
    std::vector<double> xyz;
    for (int i = 0; i < 800; ++i) {
        const int kind = i % 3;
        const double x = along(rng);
        const double y = kind == 0 ? across(rng) : (kind == 1 ? -1.5 : 1.5);
        const double z = kind == 0 ? -1.0 : up(rng) - 1.0;
        xyz.insert(xyz.end(), {x, y, z});
    }
    return xyz;
}

// Heap bytes after frames 10 and 30 of a drive along x.
std::pair<size_t, size_t> drive(bool window) {
    auto tree = unit::empty_octree(0.05);
    std::mt19937_64 rng(7);
    size_t at_10 = 0, at_40 = 0;
    for (int frame = 1; frame <= 30; ++frame) {
        const double x = 0.5 * frame;
        InsertSettings settings;
        settings.sensor_pose.translation = Vec3(x, 0.0, 1.0);
        unit::insert_xyz(*tree, corridor_frame(rng), settings);
        if (window) {
            CellRange keep;
            for (int axis = 0; axis < 3; ++axis) {
                const double centre = axis == 0 ? x : 0.0;
                keep.lo[axis] = clamped_key(centre - 3.0, 0.05);
                keep.hi[axis] = clamped_key(centre + 3.0, 0.05);
            }
            tree->crop(keep);
            tree->decay(0.2);
        }
        if (frame == 10) at_10 = bench::heap_live_bytes();
        if (frame == 30) at_40 = bench::heap_live_bytes();
    }
    return {at_10, at_40};
}

TEST(MapWindow, HeapStaysFlatWithACroppedWindow) {
    const auto [free_10, free_40] = drive(false);
    const auto [window_10, window_40] = drive(true);
    std::printf("heap at frames 10 and 30: %zu, %zu without the window; %zu, %zu with it\n", free_10, free_40,
                window_10, window_40);
    // Without the window the map grows with the distance driven...
    EXPECT_GT(free_40, free_10 + free_10 / 2) << free_10 << " -> " << free_40;
    // ...with it, the heap after 30 frames is within a fifth of frame 10's.
    EXPECT_LT(window_40, window_10 + window_10 / 5) << window_10 << " -> " << window_40;
}

}  // namespace
