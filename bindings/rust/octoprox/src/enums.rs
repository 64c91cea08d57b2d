//! The typed forms of the C headers' `#define` classes and switches: cell
//! classes and sets of them, what unknown space is, which engine a query
//! context runs, how a sensor frame is inserted, what an occupied cell is
//! as an obstacle, and map file formats.
//!
//! ```
//! use octoprox::{pose_at, CellClass, InsertMode, InsertOptions, Octree, OctreeOptions};
//!
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() })?;
//! // A ray from (0.125, 0.125, 0.125) to 1 m along x: free cells, one occupied.
//! let sensor = InsertOptions { sensor_pose: pose_at(0.125, 0.125, 0.125), ..Default::default() };
//! assert_eq!(sensor.mode, InsertMode::Raycast);
//! map.insert_points(&[[1.0f32, 0.0, 0.0]], &sensor)?;
//! let seen = map.leaves(CellClass::Occupied | CellClass::Free)?;
//! assert!(seen.iter().any(|leaf| leaf.cell_class == CellClass::Occupied));
//! assert!(seen.iter().any(|leaf| leaf.cell_class == CellClass::Free));
//! assert_eq!(map.leaves(CellClass::Occupied)?.len(), 1);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{Error, ErrorKind};
use crate::sys;
use std::ops::BitOr;

/// Declares a fieldless enum whose variants stand for C constants, with
/// `raw()` (the constant) and `from_raw()` (None for a value the bindings
/// do not know).
macro_rules! c_enum {
    ($(#[$meta:meta])* $name:ident { $($(#[$vmeta:meta])* $variant:ident = $value:path),+ $(,)? }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum $name {
            $($(#[$vmeta])* $variant),+
        }

        impl $name {
            /// The C constant of this value.
            pub fn raw(self) -> i32 {
                match self {
                    $($name::$variant => $value),+
                }
            }

            /// The value of a C constant; `None` for a value these bindings
            /// do not know.
            pub fn from_raw(raw: i32) -> Option<$name> {
                match raw {
                    $(v if v == $value => Some($name::$variant),)+
                    _ => None,
                }
            }
        }
    };
}

c_enum! {
    /// The class of a cell by its occupancy probability `p` (OctoMap's
    /// rules; thresholds from [`crate::OctreeOptions`]).
    CellClass {
        /// Never observed: no cell in the tree.
        Unknown = sys::OPX_CELL_UNKNOWN,
        /// `p < free_threshold`.
        Free = sys::OPX_CELL_FREE,
        /// `free_threshold <= p < occupied_threshold` (none with the
        /// default thresholds, both 0.5).
        Uncertain = sys::OPX_CELL_UNCERTAIN,
        /// `p >= occupied_threshold`.
        Occupied = sys::OPX_CELL_OCCUPIED,
    }
}

c_enum! {
    /// What unknown (never observed) space is during a query.  Only the map
    /// cube (+-32768 cells on each axis around the origin) is searched:
    /// space outside it is neither an obstacle nor reported.
    UnknownPolicy {
        /// Free: optimistic, as MoveIt and FCL (the default).
        Free = sys::OPX_UNKNOWN_FREE,
        /// An obstacle: safe, a link must lie in observed space.
        Occupied = sys::OPX_UNKNOWN_OCCUPIED,
    }
}

c_enum! {
    /// How a query context searches the map.  Both engines give the same
    /// answers (collided, distances, costs, counts).
    Engine {
        /// Direct octree traversal, no per-frame preprocessing (the default).
        Direct = sys::OPX_ENGINE_DIRECT,
        /// The first query on a map frame turns its obstacle cells into
        /// boxes in a tree held by the context, which later queries refine;
        /// pays off when many queries hit one frame.  The only engine that
        /// takes a caller's boxes ([`crate::Query::bind_boxes`]).
        Amortized = sys::OPX_ENGINE_AMORTIZED,
    }
}

c_enum! {
    /// How a sensor frame updates the map.
    InsertMode {
        /// Cells along each ray become more free, the endpoint's cell more
        /// occupied; each cell is updated once per frame, an endpoint
        /// winning over a ray (OctoMap's `insertPointCloud`; the default).
        Raycast = sys::OPX_INSERT_RAYCAST,
        /// Each endpoint's cell gets one hit; no free space is marked.
        Endpoints = sys::OPX_INSERT_ENDPOINTS,
    }
}

c_enum! {
    /// What an occupied cell is as an obstacle (`docs/geometry.md`).
    /// Uncertain and unknown space are whole cubes either way.
    ObstacleGeometry {
        /// Its whole cube, as FCL and MoveIt (the default).
        Cells = sys::OPX_OBSTACLE_CELLS,
        /// The box of the sensed points that made it occupied, where the
        /// map recorded one (cells hit by [`crate::Octree::insert_points`]
        /// or a depth image); a cell without one (read from a file or a
        /// message) is its whole cube.
        PointExtents = sys::OPX_OBSTACLE_POINT_EXTENTS,
    }
}

c_enum! {
    /// Map file formats, for saving and loading maps.
    MapFormat {
        /// Saving: by the path's extension (`.bt`, `.ot` or `.opx`), BT for
        /// memory.  Loading reads the header.
        Auto = sys::OPX_FORMAT_AUTO,
        /// OctoMap binary (`.bt`): per leaf only occupied or free; a loaded
        /// leaf gets the clamping bound of its class as probability.
        Bt = sys::OPX_FORMAT_BT,
        /// OctoMap full (`.ot`, type "OcTree"): the log-odds of every node.
        Ot = sys::OPX_FORMAT_OT,
        /// OctoProx map (`.opx`): the `.ot` content and every occupied
        /// leaf's point extent ([`ObstacleGeometry::PointExtents`]), which
        /// `.bt` and `.ot` cannot hold.
        Opx = sys::OPX_FORMAT_OPX,
    }
}

pub(crate) use c_enum;

macro_rules! default_variant {
    ($($name:ident::$variant:ident),*) => {$(
        impl Default for $name {
            /// The C header's default.
            fn default() -> $name {
                $name::$variant
            }
        }
    )*};
}

c_enum! {
    /// What a row of joint values holds in the batch queries
    /// ([`crate::BatchRequest::joint_order`],
    /// [`crate::MotionRequest::joint_order`]).
    JointOrder {
        /// Told by the row's length (the default): the joint count means
        /// every joint in model order, the active joint count the active
        /// joints alone.  Never ambiguous: the two counts are equal only
        /// when every joint is active, and the two orders are then one.
        /// The calls taking rows as one flat slice
        /// ([`crate::Query::check_configurations`],
        /// [`crate::Query::check_motions`]) cannot tell a row's length
        /// from it: there this reads rows of the joint count.
        ByCount = sys::OPX_JOINTS_BY_COUNT,
        /// Every joint, in model order ([`crate::LinkSet::set_joint_positions`]).
        Model = sys::OPX_JOINTS_MODEL,
        /// The active joints alone, in model order
        /// ([`crate::LinkSet::set_active_joint_positions`]).
        Active = sys::OPX_JOINTS_ACTIVE,
    }
}

default_variant!(UnknownPolicy::Free, Engine::Direct, InsertMode::Raycast,
                 ObstacleGeometry::Cells, MapFormat::Auto, JointOrder::ByCount);

/// A set of [`CellClass`]es, to choose which leaves
/// [`crate::Octree::leaves`] returns.  Built from one class, with `|`, from
/// an array or an iterator of classes, or from the constants.  Unknown space
/// has no leaves: a set holding [`CellClass::Unknown`] is an invalid
/// argument there.
///
/// ```
/// use octoprox::{CellClass, CellClasses};
///
/// let known = CellClass::Free | CellClass::Uncertain | CellClass::Occupied;
/// assert_eq!(known, CellClasses::ALL_KNOWN);
/// assert_eq!(CellClasses::from([CellClass::Free, CellClass::Occupied]),
///            CellClass::Occupied | CellClass::Free);
/// assert!(known.contains(CellClass::Free) && !known.contains(CellClass::Unknown));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct CellClasses(u32);

impl CellClasses {
    /// No class.
    pub const NONE: CellClasses = CellClasses(0);
    /// Free cells.
    pub const FREE: CellClasses = CellClasses(sys::OPX_MASK_FREE as u32);
    /// Uncertain cells.
    pub const UNCERTAIN: CellClasses = CellClasses(sys::OPX_MASK_UNCERTAIN as u32);
    /// Occupied cells.
    pub const OCCUPIED: CellClasses = CellClasses(sys::OPX_MASK_OCCUPIED as u32);
    /// Every observed cell: free, uncertain and occupied.
    pub const ALL_KNOWN: CellClasses = CellClasses(sys::OPX_MASK_ALL_KNOWN as u32);

    /// Whether the set holds `class`.
    pub fn contains(self, class: CellClass) -> bool {
        self.0 & CellClasses::from(class).0 != 0
    }

    /// The C mask (`OPX_MASK_*` bits: bit `c` for the class of value `c`).
    pub fn bits(self) -> u32 {
        self.0
    }
}

impl From<CellClass> for CellClasses {
    fn from(class: CellClass) -> CellClasses {
        CellClasses(1u32 << class.raw())
    }
}

impl<const N: usize> From<[CellClass; N]> for CellClasses {
    fn from(classes: [CellClass; N]) -> CellClasses {
        classes.into_iter().collect()
    }
}

impl From<&[CellClass]> for CellClasses {
    fn from(classes: &[CellClass]) -> CellClasses {
        classes.iter().copied().collect()
    }
}

impl FromIterator<CellClass> for CellClasses {
    fn from_iter<I: IntoIterator<Item = CellClass>>(classes: I) -> CellClasses {
        classes.into_iter().fold(CellClasses::NONE, |set, class| set | class)
    }
}

impl<T: Into<CellClasses>> BitOr<T> for CellClasses {
    type Output = CellClasses;
    fn bitor(self, other: T) -> CellClasses {
        CellClasses(self.0 | other.into().0)
    }
}

impl<T: Into<CellClasses>> BitOr<T> for CellClass {
    type Output = CellClasses;
    fn bitor(self, other: T) -> CellClasses {
        CellClasses::from(self) | other
    }
}

/// The C flag of a `bool` (1 or 0).
pub(crate) fn flag(value: bool) -> i32 {
    i32::from(value)
}

/// A C flag as a `bool` (nonzero is true).
pub(crate) fn is_set(flag: i32) -> bool {
    flag != 0
}

/// An index the C API reports as -1 when there is none.
pub(crate) fn index(raw: i64) -> Option<usize> {
    usize::try_from(raw).ok()
}

/// A value the library returned, in the enum of `what`; a value unknown to
/// these bindings (a newer library) is an `ErrorKind::Version` error.
pub(crate) fn known<T>(value: Option<T>, raw: i32, what: &str) -> Result<T, Error> {
    value.ok_or_else(|| {
        Error::of_kind(ErrorKind::Version,
                       format!("octoprox: {} {} is unknown to these bindings", what, raw))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_round_trips_through_its_constant() {
        for class in [CellClass::Unknown, CellClass::Free, CellClass::Uncertain, CellClass::Occupied] {
            assert_eq!(CellClass::from_raw(class.raw()), Some(class));
        }
        assert_eq!(CellClass::from_raw(42), None);
        assert_eq!(ObstacleGeometry::PointExtents.raw(), sys::OPX_OBSTACLE_POINT_EXTENTS);
        assert_eq!(ObstacleGeometry::from_raw(sys::OPX_OBSTACLE_CELLS), Some(ObstacleGeometry::Cells));
        assert_eq!(Engine::from_raw(sys::OPX_ENGINE_AMORTIZED), Some(Engine::Amortized));
        assert_eq!(MapFormat::Ot.raw(), sys::OPX_FORMAT_OT);
        assert_eq!(MapFormat::Opx.raw(), sys::OPX_FORMAT_OPX);
    }

    #[test]
    fn class_sets_are_the_c_masks() {
        assert_eq!(CellClasses::from(CellClass::Occupied).bits(), sys::OPX_MASK_OCCUPIED as u32);
        let known: CellClasses = [CellClass::Free, CellClass::Uncertain, CellClass::Occupied].into();
        assert_eq!(known.bits(), sys::OPX_MASK_ALL_KNOWN as u32);
        assert_eq!(CellClasses::FREE | CellClasses::UNCERTAIN | CellClass::Occupied, known);
        assert!(!CellClasses::NONE.contains(CellClass::Free));
    }
}
