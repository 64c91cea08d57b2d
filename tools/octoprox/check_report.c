/* The report of `octoprox check`: see check_report.h. */
#include "check_report.h"

#include <string.h>

const char *check_class_name(int32_t cell_class) {
    switch (cell_class) {
    case OPX_CELL_FREE: return "free";
    case OPX_CELL_UNCERTAIN: return "uncertain";
    case OPX_CELL_OCCUPIED: return "occupied";
    default: return "unknown";
    }
}

static const char *object_name(const opx_world *world, int32_t object) {
    const char *name = "?";
    opx_world_get_object_name(world, (uint32_t)object, &name);
    return name;
}

const char *check_link_name(const opx_linkset *links, uint32_t link) {
    const char *name = "?";
    opx_linkset_get_link_name(links, link, &name);
    return name;
}

static void print_robot_options_text(const robot_args *r, uint32_t disabled_pairs) {
    int i;
    if (r->padding > 0.0) printf("padding    %g m\n", r->padding);
    if (r->disabled_link_count > 0) {
        fputs("disabled  ", stdout);
        for (i = 0; i < r->disabled_link_count; ++i) printf(" %s", r->disabled_links[i]);
        fputc('\n', stdout);
    }
    if (r->srdf != NULL) printf("srdf       %s (%u disabled collision pairs)\n", r->srdf, disabled_pairs);
}

static void print_scene(const check_context *c) {
    uint32_t objects = 0;
    if (c->world != NULL) opx_world_get_object_count(c->world, &objects);
    if (!c->json) {
        if (c->scene_path != NULL) printf("scene      %s (%u objects)\n", c->scene_path, objects);
        return;
    }
    fputs(",\n  \"scene\": ", stdout);
    if (c->scene_path != NULL) json_string(stdout, c->scene_path);
    else fputs("null", stdout);
    printf(",\n  \"scene_objects\": %u", objects);
}

static void print_robot_options_json(const robot_args *r, uint32_t disabled_pairs) {
    int i;
    fputs(",\n  \"padding\": ", stdout);
    json_number(stdout, r->padding);
    fputs(",\n  \"disabled_links\": [", stdout);
    for (i = 0; i < r->disabled_link_count; ++i) {
        fputs(i > 0 ? ", " : "", stdout);
        json_string(stdout, r->disabled_links[i]);
    }
    fputs("],\n  \"srdf\": ", stdout);
    if (r->srdf != NULL) json_string(stdout, r->srdf);
    else fputs("null", stdout);
    printf(",\n  \"srdf_disabled_pairs\": %u", disabled_pairs);
}

void check_print_head(const check_context *c) {
    uint32_t links = 0, disabled_pairs = 0;
    const char *policy = c->unknown_policy == OPX_UNKNOWN_OCCUPIED ? "occupied" : "free";
    const char *obstacles = c->obstacle_geometry == OPX_OBSTACLE_POINT_EXTENTS ? "point-extents" : "cells";
    opx_linkset_get_link_count(c->links, &links);
    opx_linkset_get_disabled_pair_count(c->links, &disabled_pairs);
    if (!c->json) {
        printf("map        %s\n", c->map_path ? c->map_path : c->scene_path ? "none (scene objects only)" : "none (--self only)");
        print_scene(c);
        printf("robot      %s (%u links)\n", c->urdf_path, links);
        print_robot_options_text(c->robot, disabled_pairs);
        printf("unknown    %s\nobstacles  %s\n", policy, obstacles);
        return;
    }
    fputs("{\n  \"map\": ", stdout);
    if (c->map_path != NULL) json_string(stdout, c->map_path);
    else fputs("null", stdout);
    print_scene(c);
    fputs(",\n  \"urdf\": ", stdout);
    json_string(stdout, c->urdf_path);
    printf(",\n  \"links\": %u", links);
    print_robot_options_json(c->robot, disabled_pairs);
    printf(",\n  \"unknown\": \"%s\",\n  \"obstacles\": \"%s\"", policy, obstacles);
}

/* Marks which links have contacts; returns how many do. */
static size_t colliding_links(const check_context *c, uint64_t contacts, unsigned char *mark, uint32_t link_count) {
    size_t n = 0;
    uint64_t i;
    memset(mark, 0, link_count);
    for (i = 0; i < contacts; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(c->query, (size_t)i, &contact) != OPX_OK || contact.link >= link_count) continue;
        if (!mark[contact.link]) ++n;
        mark[contact.link] = 1;
    }
    return n;
}

/* A contact with a scene object: the object's name instead of a cell. */
static void print_object_contact(const check_context *c, const opx_contact *k, int last) {
    if (!c->json) {
        printf("  %-28s object %s (shape %u)\n", check_link_name(c->links, k->link), object_name(c->world, k->object),
               k->object_shape);
        return;
    }
    fputs("    {\"link\": ", stdout);
    json_string(stdout, check_link_name(c->links, k->link));
    fputs(", \"object\": ", stdout);
    json_string(stdout, object_name(c->world, k->object));
    printf(", \"object_shape\": %u}%s\n", k->object_shape, last ? "" : ",");
}

static void print_contact(const check_context *c, const opx_contact *k, int last) {
    if (k->object >= 0) {
        print_object_contact(c, k, last);
    } else if (c->json) {
        fputs("    {\"link\": ", stdout);
        json_string(stdout, check_link_name(c->links, k->link));
        fputs(", \"object\": null", stdout);
        printf(", \"cell_class\": \"%s\", \"cell_center\": ", check_class_name(k->cell_class));
        json_vec3(stdout, k->cell_center);
        fputs(", \"cell_size\": ", stdout);
        json_number(stdout, k->cell_size);
        printf("}%s\n", last ? "" : ",");
    } else {
        printf("  %-28s %-9s cell at (%.3f, %.3f, %.3f), %.3f m\n", check_link_name(c->links, k->link),
               check_class_name(k->cell_class), k->cell_center[0], k->cell_center[1], k->cell_center[2], k->cell_size);
    }
}

void check_print_contacts(const check_context *c, const opx_collision_result *r) {
    static unsigned char mark[65536];
    uint32_t link_count = 0, l;
    size_t listed = r->contact_count < CHECK_MAX_LISTED ? (size_t)r->contact_count : CHECK_MAX_LISTED, i, first = 1;
    opx_linkset_get_link_count(c->links, &link_count);
    if (link_count > sizeof mark) link_count = sizeof mark;
    colliding_links(c, r->contact_count, mark, link_count);
    if (c->json) printf(",\n  \"contact_count\": %llu,\n  \"colliding_links\": [", (unsigned long long)r->contact_count);
    else printf("contacts   %llu\ncolliding links:%s", (unsigned long long)r->contact_count, r->contact_count ? "" : " none");
    for (l = 0; l < link_count; ++l) {
        if (!mark[l]) continue;
        if (c->json) {
            fputs(first ? "" : ", ", stdout);
            json_string(stdout, check_link_name(c->links, l));
        } else {
            printf(" %s", check_link_name(c->links, l));
        }
        first = 0;
    }
    fputs(c->json ? "],\n  \"contacts\": [\n" : "\n", stdout);
    for (i = 0; i < listed; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(c->query, i, &contact) == OPX_OK) print_contact(c, &contact, i + 1 == listed);
    }
    if (c->json) fputs("  ]", stdout);
}

static void print_cost_box(const check_context *c, const opx_cost_box *b, int last) {
    if (!c->json) {
        printf("  %-28s %-9s (%.3f, %.3f, %.3f) .. (%.3f, %.3f, %.3f)  %.3g m^3\n", check_link_name(c->links, b->link),
               check_class_name(b->cell_class), b->min[0], b->min[1], b->min[2], b->max[0], b->max[1], b->max[2],
               b->cost);
        return;
    }
    fputs("      {\"link\": ", stdout);
    json_string(stdout, check_link_name(c->links, b->link));
    printf(", \"cell_class\": \"%s\", \"min\": ", check_class_name(b->cell_class));
    json_vec3(stdout, b->min);
    fputs(", \"max\": ", stdout);
    json_vec3(stdout, b->max);
    fputs(", \"probability\": ", stdout);
    json_number(stdout, b->probability);
    fputs(", \"cost\": ", stdout);
    json_number(stdout, b->cost);
    printf("}%s\n", last ? "" : ",");
}

void check_print_cost(const check_context *c, double total, uint64_t found, uint64_t held) {
    const size_t listed = held < CHECK_MAX_LISTED ? (size_t)held : CHECK_MAX_LISTED;
    size_t i;
    if (c->json) {
        fputs(",\n  \"cost\": {\"total\": ", stdout);
        json_number(stdout, total);
        printf(", \"boxes_found\": %llu, \"boxes\": [\n", (unsigned long long)found);
    } else {
        printf("cost       %.6g m^3 of uncertain/unknown space in %llu boxes%s\n", total, (unsigned long long)found,
               listed ? "; the costliest:" : "");
    }
    for (i = 0; i < listed; ++i) {
        opx_cost_box box = OPX_COST_BOX_INIT;
        if (opx_query_get_cost_box(c->query, i, &box) == OPX_OK) print_cost_box(c, &box, i + 1 == listed);
    }
    if (c->json) fputs("  ]}", stdout);
}

void check_print_distance(const check_context *c, const opx_distance_result *d) {
    if (!c->json) {
        if (!d->found) {
            printf("distance   no obstacle in the map%s\n", c->world != NULL ? " or the scene" : "");
            return;
        }
        if (d->object >= 0) {
            printf("distance   %.9f m, link %s to object %s\n", d->distance, check_link_name(c->links, d->link),
                   object_name(c->world, d->object));
            return;
        }
        printf("distance   %.9f m, link %s to a %s cell at (%.3f, %.3f, %.3f)\n", d->distance,
               check_link_name(c->links, d->link), check_class_name(d->cell_class), d->cell_center[0],
               d->cell_center[1], d->cell_center[2]);
        return;
    }
    printf(",\n  \"distance\": {\"found\": %s, \"distance\": ", d->found ? "true" : "false");
    json_number(stdout, d->distance);
    fputs(", \"link\": ", stdout);
    json_string(stdout, d->found ? check_link_name(c->links, d->link) : "");
    fputs(", \"object\": ", stdout);
    if (d->found && d->object >= 0) json_string(stdout, object_name(c->world, d->object));
    else fputs("null", stdout);
    fputs(", \"point_on_link\": ", stdout);
    json_vec3(stdout, d->point_on_link);
    fputs(", \"point_on_cell\": ", stdout);
    json_vec3(stdout, d->point_on_cell);
    fputs("}", stdout);
}

void check_print_path(const check_context *c, size_t waypoints, const opx_path_result *r) {
    if (!c->json) {
        printf("path       %s, %zu waypoints\n", c->path_file, waypoints);
        if (r->collided) printf("first collision at waypoint %lld\n", (long long)r->first_colliding_waypoint);
        if (c->want_distance)
            printf("min distance %.9f m at waypoint %lld\n", r->min_distance, (long long)r->min_distance_waypoint);
        return;
    }
    fputs(",\n  \"path\": {\"file\": ", stdout);
    json_string(stdout, c->path_file);
    printf(", \"waypoints\": %zu, \"first_colliding_waypoint\": %lld, \"min_distance\": ", waypoints,
           (long long)r->first_colliding_waypoint);
    if (c->want_distance) json_number(stdout, r->min_distance);
    else fputs("null", stdout);
    printf(", \"min_distance_waypoint\": %lld}", (long long)r->min_distance_waypoint);
}

void check_print_motions(const check_context *c, const check_motions_report *m) {
    if (!c->json) {
        if (c->certified)
            printf("motions    %zu between the waypoints, every configuration checked (certified)\n", m->count);
        else
            printf("motions    %zu between the waypoints, checked every %g rad (or m) of joint motion\n", m->count,
                   c->resolution);
        if (m->first_colliding >= 0)
            printf("first collision between waypoints %lld and %lld, at %.6f of the way\n",
                   (long long)m->first_colliding, (long long)m->first_colliding + 1, m->first_fraction);
        return;
    }
    printf(",\n  \"motions\": {\"count\": %zu, \"certified\": %s, \"resolution\": ", m->count,
           c->certified ? "true" : "false");
    if (c->certified) fputs("null", stdout);
    else json_number(stdout, c->resolution);
    printf(", \"first_colliding\": %lld, \"first_collision_fraction\": ", (long long)m->first_colliding);
    json_number(stdout, m->first_fraction);
    fputs("}", stdout);
}

void check_print_tail(const check_context *c, int collided, double query_ms) {
    if (c->json) {
        printf(",\n  \"collided\": %s,\n  \"query_ms\": %.3f\n}\n", collided ? "true" : "false", query_ms);
        return;
    }
    printf("query      %.3f ms\nresult     %s\n", query_ms, collided ? "COLLISION" : "no collision");
}
