//! Borrowed point arrays handed to the library by address and stride,
//! never copied.
//!
//! ```
//! use octoprox::{Octree, OctreeOptions, Points};
//!
//! // x y z float32 then an rgb word: a ROS PointCloud2 with point_step 16.
//! let mut data = Vec::new();
//! for xyz in [[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0]] {
//!     xyz.iter().for_each(|v| data.extend_from_slice(&v.to_ne_bytes()));
//!     data.extend_from_slice(&0x00ff00u32.to_ne_bytes());
//! }
//! let points = Points::strided_f32(&data, 2, 16)?;
//! assert_eq!((points.len(), points.stride(), points.as_ptr()), (2, 16, data.as_ptr()));
//! let mut map = Octree::new(&OctreeOptions::default())?;
//! assert_eq!(map.insert_points(points, &Default::default())?.points_used, 2);
//! // Every other row of a 4-column f64 array: 8 values apart.
//! let rows = [1.0, 0.0, 0.0, 5.0, 7.0, 7.0, 7.0, 7.0, 0.0, 1.0, 0.0, 5.0];
//! assert_eq!(Points::from_f64_rows(&rows, 8)?.len(), 2);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{Error, Result};
use crate::sys;
use std::marker::PhantomData;
use std::os::raw::c_void;

/// `count` points of x, y, z (float32 or float64), each `stride` bytes
/// after the previous, borrowed for `'a`.  Build it from `&[[f32; 3]]`,
/// `&[[f64; 3]]`, `&[[f32; 4]]`, `&[[f64; 4]]` (with `.into()`), or from a
/// byte buffer with a stride, such as a ROS `PointCloud2` `data` with its
/// `point_step` ([`Points::strided_f32`]).  Extra fields after z are ignored.
#[derive(Debug, Clone, Copy)]
pub struct Points<'a> {
    data: *const u8,
    count: usize,
    stride: usize,
    scalar_type: i32,
    _borrow: PhantomData<&'a [u8]>,
}

impl<'a> Points<'a> {
    /// float32 points in `bytes`: point i's x, y, z are the three
    /// native-endian floats at byte `i * stride` (stride >= 12; x, y, z need
    /// not be aligned).  For a `PointCloud2` whose x is at offset `o`, pass
    /// `&data[o..]`.  A stride below one point, or points past the end of
    /// `bytes`, are an invalid argument.
    pub fn strided_f32(bytes: &'a [u8], count: usize, stride: usize) -> Result<Points<'a>> {
        Points::strided(bytes, count, stride, sys::OPX_SCALAR_FLOAT32, 4)
    }

    /// float64 points in `bytes`, as [`Points::strided_f32`] (stride >= 24).
    pub fn strided_f64(bytes: &'a [u8], count: usize, stride: usize) -> Result<Points<'a>> {
        Points::strided(bytes, count, stride, sys::OPX_SCALAR_FLOAT64, 8)
    }

    /// float32 points in a flat slice, `stride` floats apart (e.g. 4 for
    /// x y z intensity), as many as fit; a stride below 3 is an invalid
    /// argument.
    pub fn from_f32_rows(values: &'a [f32], stride: usize) -> Result<Points<'a>> {
        let count = row_count(values.len(), stride, "Points::from_f32_rows")?;
        Ok(Points::raw(values.as_ptr().cast(), count, stride * 4, sys::OPX_SCALAR_FLOAT32))
    }

    /// float64 points in a flat slice, `stride` doubles apart.
    pub fn from_f64_rows(values: &'a [f64], stride: usize) -> Result<Points<'a>> {
        let count = row_count(values.len(), stride, "Points::from_f64_rows")?;
        Ok(Points::raw(values.as_ptr().cast(), count, stride * 8, sys::OPX_SCALAR_FLOAT64))
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The address of the first point, as handed to the library (for
    /// checking that nothing was copied).
    pub fn as_ptr(&self) -> *const u8 {
        self.data
    }

    /// Bytes from one point to the next.
    pub fn stride(&self) -> usize {
        self.stride
    }

    pub(crate) fn c_data(&self) -> *const c_void {
        self.data.cast()
    }

    pub(crate) fn scalar_type(&self) -> i32 {
        self.scalar_type
    }

    fn strided(bytes: &'a [u8], count: usize, stride: usize, scalar_type: i32, scalar: usize)
        -> Result<Points<'a>> {
        let point = 3 * scalar;
        if stride < point {
            return Err(Error::invalid(format!(
                "Points::strided: stride {} is smaller than one point ({} bytes)",
                stride, point
            )));
        }
        let needed = if count == 0 { 0 } else { (count - 1) * stride + point };
        if needed > bytes.len() {
            return Err(Error::invalid(format!(
                "Points::strided: {} points of stride {} need {} bytes, the buffer has {}",
                count,
                stride,
                needed,
                bytes.len()
            )));
        }
        Ok(Points::raw(bytes.as_ptr(), count, stride, scalar_type))
    }

    fn raw(data: *const u8, count: usize, stride: usize, scalar_type: i32) -> Points<'a> {
        Points { data, count, stride, scalar_type, _borrow: PhantomData }
    }
}

fn row_count(len: usize, stride: usize, what: &str) -> Result<usize> {
    if stride < 3 {
        return Err(Error::invalid(format!("{}: stride {} is below 3 values", what, stride)));
    }
    // The last row may be short of its extra fields, but needs x, y, z.
    Ok(if len < 3 { 0 } else { (len - 3) / stride + 1 })
}

macro_rules! points_from_arrays {
    ($($scalar:ty, $width:literal, $code:expr);* $(;)?) => {$(
        impl<'a> From<&'a [[$scalar; $width]]> for Points<'a> {
            fn from(points: &'a [[$scalar; $width]]) -> Points<'a> {
                Points::raw(points.as_ptr().cast(), points.len(),
                            std::mem::size_of::<[$scalar; $width]>(), $code)
            }
        }
        impl<'a> From<&'a Vec<[$scalar; $width]>> for Points<'a> {
            fn from(points: &'a Vec<[$scalar; $width]>) -> Points<'a> {
                Points::from(points.as_slice())
            }
        }
        impl<'a, const N: usize> From<&'a [[$scalar; $width]; N]> for Points<'a> {
            fn from(points: &'a [[$scalar; $width]; N]) -> Points<'a> {
                Points::from(&points[..])
            }
        }
    )*};
}

points_from_arrays! {
    f32, 3, sys::OPX_SCALAR_FLOAT32;
    f32, 4, sys::OPX_SCALAR_FLOAT32;
    f64, 3, sys::OPX_SCALAR_FLOAT64;
    f64, 4, sys::OPX_SCALAR_FLOAT64;
}
