// The self-filter's oracle: the robot's padded solids measured by exact
// brute-force distances (primitives in closed form, meshes and hulls by
// surface_solid.hpp), and each frame point judged independently of the
// library as octree.h's "The robot in its own frame" defines it:
//   robot point: its distance to some solid <= that solid's padding;
//   shadowed:    the segment sensor -> point passes through the padded robot;
//   kept:        neither.
// The cut point (where the ray enters the padded robot) is found by sphere
// tracing on the padded distance to 1e-12 m.  Verdicts within 1e-8 m of
// flipping (a point on the band's edge, a ray grazing the padded robot)
// are flagged ambiguous: the library decides them within its own 1e-9 m.
#pragma once

#include "render_solids.hpp"
#include "surface_solid.hpp"

#include <memory>
#include <vector>

namespace filter_oracle {

// The filter's settings as the test gave them to the library.
struct FilterSettings {
    double robot_padding = 0.0;
    std::vector<double> link_padding;  // per link, the set's padding included; empty: 0
    std::vector<bool> enabled;         // per link; empty: all enabled
};

struct Solid {
    int32_t kind = 0;
    render::Primitive primitive;             // every kind but a mesh
    std::shared_ptr<const SurfaceSolid> surface;  // a mesh (closed, or its vertices' hull)
    double padding = 0.0;
    Vec3 center = Vec3::Zero();
    double bound = 0.0;  // a ball at center of this radius holds the unpadded solid
    // Exact distance from x to the unpadded solid (0 inside).
    double distance(const Vec3 &x) const { return distance_below(x, INFINITY); }
    // The same when it is below `limit`; else some value >= limit.
    double distance_below(const Vec3 &x, double limit) const;
    // A lower bound of distance(x), cheap.
    double lower_bound(const Vec3 &x) const;
};

struct Verdict {
    enum Kind { kKept, kOnRobot, kShadowed } kind = kKept;
    double t = 1.0;          // the cut: origin + t * (end - origin); 1 when kept
    bool ambiguous = false;  // within 1e-8 m of another verdict
    double end_gap = 0.0;    // the point's padded-distance surrogate: exact up to 1 cm, else a lower bound
    bool range_cut = false;  // the end is a ray's cut at max_range, not a point: never a robot point
};

class OracleRobot {
public:
    // Reads every enabled link's and attached object's shapes through the
    // public API.  Counts closed meshes and hulls for the log.
    OracleRobot(const opx_linkset *robot, const FilterSettings &settings);

    // The padded distance's surrogate: min over solids of distance - padding
    // (<= 0: inside the padded robot), exact when below `limit`, else a
    // lower bound >= limit.
    double gap(const Vec3 &x, double limit = INFINITY) const;
    // Each point's verdict for a sensor at `origin` (map frame, double).
    // Ends flagged in `range_cut` (may be empty) are rays cut at max_range:
    // only their segment is judged (kept or shadowed).
    std::vector<Verdict> judge_frame(const Vec3 &origin, const std::vector<Vec3> &ends,
                                     const std::vector<bool> &range_cut = {}) const;
    const std::vector<Solid> &solids() const { return solids_; }
    // The solids whose padded volume holds `origin` (they shadow nothing).
    size_t solids_holding(const Vec3 &origin) const;
    size_t closed_meshes() const { return closed_meshes_; }
    size_t hull_meshes() const { return hull_meshes_; }

private:
    std::vector<size_t> shadowing_solids(const Vec3 &origin) const;
    Verdict judge(const std::vector<size_t> &shadowing, const Vec3 &origin, const Vec3 &end, bool range_cut) const;
    double gap_over(const std::vector<size_t> &which, const Vec3 &x, double limit) const;
    bool trace(const std::vector<size_t> &which, const Vec3 &origin, const Vec3 &end, double &t,
               bool &ambiguous) const;

    std::vector<Solid> solids_;
    size_t closed_meshes_ = 0, hull_meshes_ = 0;
};

}  // namespace filter_oracle
