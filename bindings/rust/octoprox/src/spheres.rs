//! Spheres against the map (`include/octoprox/spheres.h`): the robot
//! model of sphere-based planners.  Each sphere is answered on its own, as
//! [`Query::collide`] answers a link set holding that sphere alone, without
//! a link set to place.  [`Query::distance_spheres`] gives each sphere's
//! signed distance, its gradient and a witness point, for trajectory
//! optimizers.
//!
//! ```
//! use octoprox::{InsertMode, InsertOptions, Octree, OctreeOptions, Query, QueryOptions, SphereRequest};
//!
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.1, ..Default::default() })?;
//! let endpoints = InsertOptions { mode: InsertMode::Endpoints, ..Default::default() };
//! map.insert_points(&[[1.05f64, 0.05, 0.05]], &endpoints)?; // the cell [1.0, 1.1] x [0, 0.1]^2
//! let mut query = Query::new(&QueryOptions::default())?;
//! // x, y, z, radius: one sphere reaching into the cell, one short of it.
//! let spheres = [[0.9, 0.05, 0.05, 0.15], [0.5, 0.05, 0.05, 0.2]];
//! assert_eq!(query.collide_spheres(&map, &spheres, &SphereRequest::default())?, [true, false]);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::{is_set, JointOrder, ObstacleGeometry, UnknownPolicy};
use crate::error::{check, Result};
use crate::batch::row_count;
use crate::error::Error;
use crate::{sys, LinkSet, Octree, Pose, Query, World};
use std::ptr;

/// What [`Query::collide_spheres`] takes as obstacles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// Cells with a probability `>=` this are obstacles; 0 (the default):
    /// the map's `occupied_threshold`.
    pub occupancy_threshold: f64,
    /// What an occupied cell is as an obstacle (default
    /// [`ObstacleGeometry::Cells`]).
    pub obstacle_geometry: ObstacleGeometry,
}

impl Default for SphereRequest {
    fn default() -> SphereRequest {
        let c = sys::opx_sphere_request::default();
        SphereRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
        }
    }
}

impl SphereRequest {
    fn to_c(self) -> sys::opx_sphere_request {
        sys::opx_sphere_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            obstacle_geometry: self.obstacle_geometry.raw(),
            ..Default::default()
        }
    }
}

impl Query {
    /// Checks spheres against the map, each on its own: `spheres[i]` is
    /// x, y, z (map frame, metres) and the radius (>= 0: 0 is a point);
    /// the answer's `i`-th flag says whether sphere `i` touches an
    /// obstacle.  The query's engine and world play no part.  No spheres:
    /// no answers.  A non-finite value or a negative radius is an invalid
    /// argument naming its row.
    pub fn collide_spheres(&mut self, tree: &Octree, spheres: &[[f64; 4]], request: &SphereRequest)
        -> Result<Vec<bool>> {
        let mut collided = vec![0u8; spheres.len()];
        if spheres.is_empty() {
            return Ok(Vec::new());
        }
        let request = request.to_c();
        // SAFETY: spheres holds len() packed rows of 4 doubles, collided as
        // many flags; live handles, the tree only read.
        check(unsafe {
            sys::opx_query_collide_spheres(self.as_raw_mut(), tree.as_raw(), spheres.as_ptr().cast(), spheres.len(), 0,
                                           &request, collided.as_mut_ptr(), spheres.len())
        })?;
        Ok(collided.into_iter().map(|c| is_set(c as i32)).collect())
    }
}

/// What [`Query::distance_spheres`] takes as obstacles, and how far it looks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereDistanceRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// As [`SphereRequest::occupancy_threshold`].
    pub occupancy_threshold: f64,
    /// What an occupied cell is as an obstacle.
    pub obstacle_geometry: ObstacleGeometry,
    /// 1 (the default): the caller's thread; 0: one per hardware thread.
    pub max_threads: u32,
    /// Metres, > 0 (default 0.1), infinity allowed: spheres at least this
    /// far report it, a zero gradient and a NaN witness.
    pub max_distance: f64,
}

impl Default for SphereDistanceRequest {
    fn default() -> SphereDistanceRequest {
        let c = sys::opx_sphere_distance_request::default();
        SphereDistanceRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
            max_threads: c.max_threads,
            max_distance: c.max_distance,
        }
    }
}

impl SphereDistanceRequest {
    fn to_c(self) -> sys::opx_sphere_distance_request {
        sys::opx_sphere_distance_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            obstacle_geometry: self.obstacle_geometry.raw(),
            max_threads: self.max_threads,
            max_distance: self.max_distance,
            ..Default::default()
        }
    }
}

/// The answers of [`Query::distance_spheres`], one per sphere.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SphereDistances {
    /// Signed distance, metres: surface to the nearest obstacle; negative
    /// inside (minus the centre's depth, minus the radius).
    pub distance: Vec<f64>,
    /// Unit gradient of the distance with respect to the centre (away
    /// from the nearest obstacle); zero when truncated.
    pub gradient: Vec<[f64; 3]>,
    /// The nearest obstacle point (inside: the nearest point outside every
    /// obstacle), map frame; NaN when truncated.
    pub witness: Vec<[f64; 3]>,
}

impl Query {
    /// Signed distances of spheres (`spheres[i]`: x, y, z in the map frame
    /// and the radius, metres) to the map's obstacles, with the gradient
    /// and a witness each (`spheres.h`, `opx_query_distance_spheres`,
    /// states the rules).  No spheres: no answers.
    pub fn distance_spheres(&mut self, tree: &Octree, spheres: &[[f64; 4]], request: &SphereDistanceRequest)
        -> Result<SphereDistances> {
        self.distance_spheres_tree(tree.as_raw(), spheres, request)
    }

    /// [`Query::distance_spheres`] against the octree (`None`: no map) and
    /// the enabled objects of `world` together.
    pub fn distance_spheres_with_world(&mut self, tree: Option<&Octree>, world: &World, spheres: &[[f64; 4]],
                                       request: &SphereDistanceRequest) -> Result<SphereDistances> {
        let tree = tree.map_or(ptr::null(), Octree::as_raw);
        self.with_world(world, |query| query.distance_spheres_tree(tree, spheres, request))
    }

    fn distance_spheres_tree(&mut self, tree: *const sys::opx_octree, spheres: &[[f64; 4]],
                             request: &SphereDistanceRequest) -> Result<SphereDistances> {
        let n = spheres.len();
        let mut out = SphereDistances { distance: vec![0.0; n], gradient: vec![[0.0; 3]; n], witness: vec![[0.0; 3]; n] };
        if n == 0 {
            return Ok(out);
        }
        let request = request.to_c();
        // SAFETY: spheres holds n packed rows of 4 doubles, the outputs n
        // doubles and n packed rows of 3; live handles (tree may be NULL
        // with a world), the tree only read.
        check(unsafe {
            sys::opx_query_distance_spheres(self.as_raw_mut(), tree, spheres.as_ptr().cast(), n, 0, &request,
                                            out.distance.as_mut_ptr(), out.gradient.as_mut_ptr().cast(),
                                            out.witness.as_mut_ptr().cast(), n)
        })?;
        Ok(out)
    }
}

/// What [`Query::trajectory_cost`] takes as obstacles, its activation
/// distance and the rows' order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrajectoryCostRequest {
    /// What unknown space is (default [`UnknownPolicy::Free`]).
    pub unknown_policy: UnknownPolicy,
    /// As [`SphereRequest::occupancy_threshold`].
    pub occupancy_threshold: f64,
    /// What an occupied cell is as an obstacle.
    pub obstacle_geometry: ObstacleGeometry,
    /// What a row holds (default [`JointOrder::ByCount`]).
    pub joint_order: JointOrder,
    /// CHOMP's activation distance eps, metres (> 0, finite; default 0.05).
    pub activation: f64,
}

impl Default for TrajectoryCostRequest {
    fn default() -> TrajectoryCostRequest {
        let c = sys::opx_trajectory_cost_request::default();
        TrajectoryCostRequest {
            unknown_policy: UnknownPolicy::from_raw(c.unknown_policy).unwrap_or_default(),
            occupancy_threshold: c.occupancy_threshold,
            obstacle_geometry: ObstacleGeometry::from_raw(c.obstacle_geometry).unwrap_or_default(),
            joint_order: JointOrder::from_raw(c.joint_order).unwrap_or_default(),
            activation: c.activation,
        }
    }
}

impl TrajectoryCostRequest {
    fn to_c(self) -> sys::opx_trajectory_cost_request {
        sys::opx_trajectory_cost_request {
            unknown_policy: self.unknown_policy.raw(),
            occupancy_threshold: self.occupancy_threshold,
            obstacle_geometry: self.obstacle_geometry.raw(),
            joint_order: self.joint_order.raw(),
            activation: self.activation,
            ..Default::default()
        }
    }
}

/// The answer of [`Query::trajectory_cost`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TrajectoryCost {
    /// The summed penalty of every sphere at every waypoint.
    pub cost: f64,
    /// d cost / d joint value, in the rows' layout (waypoints x joints).
    pub gradient: Vec<f64>,
}

impl Query {
    /// The obstacle cost of a trajectory of a robot made of spheres and its
    /// gradient (`spheres.h`, `opx_query_trajectory_cost`, states the
    /// penalty): `rows` holds waypoints of every joint's value in model
    /// order (with `request.joint_order` [`JointOrder::Active`], of the
    /// active joints'), the root link at `base` (map frame; `None`: the
    /// origin).
    pub fn trajectory_cost(&mut self, tree: &Octree, robot: &LinkSet, rows: &[f64], base: Option<&Pose>,
                           request: &TrajectoryCostRequest) -> Result<TrajectoryCost> {
        self.trajectory_cost_tree(tree.as_raw(), robot, rows, base, request)
    }

    /// [`Query::trajectory_cost`] against the octree (`None`: no map) and
    /// the enabled objects of `world` together.
    pub fn trajectory_cost_with_world(&mut self, tree: Option<&Octree>, world: &World, robot: &LinkSet,
                                      rows: &[f64], base: Option<&Pose>, request: &TrajectoryCostRequest)
        -> Result<TrajectoryCost> {
        let tree = tree.map_or(ptr::null(), Octree::as_raw);
        self.with_world(world, |query| query.trajectory_cost_tree(tree, robot, rows, base, request))
    }

    fn trajectory_cost_tree(&mut self, tree: *const sys::opx_octree, robot: &LinkSet, rows: &[f64],
                            base: Option<&Pose>, request: &TrajectoryCostRequest) -> Result<TrajectoryCost> {
        let (waypoints, joints) = row_count(robot, rows, request.joint_order, "Query::trajectory_cost: rows")?;
        if waypoints == 0 {
            return Err(Error::invalid("Query::trajectory_cost: rows holds no waypoint".to_string()));
        }
        let mut out = TrajectoryCost { cost: 0.0, gradient: vec![0.0; rows.len()] };
        let request = request.to_c();
        let base = base.map_or(ptr::null(), |b| b as *const Pose);
        // SAFETY: rows holds `waypoints` packed rows of `joints` doubles,
        // the gradient as many; live handles (tree may be NULL with a
        // world), only read.
        check(unsafe {
            sys::opx_query_trajectory_cost(self.as_raw_mut(), tree, robot.as_raw(), rows.as_ptr(), waypoints, joints,
                                           0, base, &request, &mut out.cost, out.gradient.as_mut_ptr(), waypoints)
        })?;
        Ok(out)
    }
}
