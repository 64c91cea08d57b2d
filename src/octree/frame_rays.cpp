// Built with -ffp-contract=off (src/CMakeLists.txt): the range test and the
// cut ray's end use OctoMap's float arithmetic, unfused.
#include "octree/frame_rays.hpp"

#include "base/avx2.hpp"
#include "base/error.hpp"
#include "base/parallel.hpp"
#include "broadphase/morton.hpp"
#include "broadphase/radix_sort.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/octree_view.hpp"
#include "octree/point_slots.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

// Frames whose box holds more cells than this (a megabyte of marks, the
// size of a core's L2 cache) walk their rays in the order of their ends.
constexpr uint64_t kOrderedAboveCells = uint64_t{1} << 23;
// Parts of the frame's points per thread when a clip cuts rays (see
// prepare_rays).
constexpr size_t kClipPartsPerThread = 16;

bool is_finite(const Vec3 &p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

octomap::point3d to_float(const Vec3 &p) {
    return octomap::point3d(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
}

// OctoMap's coordToKeyChecked, with the range tested on the double before
// it becomes an int (OctoMap converts first: undefined for far points).
class KeyMapper {
public:
    explicit KeyMapper(const BoundedOcTree &tree)
        : resolution_(tree.getResolution()), factor_(1.0 / tree.getResolution()) {}
    double resolution() const { return resolution_; }

    bool key(const octomap::point3d &p, octomap::OcTreeKey &out) const {
        for (int axis = 0; axis < 3; ++axis) {
            const double scaled = factor_ * p(axis);
            if (!(scaled >= -kHalf && scaled < kHalf)) return false;
            const int cell = static_cast<int>(std::floor(scaled));
            out[axis] = static_cast<octomap::key_type>(cell + static_cast<int>(kHalf));
        }
        return true;
    }

private:
    static constexpr double kHalf = kKeyCenter;  // OctoMap's tree_max_val
    double resolution_;
    double factor_;
};

// Once a point: inlined at both calls (GCC keeps one out-of-line copy otherwise).
// Neighbouring points of a scan mostly end in one cell: the box grows only
// when the key differs from the last ray's.
inline __attribute__((always_inline)) void add_ray(const octomap::point3d &end, const octomap::OcTreeKey &key,
                                                   RaySegment &rays, KeyBox &box) {
    if (rays.end_keys.empty() || !(rays.end_keys.back() == key)) {
        const uint32_t k[3] = {key[0], key[1], key[2]};
        box.grow(k);
    }
    rays.ends.push_back(end);
    rays.end_keys.push_back(key);
}

struct RayPart {
    RaySegment rays;
    std::vector<CellExtent> hit_extents;
    KeyBox box;
    InsertCounts counts;
};

// The extent of the points of one run of consecutive points in one cell
// (neighbouring points of a scan mostly share a cell): a run keeps the
// bounds of its coordinates and becomes one entry, in slots, when it ends;
// only the entries are sorted later.
class ExtentRuns {
public:
    ExtentRuns(double resolution, std::vector<CellExtent> &out) : slots_(resolution), out_(out) {}

    // A sensed point (map frame, before OctoMap's rounding to float) in the cell `key`.
    void add(const octomap::OcTreeKey &key, const Vec3 &point) {
        if (open_ && key == key_) {
            lo_ = lo_.cwiseMin(point), hi_ = hi_.cwiseMax(point);
            return;
        }
        flush();
        open_ = true, key_ = key, lo_ = point, hi_ = point;
    }

    // Ends the last run.
    void flush() {
        if (!open_) return;
        int lo[3], hi[3], unused;
        for (int axis = 0; axis < 3; ++axis) {
            slots_.of(key_[axis], lo_[axis], lo[axis], unused);
            slots_.of(key_[axis], hi_[axis], unused, hi[axis]);
        }
        out_.push_back(CellExtent{morton_encode(key_[0], key_[1], key_[2]), extent::pack(lo, hi)});
        open_ = false;
    }

private:
    extent::PointSlots slots_;
    std::vector<CellExtent> &out_;
    bool open_ = false;
    octomap::OcTreeKey key_;
    Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();
};

// A type, not a function, so that the sort inlines it.
struct ByCode {
    bool operator()(const CellExtent &a, const CellExtent &b) const { return a.code < b.code; }
};

// Merges each cell's entries, sorted by code, into one.
void merge_same_cells(std::vector<CellExtent> &extents) {
    size_t kept = 0;
    for (size_t i = 0; i < extents.size(); ++i) {
        if (kept > 0 && extents[kept - 1].code == extents[i].code)
            extents[kept - 1].packed = extent::merge(extents[kept - 1].packed, extents[i].packed);
        else
            extents[kept++] = extents[i];
    }
    extents.resize(kept);
}

Vec3 to_vec(const octomap::point3d &p) { return Vec3(p.x(), p.y(), p.z()); }

// Where the clip cuts the ray to `end` (map frame), rounded to float as
// OctoMap's points are; `end` itself when the ray is kept.
octomap::point3d clipped_end(const RayClip &clip, const InsertSettings &settings, const Vec3 &end,
                             bool end_is_point, RayCut::Kind *kind) {
    const RayCut cut = clip.cut(end, end_is_point);
    if (kind != nullptr) *kind = cut.kind;
    if (cut.kind == RayCut::kKeep) return to_float(end);
    const Vec3 &origin = settings.sensor_pose.translation;
    return to_float(origin + cut.t * (end - origin));
}

// The rays of points [begin, end).
inline __attribute__((always_inline)) void prepare_points(const KeyMapper &mapper, const PointSource &points,
                                                           const InsertSettings &settings,
                                                           const octomap::point3d &origin, size_t begin, size_t end,
                                                           RayPart &part) {
    const bool limited = settings.max_range > 0.0 && std::isfinite(settings.max_range);
    RaySegment &rays = part.rays;
    InsertCounts &counts = part.counts;
    rays.ends.reserve(end - begin);
    rays.end_keys.reserve(end - begin);
    ExtentRuns extents(mapper.resolution(), part.hit_extents);
    octomap::OcTreeKey key;
    for (size_t i = begin; i < end; ++i) {
        const Vec3 p_sensor = points.read(i);
        if (!is_finite(p_sensor)) {
            ++counts.nonfinite;
            continue;
        }
        // OctoMap works in float: round once, then test the rounded point.
        const Vec3 p_map = settings.sensor_pose.apply(p_sensor);
        const octomap::point3d p = to_float(p_map);
        if (limited && !((p - origin).norm() <= settings.max_range)) {
            ++counts.out_of_range;
            if (!settings.raycast) continue;
            octomap::point3d cut = origin + (p - origin).normalized() * static_cast<float>(settings.max_range);
            if (settings.clip != nullptr) cut = clipped_end(*settings.clip, settings, to_vec(cut), false, nullptr);
            if (!mapper.key(cut, key)) continue;
            add_ray(cut, key, rays, part.box);
            continue;
        }
        if (settings.clip != nullptr) {
            RayCut::Kind kind = RayCut::kKeep;
            const octomap::point3d cut = clipped_end(*settings.clip, settings, p_map, true, &kind);
            if (kind != RayCut::kKeep) {
                ++(kind == RayCut::kOnRobot ? counts.on_robot : counts.shadowed);
                if (settings.raycast && mapper.key(cut, key)) add_ray(cut, key, rays, part.box);
                continue;
            }
        }
        if (!mapper.key(p, key)) {
            ++counts.outside_map;
            continue;
        }
        add_ray(p, key, rays, part.box);
        extents.add(key, p_map);
        ++counts.used;
    }
    extents.flush();
    std::sort(part.hit_extents.begin(), part.hit_extents.end(), ByCode());
    merge_same_cells(part.hit_extents);
}

#if defined(OPX_AVX2_LANES)
// Compiled for AVX2 too, where a floor is one instruction (SSE4.1's
// round): the same operations, in fewer instructions.
OPX_AVX2 void prepare_part_avx2(const KeyMapper &mapper, const PointSource &points, const InsertSettings &settings,
                                const octomap::point3d &origin, size_t begin, size_t end, RayPart &part) {
    prepare_points(mapper, points, settings, origin, begin, end, part);
}
#endif

void prepare_part(const KeyMapper &mapper, const PointSource &points, const InsertSettings &settings,
                  const octomap::point3d &origin, size_t begin, size_t end, RayPart &part) {
#if defined(OPX_AVX2_LANES)
    if (cpu_has_avx2()) return prepare_part_avx2(mapper, points, settings, origin, begin, end, part);
#endif
    prepare_points(mapper, points, settings, origin, begin, end, part);
}

template <class T>
void append(std::vector<T> &to, const std::vector<T> &from) {
    to.insert(to.end(), from.begin(), from.end());
}

// Rays whose ends lie close together cross nearly the same cells on their
// way from the origin.  Walked one after another they find those cells'
// marks still in the cache, where rays in the sensor's row order (a row's
// rays reach across the whole frame) do not once the marks outgrow it.
// The walk's result does not depend on the order.
void order_by_end(FrameRays &rays) {
    RaySegment all;
    for (const RaySegment &segment : rays.segments) {
        append(all.ends, segment.ends);
        append(all.end_keys, segment.end_keys);
    }
    const size_t count = all.ends.size();
    std::vector<uint64_t> codes(count);
    std::vector<uint32_t> order(count);
    for (size_t i = 0; i < count; ++i) {
        const octomap::OcTreeKey &key = all.end_keys[i];
        codes[i] = morton_encode(key[0], key[1], key[2]);
        order[i] = static_cast<uint32_t>(i);
    }
    RadixScratch scratch;
    RadixSortOptions options;
    options.key_bits = 48;
    radix_sort(codes, order, scratch, options);
    RaySegment sorted;
    sorted.ends.resize(count);
    sorted.end_keys.resize(count);
    for (size_t i = 0; i < count; ++i) {
        sorted.ends[i] = all.ends[order[i]];
        sorted.end_keys[i] = all.end_keys[order[i]];
    }
    rays.segments.clear();
    rays.segments.push_back(std::move(sorted));
}

}  // namespace

FrameRays prepare_rays(const SensorOctree &tree, const PointSource &points, const InsertSettings &settings,
                       size_t threads, InsertCounts &counts) {
    const KeyMapper mapper(tree.octomap_tree());
    const octomap::point3d origin = to_float(settings.sensor_pose.translation);
    octomap::OcTreeKey origin_key(0, 0, 0);
    const bool origin_inside = mapper.key(origin, origin_key);
    if (settings.raycast && !origin_inside) throw_invalid("sensor_pose.position lies outside the map cube");

    // A clip's work gathers where the robot is in view (a part of the
    // image): its threads take many small parts in turn instead of one
    // share each.  The parts' order changes nothing in the map.
    const size_t part_count = settings.clip != nullptr && threads > 1 ? threads * kClipPartsPerThread : threads;
    std::vector<RayPart> parts(part_count);
    run_tasks(threads, [&](size_t t) {
        for (size_t i = t; i < part_count; i += threads) {
            const size_t begin = points.count * i / part_count, end = points.count * (i + 1) / part_count;
            prepare_part(mapper, points, settings, origin, begin, end, parts[i]);
        }
    });
    FrameRays rays;
    rays.origin = origin;
    rays.origin_key = origin_key;
    if (settings.raycast) {
        const uint32_t k[3] = {origin_key[0], origin_key[1], origin_key[2]};
        rays.box.grow(k);
    }
    rays.hit_extents = std::move(parts[0].hit_extents);
    for (size_t i = 0; i < part_count; ++i) {
        rays.box.grow(parts[i].box);
        if (i > 0) {
            // Each part's entries are sorted (and merged) already.
            const size_t before = rays.hit_extents.size();
            append(rays.hit_extents, parts[i].hit_extents);
            std::inplace_merge(rays.hit_extents.begin(), rays.hit_extents.begin() + static_cast<std::ptrdiff_t>(before),
                               rays.hit_extents.end(), ByCode());
        }
        if (!parts[i].rays.ends.empty()) rays.segments.push_back(std::move(parts[i].rays));
    }
    if (part_count > 1) merge_same_cells(rays.hit_extents);
    if (settings.raycast && rays.box.volume() > kOrderedAboveCells) order_by_end(rays);
    for (const RayPart &part : parts) {
        counts.used += part.counts.used;
        counts.nonfinite += part.counts.nonfinite;
        counts.out_of_range += part.counts.out_of_range;
        counts.outside_map += part.counts.outside_map;
        counts.on_robot += part.counts.on_robot;
        counts.shadowed += part.counts.shadowed;
    }
    return rays;
}

}  // namespace octoprox
