"""Self-collision (include/octoprox/self_collision.h): a link set against
itself at its current poses.  Query inherits these methods.

Every pair of two enabled links with shapes is checked but the disabled
pairs: an SRDF's <disable_collisions> pairs (LinkSet.from_urdf(srdf=...))
and those LinkSet.set_pair_enabled turns off; links joined by a joint are
NOT skipped implicitly (LinkSet.disable_never_colliding_pairs finds the
pairs that never collide).  Shapes are padded on both sides of a pair and
touching (distance <= 1e-9 m) collides; the shapes of one link never
collide with each other.
"""
from __future__ import annotations

import numpy as np

from . import _structs as s
from ._arrays import SELF_CONTACT_DTYPE
from ._handle import api
from ._library import init_struct, lib
from ._requests import RequestCache
from ._structs import SelfCollisionResult, SelfDistanceResult
from .linkset import LinkSet


class SelfCollisionQueries:
    """Query.self_collide, self_contacts and self_distance (mixed into Query)."""

    def _init_self_collision(self):
        self._self_collide_requests = RequestCache(
            s.SelfCollisionRequest, ("max_contacts", "compute_penetration"), "Query.self_collide")
        self._self_distance_requests = RequestCache(
            s.SelfDistanceRequest, ("signed_distance", "cutoff"), "Query.self_distance")

    @api("Query.self_collide")
    def self_collide(self, links: LinkSet, *, max_contacts: int = 1,
                     compute_penetration: bool = False) -> SelfCollisionResult:
        """Does the link set collide with itself at its current poses?

        max_contacts: 0 answers yes/no; 1 (the default) stops at the first
          touching pair of shapes and reports it; N collects up to N, one
          per touching pair (ALL_CONTACTS: every one).
        compute_penetration: each contact also gets its depth, normal and
          point.

        Returns a SelfCollisionResult: collided (bool), contact_count,
        truncated, link_pairs, narrow_tests; self_contacts() gives the
        contacts (kept apart from those of collide()).  Raises TypeError
        when links is not a LinkSet.
        """
        self._check_links(links, "Query.self_collide")
        request = self._self_collide_requests.lookup((max_contacts, compute_penetration))
        out = init_struct(s.SelfCollisionResult)
        self._self_result = None
        lib.opx_query_self_collide(self, links, request, out)
        self._self_result = out
        return out

    @api("Query.self_contacts")
    def self_contacts(self) -> np.ndarray:
        """The contacts of the last self_collide, a structured array with
        the fields of SelfContact: link_a < link_b, shape_a, shape_b, and
        with compute_penetration depth, normal (moving link_a by -depth *
        normal separates the pair) and position (map frame)."""
        count = getattr(self._self_result, "contact_count", 0)
        return self._rows(lib.opx_query_get_self_contact, SELF_CONTACT_DTYPE, count)

    @api("Query.self_distance")
    def self_distance(self, links: LinkSet, *, signed_distance: bool = False,
                      cutoff: float = 0.0) -> SelfDistanceResult:
        """The minimum distance between the link set's checked pairs of
        links (paddings included).

        signed_distance: overlapping shapes give minus the deepest
          penetration instead of 0.
        cutoff: pairs farther than this (m) are not measured; the result is
          then found False and distance = cutoff.  0: none.

        Returns a SelfDistanceResult: found, collided, distance (m),
        link_a < link_b, shape_a, shape_b, point_on_a and point_on_b (map
        frame), link_pairs, narrow_tests.  Raises TypeError when links is
        not a LinkSet, InvalidArgumentError for a negative cutoff.
        """
        self._check_links(links, "Query.self_distance")
        request = self._self_distance_requests.lookup((signed_distance, cutoff))
        out = init_struct(s.SelfDistanceResult)
        lib.opx_query_self_distance(self, links, request, out)
        return out
