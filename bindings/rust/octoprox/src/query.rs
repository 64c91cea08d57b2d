//! Query contexts (`opx_query`): collision, distance and path queries
//! against a map (self-collision: `self_collision.rs`; many configurations
//! per call: `batch.rs`; with world objects: `world.rs`).
//!
//! ```
//! use octoprox::{pose_at, CollisionRequest, InsertMode, InsertOptions, LinkSet, Octree,
//!                OctreeOptions, Query, QueryOptions, Shape};
//!
//! let mut map = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() })?;
//! let endpoints = InsertOptions { mode: InsertMode::Endpoints, ..Default::default() };
//! map.insert_points(&[[0.125f64, 0.125, 0.125]], &endpoints)?; // the cell [0, 0.25]^3
//! let mut robot = LinkSet::new()?;
//! let ball = robot.add_link("ball")?;
//! robot.add_shape(ball, &Shape::sphere(0.1))?;
//! robot.set_poses(&[pose_at(0.35, 0.125, 0.125)])?; // touching the face x = 0.25
//! let mut query = Query::new(&QueryOptions::default())?;
//! let hit = query.collide(&map, &robot, &CollisionRequest::default())?;
//! assert!(hit.collided);
//! let contact = query.contacts()?[0];
//! assert_eq!((contact.link, contact.cell_center), (ball, [0.125; 3]));
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{check, Result};
use crate::{check_version, sys, CollisionRequest, CollisionResult, Contact, CostBox,
            DistanceRequest, DistanceResult, LinkSet, Octree, PathRequest, PathResult, Pose,
            QueryOptions, QueryStats};
use std::ptr;

/// A query context: the engine, its scratch memory and the contacts and
/// cost boxes of its last query, so repeated queries allocate nothing once
/// warm.  Use one per thread (it is `Send`, not `Sync`); many contexts may
/// query one `Octree` and `LinkSet` at once.  Links take part with their
/// current poses (map frame) and paddings; disabled links take no part.
#[derive(Debug)]
pub struct Query {
    raw: *mut sys::opx_query,
    contact_count: usize,
    cost_box_count: usize,
    pub(crate) self_contact_count: usize,  // of the last self-collision query
}

// SAFETY: a context is not tied to the thread that made it; it needs
// exclusive access for queries, which `&mut self` gives.  It is not Sync:
// its results change under queries.
unsafe impl Send for Query {}

impl Drop for Query {
    fn drop(&mut self) {
        // SAFETY: raw is a live handle, destroyed once.
        unsafe { sys::opx_query_destroy(self.raw) }
    }
}

impl Query {
    /// A context with these options (`QueryOptions::default()`: the direct
    /// engine).  `morton_bits` outside 1..=21 is an invalid argument.
    pub fn new(options: &QueryOptions) -> Result<Query> {
        check_version()?;
        let options = options.to_c();
        let mut raw = ptr::null_mut();
        // SAFETY: options and out are valid.
        check(unsafe { sys::opx_query_create(&options, &mut raw) })?;
        Ok(Query { raw, contact_count: 0, cost_box_count: 0, self_contact_count: 0 })
    }

    pub(crate) fn as_raw(&self) -> *const sys::opx_query {
        self.raw
    }

    pub(crate) fn as_raw_mut(&mut self) -> *mut sys::opx_query {
        self.raw
    }

    /// After a call that leaves `cost_boxes` cost boxes and no contacts.
    pub(crate) fn hold_cost_boxes(&mut self, cost_boxes: usize) {
        (self.contact_count, self.cost_box_count) = (0, cost_boxes);
    }

    /// What the context holds (amortized engine; zeros for the direct one).
    pub fn stats(&self) -> Result<QueryStats> {
        let mut out = sys::opx_query_stats::default();
        // SAFETY: const call (the SAH reference it computes on demand is
        // guarded inside the library).
        check(unsafe { sys::opx_query_get_stats(self.raw, &mut out) })?;
        QueryStats::from_c(&out)
    }

    /// Does the link set (enabled links, padded, at their poses in the map
    /// frame) collide with the octree?  Touching collides.  With known
    /// objects beside the map: [`Query::collide_with_world`].  Contacts and
    /// cost boxes are then read with [`Query::contacts`] and
    /// [`Query::cost_boxes`] until the next collision or path query.  An
    /// invalid request field is an [`crate::ErrorKind::InvalidArgument`]
    /// naming it.
    pub fn collide(&mut self, tree: &Octree, links: &LinkSet, request: &CollisionRequest)
        -> Result<CollisionResult> {
        self.collide_tree(tree.as_raw(), links, request)
    }

    /// [`Query::collide`] on a live octree handle, or NULL with a world set
    /// ([`Query::collide_with_world`]).
    pub(crate) fn collide_tree(&mut self, tree: *const sys::opx_octree, links: &LinkSet,
                               request: &CollisionRequest) -> Result<CollisionResult> {
        let request = request.to_c();
        let mut out = sys::opx_collision_result::default();
        (self.contact_count, self.cost_box_count) = (0, 0);
        // SAFETY: live handles (tree may be NULL: the library checks it);
        // tree and links are only read.
        check(unsafe { sys::opx_query_collide(self.raw, tree, links.as_raw(), &request, &mut out) })?;
        (self.contact_count, self.cost_box_count) =
            (out.contact_count as usize, out.cost_box_count as usize);
        Ok(CollisionResult::from_c(&out))
    }

    /// Contact `index` of the last collision query; an index past the
    /// contacts is an invalid argument.
    pub fn contact(&self, index: usize) -> Result<Contact> {
        let mut out = sys::opx_contact::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_query_get_contact(self.raw, index, &mut out) })?;
        Contact::from_c(&out)
    }

    /// All contacts of the last collision query.
    pub fn contacts(&self) -> Result<Vec<Contact>> {
        (0..self.contact_count).map(|i| self.contact(i)).collect()
    }

    /// Cost box `index` of the last collision, path or motion query,
    /// costliest first.
    pub fn cost_box(&self, index: usize) -> Result<CostBox> {
        let mut out = sys::opx_cost_box::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_query_get_cost_box(self.raw, index, &mut out) })?;
        CostBox::from_c(&out)
    }

    /// All cost boxes held by the query, costliest first.
    pub fn cost_boxes(&self) -> Result<Vec<CostBox>> {
        (0..self.cost_box_count).map(|i| self.cost_box(i)).collect()
    }

    /// The minimum distance between the enabled links (padding included)
    /// and the obstacle cells, with witness points in the map frame.  With
    /// known objects beside the map: [`Query::distance_with_world`].
    pub fn distance(&mut self, tree: &Octree, links: &LinkSet, request: &DistanceRequest)
        -> Result<DistanceResult> {
        self.distance_tree(tree.as_raw(), links, request)
    }

    /// [`Query::distance`] on a live octree handle, or NULL with a world
    /// set ([`Query::distance_with_world`]).
    pub(crate) fn distance_tree(&mut self, tree: *const sys::opx_octree, links: &LinkSet,
                                request: &DistanceRequest) -> Result<DistanceResult> {
        let request = request.to_c();
        let mut out = sys::opx_distance_result::default();
        // SAFETY: live handles (tree may be NULL: the library checks it);
        // tree and links are only read.
        check(unsafe { sys::opx_query_distance(self.raw, tree, links.as_raw(), &request, &mut out) })?;
        DistanceResult::from_c(&out)
    }

    /// Each link's minimum distance (metres) from the last distance query,
    /// in link order; infinity for a disabled link or nothing within the
    /// cutoff.  Empty unless that query had `per_link`.
    pub fn link_distances(&self) -> Result<Vec<f64>> {
        let mut count = 0usize;
        // SAFETY: capacity 0 with NULL asks for the count.
        let status =
            unsafe { sys::opx_query_get_link_distances(self.raw, ptr::null_mut(), 0, &mut count) };
        if status != sys::OPX_ERROR_BUFFER_TOO_SMALL {
            check(status)?;
        }
        let mut distances = vec![0.0; count];
        // SAFETY: distances holds `count` doubles.
        check(unsafe {
            sys::opx_query_get_link_distances(self.raw, distances.as_mut_ptr(), count, &mut count)
        })?;
        distances.truncate(count);
        Ok(distances)
    }

    /// Checks a path: `poses` holds the waypoints in order, each one pose
    /// per link (map frame), so `poses.len()` is waypoints x links (else an
    /// invalid argument).  The link set itself is not moved.  Without
    /// distance or cost the check stops at the first colliding waypoint.
    /// A path query holds no contacts; its cost boxes are read with
    /// [`Query::cost_boxes`].  With known objects beside the map:
    /// [`Query::path_with_world`].
    pub fn path(&mut self, tree: &Octree, links: &LinkSet, poses: &[Pose],
                request: &PathRequest) -> Result<PathResult> {
        self.path_tree(tree.as_raw(), links, poses, request)
    }

    /// [`Query::path`] on a live octree handle, or NULL with a world set
    /// ([`Query::path_with_world`]).
    pub(crate) fn path_tree(&mut self, tree: *const sys::opx_octree, links: &LinkSet, poses: &[Pose],
                            request: &PathRequest) -> Result<PathResult> {
        let waypoints = links.waypoint_count(poses, "Query::path: poses")?;
        let request = request.to_c();
        let mut out = sys::opx_path_result::default();
        (self.contact_count, self.cost_box_count) = (0, 0);
        // SAFETY: poses holds waypoints x links packed poses; live handles
        // (tree may be NULL: the library checks it).
        check(unsafe {
            sys::opx_query_path(self.raw, tree, links.as_raw(), poses.as_ptr(),
                                waypoints, 0, 0, &request, &mut out)
        })?;
        self.cost_box_count = out.cost_box_count as usize;
        Ok(PathResult::from_c(&out))
    }

    /// Binds a caller's boxes as the map (a context made with
    /// [`crate::Engine::Amortized`] only, else an invalid argument): each
    /// `[min x, min y, min z, max x, max y, max z]`, map frame, metres, min
    /// `<=` max; copied.  [`Query::collide_boxes`] and
    /// [`Query::distance_boxes`] then query them, until the next bind or an
    /// octree query.
    pub fn bind_boxes(&mut self, boxes: &[[f64; 6]]) -> Result<()> {
        let data = if boxes.is_empty() { ptr::null() } else { boxes.as_ptr() as *const f64 };
        // SAFETY: boxes holds boxes.len() packed rows of 6 doubles.
        check(unsafe { sys::opx_query_bind_boxes(self.raw, data, boxes.len(), 0) })
    }

    /// [`Query::collide`] against the bound boxes; a contact's cell centre
    /// is a box's centre, its cell size the box's longest edge, its class
    /// occupied.  `compute_cost` is an invalid argument (boxes have no
    /// uncertain or unknown space), so is a context without bound boxes.
    pub fn collide_boxes(&mut self, links: &LinkSet, request: &CollisionRequest)
        -> Result<CollisionResult> {
        let request = request.to_c();
        let mut out = sys::opx_collision_result::default();
        (self.contact_count, self.cost_box_count) = (0, 0);
        // SAFETY: live handles; links is only read.
        check(unsafe { sys::opx_query_collide_boxes(self.raw, links.as_raw(), &request, &mut out) })?;
        self.contact_count = out.contact_count as usize;
        Ok(CollisionResult::from_c(&out))
    }

    /// [`Query::distance`] against the bound boxes.
    pub fn distance_boxes(&mut self, links: &LinkSet, request: &DistanceRequest)
        -> Result<DistanceResult> {
        let request = request.to_c();
        let mut out = sys::opx_distance_result::default();
        // SAFETY: live handles; links is only read.
        check(unsafe { sys::opx_query_distance_boxes(self.raw, links.as_raw(), &request, &mut out) })?;
        DistanceResult::from_c(&out)
    }
}
