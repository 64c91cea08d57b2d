/* The self-collision part of `octoprox check`: see check_self.h. */
#include "check_self.h"

/* How many pairs of links self-collision checks: enabled pairs of two
 * links with shapes. */
static unsigned long checked_pairs(const opx_linkset *links) {
    uint32_t count = 0, shapes = 0, a, b;
    unsigned long pairs = 0;
    int32_t enabled = 0;
    opx_linkset_get_link_count(links, &count);
    for (a = 0; a < count; ++a) {
        if (opx_linkset_get_shape_count(links, a, &shapes) != OPX_OK || shapes == 0) continue;
        for (b = a + 1; b < count; ++b)
            if (opx_linkset_get_shape_count(links, b, &shapes) == OPX_OK && shapes > 0 &&
                opx_linkset_get_pair_enabled(links, a, b, &enabled) == OPX_OK && enabled)
                ++pairs;
    }
    return pairs;
}

static void print_contact(const check_context *c, const opx_self_contact *k, int last) {
    const char *a = check_link_name(c->links, k->link_a), *b = check_link_name(c->links, k->link_b);
    if (!c->json) {
        printf("  %s - %s, %.6f m deep\n", a, b, k->depth);
        return;
    }
    fputs("      {\"link_a\": ", stdout);
    json_string(stdout, a);
    fputs(", \"link_b\": ", stdout);
    json_string(stdout, b);
    fputs(", \"depth\": ", stdout);
    json_number(stdout, k->depth);
    fputs(", \"position\": ", stdout);
    json_vec3(stdout, k->position);
    printf("}%s\n", last ? "" : ",");
}

static void print_contacts(const check_context *c, const opx_self_collision_result *r) {
    const size_t listed = r->contact_count < CHECK_MAX_LISTED ? (size_t)r->contact_count : CHECK_MAX_LISTED;
    size_t i;
    if (c->json)
        printf(",\n  \"self\": {\"checked_pairs\": %lu, \"collided\": %s, \"contact_count\": %llu, \"contacts\": [\n",
               checked_pairs(c->links), r->collided ? "true" : "false", (unsigned long long)r->contact_count);
    else
        printf("self       %llu contacts (%lu pairs of links checked)%s\n", (unsigned long long)r->contact_count,
               checked_pairs(c->links), listed ? "; the first:" : "");
    for (i = 0; i < listed; ++i) {
        opx_self_contact contact = OPX_SELF_CONTACT_INIT;
        if (opx_query_get_self_contact(c->query, i, &contact) == OPX_OK) print_contact(c, &contact, i + 1 == listed);
    }
    if (c->json) fputs("  ]}", stdout);
}

static void print_distance(const check_context *c, const opx_self_distance_result *d) {
    const char *a = d->found ? check_link_name(c->links, d->link_a) : "";
    const char *b = d->found ? check_link_name(c->links, d->link_b) : "";
    if (!c->json) {
        if (d->found) printf("self distance %.9f m, between %s and %s\n", d->distance, a, b);
        else printf("self distance none (no checked pair of links with shapes)\n");
        return;
    }
    printf(",\n  \"self_distance\": {\"found\": %s, \"distance\": ", d->found ? "true" : "false");
    json_number(stdout, d->distance);
    fputs(", \"link_a\": ", stdout);
    json_string(stdout, a);
    fputs(", \"link_b\": ", stdout);
    json_string(stdout, b);
    fputs(", \"point_on_a\": ", stdout);
    json_vec3(stdout, d->point_on_a);
    fputs(", \"point_on_b\": ", stdout);
    json_vec3(stdout, d->point_on_b);
    fputs("}", stdout);
}

int check_self(const check_context *c, int *collided) {
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
    opx_self_distance_result distance = OPX_SELF_DISTANCE_RESULT_INIT;
    opx_status status;
    request.max_contacts = UINT32_MAX; /* every touching pair: the report names them */
    request.compute_penetration = 1;
    status = opx_query_self_collide(c->query, c->links, &request, &result);
    if (status != OPX_OK) return cli_library_fail("check", status, "the self-collision query");
    *collided = result.collided;
    print_contacts(c, &result);
    if (!c->want_distance) return -1;
    status = opx_query_self_distance(c->query, c->links, NULL, &distance);
    if (status != OPX_OK) return cli_library_fail("check", status, "the self-distance query");
    print_distance(c, &distance);
    return -1;
}
