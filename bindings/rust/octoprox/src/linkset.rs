//! The robot: a set of links with shapes (`opx_linkset`).
//!
//! ```
//! use octoprox::{pose_at, LinkSet, Shape, ShapeKind};
//!
//! let mut robot = LinkSet::new()?;
//! let hand = robot.add_link("hand")?;
//! robot.add_shape(hand, &Shape::sphere(0.05))?;
//! // A 20 cm long finger 10 cm ahead of the hand's origin (link frame).
//! let finger = Shape::new(ShapeKind::Capsule { radius: 0.01, length: 0.2 });
//! robot.add_shape(hand, &finger.at(pose_at(0.0, 0.0, 0.1)))?;
//! robot.set_padding(0.01)?; // 1 cm around every shape
//! robot.set_poses(&[pose_at(0.5, 0.0, 1.0)])?; // the hand in the map frame
//! assert_eq!((robot.link_count()?, robot.shape_count(hand)?), (1, 2));
//! assert_eq!(robot.find_link("hand")?, hand);
//! assert_eq!(robot.pose(hand)?.position, [0.5, 0.0, 1.0]);
//! assert_eq!(robot.poses()?, [pose_at(0.5, 0.0, 1.0)]); // every link at once
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{c_string, check, to_c_string, Error, ErrorKind, Result};
use crate::{check_version, sys, Pose};
use std::ptr;

/// The geometry of a shape, in metres, in the shape frame (centred on its
/// origin).  A padded shape is the shape grown by a ball of the padding's
/// radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShapeKind<'a> {
    /// A sphere.
    Sphere {
        /// Radius, metres.
        radius: f64,
    },
    /// A box.
    Box {
        /// FULL edge lengths along x, y, z, metres (as URDF and FCL).
        size: [f64; 3],
    },
    /// A cylinder along z.
    Cylinder {
        /// Radius, metres.
        radius: f64,
        /// FULL length along z, metres (URDF).
        length: f64,
    },
    /// A capsule along z: a cylinder with hemispherical ends.
    Capsule {
        /// Radius, metres.
        radius: f64,
        /// Length of the cylindrical part (the distance between the two
        /// sphere centres; FCL's convention), metres.
        length: f64,
    },
    /// The solid convex hull of the vertices.
    Convex {
        /// Points in the shape frame, metres.
        vertices: &'a [[f64; 3]],
    },
    /// A triangle surface over the vertices: a cell wholly inside a closed
    /// mesh touches no triangle and is not reported (use a convex hull for
    /// a solid part).
    Mesh {
        /// Points in the shape frame, metres.
        vertices: &'a [[f64; 3]],
        /// Three vertex indices per triangle.
        triangles: &'a [[u32; 3]],
    },
}

/// A shape and its pose in the link frame.  The library copies vertices
/// and triangles, so they need only live for the `add_shape` call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape<'a> {
    /// The geometry, in the shape frame.
    pub kind: ShapeKind<'a>,
    /// The shape frame in the link frame (default: identity).
    pub pose: Pose,
}

impl<'a> Shape<'a> {
    /// A shape at the link origin.
    pub fn new(kind: ShapeKind<'a>) -> Shape<'a> {
        Shape { kind, pose: Pose::default() }
    }

    /// A sphere of `radius` metres at the link origin.
    pub fn sphere(radius: f64) -> Shape<'a> {
        Shape::new(ShapeKind::Sphere { radius })
    }

    /// A box of FULL edge lengths `size` (x, y, z; metres) at the link
    /// origin.
    pub fn cuboid(size: [f64; 3]) -> Shape<'a> {
        Shape::new(ShapeKind::Box { size })
    }

    /// The same shape at `pose` in the link frame.
    pub fn at(mut self, pose: Pose) -> Shape<'a> {
        self.pose = pose;
        self
    }

    /// The C description; it borrows the vertices and triangles.
    pub(crate) fn to_c(self) -> sys::opx_shape {
        let mut c = sys::opx_shape { pose: self.pose, ..Default::default() };
        match self.kind {
            ShapeKind::Sphere { radius } => (c.kind, c.radius) = (sys::OPX_SHAPE_SPHERE, radius),
            ShapeKind::Box { size } => (c.kind, c.size) = (sys::OPX_SHAPE_BOX, size),
            ShapeKind::Cylinder { radius, length } => {
                (c.kind, c.radius, c.length) = (sys::OPX_SHAPE_CYLINDER, radius, length)
            }
            ShapeKind::Capsule { radius, length } => {
                (c.kind, c.radius, c.length) = (sys::OPX_SHAPE_CAPSULE, radius, length)
            }
            ShapeKind::Convex { vertices } => {
                c.kind = sys::OPX_SHAPE_CONVEX;
                (c.vertices, c.vertex_count) = (vertices.as_ptr().cast(), vertices.len());
            }
            ShapeKind::Mesh { vertices, triangles } => {
                c.kind = sys::OPX_SHAPE_MESH;
                (c.vertices, c.vertex_count) = (vertices.as_ptr().cast(), vertices.len());
                (c.indices, c.triangle_count) = (triangles.as_ptr().cast(), triangles.len());
            }
        }
        c
    }

    /// A shape the library describes; the slices borrow its memory.  An
    /// unknown kind is an error naming `what` (the caller).
    ///
    /// # Safety
    /// `c.vertices` must hold `vertex_count` packed points and `c.indices`
    /// `triangle_count` packed triangles, valid for `'a`.
    pub(crate) unsafe fn from_c(c: &sys::opx_shape, what: &str) -> Result<Shape<'a>> {
        let kind = match c.kind {
            sys::OPX_SHAPE_SPHERE => ShapeKind::Sphere { radius: c.radius },
            sys::OPX_SHAPE_BOX => ShapeKind::Box { size: c.size },
            sys::OPX_SHAPE_CYLINDER => ShapeKind::Cylinder { radius: c.radius, length: c.length },
            sys::OPX_SHAPE_CAPSULE => ShapeKind::Capsule { radius: c.radius, length: c.length },
            sys::OPX_SHAPE_CONVEX => ShapeKind::Convex { vertices: slice(c.vertices, c.vertex_count) },
            sys::OPX_SHAPE_MESH => ShapeKind::Mesh {
                vertices: slice(c.vertices, c.vertex_count),
                triangles: slice(c.indices, c.triangle_count),
            },
            kind => {
                return Err(Error::of_kind(ErrorKind::Version,
                                          format!("{}: unknown shape kind {}", what, kind)))
            }
        };
        Ok(Shape { kind, pose: c.pose })
    }
}

/// `count` packed items of `T` (an array of scalars) at `data`.
///
/// # Safety
/// `data` must be NULL with count 0, or hold `count` items valid for `'a`.
unsafe fn slice<'a, S, T>(data: *const S, count: usize) -> &'a [T] {
    if data.is_null() || count == 0 {
        return &[];
    }
    std::slice::from_raw_parts(data.cast::<T>(), count)
}

/// A robot as a set of links, each with shapes, a padding, an enabled flag
/// and a pose in the map frame.  Reading methods take `&self` (queries may
/// run on many threads at once); changing methods take `&mut self`.  The
/// library copies what it is given (names, vertices, poses).  A bad
/// argument (an unknown link index, a negative size or padding, a zero
/// quaternion) is an [`crate::ErrorKind::InvalidArgument`] that changes
/// nothing.
#[derive(Debug)]
pub struct LinkSet {
    raw: *mut sys::opx_linkset,
}

// SAFETY: a link set may move between threads, and functions taking a
// const handle may run concurrently; only those are reachable through `&`.
unsafe impl Send for LinkSet {}
unsafe impl Sync for LinkSet {}

impl Drop for LinkSet {
    fn drop(&mut self) {
        // SAFETY: raw is a live handle, destroyed once.
        unsafe { sys::opx_linkset_destroy(self.raw) }
    }
}

impl LinkSet {
    /// An empty link set.
    pub fn new() -> Result<LinkSet> {
        check_version()?;
        let mut raw = ptr::null_mut();
        // SAFETY: out is valid.
        check(unsafe { sys::opx_linkset_create(&mut raw) })?;
        Ok(LinkSet { raw })
    }

    /// A deep copy (shapes, names, poses, paddings, enabled flags, pairs).
    pub fn try_clone(&self) -> Result<LinkSet> {
        let mut raw = ptr::null_mut();
        // SAFETY: const call; out is valid.
        check(unsafe { sys::opx_linkset_clone(self.raw, &mut raw) })?;
        Ok(LinkSet { raw })
    }

    /// Adds a link named `name` (names need not be unique;
    /// [`LinkSet::find_link`] returns the first) with an identity pose;
    /// returns its index.
    pub fn add_link(&mut self, name: &str) -> Result<u32> {
        let name = to_c_string(name, "LinkSet::add_link: name")?;
        let mut index = 0;
        // SAFETY: name is a C string; exclusive access.
        check(unsafe { sys::opx_linkset_add_link(self.raw, name.as_ptr(), &mut index) })?;
        Ok(index)
    }

    /// Adds a shape to `link`; returns its index within the link.  A mesh
    /// is built into a tree over its triangles here, once.
    pub fn add_shape(&mut self, link: u32, shape: &Shape<'_>) -> Result<u32> {
        let c = shape.to_c();
        let mut index = 0;
        // SAFETY: c borrows slices that outlive the call (the library copies
        // them); exclusive access.
        check(unsafe { sys::opx_linkset_add_shape(self.raw, link, &c, &mut index) })?;
        Ok(index)
    }

    /// The number of links.
    pub fn link_count(&self) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_link_count(self.raw, &mut count) })?;
        Ok(count)
    }

    /// The number of shapes of `link`.
    pub fn shape_count(&self, link: u32) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_shape_count(self.raw, link, &mut count) })?;
        Ok(count)
    }

    /// Shape `shape` of `link` as stored (kind, pose in the link frame,
    /// sizes); convex and mesh vertices and triangles are borrowed from the
    /// link set (a mesh keeps only the vertices its triangles use).
    pub fn shape(&self, link: u32, shape: u32) -> Result<Shape<'_>> {
        let mut c = sys::opx_shape::default();
        // SAFETY: const call; the returned arrays stay valid while the set
        // is unchanged, which the borrow of self guarantees.
        unsafe {
            check(sys::opx_linkset_get_shape(self.raw, link, shape, &mut c))?;
            Shape::from_c(&c, "LinkSet::shape")
        }
    }

    /// The link's name (copied).
    pub fn link_name(&self, link: u32) -> Result<String> {
        let mut name = ptr::null();
        // SAFETY: const call; the name stays valid while we hold &self and
        // is copied at once.
        check(unsafe { sys::opx_linkset_get_link_name(self.raw, link, &mut name) })?;
        Ok(unsafe { c_string(name) })
    }

    /// The first link named `name`; an invalid argument when none.
    pub fn find_link(&self, name: &str) -> Result<u32> {
        let name = to_c_string(name, "LinkSet::find_link: name")?;
        let mut index = 0;
        // SAFETY: const call; name is a C string.
        check(unsafe { sys::opx_linkset_find_link(self.raw, name.as_ptr(), &mut index) })?;
        Ok(index)
    }

    /// The global padding, metres (>= 0).
    pub fn set_padding(&mut self, padding: f64) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe { sys::opx_linkset_set_padding(self.raw, padding) })
    }

    /// A link's own padding, metres (>= 0), added to the global one.
    pub fn set_link_padding(&mut self, link: u32, padding: f64) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe { sys::opx_linkset_set_link_padding(self.raw, link, padding) })
    }

    /// Enables or disables a link: disabled links take part in no query
    /// (e.g. links the sensor cannot see).  All links start enabled.
    pub fn set_link_enabled(&mut self, link: u32, enabled: bool) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe { sys::opx_linkset_set_link_enabled(self.raw, link, i32::from(enabled)) })
    }

    /// Every link's pose in the map frame, in link order: `poses.len()` must
    /// equal the link count.  On an invalid pose nothing changes.
    pub fn set_poses(&mut self, poses: &[Pose]) -> Result<()> {
        // SAFETY: poses holds poses.len() packed poses; exclusive access.
        check(unsafe { sys::opx_linkset_set_poses(self.raw, poses.as_ptr(), poses.len(), 0) })
    }

    /// A link's pose in the map frame.
    pub fn pose(&self, link: u32) -> Result<Pose> {
        let mut pose = Pose::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_pose(self.raw, link, &mut pose) })?;
        Ok(pose)
    }

    /// Every link's pose in the map frame, in link order (element i is
    /// [`LinkSet::pose`] of link i).
    pub fn poses(&self) -> Result<Vec<Pose>> {
        let mut poses = vec![Pose::default(); self.link_count()? as usize];
        let mut count = 0usize;
        // SAFETY: poses holds poses.len() packed poses; const call.
        check(unsafe { sys::opx_linkset_get_poses(self.raw, poses.as_mut_ptr(), poses.len(), &mut count) })?;
        poses.truncate(count);
        Ok(poses)
    }

    pub(crate) fn as_raw(&self) -> *const sys::opx_linkset {
        self.raw
    }

    pub(crate) fn as_raw_mut(&mut self) -> *mut sys::opx_linkset {
        self.raw
    }

    /// Takes ownership of a handle a constructor returned.
    pub(crate) fn from_raw(raw: *mut sys::opx_linkset) -> LinkSet {
        LinkSet { raw }
    }

    /// Checks that `poses` holds whole waypoints of one pose per link and
    /// returns the number of waypoints.
    pub(crate) fn waypoint_count(&self, poses: &[Pose], what: &str) -> Result<usize> {
        let links = self.link_count()? as usize;
        if links == 0 || poses.len() % links != 0 {
            return Err(Error::invalid(format!(
                "{}: {} poses are not whole waypoints of {} links",
                what,
                poses.len(),
                links
            )));
        }
        Ok(poses.len() / links)
    }
}
