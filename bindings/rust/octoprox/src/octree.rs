//! The occupancy octree (`opx_octree`): the map, built from sensor frames
//! and read back by point, by leaf or as OctoMap bytes.
//!
//! ```
//! use octoprox::{pose_at, CellClass, InsertOptions, MapFormat, Octree, OctreeOptions};
//!
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() })?;
//! let sensor = InsertOptions { sensor_pose: pose_at(0.125, 0.125, 0.125), ..Default::default() };
//! map.insert_points(&[[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0]], &sensor)?; // two rays
//! assert_eq!(map.classify([1.125, 0.125, 0.125])?.cell_class, CellClass::Occupied);
//! assert_eq!(map.classify([0.625, 0.125, 0.125])?.cell_class, CellClass::Free);
//! assert_eq!(map.classify([-3.0, -3.0, -3.0])?.cell_class, CellClass::Unknown);
//! let bytes = map.save_memory(MapFormat::Ot)?;
//! let copy = Octree::load_memory(&bytes, &OctreeOptions::default())?;
//! assert_eq!(copy.stats()?.leaves_occupied, 2);
//! assert_eq!(copy.options()?.resolution, 0.25);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{check, to_c_string, Result};
use crate::{check_version, sys, CameraIntrinsics, CellClass, CellClasses, CellInfo, DepthImage,
            InsertOptions, InsertReport, Leaf, MapFormat, OctreeOptions, OctreeStats, Points, Pose,
            Shape};
use std::path::Path;
use std::ptr;

/// An occupancy octree in the map frame (OctoMap semantics: log-odds per
/// cell, hit and miss updates, clamping).  The map is a cube of 2^16 cells
/// per axis centred on the origin (+-1638.4 m at 5 cm).  Reading methods
/// take `&self` and may run on many threads at once; changing methods take
/// `&mut self`.  A failed call leaves the map as it was.
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
    /// 5 cm cells, OctoMap's probabilities).  Options outside their ranges
    /// are an [`crate::ErrorKind::InvalidArgument`] naming the field.
    pub fn new(options: &OctreeOptions) -> Result<Octree> {
        let options = options.to_c();
        // SAFETY: options and out are valid for the call.
        create(|out| unsafe { sys::opx_octree_create(&options, out) })
    }

    /// Loads a `.bt` or `.ot` file (OctoMap 1.x, type OcTree); the
    /// resolution comes from the file, the other options (probabilities,
    /// thresholds) from `options`.  Errors: [`crate::ErrorKind::Io`] when
    /// the file cannot be read, [`crate::ErrorKind::Corrupt`] for
    /// malformed or truncated data.
    pub fn load_file(path: impl AsRef<Path>, options: &OctreeOptions) -> Result<Octree> {
        let text = path.as_ref().to_string_lossy().into_owned();
        let path = to_c_string(&text, "Octree::load_file: path")?;
        let options = options.to_c();
        // SAFETY: path, options and out are valid for the call.
        create(|out| unsafe { sys::opx_octree_load_file(path.as_ptr(), &options, out) })
    }

    /// Loads the bytes of a `.bt` or `.ot` file, as [`Octree::load_file`].
    pub fn load_memory(data: &[u8], options: &OctreeOptions) -> Result<Octree> {
        let options = options.to_c();
        // SAFETY: data is valid for data.len() bytes.
        create(|out| unsafe {
            sys::opx_octree_load_memory(data.as_ptr().cast(), data.len(), &options, out)
        })
    }

    /// Loads the `data` of a ROS `octomap_msgs/Octomap` message: `binary`
    /// as in the message (a `.bt` body, else `.ot`), `resolution` in metres
    /// (1e-6 to 1e6).  The caller checks the message's `id`: only "OcTree"
    /// maps are read correctly.
    pub fn load_message(data: &[u8], binary: bool, resolution: f64, options: &OctreeOptions)
        -> Result<Octree> {
        let options = options.to_c();
        // SAFETY: data is valid for data.len() bytes.
        create(|out| unsafe {
            sys::opx_octree_load_message(data.as_ptr().cast(), data.len(), i32::from(binary),
                                         resolution, &options, out)
        })
    }

    /// Removes every cell; the options stay.
    pub fn clear(&mut self) -> Result<()> {
        // SAFETY: exclusive access to a live handle.
        check(unsafe { sys::opx_octree_clear(self.raw) })
    }

    /// Clears every cell of the box `[box_min, box_max]` (map frame,
    /// metres; a corner may be infinite) to `to`: [`CellClass::Unknown`]
    /// removes it, [`CellClass::Free`] sets it to the free clamp (unknown
    /// cells too).  The box covers the cells holding a point of it, as
    /// [`Octree::classify`] finds them: a face on a cell face takes the
    /// cell above it too.  A NaN corner, `box_min` above `box_max` or
    /// another class is an invalid argument; the map is then unchanged.
    pub fn clear_region(&mut self, box_min: [f64; 3], box_max: [f64; 3], to: CellClass) -> Result<()> {
        // SAFETY: the corners are 3 doubles each; exclusive access.
        check(unsafe { sys::opx_octree_clear_region(self.raw, box_min.as_ptr(), box_max.as_ptr(), to.raw()) })
    }

    /// Clears the cells an object occupies to `to` (as
    /// [`Octree::clear_region`]): `shapes` at their poses in the OBJECT
    /// frame, the object at `pose` in the map frame (a world object's
    /// shapes and pose, or an attached object's).  A cell is cleared when a
    /// shape touches it as a collision query decides it, so afterwards (to
    /// unknown) the shapes collide with no cell of the map.
    pub fn clear_shapes(&mut self, shapes: &[Shape<'_>], pose: &Pose, to: CellClass) -> Result<()> {
        // The C shapes borrow the vertices of `shapes`, which outlive the call.
        let shapes: Vec<sys::opx_shape> = shapes.iter().map(|shape| shape.to_c()).collect();
        let data = if shapes.is_empty() { ptr::null() } else { shapes.as_ptr() };
        // SAFETY: every pointer is valid for the call; exclusive access.
        check(unsafe { sys::opx_octree_clear_shapes(self.raw, data, shapes.len(), pose, to.raw()) })
    }

    /// Moves every known cell's log-odds toward 0 by `amount` (`>= 0`),
    /// never across it; a cell that reaches 0 becomes unknown.  Called once
    /// a frame, obstacles that left the view fade.  NaN or a negative
    /// amount is an invalid argument.
    pub fn decay(&mut self, amount: f64) -> Result<()> {
        // SAFETY: exclusive access to a live handle.
        check(unsafe { sys::opx_octree_decay(self.raw, amount) })
    }

    /// Removes every cell outside the box `[box_min, box_max]` (map frame;
    /// cells as [`Octree::clear_region`] takes them) and gives their memory
    /// back: a mobile base keeps a window around itself.
    pub fn crop(&mut self, box_min: [f64; 3], box_max: [f64; 3]) -> Result<()> {
        // SAFETY: the corners are 3 doubles each; exclusive access.
        check(unsafe { sys::opx_octree_crop(self.raw, box_min.as_ptr(), box_max.as_ptr()) })
    }

    /// The octree's options (a loaded map's resolution included).
    pub fn options(&self) -> Result<OctreeOptions> {
        let mut out = sys::opx_octree_options::default();
        // SAFETY: const call on a live handle; out is a valid struct.
        check(unsafe { sys::opx_octree_get_options(self.raw, &mut out) })?;
        Ok(OctreeOptions::from_c(&out))
    }

    /// Inserts one sensor frame: points in the SENSOR frame, the sensor at
    /// `options.sensor_pose` in the map frame; successive frames accumulate.
    /// The points are read in place (no copy).  Non-finite points are
    /// counted and skipped; an invalid option leaves the map unchanged.
    /// With `options.robot`, points on or behind the robot give no
    /// occupied cell (self-filtering, counted in the report's
    /// `points_on_robot` and `points_shadowed`).
    pub fn insert_points<'a>(&mut self, points: impl Into<Points<'a>>, options: &InsertOptions<'_>)
        -> Result<InsertReport> {
        let points = points.into();
        let options = options.to_c();
        let mut report = sys::opx_insert_report::default();
        // SAFETY: points borrow count points of stride bytes (checked when
        // the Points was built); exclusive access to the octree.
        check(unsafe {
            sys::opx_octree_insert_points(self.raw, points.c_data(), points.len(),
                                          points.stride(), points.scalar_type(), &options,
                                          &mut report)
        })?;
        Ok(InsertReport::from_c(&report))
    }

    /// Inserts one depth frame, as [`Octree::insert_points`] inserts the
    /// points it back-projects: the pixel in column `u`, row `v` with
    /// depth `z` metres becomes `((u - cx) * z / fx, (v - cy) * z / fy, z)`
    /// in the camera's optical frame (z forward, x right, y down), which
    /// `options.sensor_pose` places in the map frame.  Pixels without a
    /// return are skipped and counted in `pixels_no_return`.  The image is
    /// read in place.  Focal lengths must be positive (else
    /// [`crate::ErrorKind::InvalidArgument`] naming `intrinsics.fx` or
    /// `.fy`), a uint16 image's depth scale too.  Self-filtering
    /// (`options.robot`) applies to the back-projected points.
    pub fn insert_depth_image(&mut self, image: &DepthImage<'_>, intrinsics: &CameraIntrinsics,
                              options: &InsertOptions<'_>) -> Result<InsertReport> {
        let (intrinsics, options) = (intrinsics.to_c(), options.to_c());
        let mut report = sys::opx_insert_report::default();
        // SAFETY: the image borrows its pixels for its lifetime and its
        // rows were checked to lie inside them; exclusive access to the
        // octree; the other arguments are valid structs.
        check(unsafe {
            sys::opx_octree_insert_depth_image(self.raw, image.as_raw(), &intrinsics, &options,
                                               &mut report)
        })?;
        Ok(InsertReport::from_c(&report))
    }

    /// The cell holding `point` (map frame, metres) and its class.  A point
    /// outside the map's addressable cube is an invalid argument.
    pub fn classify(&self, point: [f64; 3]) -> Result<CellInfo> {
        let mut out = sys::opx_cell_info::default();
        // SAFETY: point holds three doubles; out is a valid struct.
        check(unsafe { sys::opx_octree_classify(self.raw, point.as_ptr(), &mut out) })?;
        CellInfo::from_c(&out)
    }

    /// Leaf counts, bounds and memory (one pass over the leaves).
    pub fn stats(&self) -> Result<OctreeStats> {
        let mut out = sys::opx_octree_stats::default();
        // SAFETY: const call; out is a valid struct.
        check(unsafe { sys::opx_octree_get_stats(self.raw, &mut out) })?;
        Ok(OctreeStats::from_c(&out))
    }

    /// The leaves whose class is in `classes`, depth-first: one class
    /// (`CellClass::Occupied`), several (`CellClass::Free |
    /// CellClass::Occupied`, `[CellClass::Free, CellClass::Occupied]`) or
    /// [`CellClasses::ALL_KNOWN`].  [`crate::CellClass::Unknown`] is an
    /// invalid argument: unknown space has no leaves.
    pub fn leaves(&self, classes: impl Into<CellClasses>) -> Result<Vec<Leaf>> {
        let mask = classes.into().bits();
        let mut count = 0usize;
        // SAFETY: capacity 0 with a NULL buffer asks for the count only.
        let status = unsafe {
            sys::opx_octree_get_leaves(self.raw, mask, ptr::null_mut(), 0, &mut count)
        };
        if status != sys::OPX_ERROR_BUFFER_TOO_SMALL {
            check(status)?;
        }
        let mut leaves = vec![sys::opx_leaf::default(); count];
        // SAFETY: leaves holds `count` elements; nothing changes the octree
        // in between (we hold &self, and the octree is not Sync-mutable).
        check(unsafe {
            sys::opx_octree_get_leaves(self.raw, mask, leaves.as_mut_ptr(), count, &mut count)
        })?;
        leaves.truncate(count);
        leaves.iter().map(Leaf::from_c).collect()
    }

    /// Saves to a file: [`MapFormat::Auto`] picks by the extension (`.bt`,
    /// `.ot` or `.opx`; another is an [`crate::ErrorKind::InvalidArgument`]).
    /// [`crate::ErrorKind::Io`] when the file cannot be written.
    pub fn save_file(&self, path: impl AsRef<Path>, format: MapFormat) -> Result<()> {
        let text = path.as_ref().to_string_lossy().into_owned();
        let path = to_c_string(&text, "Octree::save_file: path")?;
        // SAFETY: path is a valid C string.
        check(unsafe { sys::opx_octree_save_file(self.raw, path.as_ptr(), format.raw()) })
    }

    /// The bytes of a `.bt` ([`MapFormat::Bt`] or [`MapFormat::Auto`]) or
    /// `.ot` ([`MapFormat::Ot`]) file.
    pub fn save_memory(&self, format: MapFormat) -> Result<Vec<u8>> {
        let format = format.raw();
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
