//! Point clouds from PCD and PLY files, read by the library's own readers
//! (those of the `octoprox` tool): PCD ascii, binary and LZF
//! binary_compressed; PLY ascii and binary_little_endian.
//!
//! ```
//! use octoprox::{read_point_cloud, CloudEncoding, CloudFormat, InsertOptions, Octree,
//!                OctreeOptions};
//!
//! let path = std::env::temp_dir().join(format!("octoprox_doc_{}.pcd", std::process::id()));
//! std::fs::write(&path, "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n\
//!                        WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 1 1 0 0 0\nDATA ascii\n\
//!                        1 0 0\nnan nan nan\n").unwrap();
//! let cloud = read_point_cloud(&path)?;
//! std::fs::remove_file(&path).unwrap();
//! assert_eq!((cloud.info.format, cloud.info.encoding), (CloudFormat::Pcd, CloudEncoding::Ascii));
//! assert_eq!((cloud.info.point_count, cloud.info.finite_count), (2, 1));
//! // The viewpoint places the sensor 1 m above the map origin.
//! let sensor = InsertOptions { sensor_pose: cloud.viewpoint().unwrap(), ..Default::default() };
//! let mut map = Octree::new(&OctreeOptions::default())?;
//! let report = map.insert_points(&cloud.points, &sensor)?;
//! assert_eq!((report.points_used, report.points_nonfinite), (1, 1));
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::{c_enum, is_set, known};
use crate::error::{check, to_c_string, Result};
use crate::{check_version, sys, Pose};
use std::path::Path;
use std::ptr;

c_enum! {
    /// The format of a point cloud file, told by its extension.
    CloudFormat {
        /// PCD v0.7 (Point Cloud Library).
        Pcd = sys::OPX_CLOUD_FORMAT_PCD,
        /// The vertices of a PLY file.
        Ply = sys::OPX_CLOUD_FORMAT_PLY,
    }
}

c_enum! {
    /// How the points are stored in a point cloud file.
    CloudEncoding {
        /// Text.
        Ascii = sys::OPX_CLOUD_ENCODING_ASCII,
        /// PCD binary; PLY binary_little_endian.
        Binary = sys::OPX_CLOUD_ENCODING_BINARY,
        /// PCD binary_compressed (LZF).
        BinaryCompressed = sys::OPX_CLOUD_ENCODING_BINARY_COMPRESSED,
    }
}

/// What a point cloud file holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointCloudInfo {
    /// PCD or PLY.
    pub format: CloudFormat,
    /// How the file stores the points.
    pub encoding: CloudEncoding,
    /// The PCD header has a VIEWPOINT line.
    pub has_viewpoint: bool,
    /// Every point, non-finite ones included.
    pub point_count: u64,
    /// Points whose x, y and z are all finite.
    pub finite_count: u64,
    /// PCD WIDTH: columns of an organized cloud, else `point_count`; PLY:
    /// `point_count`.
    pub width: u64,
    /// PCD HEIGHT: rows of an organized cloud, else 1; PLY: 1.
    pub height: u64,
    /// The PCD VIEWPOINT (written tx ty tz qw qx qy qz) as a pose in ROS
    /// order, not normalised: the pose of the cloud's frame (the
    /// sensor's) in the frame the cloud is to be placed in.  Identity
    /// without a VIEWPOINT line and for PLY.
    pub viewpoint: Pose,
}

impl PointCloudInfo {
    fn from_c(c: &sys::opx_point_cloud_info) -> Result<PointCloudInfo> {
        Ok(PointCloudInfo {
            format: known(CloudFormat::from_raw(c.format), c.format, "cloud format")?,
            encoding: known(CloudEncoding::from_raw(c.encoding), c.encoding, "cloud encoding")?,
            has_viewpoint: is_set(c.has_viewpoint),
            point_count: c.point_count,
            finite_count: c.finite_count,
            width: c.width,
            height: c.height,
            viewpoint: c.viewpoint,
        })
    }
}

/// A cloud read from a file: x y z float32 per point, in the file's
/// order and frame (a camera's cloud is usually in its optical frame: z
/// forward, x right, y down), non-finite points included.
#[derive(Debug, Clone)]
pub struct PointCloud {
    /// The points, x y z in the file's frame and units (metres as written),
    /// an organized cloud row after row.
    pub points: Vec<[f32; 3]>,
    /// What the file holds.
    pub info: PointCloudInfo,
}

impl PointCloud {
    /// The PCD VIEWPOINT as a pose, when the file has one.
    pub fn viewpoint(&self) -> Option<Pose> {
        self.info.has_viewpoint.then_some(self.info.viewpoint)
    }
}

/// Frees the library's cloud when dropped.
struct Handle(*mut sys::opx_point_cloud);

impl Drop for Handle {
    fn drop(&mut self) {
        // SAFETY: the handle came from opx_point_cloud_read_file (or is NULL).
        unsafe { sys::opx_point_cloud_destroy(self.0) }
    }
}

/// Reads a `.pcd` or `.ply` file (told by its extension, any case).
/// Errors, the message naming the file: [`crate::ErrorKind::Io`] (cannot
/// be opened), [`crate::ErrorKind::Corrupt`] (a malformed or truncated
/// header or body), [`crate::ErrorKind::Unsupported`] (another extension,
/// PLY binary_big_endian, coordinates stored as integers).
pub fn read_point_cloud(path: impl AsRef<Path>) -> Result<PointCloud> {
    check_version()?;
    let path = to_c_string(&path.as_ref().to_string_lossy(), "read_point_cloud: path")?;
    let mut handle = Handle(ptr::null_mut());
    // SAFETY: path is a NUL-terminated string living across the call.
    check(unsafe { sys::opx_point_cloud_read_file(path.as_ptr(), &mut handle.0) })?;
    let mut raw_info = sys::opx_point_cloud_info::default();
    // SAFETY: handle.0 is a live cloud, raw_info a versioned struct.
    check(unsafe { sys::opx_point_cloud_get_info(handle.0, &mut raw_info) })?;
    let info = PointCloudInfo::from_c(&raw_info)?;
    let mut points = vec![[0.0f32; 3]; info.point_count as usize];
    let mut count = 0usize;
    // SAFETY: points holds point_count packed x y z floats.
    check(unsafe {
        sys::opx_point_cloud_get_points(handle.0, points.as_mut_ptr().cast(), points.len(), 0, &mut count)
    })?;
    Ok(PointCloud { points, info })
}
