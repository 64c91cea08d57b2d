//! Safe Rust bindings to OctoProx, a C library answering collision and
//! distance queries between robot links and occupancy octrees built from
//! point-cloud sensor frames.
//!
//! * [`Octree`]: the map (insert sensor frames: points or a
//!   [`DepthImage`]; classify, leaves, files).
//! * [`LinkSet`]: the robot (links, [`Shape`]s, paddings, poses), built by
//!   hand or from URDF ([`LinkSet::from_urdf_file`], joints and FK).
//! * [`Query`]: one per thread; [`Query::collide`], [`Query::distance`],
//!   [`Query::path`]; the robot against itself: [`Query::self_collide`],
//!   [`Query::self_distance`] over the pairs [`LinkSet::set_pair_enabled`]
//!   (and an SRDF) leave enabled.
//! * [`read_point_cloud`]: PCD and PLY files as points (the library's
//!   readers).
//!
//! Units are metres and radians; a [`Pose`] is `position` (x y z) and
//! `orientation` (qx qy qz qw, ROS order).  Request, option and result
//! types are the C structs themselves, with `Default` giving the library's
//! defaults; set fields with `..Default::default()`.  Every fallible call
//! returns `Result<_, Error>` with the C status and message.
//!
//! Threads: `Octree` and `LinkSet` are `Send + Sync` (any number of
//! threads may query them through `&`); a `Query` is `Send` but not `Sync`:
//! use one per thread.

mod batch;
mod cloud;
mod depth;
mod error;
mod linkset;
mod octree;
mod points;
mod query;
mod robot;
mod self_collision;

pub use batch::{BasePoses, ConfigurationAnswers, MotionAnswers};
pub use cloud::{read_point_cloud, PointCloud, PointCloudInfo};
pub use depth::{camera_intrinsics, CameraIntrinsics, DepthImage};
pub use error::{status_name, Error, Result};
pub use linkset::{LinkSet, Shape, ShapeKind};
pub use octree::Octree;
pub use points::Points;
pub use query::Query;
pub use robot::{JointInfo, UrdfOptions};

use octoprox_sys as sys;

/// A rigid transform: position in metres, unit quaternion x y z w (ROS order).
pub type Pose = sys::opx_pose;
pub type OctreeOptions = sys::opx_octree_options;
pub type InsertOptions = sys::opx_insert_options;
pub type InsertReport = sys::opx_insert_report;
pub type CellInfo = sys::opx_cell_info;
pub type OctreeStats = sys::opx_octree_stats;
pub type Leaf = sys::opx_leaf;
pub type QueryOptions = sys::opx_query_options;
pub type QueryStats = sys::opx_query_stats;
pub type CollisionRequest = sys::opx_collision_request;
pub type CollisionResult = sys::opx_collision_result;
pub type Contact = sys::opx_contact;
pub type CostBox = sys::opx_cost_box;
pub type DistanceRequest = sys::opx_distance_request;
pub type DistanceResult = sys::opx_distance_result;
pub type SelfCollisionRequest = sys::opx_self_collision_request;
pub type SelfCollisionResult = sys::opx_self_collision_result;
pub type SelfContact = sys::opx_self_contact;
pub type SelfDistanceRequest = sys::opx_self_distance_request;
pub type SelfDistanceResult = sys::opx_self_distance_result;
pub type PairSamplingOptions = sys::opx_pair_sampling_options;
pub type PairSamplingResult = sys::opx_pair_sampling_result;
pub type PathRequest = sys::opx_path_request;
pub type PathResult = sys::opx_path_result;
pub type BatchRequest = sys::opx_batch_request;
pub type MotionRequest = sys::opx_motion_request;
pub type MotionResult = sys::opx_motion_result;

/// The constants of the C headers (`OPX_CELL_OCCUPIED`, `OPX_MASK_ALL_KNOWN`,
/// `OPX_UNKNOWN_OCCUPIED`, `OPX_ENGINE_AMORTIZED`, `OPX_FORMAT_BT`, ...).
pub mod consts {
    pub use octoprox_sys::{
        OPX_CLOUD_ENCODING_ASCII, OPX_CLOUD_ENCODING_BINARY, OPX_CLOUD_ENCODING_BINARY_COMPRESSED,
        OPX_CLOUD_FORMAT_PCD, OPX_CLOUD_FORMAT_PLY,
        OPX_CELL_FREE, OPX_CELL_OCCUPIED, OPX_CELL_UNCERTAIN, OPX_CELL_UNKNOWN,
        OPX_ENGINE_AMORTIZED, OPX_ENGINE_DIRECT, OPX_ERROR_BUFFER_TOO_SMALL, OPX_ERROR_CORRUPT,
        OPX_ERROR_INTERNAL, OPX_ERROR_INVALID_ARGUMENT, OPX_ERROR_IO, OPX_ERROR_OUT_OF_MEMORY,
        OPX_ERROR_UNSUPPORTED, OPX_ERROR_VERSION, OPX_FORMAT_AUTO, OPX_FORMAT_BT, OPX_FORMAT_OT,
        OPX_INSERT_ENDPOINTS, OPX_INSERT_RAYCAST, OPX_JOINT_CONTINUOUS, OPX_JOINT_FIXED,
        OPX_JOINT_FLOATING, OPX_JOINT_NONE, OPX_JOINT_PLANAR, OPX_JOINT_PRISMATIC, OPX_JOINT_REVOLUTE, OPX_MASK_ALL_KNOWN, OPX_MASK_FREE,
        OPX_MASK_OCCUPIED, OPX_MASK_UNCERTAIN, OPX_OK, OPX_SCALAR_FLOAT32, OPX_SCALAR_FLOAT64,
        OPX_SCALAR_UINT16, OPX_UNKNOWN_FREE, OPX_UNKNOWN_OCCUPIED,
        OPX_VERSION_MAJOR, OPX_VERSION_MINOR, OPX_VERSION_PATCH,
    };
}

/// A pose at `position` with the identity orientation.
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
/// it.
pub fn check_version() -> Result<()> {
    let number = version_number() as i32;
    if compatible(number / 10000, number / 100 % 100) {
        return Ok(());
    }
    Err(Error::new(
        sys::OPX_ERROR_VERSION,
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
