//! The options, reports and answers of [`crate::Octree`]: how a map is
//! made and updated, what an insert did, and what a cell or the map holds.
//! Coordinates are in the map frame, in metres; `Default` gives the C
//! library's defaults.
//!
//! ```
//! use octoprox::{pose_at, CellClass, InsertMode, InsertOptions, Octree, OctreeOptions};
//!
//! let options = OctreeOptions { resolution: 0.1, ..Default::default() };
//! let mut map = Octree::new(&options)?;
//! // Endpoints only, the sensor 1 m above the map origin, points in its frame.
//! let sensor = InsertOptions {
//!     mode: InsertMode::Endpoints,
//!     sensor_pose: pose_at(0.0, 0.0, 1.0),
//!     ..Default::default()
//! };
//! let report = map.insert_points(&[[0.55f64, 0.05, 0.05], [f64::NAN, 0.0, 0.0]], &sensor)?;
//! assert_eq!((report.points_used, report.points_nonfinite, report.cells_hit), (1, 1, 1));
//! let cell = map.classify([0.55, 0.05, 1.05])?;
//! assert_eq!((cell.cell_class, cell.size, cell.depth), (CellClass::Occupied, 0.1, 16));
//! let stats = map.stats()?;
//! assert!(stats.has_occupied && stats.leaves_occupied == 1);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::{is_set, known};
use crate::error::Result;
use crate::{sys, CellClass, InsertMode, LinkSet, Pose};

/// How a new map updates its cells (OctoMap's probabilities) and classes
/// them.  Requirements: `1e-6 <= resolution <= 1e6`;
/// `prob_miss < 0.5 < prob_hit`; `clamp_min < clamp_max`;
/// `0 < free_threshold <= occupied_threshold < 1`; an option outside them
/// is an [`crate::ErrorKind::InvalidArgument`] naming the field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OctreeOptions {
    /// Edge of a finest cell, metres (default 0.05).  A loaded map takes
    /// its file's resolution instead.
    pub resolution: f64,
    /// Probability update of a cell holding an endpoint (default 0.7).
    pub prob_hit: f64,
    /// Probability update of a cell a ray passes through (default 0.4).
    pub prob_miss: f64,
    /// Lower clamping bound of a cell's probability (default 0.1192).
    pub clamp_min: f64,
    /// Upper clamping bound of a cell's probability (default 0.971).
    pub clamp_max: f64,
    /// A cell is occupied when its probability is `>=` this (default 0.5).
    pub occupied_threshold: f64,
    /// A cell is free when its probability is `<` this (default 0.5, so no
    /// cell is uncertain; 0.3 gives an uncertain band).
    pub free_threshold: f64,
}

impl Default for OctreeOptions {
    fn default() -> OctreeOptions {
        OctreeOptions::from_c(&sys::opx_octree_options::default())
    }
}

impl OctreeOptions {
    pub(crate) fn to_c(self) -> sys::opx_octree_options {
        sys::opx_octree_options {
            resolution: self.resolution,
            prob_hit: self.prob_hit,
            prob_miss: self.prob_miss,
            clamp_min: self.clamp_min,
            clamp_max: self.clamp_max,
            occupied_threshold: self.occupied_threshold,
            free_threshold: self.free_threshold,
            ..Default::default()
        }
    }

    pub(crate) fn from_c(c: &sys::opx_octree_options) -> OctreeOptions {
        OctreeOptions {
            resolution: c.resolution,
            prob_hit: c.prob_hit,
            prob_miss: c.prob_miss,
            clamp_min: c.clamp_min,
            clamp_max: c.clamp_max,
            occupied_threshold: c.occupied_threshold,
            free_threshold: c.free_threshold,
        }
    }
}

/// How one sensor frame is inserted.  Borrows the robot it filters out,
/// if any, for as long as the options live.
///
/// ```
/// use octoprox::{pose_at, InsertOptions, LinkSet, Octree, OctreeOptions, Shape};
///
/// // The robot: a ball of radius 0.2 m, 2 m in front of the sensor.
/// let mut robot = LinkSet::new()?;
/// let link = robot.add_link("ball")?;
/// robot.add_shape(link, &Shape::sphere(0.2))?;
/// robot.set_poses(&[pose_at(2.0, 0.0, 0.0)])?;
/// let mut map = Octree::new(&OctreeOptions::default())?;
/// let filtered = InsertOptions { robot: Some(&robot), robot_padding: 0.02, ..Default::default() };
/// // On the ball, behind it, elsewhere.
/// let points = [[1.8f64, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
/// let report = map.insert_points(&points, &filtered)?;
/// assert_eq!((report.points_on_robot, report.points_shadowed, report.points_used), (1, 1, 1));
/// # Ok::<(), octoprox::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct InsertOptions<'a> {
    /// Ray-cast (the default) or endpoints only.
    pub mode: InsertMode,
    /// The sensor frame in the map frame; the points are in the sensor
    /// frame (default: identity).
    pub sensor_pose: Pose,
    /// Points farther than this from the sensor origin (metres) are counted
    /// as out of range and give no occupied cell: a ray is cut there and
    /// its cells become more free; in endpoint mode the point changes
    /// nothing.  `<= 0` or infinite: no limit (the default, -1).  NaN is an
    /// invalid argument.
    pub max_range: f64,
    /// Threads a ray-cast insert may use, the caller's included: 1 (the
    /// default) starts none, 0 takes one per hardware thread.  The map does
    /// not depend on it.
    pub max_threads: u32,
    /// Self-filtering: the robot when the frame was captured (a
    /// [`LinkSet`], from URDF or built by hand), its link poses as last
    /// set, attached objects included.  Points within a link's padding
    /// plus `robot_padding` of it are robot points, points whose ray passes
    /// through the padded robot are shadowed; neither gives an occupied
    /// cell, and their rays carve free space up to the robot (the C
    /// header's "The robot in its own frame").  A robot whose poses were
    /// never set is an invalid argument.  `None` (the default): no
    /// filtering.
    pub robot: Option<&'a LinkSet>,
    /// Metres added to every link's padding for the filter only; finite
    /// and `>= 0` (else an invalid argument naming `robot_padding`).
    /// Default 0.
    pub robot_padding: f64,
    /// Cells lying entirely inside the robot's unpadded solids become free
    /// in the same update (counted in [`InsertReport::cells_cleared`]).
    /// Needs `robot` (else an invalid argument).  Default false.
    pub clear_robot_volume: bool,
    /// `Some((box_min, box_max))`: only the cells of this box (map frame;
    /// cells as [`crate::Octree::clear_region`] takes them) change; a ray
    /// from outside still carves the cells it crosses inside.  A NaN or
    /// inverted box is an invalid argument.  `None` (the default): the
    /// whole map.
    pub bounds: Option<([f64; 3], [f64; 3])>,
}

impl Default for InsertOptions<'_> {
    fn default() -> Self {
        let c = sys::opx_insert_options::default();
        InsertOptions {
            mode: InsertMode::from_raw(c.mode).unwrap_or_default(),
            sensor_pose: c.sensor_pose,
            max_range: c.max_range,
            max_threads: c.max_threads,
            robot: None,
            robot_padding: c.robot_padding,
            clear_robot_volume: c.clear_robot_volume != 0,
            bounds: None,
        }
    }
}

/// Equal options: the same fields, the same robot (the same [`LinkSet`]
/// object, not an equal one).
impl PartialEq for InsertOptions<'_> {
    fn eq(&self, other: &Self) -> bool {
        let same_robot = match (self.robot, other.robot) {
            (Some(a), Some(b)) => std::ptr::eq(a, b),
            (a, b) => a.is_none() && b.is_none(),
        };
        same_robot
            && (self.mode, self.sensor_pose, self.max_range, self.max_threads)
                == (other.mode, other.sensor_pose, other.max_range, other.max_threads)
            && (self.robot_padding, self.clear_robot_volume, self.bounds)
                == (other.robot_padding, other.clear_robot_volume, other.bounds)
    }
}

impl InsertOptions<'_> {
    /// The C options; their robot pointer is valid while the borrow of
    /// the robot (`'_`) lasts, which spans the insert call.
    pub(crate) fn to_c(self) -> sys::opx_insert_options {
        sys::opx_insert_options {
            mode: self.mode.raw(),
            sensor_pose: self.sensor_pose,
            max_range: self.max_range,
            max_threads: self.max_threads,
            robot: self.robot.map_or(std::ptr::null_mut(), |r| r.as_raw() as *mut _),
            robot_padding: self.robot_padding,
            clear_robot_volume: u32::from(self.clear_robot_volume),
            use_bounds: u32::from(self.bounds.is_some()),
            bounds_min: self.bounds.map_or([0.0; 3], |b| b.0),
            bounds_max: self.bounds.map_or([0.0; 3], |b| b.1),
            ..Default::default()
        }
    }
}

/// What one insert did.  Every point (every pixel of a depth image) is
/// counted once: `points_used + points_nonfinite + points_out_of_range +
/// points_outside_map + points_on_robot + points_shadowed +
/// pixels_no_return` is the number of points (width x height of a depth
/// image).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct InsertReport {
    /// Points that updated the map.
    pub points_used: u64,
    /// Points with a NaN or infinite coordinate, skipped.
    pub points_nonfinite: u64,
    /// Points beyond `max_range` of the sensor.
    pub points_out_of_range: u64,
    /// Points outside the map's addressable cube.
    pub points_outside_map: u64,
    /// Cells updated as occupied.
    pub cells_hit: u64,
    /// Cells updated as free.
    pub cells_missed: u64,
    /// Depth-image pixels without a depth, skipped; 0 for points.
    pub pixels_no_return: u64,
    /// Self-filtering: points inside the padded robot (no occupied cell).
    pub points_on_robot: u64,
    /// Self-filtering: points whose ray passes through the padded robot
    /// first (no occupied cell).
    pub points_shadowed: u64,
    /// Self-filtering: cells set free as lying inside the robot.
    pub cells_cleared: u64,
}

impl InsertReport {
    pub(crate) fn from_c(c: &sys::opx_insert_report) -> InsertReport {
        InsertReport {
            points_used: c.points_used,
            points_nonfinite: c.points_nonfinite,
            points_out_of_range: c.points_out_of_range,
            points_outside_map: c.points_outside_map,
            cells_hit: c.cells_hit,
            cells_missed: c.cells_missed,
            pixels_no_return: c.pixels_no_return,
            points_on_robot: c.points_on_robot,
            points_shadowed: c.points_shadowed,
            cells_cleared: c.cells_cleared,
        }
    }
}

/// The cell holding a point, from [`crate::Octree::classify`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellInfo {
    /// The cell's class.
    pub cell_class: CellClass,
    /// Its occupancy probability; 0.5 (the prior) when unknown.
    pub probability: f64,
    /// The centre of the cell, map frame, metres.
    pub center: [f64; 3],
    /// The edge of the cell, metres; for unknown space the largest
    /// unobserved cube holding the point.
    pub size: f64,
    /// Its depth in the tree: 0 (the root cube) to 16 (finest cells).
    pub depth: u32,
}

impl CellInfo {
    pub(crate) fn from_c(c: &sys::opx_cell_info) -> Result<CellInfo> {
        Ok(CellInfo {
            cell_class: known(CellClass::from_raw(c.cell_class), c.cell_class, "cell class")?,
            probability: c.probability,
            center: c.center,
            size: c.size,
            depth: c.depth,
        })
    }
}

/// Counts, bounds and memory of a map, from [`crate::Octree::stats`].
/// Bounds are in the map frame, metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OctreeStats {
    /// Whether the map has occupied cells (and `occupied_min`/`_max` are set).
    pub has_occupied: bool,
    /// Edge of a finest cell, metres.
    pub resolution: f64,
    /// Occupied leaves.
    pub leaves_occupied: u64,
    /// Uncertain leaves.
    pub leaves_uncertain: u64,
    /// Free leaves.
    pub leaves_free: u64,
    /// Nodes with children, the root included.
    pub inner_nodes: u64,
    /// Bytes the tree holds: nodes, in blocks of 8 children.
    pub memory_bytes: u64,
    /// Lower corner of the occupied cells' boxes; zeros without any.
    pub occupied_min: [f64; 3],
    /// Upper corner of the occupied cells' boxes; zeros without any.
    pub occupied_max: [f64; 3],
    /// Lower corner of all observed cells' boxes; zeros for an empty map.
    pub known_min: [f64; 3],
    /// Upper corner of all observed cells' boxes; zeros for an empty map.
    pub known_max: [f64; 3],
    /// Occupied leaves that keep the box of their sensed points
    /// ([`crate::ObstacleGeometry::PointExtents`]); the others are whole cubes.
    pub leaves_with_extent: u64,
}

impl OctreeStats {
    pub(crate) fn from_c(c: &sys::opx_octree_stats) -> OctreeStats {
        OctreeStats {
            has_occupied: is_set(c.has_occupied),
            resolution: c.resolution,
            leaves_occupied: c.leaves_occupied,
            leaves_uncertain: c.leaves_uncertain,
            leaves_free: c.leaves_free,
            inner_nodes: c.inner_nodes,
            memory_bytes: c.memory_bytes,
            occupied_min: c.occupied_min,
            occupied_max: c.occupied_max,
            known_min: c.known_min,
            known_max: c.known_max,
            leaves_with_extent: c.leaves_with_extent,
        }
    }
}

/// One leaf of the map (the paper's "collision map" entry), from
/// [`crate::Octree::leaves`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leaf {
    /// The centre of the cell, map frame, metres.
    pub center: [f64; 3],
    /// The edge of the cell, metres.
    pub size: f64,
    /// Its occupancy probability.
    pub probability: f64,
    /// Its class (never [`CellClass::Unknown`]).
    pub cell_class: CellClass,
    /// Its depth in the tree: 0 (the root cube) to 16 (finest cells).
    pub depth: u32,
}

impl Leaf {
    pub(crate) fn from_c(c: &sys::opx_leaf) -> Result<Leaf> {
        Ok(Leaf {
            center: c.center,
            size: c.size,
            probability: c.probability,
            cell_class: known(CellClass::from_raw(c.cell_class), c.cell_class, "cell class")?,
            depth: c.depth,
        })
    }
}
