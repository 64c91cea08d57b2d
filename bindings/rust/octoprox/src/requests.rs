//! What a [`crate::Query`] is asked: its engine, and the collision,
//! distance and path requests.  Build them with `Default` (the C library's
//! defaults) and struct update syntax.  Distances are in metres, points in
//! the map frame.
//!
//! ```
//! use octoprox::{pose_at, CellClass, CollisionRequest, LinkSet, ObstacleGeometry, Octree,
//!                OctreeOptions, InsertOptions, Query, QueryOptions, Shape, UnknownPolicy};
//!
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() })?;
//! let sensor = InsertOptions { sensor_pose: pose_at(0.125, 0.125, 0.125), ..Default::default() };
//! map.insert_points(&[[1.0f32, 0.0, 0.0]], &sensor)?; // one occupied cell, free cells before it
//! let mut robot = LinkSet::new()?;
//! let ball = robot.add_link("ball")?;
//! robot.add_shape(ball, &Shape::sphere(0.1))?;
//! robot.set_poses(&[pose_at(3.0, 3.0, 3.0)])?; // in unknown space
//! let mut query = Query::new(&QueryOptions::default())?;
//! assert!(!query.collide(&map, &robot, &CollisionRequest::default())?.collided);
//! let careful = CollisionRequest {
//!     unknown_policy: UnknownPolicy::Occupied,
//!     obstacle_geometry: ObstacleGeometry::PointExtents,
//!     max_contacts: u32::MAX,
//!     ..Default::default()
//! };
//! assert!(query.collide(&map, &robot, &careful)?.collided);
//! assert_eq!(query.contacts()?[0].cell_class, CellClass::Unknown);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::{flag, is_set};
use crate::{sys, Engine, ObstacleGeometry, UnknownPolicy};

/// The engine of a new [`crate::Query`] and its tuning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct QueryOptions {
    /// [`Engine::Direct`] (the default) or [`Engine::Amortized`].
    pub engine: Engine,
    /// Amortized engine: refinement paths per query (default 1).
    pub refine_steps: u32,
    /// Amortized engine: lattice bits per axis of its Morton codes, 1 to 21
    /// (default 10).
    pub morton_bits: u32,
}

impl Default for QueryOptions {
    fn default() -> QueryOptions {
        let c = sys::opx_query_options::default();
        QueryOptions {
            engine: Engine::from_raw(c.engine).unwrap_or_default(),
            refine_steps: c.refine_steps,
            morton_bits: c.morton_bits,
        }
    }
}

impl QueryOptions {
    pub(crate) fn to_c(self) -> sys::opx_query_options {
        sys::opx_query_options {
            engine: self.engine.raw(),
            refine_steps: self.refine_steps,
            morton_bits: self.morton_bits,
            ..Default::default()
        }
    }
}

/// A collision query ([`crate::Query::collide`]): which cells are
/// obstacles, how many contacts to keep, and optionally the cost of
/// uncertain and unknown space and penetration depths.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CollisionRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// Cells with a probability `>=` this are obstacles; 0 (the default)
    /// takes the map's `occupied_threshold`.
    pub occupancy_threshold: f64,
    /// 0: answer yes or no only; 1 (the default): stop at the first contact
    /// and report it; N: collect up to N contacts (`u32::MAX`: all).
    pub max_contacts: u32,
    /// Also the cost of uncertain and unknown space (paper IV.C): boxes
    /// where links overlap cells that are neither free nor obstacles,
    /// unknown space counted inside `region_min`..`region_max`; each box is
    /// a cell cut by a link's bounding box, its cost probability x volume
    /// (m^3).  Default false.
    pub compute_cost: bool,
    /// The costliest boxes kept (default 16).
    pub max_cost_boxes: u32,
    /// The probability given to unknown space in costs (default 0.5).
    pub unknown_probability: f64,
    /// Lower corner of where unknown space counts (map frame, metres).
    /// When it is not below `region_max` on every axis (the default zeros):
    /// the bounds of the observed cells.
    pub region_min: [f64; 3],
    /// Upper corner of where unknown space counts (map frame, metres).
    pub region_max: [f64; 3],
    /// Each contact also gets its penetration depth, normal and point
    /// (exact for polytopes).  Default false.
    pub compute_penetration: bool,
    /// What an occupied cell is as an obstacle (default
    /// [`ObstacleGeometry::Cells`]).
    pub obstacle_geometry: ObstacleGeometry,
}

impl Default for CollisionRequest {
    fn default() -> CollisionRequest {
        let c = sys::opx_collision_request::default();
        CollisionRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            max_contacts: c.max_contacts,
            compute_cost: is_set(c.compute_cost),
            max_cost_boxes: c.max_cost_boxes,
            unknown_probability: c.unknown_probability,
            region_min: c.region_min,
            region_max: c.region_max,
            compute_penetration: is_set(c.compute_penetration),
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
        }
    }
}

impl CollisionRequest {
    pub(crate) fn to_c(self) -> sys::opx_collision_request {
        sys::opx_collision_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            max_contacts: self.max_contacts,
            compute_cost: flag(self.compute_cost),
            max_cost_boxes: self.max_cost_boxes,
            unknown_probability: self.unknown_probability,
            region_min: self.region_min,
            region_max: self.region_max,
            compute_penetration: flag(self.compute_penetration),
            obstacle_geometry: self.obstacle_geometry.raw(),
            ..Default::default()
        }
    }
}

/// A distance query ([`crate::Query::distance`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistanceRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// As in [`CollisionRequest`]; 0 (the default): the map's threshold.
    pub occupancy_threshold: f64,
    /// Allowed absolute error, metres: the reported distance exceeds the
    /// true minimum by at most `max(abs_err, rel_err * distance)`.  0 and 0
    /// (the defaults): exact.
    pub abs_err: f64,
    /// Allowed relative error (see `abs_err`).
    pub rel_err: f64,
    /// Obstacles farther than this (metres) are not searched; the result is
    /// then `found == false` with the cutoff as distance.  0 (the default)
    /// or infinity: no cutoff.
    pub cutoff: f64,
    /// Also each link's minimum, read with [`crate::Query::link_distances`].
    /// Default false.
    pub per_link: bool,
    /// When links overlap obstacles the distance is minus the deepest
    /// penetration, else overlap is distance 0 (the default, false).
    pub signed_distance: bool,
    /// What an occupied cell is as an obstacle (default
    /// [`ObstacleGeometry::Cells`]); with point extents the witness on the
    /// cell lies on its points' box.
    pub obstacle_geometry: ObstacleGeometry,
}

impl Default for DistanceRequest {
    fn default() -> DistanceRequest {
        let c = sys::opx_distance_request::default();
        DistanceRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            abs_err: c.abs_err,
            rel_err: c.rel_err,
            cutoff: c.cutoff,
            per_link: is_set(c.per_link),
            signed_distance: is_set(c.signed_distance),
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
        }
    }
}

impl DistanceRequest {
    pub(crate) fn to_c(self) -> sys::opx_distance_request {
        sys::opx_distance_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            abs_err: self.abs_err,
            rel_err: self.rel_err,
            cutoff: self.cutoff,
            per_link: flag(self.per_link),
            signed_distance: flag(self.signed_distance),
            obstacle_geometry: self.obstacle_geometry.raw(),
            ..Default::default()
        }
    }
}

/// A path query ([`crate::Query::path`]): waypoints checked in order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// As in [`CollisionRequest`]; 0 (the default): the map's threshold.
    pub occupancy_threshold: f64,
    /// Also the minimum (unsigned) distance along the path and its
    /// waypoint.  Default false.
    pub compute_distance: bool,
    /// Also the cost of uncertain and unknown space the path sweeps
    /// through, each cell counted once (paper Fig. 3); fields below as in
    /// [`CollisionRequest`].  Default false.
    pub compute_cost: bool,
    /// The costliest boxes kept (default 16).
    pub max_cost_boxes: u32,
    /// What an occupied cell is as an obstacle (default
    /// [`ObstacleGeometry::Cells`]).
    pub obstacle_geometry: ObstacleGeometry,
    /// The probability given to unknown space in costs (default 0.5).
    pub unknown_probability: f64,
    /// Lower corner of where unknown space counts (map frame); see
    /// [`CollisionRequest::region_min`].
    pub region_min: [f64; 3],
    /// Upper corner of where unknown space counts (map frame).
    pub region_max: [f64; 3],
}

impl Default for PathRequest {
    fn default() -> PathRequest {
        let c = sys::opx_path_request::default();
        PathRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            compute_distance: is_set(c.compute_distance),
            compute_cost: is_set(c.compute_cost),
            max_cost_boxes: c.max_cost_boxes,
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
            unknown_probability: c.unknown_probability,
            region_min: c.region_min,
            region_max: c.region_max,
        }
    }
}

impl PathRequest {
    pub(crate) fn to_c(self) -> sys::opx_path_request {
        sys::opx_path_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            compute_distance: flag(self.compute_distance),
            compute_cost: flag(self.compute_cost),
            max_cost_boxes: self.max_cost_boxes,
            obstacle_geometry: self.obstacle_geometry.raw(),
            unknown_probability: self.unknown_probability,
            region_min: self.region_min,
            region_max: self.region_max,
            ..Default::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_c_defaults() {
        assert_eq!(CollisionRequest::default().to_c(), sys::opx_collision_request::default());
        assert_eq!(DistanceRequest::default().to_c(), sys::opx_distance_request::default());
        assert_eq!(PathRequest::default().to_c(), sys::opx_path_request::default());
        assert_eq!(QueryOptions::default().to_c(), sys::opx_query_options::default());
    }

    #[test]
    fn obstacle_geometry_reaches_every_request() {
        let extents = ObstacleGeometry::PointExtents;
        let raw = sys::OPX_OBSTACLE_POINT_EXTENTS;
        let collision = CollisionRequest { obstacle_geometry: extents, ..Default::default() };
        assert_eq!(collision.to_c().obstacle_geometry, raw);
        let distance = DistanceRequest { obstacle_geometry: extents, ..Default::default() };
        assert_eq!(distance.to_c().obstacle_geometry, raw);
        let path = PathRequest { obstacle_geometry: extents, ..Default::default() };
        assert_eq!(path.to_c().obstacle_geometry, raw);
    }
}
