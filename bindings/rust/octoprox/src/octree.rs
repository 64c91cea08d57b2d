//! The occupancy octree (`opx_octree`).
use crate::error::{check, to_c_string, Result};
use crate::{check_version, sys, CameraIntrinsics, CellInfo, DepthImage, InsertOptions,
            InsertReport, Leaf, OctreeOptions, OctreeStats, Points};
use std::path::Path;
use std::ptr;

/// An occupancy octree in the map frame (OctoMap semantics).  Reading
/// methods take `&self` and may run on many threads at once; changing
/// methods take `&mut self`.
#[derive(Debug)]
pub struct Octree {
    raw: *mut sys::opx_octree,
}

// SAFETY: the C contract lets an octree move between threads, and lets any
// number of threads call the functions taking a const handle at once; only
// those are reachable through `&Octree`.
unsafe impl Send for Octree {}
unsafe impl Sync for Octree {}

impl Drop for Octree {
    fn drop(&mut self) {
        // SAFETY: raw came from opx_octree_create/load and is destroyed once.
        unsafe { sys::opx_octree_destroy(self.raw) }
    }
}

/// Runs a constructor `f(&mut out)` and wraps its handle.
fn create(f: impl FnOnce(*mut *mut sys::opx_octree) -> sys::opx_status) -> Result<Octree> {
    check_version()?;
    let mut raw = ptr::null_mut();
    check(f(&mut raw))?;
    Ok(Octree { raw })
}

impl Octree {
    /// An empty octree with these options (`OctreeOptions::default()`:
    /// 5 cm cells, OctoMap's probabilities).
    pub fn new(options: &OctreeOptions) -> Result<Octree> {
        // SAFETY: options and out are valid for the call.
        create(|out| unsafe { sys::opx_octree_create(options, out) })
    }

    /// Loads a `.bt` or `.ot` file; the resolution comes from the file,
    /// the other options (probabilities, thresholds) from `options`.
    pub fn load_file(path: impl AsRef<Path>, options: &OctreeOptions) -> Result<Octree> {
        let text = path.as_ref().to_string_lossy().into_owned();
        let path = to_c_string(&text, "Octree::load_file: path")?;
        // SAFETY: path, options and out are valid for the call.
        create(|out| unsafe { sys::opx_octree_load_file(path.as_ptr(), options, out) })
    }

    /// Loads the bytes of a `.bt` or `.ot` file.
    pub fn load_memory(data: &[u8], options: &OctreeOptions) -> Result<Octree> {
        // SAFETY: data is valid for data.len() bytes.
        create(|out| unsafe {
            sys::opx_octree_load_memory(data.as_ptr().cast(), data.len(), options, out)
        })
    }

    /// Loads the `data` of a ROS `octomap_msgs/Octomap` message (`binary`
    /// as in the message; `resolution` in metres).
    pub fn load_message(data: &[u8], binary: bool, resolution: f64, options: &OctreeOptions)
        -> Result<Octree> {
        // SAFETY: data is valid for data.len() bytes.
        create(|out| unsafe {
            sys::opx_octree_load_message(data.as_ptr().cast(), data.len(), i32::from(binary),
                                         resolution, options, out)
        })
    }

    /// Removes every cell; the options stay.
    pub fn clear(&mut self) -> Result<()> {
        // SAFETY: exclusive access to a live handle.
        check(unsafe { sys::opx_octree_clear(self.raw) })
    }

    /// The octree's options (a loaded map's resolution included).
    pub fn options(&self) -> Result<OctreeOptions> {
        let mut out = OctreeOptions::default();
        // SAFETY: const call on a live handle; out is a valid struct.
        check(unsafe { sys::opx_octree_get_options(self.raw, &mut out) })?;
        Ok(out)
    }

    /// Inserts one sensor frame: points in the SENSOR frame, the sensor at
    /// `options.sensor_pose` in the map frame.  The points are read in
    /// place (no copy).
    pub fn insert_points<'a>(&mut self, points: impl Into<Points<'a>>, options: &InsertOptions)
        -> Result<InsertReport> {
        let points = points.into();
        let mut report = InsertReport::default();
        // SAFETY: points borrow count points of stride bytes (checked when
        // the Points was built); exclusive access to the octree.
        check(unsafe {
            sys::opx_octree_insert_points(self.raw, points.c_data(), points.len(),
                                          points.stride(), points.scalar_type(), options,
                                          &mut report)
        })?;
        Ok(report)
    }

    /// Inserts one depth frame, as [`Octree::insert_points`] inserts the
    /// points it back-projects: the pixel in column `u`, row `v` with
    /// depth `z` metres becomes `((u - cx) * z / fx, (v - cy) * z / fy, z)`
    /// in the camera's optical frame (z forward, x right, y down), which
    /// `options.sensor_pose` places in the map frame.  Pixels without a
    /// return are skipped and counted in `pixels_no_return`.  The image is
    /// read in place.
    pub fn insert_depth_image(&mut self, image: &DepthImage<'_>, intrinsics: &CameraIntrinsics,
                              options: &InsertOptions) -> Result<InsertReport> {
        let mut report = InsertReport::default();
        // SAFETY: the image borrows its pixels for its lifetime and its
        // rows were checked to lie inside them; exclusive access to the
        // octree; the other arguments are valid structs.
        check(unsafe {
            sys::opx_octree_insert_depth_image(self.raw, image.as_raw(), intrinsics, options,
                                               &mut report)
        })?;
        Ok(report)
    }

    /// The cell holding `point` (map frame) and its class.
    pub fn classify(&self, point: [f64; 3]) -> Result<CellInfo> {
        let mut out = CellInfo::default();
        // SAFETY: point holds three doubles; out is a valid struct.
        check(unsafe { sys::opx_octree_classify(self.raw, point.as_ptr(), &mut out) })?;
        Ok(out)
    }

    /// Leaf counts, bounds and memory.
    pub fn stats(&self) -> Result<OctreeStats> {
        let mut out = OctreeStats::default();
        // SAFETY: const call; out is a valid struct.
        check(unsafe { sys::opx_octree_get_stats(self.raw, &mut out) })?;
        Ok(out)
    }

    /// The leaves whose class is in `class_mask` (`consts::OPX_MASK_*`),
    /// depth-first.
    pub fn leaves(&self, class_mask: i32) -> Result<Vec<Leaf>> {
        let mask = class_mask as u32;
        let mut count = 0usize;
        // SAFETY: capacity 0 with a NULL buffer asks for the count only.
        let status = unsafe {
            sys::opx_octree_get_leaves(self.raw, mask, ptr::null_mut(), 0, &mut count)
        };
        if status != sys::OPX_ERROR_BUFFER_TOO_SMALL {
            check(status)?;
        }
        let mut leaves = vec![Leaf::default(); count];
        // SAFETY: leaves holds `count` elements; nothing changes the octree
        // in between (we hold &self, and the octree is not Sync-mutable).
        check(unsafe {
            sys::opx_octree_get_leaves(self.raw, mask, leaves.as_mut_ptr(), count, &mut count)
        })?;
        leaves.truncate(count);
        Ok(leaves)
    }

    /// Saves to a file; `format` is `consts::OPX_FORMAT_AUTO` (by the
    /// extension), `_BT` or `_OT`.
    pub fn save_file(&self, path: impl AsRef<Path>, format: i32) -> Result<()> {
        let text = path.as_ref().to_string_lossy().into_owned();
        let path = to_c_string(&text, "Octree::save_file: path")?;
        // SAFETY: path is a valid C string.
        check(unsafe { sys::opx_octree_save_file(self.raw, path.as_ptr(), format) })
    }

    /// The bytes of a `.bt` (`OPX_FORMAT_BT` or `_AUTO`) or `.ot` file.
    pub fn save_memory(&self, format: i32) -> Result<Vec<u8>> {
        let mut size = 0usize;
        // SAFETY: capacity 0 with a NULL buffer asks for the size only.
        let status = unsafe {
            sys::opx_octree_save_memory(self.raw, format, ptr::null_mut(), 0, &mut size)
        };
        if status != sys::OPX_ERROR_BUFFER_TOO_SMALL {
            check(status)?;
        }
        let mut bytes = vec![0u8; size];
        // SAFETY: bytes holds `size` bytes.
        check(unsafe {
            sys::opx_octree_save_memory(self.raw, format, bytes.as_mut_ptr().cast(), size,
                                        &mut size)
        })?;
        bytes.truncate(size);
        Ok(bytes)
    }

    /// The C handle, for the other wrappers.
    pub(crate) fn as_raw(&self) -> *const sys::opx_octree {
        self.raw
    }
}
