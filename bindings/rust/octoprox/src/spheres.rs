//! Spheres against the map (`include/octoprox/spheres.h`): the robot
//! model of sphere-based planners.  Each sphere is answered on its own, as
//! [`Query::collide`] answers a link set holding that sphere alone, without
//! a link set to place.
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
use crate::enums::{is_set, ObstacleGeometry, UnknownPolicy};
use crate::error::{check, Result};
use crate::{sys, Octree, Query};

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
