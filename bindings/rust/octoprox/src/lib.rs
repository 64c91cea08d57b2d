//! Safe Rust bindings to OctoProx, a C library answering collision and
//! distance queries between robot links and occupancy octrees built from
//! point-cloud sensor frames.
//!
//! * [`Octree`]: the map (insert sensor frames: [`Points`] or a
//!   [`DepthImage`]; classify, leaves, files).
//! * [`LinkSet`]: the robot (links, [`Shape`]s, paddings, poses), built by
//!   hand or from URDF ([`LinkSet::from_urdf_file`], joints and FK, from
//!   every joint or from the active joints alone:
//!   [`LinkSet::set_active_joint_positions`]).
//! * [`Query`]: one per thread; [`Query::collide`], [`Query::distance`],
//!   [`Query::path`]; many configurations and motions per call
//!   ([`Query::check_configurations`], [`Query::check_motions`]); the robot
//!   against itself: [`Query::self_collide`], [`Query::self_distance`] over
//!   the pairs [`LinkSet::set_pair_enabled`] (and an SRDF) leave enabled.
//! * [`World`]: known objects beside the map (tables, shelves, walls),
//!   built by hand or read from MoveIt planning scenes
//!   ([`World::from_scene_file`]); [`Query::collide_with_world`],
//!   [`Query::distance_with_world`], [`Query::path_with_world`] and the
//!   batches' `_with_world` variants check them with or without a map.
//! * Objects attached to links (a grasped part, with the fingers as touch
//!   links): [`LinkSet::attach_object`], [`LinkSet::attach_world_object`],
//!   [`LinkSet::detach`]; contacts and distances name them (`attached`).
//! * [`read_point_cloud`]: PCD and PLY files as points (the library's
//!   readers).
//!
//! Units are metres and radians; frames are right-handed; a [`Pose`] is
//! `position` (x y z) and `orientation` (qx qy qz qw, ROS order), and every
//! pose and point says which frame it is in (the map frame unless told
//! otherwise).  Requests, options and results are plain structs: build them
//! with `Default` (the C library's own defaults) and struct update syntax
//! (`..Default::default()`); classes and switches are enums
//! ([`CellClass`], [`UnknownPolicy`], [`Engine`], [`InsertMode`],
//! [`ObstacleGeometry`], [`JointOrder`], [`SceneFormat`]), flags are
//! `bool`.  Every fallible
//! call returns [`Result`], whose [`Error`] has the C status as an
//! [`ErrorKind`] and the library's message naming the function and the
//! argument.
//!
//! Threads: `Octree`, `LinkSet` and `World` are `Send + Sync` (any number
//! of threads may query them through `&`); a `Query` is `Send` but not
//! `Sync`: use one per thread.
//!
//! ```
//! use octoprox::{pose_at, CollisionRequest, InsertOptions, LinkSet, Octree, Query, Shape};
//!
//! let mut map = Octree::new(&Default::default())?; // 5 cm cells
//! let frame = [[1.0f32, 0.0, 0.0], [1.0, 0.5, 0.0]]; // sensor frame, metres
//! let sensor = InsertOptions { sensor_pose: pose_at(0.0, 0.0, 1.2), ..Default::default() };
//! map.insert_points(&frame, &sensor)?;
//! let mut robot = LinkSet::new()?;
//! let hand = robot.add_link("hand")?;
//! robot.add_shape(hand, &Shape::sphere(0.08))?;
//! robot.set_poses(&[pose_at(0.95, 0.0, 1.2)])?; // map frame
//! let hit = Query::new(&Default::default())?.collide(&map, &robot, &CollisionRequest::default())?;
//! assert!(hit.collided);
//! # Ok::<(), octoprox::Error>(())
//! ```
#![deny(missing_docs)]

mod attached;
mod batch;
mod batch_types;
mod cloud;
mod depth;
mod enums;
mod error;
mod joints;
mod linkset;
mod map_types;
mod octree;
mod points;
mod query;
mod requests;
mod results;
mod robot;
mod self_collision;
mod self_types;
mod spheres;
mod world;

pub use batch::{BasePoses, ConfigurationAnswers, MotionAnswers};
pub use batch_types::{BatchRequest, MotionRequest, MotionResult};
pub use cloud::{read_point_cloud, CloudEncoding, CloudFormat, PointCloud, PointCloudInfo};
pub use depth::{camera_intrinsics, CameraIntrinsics, DepthImage};
pub use enums::{CellClass, CellClasses, Engine, InsertMode, JointOrder, MapFormat, ObstacleGeometry,
                UnknownPolicy};
pub use error::{status_name, Error, ErrorKind, Result};
pub use linkset::{LinkSet, Shape, ShapeKind};
pub use map_types::{CellInfo, InsertOptions, InsertReport, Leaf, OctreeOptions, OctreeStats};
pub use octree::Octree;
pub use points::Points;
pub use query::Query;
pub use requests::{CollisionRequest, DistanceRequest, PathRequest, QueryOptions};
pub use results::{CollisionResult, Contact, CostBox, DistanceResult, PathResult, QueryStats};
pub use robot::{JointInfo, JointType, UrdfOptions};
pub use self_types::{PairSamplingOptions, PairSamplingResult, SelfCollisionRequest,
                     SelfCollisionResult, SelfContact, SelfDistanceRequest, SelfDistanceResult};
pub use spheres::{SphereDistanceRequest, SphereDistances, SphereRequest, TrajectoryCost, TrajectoryCostRequest};
pub use world::{SceneFormat, World};

use octoprox_sys as sys;

/// A rigid transform: the pose of a child frame in a parent frame.
/// `position` in metres, `orientation` a unit quaternion x y z w (ROS
/// order), normalised by the library; a zero or non-finite quaternion is an
/// invalid argument.  `Pose::default()` is the identity.
pub type Pose = sys::opx_pose;

/// The constants of the C headers (`OPX_CELL_OCCUPIED`, `OPX_MASK_ALL_KNOWN`,
/// `OPX_ERROR_IO`, ...), for code that also talks to `octoprox-sys`; this
/// crate's API takes and returns their enums ([`CellClass`],
/// [`CellClasses`], [`ErrorKind`], ...).
pub mod consts {
    pub use octoprox_sys::{
        OPX_CLOUD_ENCODING_ASCII, OPX_CLOUD_ENCODING_BINARY, OPX_CLOUD_ENCODING_BINARY_COMPRESSED,
        OPX_CLOUD_FORMAT_PCD, OPX_CLOUD_FORMAT_PLY,
        OPX_CELL_FREE, OPX_CELL_OCCUPIED, OPX_CELL_UNCERTAIN, OPX_CELL_UNKNOWN,
        OPX_ENGINE_AMORTIZED, OPX_ENGINE_DIRECT, OPX_ERROR_BUFFER_TOO_SMALL, OPX_ERROR_CORRUPT,
        OPX_ERROR_INTERNAL, OPX_ERROR_INVALID_ARGUMENT, OPX_ERROR_IO, OPX_ERROR_OUT_OF_MEMORY,
        OPX_ERROR_UNSUPPORTED, OPX_ERROR_VERSION, OPX_FORMAT_AUTO, OPX_FORMAT_BT, OPX_FORMAT_OT,
        OPX_INSERT_ENDPOINTS, OPX_INSERT_RAYCAST, OPX_JOINTS_ACTIVE, OPX_JOINTS_BY_COUNT,
        OPX_JOINTS_MODEL, OPX_JOINT_CONTINUOUS, OPX_JOINT_FIXED,
        OPX_JOINT_FLOATING, OPX_JOINT_NONE, OPX_JOINT_PLANAR, OPX_JOINT_PRISMATIC, OPX_JOINT_REVOLUTE, OPX_MASK_ALL_KNOWN, OPX_MASK_FREE,
        OPX_MASK_OCCUPIED, OPX_MASK_UNCERTAIN, OPX_OBSTACLE_CELLS, OPX_OBSTACLE_POINT_EXTENTS,
        OPX_OK, OPX_SCALAR_FLOAT32, OPX_SCALAR_FLOAT64, OPX_SCENE_FORMAT_TEXT, OPX_SCENE_FORMAT_YAML,
        OPX_SCALAR_UINT16, OPX_UNKNOWN_FREE, OPX_UNKNOWN_OCCUPIED,
        OPX_VERSION_MAJOR, OPX_VERSION_MINOR, OPX_VERSION_PATCH,
    };
}

/// A pose at (`x`, `y`, `z`) metres in its parent frame, with the identity
/// orientation.
pub fn pose_at(x: f64, y: f64, z: f64) -> Pose {
    Pose { position: [x, y, z], orientation: [0.0, 0.0, 0.0, 1.0] }
}

/// The run-time library version, e.g. "0.1.0".
pub fn version() -> String {
    // SAFETY: opx_version returns a static NUL-terminated string.
    unsafe { error::c_string(sys::opx_version()) }
}

/// The run-time `OPX_VERSION_NUMBER` (major * 10000 + minor * 100 + patch).
pub fn version_number() -> u32 {
    // SAFETY: no arguments.
    unsafe { sys::opx_version_number() }
}

/// Checks that the linked library is compatible with the headers these
/// bindings were generated from: same major version and a minor at least
/// as new, but on 0.x (where a minor may change the ABI, as the SONAME
/// `liboctoprox.so.0.MINOR` says) the same minor.  Every constructor calls
/// it; a mismatch is an [`ErrorKind::Version`] error.
pub fn check_version() -> Result<()> {
    let number = version_number() as i32;
    if compatible(number / 10000, number / 100 % 100) {
        return Ok(());
    }
    Err(Error::of_kind(
        ErrorKind::Version,
        format!(
            "octoprox: library version {} is incompatible with the bindings' {}.{}",
            version(),
            sys::OPX_VERSION_MAJOR,
            sys::OPX_VERSION_MINOR
        ),
    ))
}

/// Whether a library of version `major.minor` serves these bindings.
fn compatible(major: i32, minor: i32) -> bool {
    if major != sys::OPX_VERSION_MAJOR {
        false
    } else if major == 0 {
        minor == sys::OPX_VERSION_MINOR
    } else {
        minor >= sys::OPX_VERSION_MINOR
    }
}

#[cfg(test)]
mod tests {
    use super::{compatible, sys};

    #[test]
    fn a_library_is_compatible_within_its_soname() {
        let (major, minor) = (sys::OPX_VERSION_MAJOR, sys::OPX_VERSION_MINOR);
        assert!(compatible(major, minor));
        assert!(!compatible(major + 1, minor));
        // 0.x: a later minor is another ABI; from 1.0 on it only adds.
        assert_eq!(compatible(major, minor + 1), major != 0);
    }
}
