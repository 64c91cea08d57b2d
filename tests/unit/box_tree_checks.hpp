// Checks of BoxTree states against their definition and brute force.
#pragma once

#include "broadphase/aabb_tree.hpp"
#include "broadphase/box_tree.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace unit {

// Empty when the tree is a valid tree over `boxes`: 2n - 1 nodes, every item
// in exactly one leaf whose box is the item's, each inner box exactly the
// union of its children's, parent links and heights consistent, no leaf
// deeper than BoxTree::kMaxDepth.  Otherwise the first problem found.
std::string check_tree(const octoprox::BoxTree &tree, const std::vector<octoprox::Aabb> &boxes);

// Items overlapping `query`, ascending: by brute force and through the tree.
std::vector<int32_t> brute_overlaps(const std::vector<octoprox::Aabb> &boxes, const octoprox::Aabb &query);
std::vector<int32_t> tree_overlaps(const octoprox::BoxTree &tree, const octoprox::Aabb &query);

// Smallest squared box distance to `query`: brute force and through the
// tree's nearest-first search.
double brute_nearest(const std::vector<octoprox::Aabb> &boxes, const octoprox::Aabb &query);
double tree_nearest(const octoprox::BoxTree &tree, const octoprox::Aabb &query);

// Query boxes: cubes of edge in [min_edge, max_edge] centred in `region`.
std::vector<octoprox::Aabb> random_queries(size_t n, const octoprox::Aabb &region, double min_edge,
                                           double max_edge, std::mt19937_64 &rng);

// Nodes whose box an overlap query tests, summed over the queries: what the
// SAH predicts, measured.
uint64_t nodes_tested(const octoprox::BoxTree &tree, const std::vector<octoprox::Aabb> &queries);
uint64_t nodes_tested(const octoprox::AabbTree &tree, const std::vector<octoprox::Aabb> &queries);

// Milliseconds of the fastest of `repeats` runs of f.
template <class F>
double best_milliseconds(int repeats, F &&f);

}  // namespace unit

#include <chrono>

template <class F>
double unit::best_milliseconds(int repeats, F &&f) {
    double best = 1e300;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        f();
        const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
    }
    return best;
}

namespace unit {

// The SAH cost (same normalisation as BoxTree::sah) of a top-down tree split
// by binned SAH (16 bins on the centres, all three axes), a stronger
// reference than the median split: where a good O(n log n) build lands.
octoprox::SahCost binned_sah_cost(const std::vector<octoprox::Aabb> &boxes);

}  // namespace unit
