//! Self-collision (`self_collision.h`): a link set against itself at its
//! current poses, over the pairs of links it checks.
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
        let mut out = SelfCollisionResult::default();
        self.self_contact_count = 0;
        // SAFETY: live handles; links is only read.
        check(unsafe {
            sys::opx_query_self_collide(self.as_raw_mut(), links.as_raw(), request, &mut out)
        })?;
        self.self_contact_count = out.contact_count as usize;
        Ok(out)
    }

    /// Contact `index` of the last self-collision query: `link_a < link_b`,
    /// their shapes, and with `compute_penetration` the depth, normal and
    /// point (map frame).
    pub fn self_contact(&self, index: usize) -> Result<SelfContact> {
        let mut out = SelfContact::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_query_get_self_contact(self.as_raw(), index, &mut out) })?;
        Ok(out)
    }

    /// All contacts of the last self-collision query.
    pub fn self_contacts(&self) -> Result<Vec<SelfContact>> {
        (0..self.self_contact_count).map(|i| self.self_contact(i)).collect()
    }

    /// The minimum distance between the link set's checked pairs of links
    /// (paddings included), the two links and shapes, and the witness
    /// points `point_on_a`, `point_on_b` (map frame).  `request.cutoff`
    /// (0: none) and `request.signed_distance` as in the C header.
    pub fn self_distance(&mut self, links: &LinkSet, request: &SelfDistanceRequest)
        -> Result<SelfDistanceResult> {
        let mut out = SelfDistanceResult::default();
        // SAFETY: live handles; links is only read.
        check(unsafe {
            sys::opx_query_self_distance(self.as_raw_mut(), links.as_raw(), request, &mut out)
        })?;
        Ok(out)
    }
}

impl LinkSet {
    /// Whether self-collision queries check links `a` and `b` (`a != b`,
    /// either order).  Every pair starts enabled but an SRDF's disabled
    /// pairs.
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
    /// `options.also_always_colliding = 1` also the pairs colliding in
    /// every sample, with `options.also_colliding_now = 1` those colliding
    /// at the current poses.  A link set from URDF only; its poses and
    /// joints do not change.  Returns how many pairs each rule disabled.
    pub fn disable_never_colliding_pairs(&mut self, options: &PairSamplingOptions)
        -> Result<PairSamplingResult> {
        let mut out = PairSamplingResult::default();
        // SAFETY: exclusive access; the output is valid.
        check(unsafe {
            sys::opx_linkset_disable_never_colliding_pairs(self.as_raw_mut(), options, &mut out)
        })?;
        Ok(out)
    }
}
