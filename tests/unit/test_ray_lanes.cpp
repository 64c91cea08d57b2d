// The ray walk's lanes: four rays at a time (AVX2) mark the same cells as
// two (SSE2), in both layouts of the marks (bricks, rows), and
// ray_setup_four gives every ray's setup bit for bit as ray_setup does, on
// random rays and on rays through cell faces, edges and corners, along the
// axes and the diagonals.  The cells themselves are compared with OctoMap
// end to end by the ingest tests.
#include "base/avx2.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/frame_marks.hpp"
#include "octree/ray_setup.hpp"
#include "octree/ray_walk.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace {

using octoprox::BoundedOcTree;
using octoprox::FrameMarks;
using octoprox::KeyBox;
using octoprox::RayLanes;

struct Rays {
    octomap::point3d origin;
    octomap::OcTreeKey origin_key;
    std::vector<octomap::point3d> ends;
    std::vector<octomap::OcTreeKey> end_keys;
    KeyBox box;
};

Rays make_rays(const BoundedOcTree &tree, const octomap::point3d &origin, const std::vector<octomap::point3d> &ends) {
    Rays rays;
    rays.origin = origin;
    EXPECT_TRUE(tree.coordToKeyChecked(origin, rays.origin_key));
    const uint32_t o[3] = {rays.origin_key[0], rays.origin_key[1], rays.origin_key[2]};
    rays.box.grow(o);
    for (const octomap::point3d &end : ends) {
        octomap::OcTreeKey key;
        if (!tree.coordToKeyChecked(end, key)) continue;
        rays.ends.push_back(end);
        rays.end_keys.push_back(key);
        const uint32_t k[3] = {key[0], key[1], key[2]};
        rays.box.grow(k);
    }
    rays.box = rays.box.padded(8);
    return rays;
}

std::vector<uint64_t> walked_words(const BoundedOcTree &tree, const Rays &rays, RayLanes lanes,
                                   FrameMarks::Layout layout) {
    FrameMarks marks;
    marks.reset(rays.box, layout);
    std::vector<uint32_t> strays;
    octoprox::RayWalker(tree, rays.origin, rays.origin_key)
        .walk(rays.ends, rays.end_keys, 0, rays.ends.size(), marks, strays, lanes);
    EXPECT_TRUE(strays.empty());
    std::vector<uint64_t> words;
    for (size_t b = 0; b < marks.brick_count(); ++b) {
        uint64_t brick[octoprox::brick::kWords];
        marks.crossed_brick(b, brick);
        words.insert(words.end(), brick, brick + octoprox::brick::kWords);
    }
    return words;
}

std::vector<octomap::point3d> random_ends(std::mt19937 &rng, const octomap::point3d &origin, int count) {
    std::uniform_real_distribution<float> across(-3.0f, 3.0f);
    std::vector<octomap::point3d> ends;
    for (int i = 0; i < count; ++i) ends.push_back(origin + octomap::point3d(across(rng), across(rng), across(rng)));
    return ends;
}

// Points on faces, edges and corners, along the axes and the diagonals.
std::vector<octomap::point3d> tie_ends(float r, const octomap::point3d &origin) {
    std::vector<octomap::point3d> ends;
    for (int i = -6; i <= 6; ++i)
        for (int j = -6; j <= 6; ++j) {
            ends.emplace_back(i * r, j * r, 7.0f * r);
            ends.emplace_back(0.5f * i * r, -7.0f * r, j * r);
        }
    for (int k = 1; k <= 9; ++k)
        for (int sx = -1; sx <= 1; ++sx)
            for (int sy = -1; sy <= 1; ++sy)
                for (int sz = -1; sz <= 1; ++sz) ends.push_back(origin + octomap::point3d(sx, sy, sz) * (k * r));
    return ends;
}

void expect_same_setups(const BoundedOcTree &tree, const Rays &rays) {
    const octoprox::RayOrigin origin = octoprox::ray_origin(tree, rays.origin_key, rays.origin);
    for (size_t i = 0; i + 4 <= rays.ends.size(); i += 4) {
        const octomap::point3d *ends[4] = {&rays.ends[i], &rays.ends[i + 1], &rays.ends[i + 2], &rays.ends[i + 3]};
        octoprox::RaySetupFour four;
        octoprox::ray_setup_four(origin, ends, four);
        for (int lane = 0; lane < 4; ++lane) {
            const octoprox::RaySetup one = octoprox::ray_setup(origin, *ends[lane]);
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_EQ(std::memcmp(&one.next_face[axis], &four.next_face[axis][lane], sizeof(double)), 0);
                EXPECT_EQ(std::memcmp(&one.face_spacing[axis], &four.face_spacing[axis][lane], sizeof(double)), 0);
                EXPECT_EQ(one.step[axis], four.step[axis][lane]);
            }
            EXPECT_EQ(static_cast<double>(one.length), four.length[lane]);
        }
    }
}

void expect_same_lanes(const BoundedOcTree &tree, const Rays &rays) {
    if (!octoprox::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2: only two lanes run";
    expect_same_setups(tree, rays);
    const std::vector<uint64_t> two = walked_words(tree, rays, RayLanes::kTwo, FrameMarks::Layout::kBricks);
    EXPECT_EQ(two, walked_words(tree, rays, RayLanes::kFour, FrameMarks::Layout::kBricks));
    EXPECT_EQ(two, walked_words(tree, rays, RayLanes::kTwo, FrameMarks::Layout::kRows));
    EXPECT_EQ(two, walked_words(tree, rays, RayLanes::kFour, FrameMarks::Layout::kRows));
}

TEST(RayLanes, RandomRaysMarkTheSameCells) {
    std::mt19937 rng(11);
    for (const double resolution : {0.1, 0.05, 0.02}) {
        BoundedOcTree tree(resolution);
        const octomap::point3d origin(0.013f, -0.2f, 0.4f);
        expect_same_lanes(tree, make_rays(tree, origin, random_ends(rng, origin, 3001)));
    }
}

TEST(RayLanes, TiesMarkTheSameCells) {
    for (const double resolution : {0.1, 0.125, 0.05}) {
        const float r = static_cast<float>(resolution);
        BoundedOcTree tree(resolution);
        for (const octomap::point3d &origin :
             {octomap::point3d(0.0f, 0.0f, 0.0f), octomap::point3d(0.5f * r, 0.0f, 0.0f),
              octomap::point3d(0.5f * r, 0.5f * r, 0.5f * r)})
            expect_same_lanes(tree, make_rays(tree, origin, tie_ends(r, origin)));
    }
}

}  // namespace
