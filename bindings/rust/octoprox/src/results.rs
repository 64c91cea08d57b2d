//! What a [`crate::Query`] answers: collision, distance and path results,
//! the contacts and cost boxes a query holds, and what its engine holds.
//! Points are in the map frame, lengths in metres, costs in m^3.  With a
//! [`crate::World`] an obstacle is a cell or an object: contacts and
//! distances say which (`object`).
//!
//! ```
//! use octoprox::{pose_at, CollisionRequest, DistanceRequest, InsertMode, InsertOptions, LinkSet,
//!                Octree, OctreeOptions, PathRequest, Query, QueryOptions, Shape};
//!
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() })?;
//! let endpoints = InsertOptions { mode: InsertMode::Endpoints, ..Default::default() };
//! map.insert_points(&[[0.125f64, 0.125, 0.125]], &endpoints)?; // the cell [0, 0.25]^3
//! let mut robot = LinkSet::new()?;
//! let ball = robot.add_link("ball")?;
//! robot.add_shape(ball, &Shape::sphere(0.1))?;
//! robot.set_poses(&[pose_at(0.125, 0.125, 1.0)])?;
//! let mut query = Query::new(&QueryOptions::default())?;
//! let near = query.distance(&map, &robot, &DistanceRequest::default())?;
//! assert!(near.found && !near.collided);
//! assert!((near.distance - 0.65).abs() < 1e-9); // 1.0 - 0.1 - 0.25
//! assert!((near.point_on_cell[2] - 0.25).abs() < 1e-9);
//! // A path down onto the cell: the waypoint at z = 0.3 touches it.
//! let waypoints: Vec<_> = [1.0, 0.6, 0.3, 0.2].iter().map(|&z| pose_at(0.125, 0.125, z)).collect();
//! let path = query.path(&map, &robot, &waypoints, &PathRequest::default())?;
//! assert_eq!((path.collided, path.first_colliding_waypoint), (true, Some(2)));
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::{index, is_set, known};
use crate::error::Result;
use crate::{sys, CellClass, Engine};

/// What a query context holds (amortized engine; zeros for the direct
/// engine), from [`crate::Query::stats`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QueryStats {
    /// The context's engine.
    pub engine: Engine,
    /// Obstacle boxes in the bound tree (not the unknown or uncertain ones).
    pub boxes: u64,
    /// Trees built: one per map frame (or threshold) bound, plus, once per
    /// frame, the unknown-cube and uncertain-cell trees when first needed.
    pub builds: u64,
    /// Refinement steps on the obstacle tree since its last build.
    pub refine_steps_done: u64,
    /// Surface-area cost of the obstacle tree over that of a top-down
    /// median-split tree on the same boxes; 1 when empty.
    pub sah_ratio: f64,
    /// Last bind: milliseconds turning obstacle cells into boxes.
    pub extract_ms: f64,
    /// Last bind: milliseconds building the obstacle tree from the boxes.
    pub build_ms: f64,
}

impl QueryStats {
    pub(crate) fn from_c(c: &sys::opx_query_stats) -> Result<QueryStats> {
        Ok(QueryStats {
            engine: known(Engine::from_raw(c.engine), c.engine, "engine")?,
            boxes: c.boxes,
            builds: c.builds,
            refine_steps_done: c.refine_steps_done,
            sah_ratio: c.sah_ratio,
            extract_ms: c.extract_ms,
            build_ms: c.build_ms,
        })
    }
}

/// The answer of [`crate::Query::collide`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CollisionResult {
    /// Some enabled link (padding included) touches an obstacle cell (or,
    /// with a world, an enabled object).
    pub collided: bool,
    /// Contacts the query holds ([`crate::Query::contacts`]).
    pub contact_count: u64,
    /// A contact beyond the first `max_contacts` was found and left out.
    /// With `max_contacts` 0 or 1 the search stops at the first contact, so
    /// this stays false although more may exist.
    pub truncated: bool,
    /// Exact shape-against-cell tests run (a cost measure).
    pub narrow_tests: u64,
    /// Sum of probability x volume over all cost boxes, m^3.
    pub total_cost: f64,
    /// Cost boxes the query holds ([`crate::Query::cost_boxes`]).
    pub cost_box_count: u64,
    /// All cost boxes found; the held ones are the costliest.
    pub cost_boxes_found: u64,
}

impl CollisionResult {
    pub(crate) fn from_c(c: &sys::opx_collision_result) -> CollisionResult {
        CollisionResult {
            collided: is_set(c.collided),
            contact_count: c.contact_count,
            truncated: is_set(c.truncated),
            narrow_tests: c.narrow_tests,
            total_cost: c.total_cost,
            cost_box_count: c.cost_box_count,
            cost_boxes_found: c.cost_boxes_found,
        }
    }
}

/// A shape of a link touching an obstacle cell (a cube in the map frame)
/// or a world object's shape ([`Contact::object`]); touching means a
/// distance `<=` the padding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// The link's index in the link set.
    pub link: u32,
    /// The shape's index within the link.
    pub shape: u32,
    /// The cell's class in the map: occupied; uncertain or free when the
    /// request's threshold is below the map's; unknown with
    /// [`crate::UnknownPolicy::Occupied`].
    pub cell_class: CellClass,
    /// The cell's centre, map frame, metres.
    pub cell_center: [f64; 3],
    /// The cell's edge, metres.
    pub cell_size: f64,
    /// The cell's occupancy probability; 0.5 for unknown cells.
    pub cell_probability: f64,
    /// With `compute_penetration` (else 0): how deep the padded shape is in
    /// the cell, metres (0 when only touching).
    pub depth: f64,
    /// With `compute_penetration`: the unit direction the shape went in;
    /// moving the link by `-depth * normal` separates the pair.
    pub normal: [f64; 3],
    /// With `compute_penetration`: the contact point, midway between the
    /// shape's deepest point and where it leaves the cell, map frame.
    pub position: [f64; 3],
    /// The world object touched (its index in the [`crate::World`]), or
    /// `None` for an octree cell.  For an object the cell fields are zeros
    /// (`cell_class` [`CellClass::Unknown`]).
    pub object: Option<u32>,
    /// The object's shape touched (its index within the object); 0 for a
    /// cell.
    pub object_shape: u32,
    /// The object attached to the link ([`crate::LinkSet::attach_object`]:
    /// its index) whose shape touched, `shape` then being the shape's index
    /// within that object; `None` for one of the link's own shapes.
    pub attached: Option<u32>,
}

impl Contact {
    pub(crate) fn from_c(c: &sys::opx_contact) -> Result<Contact> {
        Ok(Contact {
            link: c.link,
            shape: c.shape,
            cell_class: known(CellClass::from_raw(c.cell_class), c.cell_class, "cell class")?,
            cell_center: c.cell_center,
            cell_size: c.cell_size,
            cell_probability: c.cell_probability,
            depth: c.depth,
            normal: c.normal,
            position: c.position,
            object: object_index(c.object),
            object_shape: c.object_shape,
            attached: object_index(c.attached),
        })
    }
}

/// A box of uncertain or unknown space overlapped by a link (a cell cut by
/// the link's bounding box), with its cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CostBox {
    /// The link's index in the link set.
    pub link: u32,
    /// [`CellClass::Uncertain`] or [`CellClass::Unknown`].
    pub cell_class: CellClass,
    /// Lower corner of the box, map frame, metres.
    pub min: [f64; 3],
    /// Upper corner of the box, map frame, metres.
    pub max: [f64; 3],
    /// The cell's probability (unknown space: the request's).
    pub probability: f64,
    /// Probability x volume, m^3.
    pub cost: f64,
    /// The centre of the whole cell the box lies in, map frame.
    pub cell_center: [f64; 3],
    /// The edge of that cell, metres.
    pub cell_size: f64,
}

impl CostBox {
    pub(crate) fn from_c(c: &sys::opx_cost_box) -> Result<CostBox> {
        Ok(CostBox {
            link: c.link,
            cell_class: known(CellClass::from_raw(c.cell_class), c.cell_class, "cell class")?,
            min: c.min,
            max: c.max,
            probability: c.probability,
            cost: c.cost,
            cell_center: c.cell_center,
            cell_size: c.cell_size,
        })
    }
}

/// The answer of [`crate::Query::distance`]: the closest pair of an
/// enabled link (padding included) and an obstacle cell (or, with a world,
/// an enabled object's shape: [`DistanceResult::object`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistanceResult {
    /// An obstacle lies within the cutoff; else `distance` is the cutoff
    /// (infinity without one) and the other fields are not set.
    pub found: bool,
    /// The distance is `<=` 1e-9 m: touching or overlapping, the rule of
    /// collision queries.
    pub collided: bool,
    /// The class of the closest cell (unknown for unknown space with
    /// [`crate::UnknownPolicy::Occupied`]).
    pub cell_class: CellClass,
    /// The closest link's index.
    pub link: u32,
    /// The closest shape's index within that link.
    pub shape: u32,
    /// Metres, padding included; `>= 0` unless `signed_distance`.
    pub distance: f64,
    /// Witness point on the padded shape, map frame.
    pub point_on_link: [f64; 3],
    /// Witness point on the cell, map frame; `distance` from `point_on_link`.
    pub point_on_cell: [f64; 3],
    /// The closest cell's centre, map frame.
    pub cell_center: [f64; 3],
    /// The closest cell's edge, metres.
    pub cell_size: f64,
    /// The closest cell's probability; 0.5 for unknown cells.
    pub cell_probability: f64,
    /// Exact shape-to-cell distances computed (a cost measure).
    pub narrow_tests: u64,
    /// The nearest world object (its index in the [`crate::World`];
    /// `point_on_cell` then lies on it and the cell fields are zeros), or
    /// `None` for a cell.
    pub object: Option<u32>,
    /// The object's nearest shape (its index within the object); 0 for a
    /// cell.
    pub object_shape: u32,
    /// The object attached to `link` ([`crate::LinkSet::attach_object`]:
    /// its index) whose shape is the nearest, `shape` then being its index
    /// within that object; `None` for one of the link's own shapes.
    pub attached: Option<u32>,
}

impl DistanceResult {
    pub(crate) fn from_c(c: &sys::opx_distance_result) -> Result<DistanceResult> {
        Ok(DistanceResult {
            found: is_set(c.found),
            collided: is_set(c.collided),
            cell_class: known(CellClass::from_raw(c.cell_class), c.cell_class, "cell class")?,
            link: c.link,
            shape: c.shape,
            distance: c.distance,
            point_on_link: c.point_on_link,
            point_on_cell: c.point_on_cell,
            cell_center: c.cell_center,
            cell_size: c.cell_size,
            cell_probability: c.cell_probability,
            narrow_tests: c.narrow_tests,
            object: object_index(c.object),
            object_shape: c.object_shape,
            attached: object_index(c.attached),
        })
    }
}

/// A world or attached object's index as the C API gives it, -1 meaning
/// none (a cell, or the link's own shape).
pub(crate) fn object_index(raw: i32) -> Option<u32> {
    u32::try_from(raw).ok()
}

/// The answer of [`crate::Query::path`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathResult {
    /// Some waypoint collides.
    pub collided: bool,
    /// The first colliding waypoint's index, if any.
    pub first_colliding_waypoint: Option<usize>,
    /// With `compute_distance`: the minimum distance along the path,
    /// metres; infinity otherwise or when the map holds no obstacle.
    pub min_distance: f64,
    /// The waypoint of `min_distance`, if any.
    pub min_distance_waypoint: Option<usize>,
    /// With `compute_cost`: m^3 over all cells swept.
    pub total_cost: f64,
    /// Cost boxes the query holds ([`crate::Query::cost_boxes`]).
    pub cost_box_count: u64,
    /// All cells swept.
    pub cost_boxes_found: u64,
    /// Exact tests run (a cost measure).
    pub narrow_tests: u64,
}

impl PathResult {
    pub(crate) fn from_c(c: &sys::opx_path_result) -> PathResult {
        PathResult {
            collided: is_set(c.collided),
            first_colliding_waypoint: index(c.first_colliding_waypoint),
            min_distance: c.min_distance,
            min_distance_waypoint: index(c.min_distance_waypoint),
            total_cost: c.total_cost,
            cost_box_count: c.cost_box_count,
            cost_boxes_found: c.cost_boxes_found,
            narrow_tests: c.narrow_tests,
        }
    }
}
