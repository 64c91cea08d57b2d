//! Query contexts (`opx_query`): collision, distance and path queries
//! (self-collision: `self_collision.rs`).
use crate::error::{check, Result};
use crate::{check_version, sys, CollisionRequest, CollisionResult, Contact, CostBox,
            DistanceRequest, DistanceResult, LinkSet, Octree, PathRequest, PathResult, Pose,
            QueryOptions, QueryStats};
use std::ptr;

/// A query context: the engine, its scratch memory and the contacts and
/// cost boxes of its last query.  Use one per thread (it is `Send`, not
/// `Sync`); many contexts may query one `Octree` and `LinkSet` at once.
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
    /// engine).
    pub fn new(options: &QueryOptions) -> Result<Query> {
        check_version()?;
        let mut raw = ptr::null_mut();
        // SAFETY: options and out are valid.
        check(unsafe { sys::opx_query_create(options, &mut raw) })?;
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

    /// What the context holds (amortized engine).
    pub fn stats(&self) -> Result<QueryStats> {
        let mut out = QueryStats::default();
        // SAFETY: const call (the SAH reference it computes on demand is
        // guarded inside the library).
        check(unsafe { sys::opx_query_get_stats(self.raw, &mut out) })?;
        Ok(out)
    }

    /// Does the link set (enabled links, padded, at their poses) collide
    /// with the octree?  Contacts and cost boxes are then read with
    /// [`Query::contacts`] and [`Query::cost_boxes`].
    pub fn collide(&mut self, tree: &Octree, links: &LinkSet, request: &CollisionRequest)
        -> Result<CollisionResult> {
        let mut out = CollisionResult::default();
        (self.contact_count, self.cost_box_count) = (0, 0);
        // SAFETY: live handles; tree and links are only read.
        check(unsafe {
            sys::opx_query_collide(self.raw, tree.as_raw(), links.as_raw(), request, &mut out)
        })?;
        (self.contact_count, self.cost_box_count) =
            (out.contact_count as usize, out.cost_box_count as usize);
        Ok(out)
    }

    /// Contact `index` of the last collision query.
    pub fn contact(&self, index: usize) -> Result<Contact> {
        let mut out = Contact::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_query_get_contact(self.raw, index, &mut out) })?;
        Ok(out)
    }

    /// All contacts of the last collision query.
    pub fn contacts(&self) -> Result<Vec<Contact>> {
        (0..self.contact_count).map(|i| self.contact(i)).collect()
    }

    /// Cost box `index` of the last collision or path query, costliest first.
    pub fn cost_box(&self, index: usize) -> Result<CostBox> {
        let mut out = CostBox::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_query_get_cost_box(self.raw, index, &mut out) })?;
        Ok(out)
    }

    /// All cost boxes held by the query, costliest first.
    pub fn cost_boxes(&self) -> Result<Vec<CostBox>> {
        (0..self.cost_box_count).map(|i| self.cost_box(i)).collect()
    }

    /// The minimum distance between the enabled links and the obstacles.
    pub fn distance(&mut self, tree: &Octree, links: &LinkSet, request: &DistanceRequest)
        -> Result<DistanceResult> {
        let mut out = DistanceResult::default();
        // SAFETY: live handles; tree and links are only read.
        check(unsafe {
            sys::opx_query_distance(self.raw, tree.as_raw(), links.as_raw(), request, &mut out)
        })?;
        Ok(out)
    }

    /// Each link's minimum distance from the last distance query (which
    /// needs `per_link = 1`; else empty).
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
    /// per link (map frame), so `poses.len()` is waypoints x links.
    pub fn path(&mut self, tree: &Octree, links: &LinkSet, poses: &[Pose],
                request: &PathRequest) -> Result<PathResult> {
        let waypoints = links.waypoint_count(poses, "Query::path: poses")?;
        let mut out = PathResult::default();
        (self.contact_count, self.cost_box_count) = (0, 0);
        // SAFETY: poses holds waypoints x links packed poses; live handles.
        check(unsafe {
            sys::opx_query_path(self.raw, tree.as_raw(), links.as_raw(), poses.as_ptr(),
                                waypoints, 0, 0, request, &mut out)
        })?;
        self.cost_box_count = out.cost_box_count as usize;
        Ok(out)
    }

    /// Binds a caller's boxes as the map (a context made with the amortized
    /// engine only): each `[min x, min y, min z, max x, max y, max z]`, map
    /// frame, metres; copied.  [`Query::collide_boxes`] and
    /// [`Query::distance_boxes`] then query them, until the next bind or an
    /// octree query.
    pub fn bind_boxes(&mut self, boxes: &[[f64; 6]]) -> Result<()> {
        let data = if boxes.is_empty() { ptr::null() } else { boxes.as_ptr() as *const f64 };
        // SAFETY: boxes holds boxes.len() packed rows of 6 doubles.
        check(unsafe { sys::opx_query_bind_boxes(self.raw, data, boxes.len(), 0) })
    }

    /// [`Query::collide`] against the bound boxes; a contact's cell centre
    /// is a box's centre, its cell size the box's longest edge.
    pub fn collide_boxes(&mut self, links: &LinkSet, request: &CollisionRequest)
        -> Result<CollisionResult> {
        let mut out = CollisionResult::default();
        (self.contact_count, self.cost_box_count) = (0, 0);
        // SAFETY: live handles; links is only read.
        check(unsafe { sys::opx_query_collide_boxes(self.raw, links.as_raw(), request, &mut out) })?;
        self.contact_count = out.contact_count as usize;
        Ok(out)
    }

    /// [`Query::distance`] against the bound boxes.
    pub fn distance_boxes(&mut self, links: &LinkSet, request: &DistanceRequest)
        -> Result<DistanceResult> {
        let mut out = DistanceResult::default();
        // SAFETY: live handles; links is only read.
        check(unsafe { sys::opx_query_distance_boxes(self.raw, links.as_raw(), request, &mut out) })?;
        Ok(out)
    }
}
