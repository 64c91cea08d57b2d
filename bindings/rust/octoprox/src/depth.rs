//! Borrowed depth images handed to the library by address and row stride,
//! never copied, and the pinhole camera that back-projects them.
//!
//! ```
//! use octoprox::{camera_intrinsics, pose_at, CellClass, DepthImage, InsertOptions, Octree,
//!                OctreeOptions};
//!
//! // 2 x 2 pixels, millimetres; 0 is no return.
//! let depth: [u16; 4] = [1000, 1000, 0, 1000];
//! let image = DepthImage::from_u16(&depth, 2, 2, 0, 1000.0)?;
//! let camera = camera_intrinsics(1.0, 1.0, 0.5, 0.5); // fx, fy, cx, cy in pixels
//! // The optical frame 1 m above the map origin, looking along +z.
//! let sensor = InsertOptions { sensor_pose: pose_at(0.0, 0.0, 1.0), ..Default::default() };
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.1, ..Default::default() })?;
//! let report = map.insert_depth_image(&image, &camera, &sensor)?;
//! assert_eq!((report.points_used, report.pixels_no_return), (3, 1));
//! // Pixel (0, 0) at 1 m: ((0 - 0.5) * 1 / 1, (0 - 0.5) * 1 / 1, 1) in the optical
//! // frame, (-0.5, -0.5, 2) in the map frame.
//! assert_eq!(map.classify([-0.5, -0.5, 2.0])?.cell_class, CellClass::Occupied);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{Error, Result};
use crate::sys;
use std::marker::PhantomData;
use std::mem::size_of;

/// A pinhole camera without distortion, in pixels: focal lengths `fx`,
/// `fy` and principal point `cx` (column), `cy` (row); a ROS
/// `CameraInfo`'s `K` holds them at indices 0, 4, 2 and 5.  `fx` and `fy`
/// must be positive, `cx` and `cy` finite.  The defaults are all 0: set
/// every field (or use [`camera_intrinsics`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CameraIntrinsics {
    /// Horizontal focal length (along x, columns), pixels.
    pub fx: f64,
    /// Vertical focal length (along y, rows), pixels.
    pub fy: f64,
    /// Principal point: column (x), pixels.
    pub cx: f64,
    /// Principal point: row (y), pixels.
    pub cy: f64,
}

impl CameraIntrinsics {
    pub(crate) fn to_c(self) -> sys::opx_camera_intrinsics {
        sys::opx_camera_intrinsics { fx: self.fx, fy: self.fy, cx: self.cx, cy: self.cy,
                                     ..Default::default() }
    }
}

/// The [`CameraIntrinsics`] of focal lengths `fx`, `fy` and principal
/// point (`cx`, `cy`), all in pixels.
pub fn camera_intrinsics(fx: f64, fy: f64, cx: f64, cy: f64) -> CameraIntrinsics {
    CameraIntrinsics { fx, fy, cx, cy }
}

/// An organized depth frame borrowed for `'a`: `height` rows of `width`
/// pixels, each row `stride` pixels after the previous, left to right and
/// top to bottom.  Build it with [`DepthImage::from_u16`] (depth in units of
/// `1 / depth_scale` metres, 0 for no return) or [`DepthImage::from_f32`]
/// (metres; 0, NaN, infinite and negative for no return), and insert it
/// with [`crate::Octree::insert_depth_image`].
#[derive(Debug, Clone, Copy)]
pub struct DepthImage<'a> {
    raw: sys::opx_depth_image,
    _borrow: PhantomData<&'a [u8]>,
}

impl<'a> DepthImage<'a> {
    /// uint16 depth: `depth_scale` units per metre (1000 for millimetres,
    /// as OpenNI and ROS 16UC1 images; 5000 for TUM RGB-D PNGs), 0 for no
    /// return.  `stride` is in pixels (0: `width`, rows packed).  Rows that
    /// do not fit in `pixels`, or a stride below the width, are an invalid
    /// argument.
    pub fn from_u16(pixels: &'a [u16], width: usize, height: usize, stride: usize,
                    depth_scale: f64) -> Result<DepthImage<'a>> {
        let stride = checked_stride(pixels.len(), width, height, stride)?;
        Ok(DepthImage::raw(pixels.as_ptr().cast(), width, height, stride * size_of::<u16>(),
                           sys::OPX_SCALAR_UINT16, depth_scale))
    }

    /// float32 depth in metres (ROS 32FC1), 0, NaN, infinite or negative for
    /// no return; `stride` in pixels (0: `width`), checked as in
    /// [`DepthImage::from_u16`].
    pub fn from_f32(pixels: &'a [f32], width: usize, height: usize, stride: usize)
        -> Result<DepthImage<'a>> {
        let stride = checked_stride(pixels.len(), width, height, stride)?;
        Ok(DepthImage::raw(pixels.as_ptr().cast(), width, height, stride * size_of::<f32>(),
                           sys::OPX_SCALAR_FLOAT32, 1.0))
    }

    /// Pixels per row.
    pub fn width(&self) -> usize {
        self.raw.width
    }

    /// Rows.
    pub fn height(&self) -> usize {
        self.raw.height
    }

    /// The C description of the image, valid while `'a` lasts.
    pub(crate) fn as_raw(&self) -> &sys::opx_depth_image {
        &self.raw
    }

    fn raw(data: *const std::os::raw::c_void, width: usize, height: usize, row_stride: usize,
           scalar_type: i32, depth_scale: f64) -> DepthImage<'a> {
        let raw = sys::opx_depth_image {
            scalar_type, data, width, height, row_stride, depth_scale, ..Default::default()
        };
        DepthImage { raw, _borrow: PhantomData }
    }
}

/// The stride in pixels (0 meaning `width`) after checking that `height`
/// rows of `width` pixels, `stride` apart, lie inside a slice of `len`.
/// A single row is given the stride `width` (so it cannot overflow bytes).
fn checked_stride(len: usize, width: usize, height: usize, stride: usize) -> Result<usize> {
    if stride != 0 && stride < width {
        return Err(Error::invalid(format!(
            "DepthImage: stride {} pixels is smaller than the width {}", stride, width
        )));
    }
    let stride = if stride == 0 || height < 2 { width } else { stride };
    let needed = if width == 0 || height == 0 {
        Some(0)
    } else {
        (height - 1).checked_mul(stride).and_then(|n| n.checked_add(width))
    };
    match needed {
        Some(n) if n <= len => Ok(stride),
        _ => Err(Error::invalid(format!(
            "DepthImage: {} rows of {} pixels, {} apart, do not fit in {} pixels",
            height, width, stride, len
        ))),
    }
}
