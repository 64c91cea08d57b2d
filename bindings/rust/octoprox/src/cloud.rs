//! Point clouds from PCD and PLY files, read by the library's own readers
//! (those of the `octoprox` tool): PCD ascii, binary and LZF
//! binary_compressed; PLY ascii and binary_little_endian.
use crate::error::{check, to_c_string, Result};
use crate::{check_version, sys, Pose};
use std::path::Path;
use std::ptr;

/// What a cloud file holds (`format`, `encoding`: `OPX_CLOUD_*` in
/// [`crate::consts`]; `width` and `height` of an organized PCD cloud;
/// the PCD `viewpoint` in ROS order, identity when `has_viewpoint` is 0).
pub type PointCloudInfo = sys::opx_point_cloud_info;

/// A cloud read from a file: x y z float32 per point, in the file's
/// order and frame (a camera's cloud is usually in its optical frame: z
/// forward, x right, y down), non-finite points included.
#[derive(Debug, Clone)]
pub struct PointCloud {
    pub points: Vec<[f32; 3]>,
    pub info: PointCloudInfo,
}

impl PointCloud {
    /// The PCD VIEWPOINT as a pose, when the file has one.
    pub fn viewpoint(&self) -> Option<Pose> {
        (self.info.has_viewpoint != 0).then_some(self.info.viewpoint)
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

/// Reads a `.pcd` or `.ply` file (told by its extension).
pub fn read_point_cloud(path: impl AsRef<Path>) -> Result<PointCloud> {
    check_version()?;
    let path = to_c_string(&path.as_ref().to_string_lossy(), "read_point_cloud: path")?;
    let mut handle = Handle(ptr::null_mut());
    // SAFETY: path is a NUL-terminated string living across the call.
    check(unsafe { sys::opx_point_cloud_read_file(path.as_ptr(), &mut handle.0) })?;
    let mut info = PointCloudInfo::default();
    // SAFETY: handle.0 is a live cloud, info a versioned struct.
    check(unsafe { sys::opx_point_cloud_get_info(handle.0, &mut info) })?;
    let mut points = vec![[0.0f32; 3]; info.point_count as usize];
    let mut count = 0usize;
    // SAFETY: points holds point_count packed x y z floats.
    check(unsafe {
        sys::opx_point_cloud_get_points(handle.0, points.as_mut_ptr().cast(), points.len(), 0, &mut count)
    })?;
    Ok(PointCloud { points, info })
}
