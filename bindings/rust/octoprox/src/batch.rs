//! Many configurations and joint-space motions per call
//! (`include/octoprox/batch.h`).  Joint vectors are rows of every joint of
//! a robot made from URDF, in model order (as
//! [`LinkSet::set_joint_positions`] takes them), or with
//! [`JointOrder::Active`] rows of the active joints alone (as
//! [`LinkSet::set_active_joint_positions`] takes them), packed one after
//! the other in one slice.  The robot is only read (`&LinkSet`): forward
//! kinematics runs on the query's own copies, so other threads may use the
//! same robot.
//!
//! ```
//! use octoprox::{BasePoses, BatchRequest, InsertMode, InsertOptions, JointOrder, LinkSet, Octree,
//!                OctreeOptions, Query, QueryOptions, UrdfOptions};
//!
//! // A 1 m arm turning about z at the origin; its tip a sphere at x = 1.
//! let urdf = r#"<robot name="arm">
//!   <link name="base"/>
//!   <link name="arm"><collision><origin xyz="1 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
//!   <joint name="turn" type="continuous"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/></joint>
//! </robot>"#;
//! let robot = LinkSet::from_urdf_string(urdf, &UrdfOptions::default())?;
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.1, ..Default::default() })?;
//! let endpoints = InsertOptions { mode: InsertMode::Endpoints, ..Default::default() };
//! map.insert_points(&[[0.05f64, 1.05, 0.05]], &endpoints)?; // an obstacle at +y
//! let rows = [0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI]; // one joint per row
//! let request = BatchRequest { compute_distance: true, ..Default::default() };
//! let mut query = Query::new(&QueryOptions::default())?;
//! let answers = query.check_configurations(&map, &robot, &rows, BasePoses::Origin, &request)?;
//! assert_eq!(answers.collided, [false, true, false]);
//! assert_eq!(answers.distances[1], 0.0);
//! // The same rows as active joints: here every joint is active, so the
//! // two orders are one.
//! let active = BatchRequest { joint_order: JointOrder::Active, ..request };
//! assert_eq!(query.check_configurations(&map, &robot, &rows, BasePoses::Origin, &active)?, answers);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::batch_types::fraction;
use crate::error::{check, Error, Result};
use crate::{sys, BatchRequest, JointOrder, LinkSet, MotionRequest, MotionResult, Octree, Pose, Query, World};
use std::ptr;

/// Where the robot's root link is (map frame) for each row.
#[derive(Debug, Clone, Copy)]
pub enum BasePoses<'a> {
    /// At the map origin.
    Origin,
    /// The same pose for every row.
    Shared(Pose),
    /// One pose per row (as many as rows, else an invalid argument).
    PerRow(&'a [Pose]),
}

impl BasePoses<'_> {
    fn raw(&self) -> (*const Pose, usize) {
        match self {
            BasePoses::Origin => (ptr::null(), 0),
            BasePoses::Shared(pose) => (pose as *const Pose, 1),
            BasePoses::PerRow(poses) => (poses.as_ptr(), poses.len()),
        }
    }
}

/// The answers of [`Query::check_configurations`], one per row.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigurationAnswers {
    /// The configuration touches the map (or, with `self_collision`, itself).
    pub collided: Vec<bool>,
    /// With `compute_distance`: each configuration's minimum distance
    /// (metres); empty otherwise.
    pub distances: Vec<f64>,
}

/// The answers of [`Query::check_motions`], one per motion.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionAnswers {
    /// Some checked configuration of the motion collides.
    pub collided: Vec<bool>,
    /// Where the first colliding configuration lies along the motion, in
    /// [0, 1]; `None` when none collides.
    pub first_fractions: Vec<Option<f64>>,
}

/// Rows of `values` for the robot: the row count, each row `joints` values
/// (the active joints with [`JointOrder::Active`], else every joint).
pub(crate) fn row_count(robot: &LinkSet, values: &[f64], order: JointOrder, what: &str) -> Result<(usize, usize)> {
    let (joints, kind) = match order {
        JointOrder::Active => (robot.active_joint_count()? as usize, "active joints"),
        JointOrder::ByCount | JointOrder::Model => (robot.joint_count()? as usize, "joints"),
    };
    if (joints == 0 && !values.is_empty()) || (joints > 0 && values.len() % joints != 0) {
        return Err(Error::invalid(
            format!("{what}: {} values are not rows of the robot's {joints} {kind}", values.len()),
        ));
    }
    Ok((if joints == 0 { 0 } else { values.len() / joints }, joints))
}

fn flags(bytes: Vec<u8>) -> Vec<bool> {
    bytes.into_iter().map(|b| b != 0).collect()
}

impl Query {
    /// Checks many configurations of `robot` against `tree` in one call:
    /// `rows` holds N joint vectors (N x joint count values, model order;
    /// with `request.joint_order` [`JointOrder::Active`], N x active joint
    /// count values, the active joints; else an invalid argument), the
    /// root link placed by `bases` (map frame).  `request.max_threads` workers split them (1, the default:
    /// the calling thread; 0: every core); the answers do not depend on it.
    /// `request.self_collision` also checks the robot against itself,
    /// `request.compute_distance` gives each configuration's minimum
    /// distance.  No rows: no answers.  A non-finite joint value is an
    /// invalid argument naming its row and joint.  A robot made of spheres
    /// alone, asked for collisions with the map only (no distance,
    /// self-collision or world; unknown space free), is checked sphere by
    /// sphere on the map's obstacle grid, with the same answers: about
    /// 10 ns a sphere; the first such call after the map changed builds
    /// the grid.
    pub fn check_configurations(&mut self, tree: &Octree, robot: &LinkSet, rows: &[f64],
                                bases: BasePoses<'_>, request: &BatchRequest)
        -> Result<ConfigurationAnswers> {
        self.check_configurations_tree(tree.as_raw(), robot, rows, bases, request)
    }

    /// [`Query::check_configurations`] on a live octree handle, or NULL
    /// with a world set.
    fn check_configurations_tree(&mut self, tree: *const sys::opx_octree, robot: &LinkSet, rows: &[f64],
                                 bases: BasePoses<'_>, request: &BatchRequest)
        -> Result<ConfigurationAnswers> {
        let (count, joints) = row_count(robot, rows, request.joint_order, "Query::check_configurations: rows")?;
        let mut collided = vec![0u8; count];
        let mut distances = vec![0.0; if request.compute_distance { count } else { 0 }];
        let request = request.to_c();
        if count > 0 {
            let (base, base_count) = bases.raw();
            let out_distances = if distances.is_empty() { ptr::null_mut() } else { distances.as_mut_ptr() };
            // SAFETY: rows holds count packed rows of `joints` doubles, the
            // bases base_count poses, the outputs `count` values each; live
            // handles (tree may be NULL: the library checks it), only read.
            check(unsafe {
                sys::opx_query_check_configurations(
                    self.as_raw_mut(), tree, robot.as_raw(), rows.as_ptr(), count, joints, 0,
                    base, base_count, 0, &request, collided.as_mut_ptr(), out_distances, count)
            })?;
        }
        Ok(ConfigurationAnswers { collided: flags(collided), distances })
    }

    /// Checks the straight joint-space motion from `start` to `goal` (joint
    /// vectors of every joint in model order or of the active joints, told
    /// by their length unless `request.joint_order` insists on one) at
    /// configurations no joint step farther apart
    /// than `request.resolution` (rad or m); the root link at `base` (map
    /// frame; `None`: the origin).  With `request.compute_cost` the swept
    /// cost's boxes are then read with [`Query::cost_boxes`].
    pub fn check_motion(&mut self, tree: &Octree, robot: &LinkSet, start: &[f64], goal: &[f64],
                        base: Option<&Pose>, request: &MotionRequest) -> Result<MotionResult> {
        self.check_motion_tree(tree.as_raw(), robot, start, goal, base, request)
    }

    /// [`Query::check_motion`] on a live octree handle, or NULL with a
    /// world set.
    fn check_motion_tree(&mut self, tree: *const sys::opx_octree, robot: &LinkSet, start: &[f64],
                         goal: &[f64], base: Option<&Pose>, request: &MotionRequest) -> Result<MotionResult> {
        if start.len() != goal.len() {
            return Err(Error::invalid(
                format!("Query::check_motion: start has {} joints, goal {}", start.len(), goal.len()),
            ));
        }
        let request = request.to_c();
        let mut out = sys::opx_motion_result::default();
        self.hold_cost_boxes(0);
        let base = base.map_or(ptr::null(), |b| b as *const Pose);
        // SAFETY: start and goal hold start.len() doubles each; live handles
        // (tree may be NULL: the library checks it).
        check(unsafe {
            sys::opx_query_check_motion(self.as_raw_mut(), tree, robot.as_raw(), start.as_ptr(),
                                        goal.as_ptr(), start.len(), base, &request, &mut out)
        })?;
        self.hold_cost_boxes(out.cost_box_count as usize);
        Ok(MotionResult::from_c(&out))
    }

    /// Checks many motions (a planner's edges): row m of `starts` to row m
    /// of `goals` (equal lengths, rows of the robot's joints, or of its
    /// active joints with `request.joint_order` [`JointOrder::Active`]),
    /// split over
    /// `request.max_threads` workers, as [`Query::check_motion`] checks one
    /// (without cost), the root link placed by `bases` (map frame).
    pub fn check_motions(&mut self, tree: &Octree, robot: &LinkSet, starts: &[f64], goals: &[f64],
                         bases: BasePoses<'_>, request: &MotionRequest) -> Result<MotionAnswers> {
        self.check_motions_tree(tree.as_raw(), robot, starts, goals, bases, request)
    }

    /// [`Query::check_motions`] on a live octree handle, or NULL with a
    /// world set.
    fn check_motions_tree(&mut self, tree: *const sys::opx_octree, robot: &LinkSet, starts: &[f64],
                          goals: &[f64], bases: BasePoses<'_>, request: &MotionRequest)
        -> Result<MotionAnswers> {
        let (count, joints) = row_count(robot, starts, request.joint_order, "Query::check_motions: starts")?;
        if goals.len() != starts.len() {
            return Err(Error::invalid(
                format!("Query::check_motions: {} start values but {} goal values", starts.len(), goals.len()),
            ));
        }
        let request = request.to_c();
        let mut collided = vec![0u8; count];
        let mut first_fractions = vec![0.0; count];
        if count > 0 {
            let (base, base_count) = bases.raw();
            // SAFETY: starts and goals hold count packed rows of `joints`
            // doubles, the outputs `count` values; live handles (tree may be
            // NULL: the library checks it).
            check(unsafe {
                sys::opx_query_check_motions(
                    self.as_raw_mut(), tree, robot.as_raw(), starts.as_ptr(), goals.as_ptr(), count,
                    joints, 0, base, base_count, 0, &request, collided.as_mut_ptr(),
                    first_fractions.as_mut_ptr(), count)
            })?;
        }
        let first_fractions = first_fractions.into_iter().map(fraction).collect();
        Ok(MotionAnswers { collided: flags(collided), first_fractions })
    }

    /// [`Query::check_configurations`] against the octree (`None`: no map)
    /// and the enabled objects of `world` together: a configuration
    /// collides when it touches either, its distance is the least of both.
    /// Objects have no cost.  Workers share the world read-only, so the
    /// answers do not depend on `max_threads`.
    pub fn check_configurations_with_world(&mut self, tree: Option<&Octree>, world: &World, robot: &LinkSet,
                                           rows: &[f64], bases: BasePoses<'_>, request: &BatchRequest)
        -> Result<ConfigurationAnswers> {
        self.with_world(world, |query| {
            query.check_configurations_tree(tree_ptr(tree), robot, rows, bases, request)
        })
    }

    /// [`Query::check_motion`] against the octree (`None`: no map) and the
    /// enabled objects of `world` together.  The cost comes from the octree
    /// alone: `compute_cost` needs one.
    #[allow(clippy::too_many_arguments)]
    pub fn check_motion_with_world(&mut self, tree: Option<&Octree>, world: &World, robot: &LinkSet,
                                   start: &[f64], goal: &[f64], base: Option<&Pose>, request: &MotionRequest)
        -> Result<MotionResult> {
        self.with_world(world, |query| query.check_motion_tree(tree_ptr(tree), robot, start, goal, base, request))
    }

    /// [`Query::check_motions`] against the octree (`None`: no map) and
    /// the enabled objects of `world` together.
    #[allow(clippy::too_many_arguments)]
    pub fn check_motions_with_world(&mut self, tree: Option<&Octree>, world: &World, robot: &LinkSet,
                                    starts: &[f64], goals: &[f64], bases: BasePoses<'_>, request: &MotionRequest)
        -> Result<MotionAnswers> {
        self.with_world(world, |query| {
            query.check_motions_tree(tree_ptr(tree), robot, starts, goals, bases, request)
        })
    }
}

/// The octree's handle, or NULL for none (a query with a world only).
fn tree_ptr(tree: Option<&Octree>) -> *const sys::opx_octree {
    tree.map_or(ptr::null(), Octree::as_raw)
}
