// The distance between two padded shapes: a nearest-first walk over the
// pairs of their pieces' trees (PlacedSide: map-frame boxes), pruned by the
// best distance so far.
#include "narrowphase/convex_pair.hpp"
#include "narrowphase/pair_sides.hpp"
#include "narrowphase/shape_pair.hpp"

#include <cmath>

namespace octoprox {
namespace {

struct Entry {
    int32_t a, b;
    double lower;  // the boxes' distance: no pair of pieces below is nearer
};
// As in shape_pair.cpp: each split adds one entry to at most 2 x 33 levels.
constexpr int kEntryStack = 160;

class PairSearch {
public:
    PairSearch(const PlacedShape &a, const PlacedShape &b, double bound, uint64_t &tests)
        : a_(a), b_(b), scale_(pair_scale(a, b)), bound_(bound), tests_(tests) {}

    bool run(ShapePairDistance &out) {
        push(a_.root(), b_.root());
        while (top_ > 0) {
            const Entry e = stack_[--top_];
            if (e.lower >= bound_) continue;
            const bool a_leaf = a_.leaf(e.a), b_leaf = b_.leaf(e.b);
            if (a_leaf && b_leaf) {
                if (measure(e, out) && bound_ <= 0.0) return true;
                continue;
            }
            if (b_leaf || (!a_leaf && a_.size(e.a) >= b_.size(e.b)))
                push_nearer_last({a_.left(e.a), e.b, 0.0}, {a_.right(e.a), e.b, 0.0});
            else
                push_nearer_last({e.a, b_.left(e.b), 0.0}, {e.a, b_.right(e.b), 0.0});
        }
        return found_;
    }

private:
    double lower(int32_t na, int32_t nb) const {
        const double squared = a_.bounds(na).squared_distance(b_.bounds(nb));
        // Squares only where they cannot underflow (signed searches pass 1e-300).
        if (bound_ > 1e-100 && squared >= bound_ * bound_) return bound_;
        return std::sqrt(squared);
    }
    void push(int32_t na, int32_t nb) { stack_[top_++] = {na, nb, lower(na, nb)}; }
    void push_nearer_last(Entry x, Entry y) {
        x.lower = lower(x.a, x.b), y.lower = lower(y.a, y.b);
        const bool x_nearer = x.lower <= y.lower;
        stack_[top_++] = x_nearer ? y : x;
        stack_[top_++] = x_nearer ? x : y;
    }
    bool measure(const Entry &e, ShapePairDistance &out) {
        ++tests_;
        const Convex pa = a_.piece(e.a), pb = b_.piece(e.b);
        PiecePairDistance d;
        if (!piece_pair_distance({&pa, a_.shape().inflation}, {&pb, b_.shape().inflation}, scale_, bound_, d))
            return false;
        out.distance = d.distance, out.on_a = d.on_a, out.on_b = d.on_b;
        bound_ = d.distance, found_ = true;
        return true;
    }

    PlacedSide a_, b_;
    double scale_, bound_;
    uint64_t &tests_;
    bool found_ = false;
    Entry stack_[kEntryStack];
    int top_ = 0;
};

}  // namespace

bool shape_pair_distance(const PlacedShape &a, const PlacedShape &b, double bound, ShapePairDistance &out,
                         uint64_t &narrow_tests) {
    return PairSearch(a, b, bound, narrow_tests).run(out);
}

}  // namespace octoprox
