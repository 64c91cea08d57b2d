//! Objects attached to links (MoveIt's attached collision objects, e.g. a
//! part the gripper holds): [`LinkSet::attach_object`],
//! [`LinkSet::attach_world_object`], [`LinkSet::detach`] and the getters.
//!
//! An attached object moves with its link (poses, forward kinematics,
//! paths, batches and motions move it).  Against the octree and world
//! objects it is checked as the link's own shapes are (with the link's
//! padding and enabled flag); contacts and distances name the link and the
//! object ([`crate::Contact::attached`],
//! [`crate::DistanceResult::attached`]), `shape` then being the shape's
//! index within the object.  Against the robot (self-collision) it is
//! checked with every link but its own and its touch links (links it may
//! touch, e.g. the gripper's fingers), whatever the link pairs say, and
//! with the objects attached to other links
//! ([`crate::SelfContact::attached_a`], `attached_b`).  Indices are
//! positions: detaching an object moves every later one down by one.
//!
//! ```
//! use octoprox::{pose_at, LinkSet, Query, SelfCollisionRequest, Shape};
//!
//! // A hand with two fingers 4 cm apart (inner faces at y = -0.02, 0.02).
//! let mut robot = LinkSet::new()?;
//! let hand = robot.add_link("hand")?;
//! robot.add_shape(hand, &Shape::sphere(0.02))?;
//! for (name, y) in [("finger_l", 0.025), ("finger_r", -0.025)] {
//!     let finger = robot.add_link(name)?;
//!     robot.add_shape(finger, &Shape::cuboid([0.02, 0.01, 0.06]).at(pose_at(0.0, y, 0.3)))?;
//! }
//! // A box 4.2 cm wide grasped 0.3 m ahead of the hand: 1 mm into each finger.
//! let part = [Shape::cuboid([0.02, 0.042, 0.03])];
//! let mut query = Query::new(&Default::default())?;
//! let all = SelfCollisionRequest { max_contacts: u32::MAX, ..Default::default() };
//! let held = robot.attach_object(hand, "part", &part, &pose_at(0.0, 0.0, 0.3), &[])?;
//! assert_eq!(query.self_collide(&robot, &all)?.contact_count, 2); // both fingers
//! assert_eq!(query.self_contacts()?[0].attached_a, Some(held));
//! // The fingers as touch links, as MoveIt grasps: no collision.
//! robot.detach(held)?;
//! let held = robot.attach_object(hand, "part", &part, &pose_at(0.0, 0.0, 0.3), &["finger_l", "finger_r"])?;
//! assert!(!query.self_collide(&robot, &all)?.collided);
//! assert_eq!(robot.attached_touch_links(held)?, [1, 2]);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{c_string, check, to_c_string, Result};
use crate::{sys, LinkSet, Pose, Shape, World};
use std::ffi::CString;
use std::os::raw::c_char;
use std::ptr;

/// Touch link names as C strings, and the pointer array the C API takes
/// (valid while the strings live).
struct TouchLinks {
    _names: Vec<CString>,
    pointers: Vec<*const c_char>,
}

impl TouchLinks {
    fn new(names: &[&str], what: &str) -> Result<TouchLinks> {
        let names = names
            .iter()
            .map(|name| to_c_string(name, what))
            .collect::<Result<Vec<CString>>>()?;
        let pointers = names.iter().map(|name| name.as_ptr()).collect();
        Ok(TouchLinks { _names: names, pointers })
    }

    fn as_ptr(&self) -> *const *const c_char {
        if self.pointers.is_empty() { ptr::null() } else { self.pointers.as_ptr() }
    }

    fn len(&self) -> usize {
        self.pointers.len()
    }
}

impl LinkSet {
    /// Attaches an object named `name` (names need not be unique:
    /// [`LinkSet::find_attached`] returns the first) to `link`: `shapes`
    /// (at least one), each at its pose in the OBJECT frame, the object
    /// frame at `pose` in the LINK frame.  `touch_links` names the links
    /// the object may touch (each the first link of that name; an unknown
    /// name is an invalid argument); its own link always may.  Returns the
    /// object's index.  On error nothing changes.
    pub fn attach_object(&mut self, link: u32, name: &str, shapes: &[Shape<'_>], pose: &Pose,
                         touch_links: &[&str]) -> Result<u32> {
        let name = to_c_string(name, "LinkSet::attach_object: name")?;
        let touch = TouchLinks::new(touch_links, "LinkSet::attach_object: touch_links")?;
        // The C shapes borrow the vertices of `shapes`, which outlive the call.
        let shapes: Vec<sys::opx_shape> = shapes.iter().map(|shape| shape.to_c()).collect();
        let data = if shapes.is_empty() { ptr::null() } else { shapes.as_ptr() };
        let mut index = 0;
        // SAFETY: every pointer is valid for the call (the library copies
        // what it keeps); exclusive access.
        check(unsafe {
            sys::opx_linkset_attach_object(self.as_raw_mut(), link, name.as_ptr(), data, shapes.len(), pose,
                                           touch.as_ptr(), touch.len(), &mut index)
        })?;
        Ok(index)
    }

    /// Attaches a copy of `world`'s object `object` (its name and shapes)
    /// to `link` where it stands now: its pose in the link frame is the
    /// object's map pose seen from the link's current pose.  `touch_links`
    /// as in [`LinkSet::attach_object`].  The world does not change: remove
    /// or disable the object there ([`World::remove`],
    /// [`World::set_enabled`]), as MoveIt moves an object it attaches out
    /// of its world, or the copy touches the original.  An object without
    /// shapes is an invalid argument.  Returns the attached object's index.
    pub fn attach_world_object(&mut self, link: u32, world: &World, object: u32, touch_links: &[&str])
        -> Result<u32> {
        let touch = TouchLinks::new(touch_links, "LinkSet::attach_world_object: touch_links")?;
        let mut index = 0;
        // SAFETY: live handles, the world only read; the names are valid for
        // the call; exclusive access to the link set.
        check(unsafe {
            sys::opx_linkset_attach_world_object(self.as_raw_mut(), link, world.as_raw(), object,
                                                 touch.as_ptr(), touch.len(), &mut index)
        })?;
        Ok(index)
    }

    /// Detaches (removes) attached object `object`; every later one moves
    /// down by one index.
    pub fn detach(&mut self, object: u32) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe { sys::opx_linkset_detach_object(self.as_raw_mut(), object) })
    }

    /// The number of attached objects.
    pub fn attached_count(&self) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_attached_count(self.as_raw(), &mut count) })?;
        Ok(count)
    }

    /// The first attached object named `name`; an invalid argument when
    /// none is.
    pub fn find_attached(&self, name: &str) -> Result<u32> {
        let name = to_c_string(name, "LinkSet::find_attached: name")?;
        let mut index = 0;
        // SAFETY: const call; name is a C string.
        check(unsafe { sys::opx_linkset_find_attached(self.as_raw(), name.as_ptr(), &mut index) })?;
        Ok(index)
    }

    /// The attached object's name (copied).
    pub fn attached_name(&self, object: u32) -> Result<String> {
        let mut name = ptr::null();
        // SAFETY: const call; the name stays valid while we hold &self and
        // is copied at once.
        check(unsafe { sys::opx_linkset_get_attached_name(self.as_raw(), object, &mut name) })?;
        Ok(unsafe { c_string(name) })
    }

    /// Every attached object's name, in index order.
    pub fn attached_names(&self) -> Result<Vec<String>> {
        (0..self.attached_count()?).map(|object| self.attached_name(object)).collect()
    }

    /// The link the object is attached to.
    pub fn attached_link(&self, object: u32) -> Result<u32> {
        let mut link = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_attached_link(self.as_raw(), object, &mut link) })?;
        Ok(link)
    }

    /// The object frame in its link's frame.
    pub fn attached_pose(&self, object: u32) -> Result<Pose> {
        let mut pose = Pose::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_attached_pose(self.as_raw(), object, &mut pose) })?;
        Ok(pose)
    }

    /// The number of shapes of the attached object.
    pub fn attached_shape_count(&self, object: u32) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_attached_shape_count(self.as_raw(), object, &mut count) })?;
        Ok(count)
    }

    /// Shape `shape` of the attached object as it was given (its pose in
    /// the OBJECT frame); convex and mesh vertices and triangles are
    /// borrowed from the link set.
    pub fn attached_shape(&self, object: u32, shape: u32) -> Result<Shape<'_>> {
        let mut c = sys::opx_shape::default();
        // SAFETY: const call; the returned arrays stay valid while the set
        // is unchanged, which the borrow of self guarantees.
        unsafe {
            check(sys::opx_linkset_get_attached_shape(self.as_raw(), object, shape, &mut c))?;
            Shape::from_c(&c, "LinkSet::attached_shape")
        }
    }

    /// The object's touch links (link indices, ascending; its own link not
    /// among them).
    pub fn attached_touch_links(&self, object: u32) -> Result<Vec<u32>> {
        let mut count = 0usize;
        // SAFETY: capacity 0 with NULL asks for the count.
        let status = unsafe {
            sys::opx_linkset_get_attached_touch_links(self.as_raw(), object, ptr::null_mut(), 0, &mut count)
        };
        if status != sys::OPX_ERROR_BUFFER_TOO_SMALL {
            check(status)?;
        }
        let mut links = vec![0u32; count];
        // SAFETY: links holds `count` indices; const call.
        check(unsafe {
            sys::opx_linkset_get_attached_touch_links(self.as_raw(), object, links.as_mut_ptr(), count, &mut count)
        })?;
        links.truncate(count);
        Ok(links)
    }
}
