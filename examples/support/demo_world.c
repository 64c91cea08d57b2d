/* The demo's known objects: see demo_world.h. */
#include "demo_world.h"

#include "shape_mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failed(opx_status status, const char *what) {
    if (status == OPX_OK) return 0;
    fprintf(stderr, "opx-demo: %s failed: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    return -1;
}

int demo_world_load(const char *out_dir, const char *name, const char *text, char *path, size_t path_size,
                    opx_world **out) {
    FILE *file;
    snprintf(path, path_size, "%s/%s", out_dir, name);
    file = fopen(path, "w");
    if (file == NULL || fputs(text, file) < 0 || fclose(file) != 0) {
        fprintf(stderr, "opx-demo: cannot write the scene %s\n", path);
        return -1;
    }
    return failed(opx_world_load_scene_file(path, out), "opx_world_load_scene_file");
}

void demo_world_describe(const opx_world *world, char *text, size_t size) {
    uint32_t count = 0, o;
    size_t used;
    opx_world_get_object_count(world, &count);
    used = (size_t)snprintf(text, size, "%u object%s (", count, count == 1 ? "" : "s");
    for (o = 0; o < count && used < size; ++o) {
        const char *name = "";
        uint32_t shapes = 0;
        opx_world_get_object_name(world, o, &name);
        opx_world_get_shape_count(world, o, &shapes);
        used += (size_t)snprintf(text + used, size - used, "%s%s: %u shapes", o > 0 ? ", " : "", name, shapes);
    }
    if (used < size) snprintf(text + used, size - used, ")");
}

void demo_world_mesh(const opx_world *world, mesh_out *mesh) {
    const uint32_t group = mesh_add_group(mesh, "known objects", 0, 0, 0);
    uint32_t count = 0, o, s;
    opx_world_get_object_count(world, &count);
    for (o = 0; o < count; ++o) {
        opx_pose pose = OPX_POSE_IDENTITY;
        uint32_t shapes = 0;
        int32_t enabled = 0;
        opx_world_get_object_enabled(world, o, &enabled);
        if (!enabled || opx_world_get_object_pose(world, o, &pose) != OPX_OK) continue;
        opx_world_get_shape_count(world, o, &shapes);
        for (s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            if (opx_world_get_shape(world, o, s, &shape) == OPX_OK) shape_to_mesh(&shape, &pose, mesh, group);
        }
    }
}

int demo_world_contacts(const opx_world *world, const opx_linkset *robot, double **points, size_t *count) {
    opx_query *query = NULL;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    uint64_t i;
    int status;
    request.max_contacts = UINT32_MAX;
    request.compute_penetration = 1; /* the contact points */
    if (failed(opx_query_create(NULL, &query), "opx_query_create")) return -1;
    status = failed(opx_query_set_world(query, world), "opx_query_set_world");
    if (status == 0) status = failed(opx_query_collide(query, NULL, robot, &request, &hit), "opx_query_collide");
    for (i = 0; status == 0 && i < hit.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        double *grown = realloc(*points, (*count + 1) * 3 * sizeof **points);
        if (grown == NULL) break;
        *points = grown;
        if (opx_query_get_contact(query, (size_t)i, &contact) != OPX_OK) break;
        memcpy(&grown[3 * *count], contact.position, sizeof contact.position);
        ++*count;
    }
    opx_query_set_world(query, NULL);
    opx_query_destroy(query);
    return status;
}
