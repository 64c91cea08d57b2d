//! The requests and answers of self-collision
//! ([`crate::Query::self_collide`], [`crate::Query::self_distance`]) and of
//! choosing the checked pairs by sampling
//! ([`crate::LinkSet::disable_never_colliding_pairs`]).  Points are in the
//! map frame, lengths in metres; `Default` gives the C library's defaults.
//!
//! ```
//! use octoprox::{PairSamplingOptions, SelfCollisionRequest, SelfDistanceRequest};
//!
//! let all_contacts = SelfCollisionRequest { max_contacts: u32::MAX, ..Default::default() };
//! assert!(!all_contacts.compute_penetration);
//! let signed = SelfDistanceRequest { signed_distance: true, ..Default::default() };
//! assert_eq!(signed.cutoff, 0.0); // no cutoff
//! assert_eq!(PairSamplingOptions::default().samples, 10_000);
//! ```
use crate::enums::{flag, is_set};
use crate::results::object_index;
use crate::sys;

/// A self-collision query.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SelfCollisionRequest {
    /// 0: answer yes or no only; 1 (the default): stop at the first
    /// touching pair of shapes and report it; N: collect up to N contacts,
    /// one per touching pair of shapes (`u32::MAX`: all).
    pub max_contacts: u32,
    /// Each contact also gets its penetration depth, normal and point.
    /// Default false.
    pub compute_penetration: bool,
}

impl Default for SelfCollisionRequest {
    fn default() -> SelfCollisionRequest {
        let c = sys::opx_self_collision_request::default();
        SelfCollisionRequest {
            max_contacts: c.max_contacts,
            compute_penetration: is_set(c.compute_penetration),
        }
    }
}

impl SelfCollisionRequest {
    pub(crate) fn to_c(self) -> sys::opx_self_collision_request {
        sys::opx_self_collision_request {
            max_contacts: self.max_contacts,
            compute_penetration: flag(self.compute_penetration),
            ..Default::default()
        }
    }
}

/// The answer of [`crate::Query::self_collide`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SelfCollisionResult {
    /// Two shapes of a checked pair of links touch.
    pub collided: bool,
    /// Contacts the query holds ([`crate::Query::self_contacts`]).
    pub contact_count: u64,
    /// A touching pair beyond the first `max_contacts` was left out (with
    /// `max_contacts` 0 or 1 the check stops at the first: false).
    pub truncated: bool,
    /// Checked pairs of links whose bounding boxes overlap.
    pub link_pairs: u64,
    /// Exact tests between convex pieces (a cost measure).
    pub narrow_tests: u64,
}

impl SelfCollisionResult {
    pub(crate) fn from_c(c: &sys::opx_self_collision_result) -> SelfCollisionResult {
        SelfCollisionResult {
            collided: is_set(c.collided),
            contact_count: c.contact_count,
            truncated: is_set(c.truncated),
            link_pairs: c.link_pairs,
            narrow_tests: c.narrow_tests,
        }
    }
}

/// Two shapes of two links that touch; `link_a < link_b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SelfContact {
    /// The first link's index in the link set.
    pub link_a: u32,
    /// The shape's index within `link_a`.
    pub shape_a: u32,
    /// The second link's index.
    pub link_b: u32,
    /// The shape's index within `link_b`.
    pub shape_b: u32,
    /// With `compute_penetration` (else 0): how deep the padded shapes
    /// overlap, metres (0 when only touching).
    pub depth: f64,
    /// With `compute_penetration`: the unit direction `link_a` went into
    /// `link_b`; moving `link_a` by `-depth * normal` separates the pair.
    pub normal: [f64; 3],
    /// With `compute_penetration`: the contact point, midway between each
    /// shape's point deepest in the other, map frame.
    pub position: [f64; 3],
    /// The object attached to `link_a` ([`crate::LinkSet::attach_object`]:
    /// its index) whose shape touches, `shape_a` then being the shape's
    /// index within that object; `None` for one of the link's own shapes.
    pub attached_a: Option<u32>,
    /// As `attached_a`, for `link_b` and `shape_b`.
    pub attached_b: Option<u32>,
}

impl SelfContact {
    pub(crate) fn from_c(c: &sys::opx_self_contact) -> SelfContact {
        SelfContact {
            link_a: c.link_a,
            shape_a: c.shape_a,
            link_b: c.link_b,
            shape_b: c.shape_b,
            depth: c.depth,
            normal: c.normal,
            position: c.position,
            attached_a: object_index(c.attached_a),
            attached_b: object_index(c.attached_b),
        }
    }
}

/// A self-distance query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SelfDistanceRequest {
    /// When shapes overlap the distance is minus the deepest penetration,
    /// else overlap is distance 0 (the default, false).
    pub signed_distance: bool,
    /// Pairs farther than this (metres) are not measured; the result is
    /// then `found == false` with the cutoff as distance.  0 (the default)
    /// or infinity: no cutoff; a negative cutoff is an invalid argument.
    pub cutoff: f64,
}

impl Default for SelfDistanceRequest {
    fn default() -> SelfDistanceRequest {
        let c = sys::opx_self_distance_request::default();
        SelfDistanceRequest { signed_distance: is_set(c.signed_distance), cutoff: c.cutoff }
    }
}

impl SelfDistanceRequest {
    pub(crate) fn to_c(self) -> sys::opx_self_distance_request {
        sys::opx_self_distance_request {
            signed_distance: flag(self.signed_distance),
            cutoff: self.cutoff,
            ..Default::default()
        }
    }
}

/// The answer of [`crate::Query::self_distance`]: the nearest checked pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SelfDistanceResult {
    /// A checked pair lies within the cutoff; else `distance` is the cutoff
    /// (infinity without one, or without pairs).
    pub found: bool,
    /// The distance is `<=` 1e-9 m (the touch rule).
    pub collided: bool,
    /// The nearest pair's first link (`link_a < link_b`).
    pub link_a: u32,
    /// The shape's index within `link_a`.
    pub shape_a: u32,
    /// The nearest pair's second link.
    pub link_b: u32,
    /// The shape's index within `link_b`.
    pub shape_b: u32,
    /// Metres, paddings included; `>= 0` unless `signed_distance`.
    pub distance: f64,
    /// Witness point on `link_a`'s padded shape, map frame.
    pub point_on_a: [f64; 3],
    /// Witness point on `link_b`'s padded shape, map frame; `|distance|`
    /// from `point_on_a`.
    pub point_on_b: [f64; 3],
    /// Pairs of links measured beyond their bounding boxes.
    pub link_pairs: u64,
    /// Exact distances between convex pieces.
    pub narrow_tests: u64,
    /// The object attached to `link_a` whose shape is the nearest
    /// (`shape_a` then its index within the object), as in
    /// [`SelfContact::attached_a`]; `None` for the link's own shape.
    pub attached_a: Option<u32>,
    /// As `attached_a`, for `link_b` and `shape_b`.
    pub attached_b: Option<u32>,
}

impl SelfDistanceResult {
    pub(crate) fn from_c(c: &sys::opx_self_distance_result) -> SelfDistanceResult {
        SelfDistanceResult {
            found: is_set(c.found),
            collided: is_set(c.collided),
            link_a: c.link_a,
            shape_a: c.shape_a,
            link_b: c.link_b,
            shape_b: c.shape_b,
            distance: c.distance,
            point_on_a: c.point_on_a,
            point_on_b: c.point_on_b,
            link_pairs: c.link_pairs,
            narrow_tests: c.narrow_tests,
            attached_a: object_index(c.attached_a),
            attached_b: object_index(c.attached_b),
        }
    }
}

/// How [`crate::LinkSet::disable_never_colliding_pairs`] samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PairSamplingOptions {
    /// Random configurations (default 10000, as MoveIt's setup assistant).
    pub samples: u32,
    /// Seed of the generator (default 1): the same seed, the same pairs.
    pub seed: u64,
    /// Also disable the pairs colliding in every sample (links meeting at
    /// their joint: MoveIt's "Adjacent" and "Always").  Default false.
    pub also_always_colliding: bool,
    /// Also disable the pairs colliding at the link set's current poses
    /// (MoveIt's "Default").  Default false.
    pub also_colliding_now: bool,
}

impl Default for PairSamplingOptions {
    fn default() -> PairSamplingOptions {
        let c = sys::opx_pair_sampling_options::default();
        PairSamplingOptions {
            samples: c.samples,
            seed: c.seed,
            also_always_colliding: is_set(c.also_always_colliding),
            also_colliding_now: is_set(c.also_colliding_now),
        }
    }
}

impl PairSamplingOptions {
    pub(crate) fn to_c(self) -> sys::opx_pair_sampling_options {
        sys::opx_pair_sampling_options {
            samples: self.samples,
            seed: self.seed,
            also_always_colliding: flag(self.also_always_colliding),
            also_colliding_now: flag(self.also_colliding_now),
            ..Default::default()
        }
    }
}

/// How many pairs each rule disabled; a pair counts once, for the first
/// rule in this order that disabled it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PairSamplingResult {
    /// Pairs colliding at the current poses (`also_colliding_now`).
    pub now: u32,
    /// Pairs colliding in no sample.
    pub never: u32,
    /// Pairs colliding in every sample (`also_always_colliding`).
    pub always: u32,
}

impl PairSamplingResult {
    pub(crate) fn from_c(c: &sys::opx_pair_sampling_result) -> PairSamplingResult {
        PairSamplingResult { now: c.now, never: c.never, always: c.always }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_c_defaults() {
        assert_eq!(SelfCollisionRequest::default().to_c(), sys::opx_self_collision_request::default());
        assert_eq!(SelfDistanceRequest::default().to_c(), sys::opx_self_distance_request::default());
        assert_eq!(PairSamplingOptions::default().to_c(), sys::opx_pair_sampling_options::default());
    }
}
