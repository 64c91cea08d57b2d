//! The requests and answers of many configurations and motions per call
//! ([`crate::Query::check_configurations`], [`crate::Query::check_motion`],
//! [`crate::Query::check_motions`]).  Joint values are in radians
//! (revolute, continuous) or metres (prismatic); `Default` gives the C
//! library's defaults.
//!
//! ```
//! use octoprox::{BatchRequest, JointOrder, MotionRequest, ObstacleGeometry};
//!
//! let batch = BatchRequest { compute_distance: true, max_threads: 0, ..Default::default() };
//! assert!(!batch.self_collision && batch.obstacle_geometry == ObstacleGeometry::Cells);
//! let active_rows = BatchRequest { joint_order: JointOrder::Active, ..Default::default() };
//! assert_ne!(active_rows.joint_order, BatchRequest::default().joint_order); // ByCount
//! let coarse = MotionRequest { resolution: 0.05, ..Default::default() };
//! assert!(coarse.resolution > MotionRequest::default().resolution); // 0.01
//! ```
use crate::enums::{flag, is_set};
use crate::{sys, JointOrder, ObstacleGeometry, UnknownPolicy};

/// How [`crate::Query::check_configurations`] checks its rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatchRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// Cells with a probability `>=` this are obstacles; 0 (the default):
    /// the map's `occupied_threshold`.
    pub occupancy_threshold: f64,
    /// Also check the robot against itself, over its enabled pairs of
    /// links.  Default false.
    pub self_collision: bool,
    /// Also each configuration's minimum distance between the enabled links
    /// and the obstacles (metres, padding included, 0 when touching; with
    /// `self_collision` the smaller of that and the self distance); no
    /// check then stops at the first contact.  Default false.
    pub compute_distance: bool,
    /// With `compute_distance`: obstacles farther than this (metres) are
    /// not searched, the distance is then the cutoff ("at least").  0 (the
    /// default) or infinity: no cutoff.
    pub distance_cutoff: f64,
    /// Worker threads: 1 (the default) runs on the caller's thread, 0 takes
    /// one per hardware thread.  The answers do not depend on it.
    pub max_threads: u32,
    /// What an occupied cell is as an obstacle (default
    /// [`ObstacleGeometry::Cells`]).
    pub obstacle_geometry: ObstacleGeometry,
    /// What a row holds: [`JointOrder::Active`] for rows of the active
    /// joints ([`crate::LinkSet::active_joint_names`]);
    /// [`JointOrder::ByCount`] (the default) and [`JointOrder::Model`]
    /// read rows of every joint in model order.
    pub joint_order: JointOrder,
}

impl Default for BatchRequest {
    fn default() -> BatchRequest {
        let c = sys::opx_batch_request::default();
        BatchRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            self_collision: is_set(c.self_collision),
            compute_distance: is_set(c.compute_distance),
            distance_cutoff: c.distance_cutoff,
            max_threads: c.max_threads,
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
            joint_order: JointOrder::from_raw(c.joint_order).unwrap_or_default(),
        }
    }
}

impl BatchRequest {
    pub(crate) fn to_c(self) -> sys::opx_batch_request {
        sys::opx_batch_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            self_collision: flag(self.self_collision),
            compute_distance: flag(self.compute_distance),
            distance_cutoff: self.distance_cutoff,
            max_threads: self.max_threads,
            obstacle_geometry: self.obstacle_geometry.raw(),
            joint_order: self.joint_order.raw(),
            ..Default::default()
        }
    }
}

/// How a joint-space motion is checked ([`crate::Query::check_motion`],
/// [`crate::Query::check_motions`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// As in [`BatchRequest`]; 0 (the default): the map's threshold.
    pub occupancy_threshold: f64,
    /// The largest step of any joint between two checked configurations
    /// (radians or metres, > 0; default 0.01).  A motion is checked at
    /// n + 1 configurations, n = ceil(max over joints of |goal - start| /
    /// resolution), at most 1e7 steps.
    pub resolution: f64,
    /// Also check the robot against itself.  Default false.
    pub self_collision: bool,
    /// [`crate::Query::check_motion`] only: also the cost of uncertain and
    /// unknown space the motion sweeps through (boxes read with
    /// [`crate::Query::cost_boxes`]); fields below as in
    /// [`crate::CollisionRequest`].  Default false.
    pub compute_cost: bool,
    /// The costliest boxes kept (default 16).
    pub max_cost_boxes: u32,
    /// [`crate::Query::check_motions`]: worker threads, 1 (the default) or
    /// 0 for one per hardware thread.
    pub max_threads: u32,
    /// The probability given to unknown space in costs (default 0.5).
    pub unknown_probability: f64,
    /// Lower corner of where unknown space counts (map frame); see
    /// [`crate::CollisionRequest::region_min`].
    pub region_min: [f64; 3],
    /// Upper corner of where unknown space counts (map frame).
    pub region_max: [f64; 3],
    /// What an occupied cell is as an obstacle (default
    /// [`ObstacleGeometry::Cells`]).
    pub obstacle_geometry: ObstacleGeometry,
    /// What start and goal hold: [`JointOrder::ByCount`] (the default)
    /// tells by their length in [`crate::Query::check_motion`] and reads
    /// rows of every joint in [`crate::Query::check_motions`];
    /// [`JointOrder::Active`] the active joints, [`JointOrder::Model`]
    /// every joint.
    pub joint_order: JointOrder,
    /// Check every configuration of the segment, not samples of it
    /// (conservative advancement on exact distances; `resolution` does not
    /// apply, `compute_cost` is refused).  Not colliding then means no
    /// configuration of the motion collides; colliding, that the
    /// configuration at the first fraction f is within 1e-8 m of an
    /// obstacle and none before f - `tolerance` collides.  Default false.
    pub certified: bool,
    /// With `certified`: that bracket, a fraction of the motion in (0, 1]
    /// (default 1e-3).
    pub tolerance: f64,
}

impl Default for MotionRequest {
    fn default() -> MotionRequest {
        let c = sys::opx_motion_request::default();
        MotionRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            resolution: c.resolution,
            self_collision: is_set(c.self_collision),
            compute_cost: is_set(c.compute_cost),
            max_cost_boxes: c.max_cost_boxes,
            max_threads: c.max_threads,
            unknown_probability: c.unknown_probability,
            region_min: c.region_min,
            region_max: c.region_max,
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
            joint_order: JointOrder::from_raw(c.joint_order).unwrap_or_default(),
            certified: c.check == sys::OPX_MOTION_CERTIFIED,
            tolerance: c.tolerance,
        }
    }
}

impl MotionRequest {
    pub(crate) fn to_c(self) -> sys::opx_motion_request {
        sys::opx_motion_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            resolution: self.resolution,
            self_collision: flag(self.self_collision),
            compute_cost: flag(self.compute_cost),
            max_cost_boxes: self.max_cost_boxes,
            max_threads: self.max_threads,
            unknown_probability: self.unknown_probability,
            region_min: self.region_min,
            region_max: self.region_max,
            obstacle_geometry: self.obstacle_geometry.raw(),
            joint_order: self.joint_order.raw(),
            check: if self.certified { sys::OPX_MOTION_CERTIFIED } else { sys::OPX_MOTION_SAMPLED },
            tolerance: self.tolerance,
            ..Default::default()
        }
    }
}

/// The answer of [`crate::Query::check_motion`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionResult {
    /// Some checked configuration of the motion collides.
    pub collided: bool,
    /// Where the first colliding configuration lies along the motion, i / n
    /// in [0, 1]; `None` when none collides.
    pub first_collision_fraction: Option<f64>,
    /// n: the motion is checked at n + 1 configurations.
    pub steps: u64,
    /// Configurations checked: the ends first, then ever finer midpoints,
    /// none beyond the first collision found (all of them with cost).
    pub configurations_checked: u64,
    /// With `compute_cost`: m^3 over all cells swept.
    pub total_cost: f64,
    /// Cost boxes the query holds ([`crate::Query::cost_boxes`]).
    pub cost_box_count: u64,
    /// All cells swept.
    pub cost_boxes_found: u64,
}

impl MotionResult {
    pub(crate) fn from_c(c: &sys::opx_motion_result) -> MotionResult {
        MotionResult {
            collided: is_set(c.collided),
            first_collision_fraction: fraction(c.first_collision_fraction),
            steps: c.steps,
            configurations_checked: c.configurations_checked,
            total_cost: c.total_cost,
            cost_box_count: c.cost_box_count,
            cost_boxes_found: c.cost_boxes_found,
        }
    }
}

/// A fraction of a motion the C API reports as -1 when there is none.
pub(crate) fn fraction(raw: f64) -> Option<f64> {
    (raw >= 0.0).then_some(raw)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_c_defaults() {
        assert_eq!(BatchRequest::default().to_c(), sys::opx_batch_request::default());
        assert_eq!(MotionRequest::default().to_c(), sys::opx_motion_request::default());
    }

    #[test]
    fn obstacle_geometry_reaches_batch_and_motion_requests() {
        let extents = ObstacleGeometry::PointExtents;
        let batch = BatchRequest { obstacle_geometry: extents, ..Default::default() };
        assert_eq!(batch.to_c().obstacle_geometry, sys::OPX_OBSTACLE_POINT_EXTENTS);
        let motion = MotionRequest { obstacle_geometry: extents, ..Default::default() };
        assert_eq!(motion.to_c().obstacle_geometry, sys::OPX_OBSTACLE_POINT_EXTENTS);
    }

    #[test]
    fn joint_order_reaches_batch_and_motion_requests() {
        let batch = BatchRequest { joint_order: JointOrder::Active, ..Default::default() };
        assert_eq!(batch.to_c().joint_order, sys::OPX_JOINTS_ACTIVE);
        let motion = MotionRequest { joint_order: JointOrder::Model, ..Default::default() };
        assert_eq!(motion.to_c().joint_order, sys::OPX_JOINTS_MODEL);
        assert_eq!(JointOrder::from_raw(sys::OPX_JOINTS_BY_COUNT), Some(JointOrder::ByCount));
    }
}
