//! Self-collision (`self_collision.h`): a link set against itself at its
//! current poses, over the pairs of links it checks.
//!
//! ```
//! use octoprox::{pose_at, LinkSet, Query, QueryOptions, SelfCollisionRequest,
//!                SelfDistanceRequest, Shape};
//!
//! // Two 10 cm cubes, 1 cm apart along x (map frame).
//! let mut links = LinkSet::new()?;
//! for name in ["left", "right"] {
//!     let link = links.add_link(name)?;
//!     links.add_shape(link, &Shape::cuboid([0.1, 0.1, 0.1]))?;
//! }
//! links.set_poses(&[pose_at(0.0, 0.0, 0.0), pose_at(0.11, 0.0, 0.0)])?;
//! let mut query = Query::new(&QueryOptions::default())?;
//! let near = query.self_distance(&links, &SelfDistanceRequest::default())?;
//! assert!(near.found && (near.distance - 0.01).abs() < 1e-12);
//! links.set_padding(0.005)?; // 5 mm on each side: they touch
//! assert!(query.self_collide(&links, &SelfCollisionRequest::default())?.collided);
//! links.set_pair_enabled(0, 1, false)?;
//! assert!(!query.self_collide(&links, &SelfCollisionRequest::default())?.collided);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{check, Result};
use crate::{sys, LinkSet, PairSamplingOptions, PairSamplingResult, Query, SelfCollisionRequest,
            SelfCollisionResult, SelfContact, SelfDistanceRequest, SelfDistanceResult};

impl Query {
    /// Does the link set collide with itself at its current poses?  Every
    /// pair of two enabled links with shapes is checked but the disabled
    /// pairs (an SRDF's, [`LinkSet::set_pair_enabled`]); links joined by a
    /// joint are not skipped unless disabled.  Paddings count on both
    /// sides; touching collides.  `request.max_contacts`: 0 yes/no, 1 (the
    /// default) the first contact, N, or `u32::MAX` all; the contacts are
    /// then read with [`Query::self_contacts`].
    pub fn self_collide(&mut self, links: &LinkSet, request: &SelfCollisionRequest)
        -> Result<SelfCollisionResult> {
        let request = request.to_c();
        let mut out = sys::opx_self_collision_result::default();
        self.self_contact_count = 0;
        // SAFETY: live handles; links is only read.
        check(unsafe {
            sys::opx_query_self_collide(self.as_raw_mut(), links.as_raw(), &request, &mut out)
        })?;
        self.self_contact_count = out.contact_count as usize;
        Ok(SelfCollisionResult::from_c(&out))
    }

    /// Contact `index` of the last self-collision query: `link_a < link_b`,
    /// their shapes, and with `compute_penetration` the depth, normal and
    /// point (map frame).
    pub fn self_contact(&self, index: usize) -> Result<SelfContact> {
        let mut out = sys::opx_self_contact::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_query_get_self_contact(self.as_raw(), index, &mut out) })?;
        Ok(SelfContact::from_c(&out))
    }

    /// All contacts of the last self-collision query.
    pub fn self_contacts(&self) -> Result<Vec<SelfContact>> {
        (0..self.self_contact_count).map(|i| self.self_contact(i)).collect()
    }

    /// The minimum distance between the link set's checked pairs of links
    /// (paddings included), the two links and shapes, and the witness
    /// points `point_on_a`, `point_on_b` (map frame).  `request.cutoff`
    /// (0: none) and `request.signed_distance` as documented on
    /// [`SelfDistanceRequest`].
    pub fn self_distance(&mut self, links: &LinkSet, request: &SelfDistanceRequest)
        -> Result<SelfDistanceResult> {
        let request = request.to_c();
        let mut out = sys::opx_self_distance_result::default();
        // SAFETY: live handles; links is only read.
        check(unsafe {
            sys::opx_query_self_distance(self.as_raw_mut(), links.as_raw(), &request, &mut out)
        })?;
        Ok(SelfDistanceResult::from_c(&out))
    }
}

impl LinkSet {
    /// Whether self-collision queries check links `a` and `b` (`a != b`,
    /// either order; else an invalid argument).  Every pair starts enabled
    /// but an SRDF's disabled pairs; a disabled link takes part in no pair.
    pub fn set_pair_enabled(&mut self, a: u32, b: u32, enabled: bool) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe {
            sys::opx_linkset_set_pair_enabled(self.as_raw_mut(), a, b, i32::from(enabled))
        })
    }

    /// True when self-collision queries check links `a` and `b`.
    pub fn pair_enabled(&self, a: u32, b: u32) -> Result<bool> {
        let mut enabled = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_pair_enabled(self.as_raw(), a, b, &mut enabled) })?;
        Ok(enabled != 0)
    }

    /// Disables every pair of links that never collides over
    /// `options.samples` random configurations (each moving joint uniform
    /// within its limits), as MoveIt's setup assistant does; with
    /// `options.also_always_colliding` also the pairs colliding in every
    /// sample, with `options.also_colliding_now` those colliding at the
    /// current poses.  A link set from URDF only (else
    /// [`crate::ErrorKind::Unsupported`]); its poses and joints do not
    /// change.  Sampling can miss a rare colliding configuration.  Returns
    /// how many pairs each rule disabled.
    pub fn disable_never_colliding_pairs(&mut self, options: &PairSamplingOptions)
        -> Result<PairSamplingResult> {
        let options = options.to_c();
        let mut out = sys::opx_pair_sampling_result::default();
        // SAFETY: exclusive access; the output is valid.
        check(unsafe {
            sys::opx_linkset_disable_never_colliding_pairs(self.as_raw_mut(), &options, &mut out)
        })?;
        Ok(PairSamplingResult::from_c(&out))
    }
}
