/* Operations of the call-sequence fuzzer on link sets: see fuzz_api.h. */
#include "fuzz_api.h"

#include <stdlib.h>

static void put_linkset(fuzz_api *api, opx_linkset *links) {
    const size_t slot = take_slot(api);
    opx_linkset_destroy(api->linksets[slot]);
    api->linksets[slot] = links;
}

/* A new empty set, or a clone of one in the table. */
void op_linkset_create(fuzz_api *api) {
    opx_linkset *links = NULL;
    opx_status status;
    if (take_bool(&api->in)) status = FUZZ_CALL(opx_linkset_create, &links);
    else status = FUZZ_CALL(opx_linkset_clone, take_linkset(api), &links);
    FUZZ_REQUIRE((status == OPX_OK) == (links != NULL));
    if (links != NULL) put_linkset(api, links);
}

void op_linkset_destroy(fuzz_api *api) {
    const size_t slot = take_slot(api);
    opx_linkset_destroy(api->linksets[slot]);
    api->linksets[slot] = NULL;
}

/* A short name from the input (may be empty), or NULL. */
static const char *take_name(fuzz_input *in, char name[17]) {
    const size_t length = take_below(in, 17);
    if (length == 16) return NULL;
    for (size_t i = 0; i < length; ++i) name[i] = (char)('a' + take_u8(in) % 4);
    name[length] = '\0';
    return name;
}

void op_linkset_add_link(fuzz_api *api) {
    opx_linkset *links = take_linkset(api);
    char buffer[17];
    const char *name = take_name(&api->in, buffer);
    uint32_t index = 0;
    FUZZ_CALL(opx_linkset_add_link, links, name, take_u8(&api->in) < 240 ? &index : NULL);
}

static void take_vertices(fuzz_input *in, opx_shape *shape, double *vertices) {
    shape->vertex_count = take_below(in, FUZZ_MAX_VERTICES + 1);
    shape->vertex_stride = take_stride(in, 3 * sizeof(double));
    const size_t step = shape->vertex_stride == 0 ? 3 : shape->vertex_stride / sizeof(double);
    if (shape->vertex_stride % sizeof(double) == 0 && step >= 3) {
        const int flat = take_u8(in) < 32; /* coplanar or repeated points */
        for (size_t i = 0; i < shape->vertex_count; ++i)
            for (size_t axis = 0; axis < 3; ++axis)
                vertices[i * step + axis] = flat && axis == 2 ? 0.0
                                            : take_u8(in) < 224 ? (double)(int8_t)take_u8(in) / 50.0
                                                                : take_double(in);
    }
    shape->vertices = take_u8(in) < 240 ? vertices : NULL;
}

static void take_triangles(fuzz_input *in, opx_shape *shape, uint32_t *indices) {
    shape->triangle_count = take_below(in, FUZZ_MAX_TRIANGLES + 1);
    for (size_t i = 0; i < 3 * shape->triangle_count; ++i) {
        const uint8_t kind = take_u8(in);
        indices[i] = kind < 240 ? (uint32_t)take_below(in, shape->vertex_count + 1) : take_u32(in);
    }
    shape->indices = take_u8(in) < 240 ? indices : NULL;
}

void op_linkset_add_shape(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_linkset *links = take_linkset(api);
    const uint32_t link = take_link(api, links);
    opx_shape shape = OPX_SHAPE_INIT;
    shape.struct_size = take_struct_size(in, sizeof shape);
    const uint8_t kind = take_u8(in);
    shape.kind = kind < 248 ? OPX_SHAPE_SPHERE + kind % 6 : (int32_t)take_u32(in);
    take_pose(in, &shape.pose);
    shape.radius = take_u8(in) < 200 ? take_u8(in) / 100.0 : take_double(in);
    shape.length = take_u8(in) < 200 ? take_u8(in) / 100.0 : take_double(in);
    for (int axis = 0; axis < 3; ++axis) shape.size[axis] = take_u8(in) < 200 ? take_u8(in) / 100.0 : take_double(in);
    /* Room for the largest stride take_stride gives. */
    double vertices[FUZZ_MAX_VERTICES * 16];
    uint32_t indices[3 * FUZZ_MAX_TRIANGLES];
    memset(vertices, 0, sizeof vertices);
    if (shape.kind == OPX_SHAPE_CONVEX || shape.kind == OPX_SHAPE_MESH) take_vertices(in, &shape, vertices);
    if (shape.kind == OPX_SHAPE_MESH) take_triangles(in, &shape, indices);
    uint32_t index = 0;
    FUZZ_CALL(opx_linkset_add_shape, links, link, &shape, take_u8(in) < 128 ? &index : NULL);
}

/* Paddings, per-link paddings and enabled flags. */
void op_linkset_settings(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_linkset *links = take_linkset(api);
    const double padding = take_u8(in) < 200 ? take_u8(in) / 200.0 : take_double(in);
    switch (take_u8(in) % 3) {
    case 0: FUZZ_CALL(opx_linkset_set_padding, links, padding); break;
    case 1: FUZZ_CALL(opx_linkset_set_link_padding, links, take_link(api, links), padding); break;
    default: FUZZ_CALL(opx_linkset_set_link_enabled, links, take_link(api, links), (int32_t)(int8_t)take_u8(in));
    }
}

void op_linkset_set_poses(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_linkset *links = take_linkset(api);
    uint32_t link_count = 0;
    if (links != NULL) FUZZ_CALL(opx_linkset_get_link_count, links, &link_count);
    /* Mostly the right count; sometimes one off. */
    const uint8_t kind = take_u8(in);
    const size_t count = kind < 224 ? link_count : kind < 240 ? link_count + 1 : take_below(in, 4);
    const size_t stride = take_stride(in, sizeof(opx_pose));
    const size_t bytes = array_bytes(count, stride, sizeof(opx_pose));
    opx_pose *poses = calloc(bytes / sizeof(opx_pose) + 2, sizeof(opx_pose));
    FUZZ_REQUIRE(poses != NULL);
    for (size_t i = 0; i < count && i < 64; ++i) {
        opx_pose pose;
        take_pose(in, &pose);
        memcpy((char *)poses + i * (stride == 0 ? sizeof pose : stride), &pose, sizeof pose);
    }
    FUZZ_CALL(opx_linkset_set_poses, links, take_u8(in) < 240 ? poses : NULL, count, stride);
    free(poses);
}

/* Every getter of a link set, with indices in and out of range. */
void op_linkset_read(fuzz_api *api) {
    fuzz_input *in = &api->in;
    const opx_linkset *links = take_linkset(api);
    const uint32_t link = take_link(api, links);
    uint32_t count = 0;
    FUZZ_CALL(opx_linkset_get_link_count, links, &count);
    FUZZ_CALL(opx_linkset_get_shape_count, links, link, &count);
    const char *name = NULL;
    if (FUZZ_CALL(opx_linkset_get_link_name, links, link, &name) == OPX_OK) {
        uint32_t found = 0;
        FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_find_link, links, name, &found) == OPX_OK && found <= link);
    }
    char buffer[17];
    uint32_t found = 0;
    FUZZ_CALL(opx_linkset_find_link, links, take_name(in, buffer), &found);
    opx_shape shape = OPX_SHAPE_INIT;
    shape.struct_size = take_struct_size(in, sizeof shape);
    FUZZ_CALL(opx_linkset_get_shape, links, link, (uint32_t)take_below(in, 4), &shape);
    opx_pose pose;
    FUZZ_CALL(opx_linkset_get_pose, links, link, &pose);
}
