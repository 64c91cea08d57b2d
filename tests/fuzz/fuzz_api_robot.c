/* Operations of the call-sequence fuzzer on URDF robots: see fuzz_api.h.
 * The URDF is fixed (fuzz_urdf fuzzes the parser); the joints move. */
#include "fuzz_api.h"

#include <stdlib.h>

/* Every joint type and a mimic joint, shared by both robots below. */
#define ROBOT_JOINTS \
    "<link name=\"wheel\"/><link name=\"finger\"/><link name=\"float\"/><link name=\"plane\"/>" \
    "<joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/>" \
    "<origin xyz=\"0 0 0.2\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"2\" effort=\"1\" velocity=\"1\"/></joint>" \
    "<joint name=\"slide\" type=\"prismatic\"><parent link=\"arm\"/><child link=\"slider\"/>" \
    "<axis xyz=\"1 0 0\"/><limit lower=\"0\" upper=\"0.3\" effort=\"1\" velocity=\"1\"/></joint>" \
    "<joint name=\"wheel\" type=\"continuous\"><parent link=\"base\"/><child link=\"wheel\"/></joint>" \
    "<joint name=\"finger\" type=\"prismatic\"><parent link=\"slider\"/><child link=\"finger\"/>" \
    "<axis xyz=\"0 1 0\"/><limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/>" \
    "<mimic joint=\"slide\" multiplier=\"2\" offset=\"0.01\"/></joint>" \
    "<joint name=\"float\" type=\"floating\"><parent link=\"base\"/><child link=\"float\"/></joint>" \
    "<joint name=\"plane\" type=\"planar\"><parent link=\"base\"/><child link=\"plane\"/></joint>" \
    "<joint name=\"tool\" type=\"fixed\"><parent link=\"finger\"/><child link=\"tool\"/></joint>" \
    "<link name=\"tool\"><collision><geometry><sphere radius=\"0.03\"/></geometry></collision></link>"

/* Every primitive shape. */
static const char ROBOT_URDF[] =
    "<robot name=\"fuzz\">"
    "<link name=\"base\"><collision><geometry><box size=\"0.4 0.3 0.2\"/></geometry></collision></link>"
    "<link name=\"arm\"><collision><origin xyz=\"0.25 0 0\" rpy=\"0 1.57 0\"/>"
    "<geometry><cylinder radius=\"0.05\" length=\"0.5\"/></geometry></collision></link>"
    "<link name=\"slider\"><collision><geometry><sphere radius=\"0.07\"/></geometry></collision></link>"
    ROBOT_JOINTS "</robot>";

/* Spheres alone: a robot the batch checks on the map's obstacle grid. */
static const char SPHERE_ROBOT_URDF[] =
    "<robot name=\"fuzz_spheres\">"
    "<link name=\"base\"><collision><geometry><sphere radius=\"0.2\"/></geometry></collision></link>"
    "<link name=\"arm\"><collision><origin xyz=\"0.1 0 0\"/><geometry><sphere radius=\"0.05\"/></geometry>"
    "</collision><collision><origin xyz=\"0.3 0 0\"/><geometry><sphere radius=\"0.06\"/></geometry>"
    "</collision><collision><origin xyz=\"0.5 0 0\"/><geometry><sphere radius=\"0.04\"/></geometry>"
    "</collision></link>"
    "<link name=\"slider\"><collision><geometry><sphere radius=\"0.07\"/></geometry></collision></link>"
    ROBOT_JOINTS "</robot>";

static const char *const JOINT_NAMES[] = {"shoulder", "slide", "wheel", "finger", "float", "plane", "tool", "none", ""};
#define JOINT_NAME_COUNT (sizeof JOINT_NAMES / sizeof JOINT_NAMES[0])

void op_robot_load(fuzz_api *api) {
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.struct_size = take_struct_size(&api->in, sizeof options);
    opx_linkset *robot = NULL;
    const uint8_t which = take_u8(&api->in);
    const char *urdf = which < 200 ? ROBOT_URDF : which < 240 ? SPHERE_ROBOT_URDF : NULL;
    const opx_status status =
        FUZZ_CALL(opx_linkset_load_urdf_string, urdf, take_bool(&api->in) ? &options : NULL, &robot);
    FUZZ_REQUIRE((status == OPX_OK) == (robot != NULL));
    if (robot == NULL) return;
    const size_t slot = take_slot(api);
    opx_linkset_destroy(api->linksets[slot]);
    api->linksets[slot] = robot;
}

double take_joint_position(fuzz_input *in) {
    return take_u8(in) < 224 ? (double)(int8_t)take_u8(in) / 40.0 : take_double(in);
}

static void set_positions(fuzz_api *api, opx_linkset *links, uint32_t joint_count) {
    fuzz_input *in = &api->in;
    const uint8_t kind = take_u8(in);
    const size_t count = kind < 224 ? joint_count : take_below(in, (size_t)joint_count + 2);
    double positions[16] = {0};
    for (size_t i = 0; i < count && i < 16; ++i) positions[i] = take_joint_position(in);
    opx_pose base;
    take_pose(in, &base);
    const uint8_t nulls = take_u8(in);
    if (count > 16) return;
    FUZZ_CALL(opx_linkset_set_joint_positions, links, nulls < 240 ? positions : NULL, count,
              nulls & 1 ? &base : NULL);
}

static void set_named_positions(fuzz_api *api, opx_linkset *links) {
    fuzz_input *in = &api->in;
    const size_t count = take_below(in, 5);
    const char *names[4];
    double positions[4];
    for (size_t i = 0; i < count; ++i) {
        names[i] = take_u8(in) < 248 ? JOINT_NAMES[take_below(in, JOINT_NAME_COUNT)] : NULL;
        positions[i] = take_joint_position(in);
    }
    FUZZ_CALL(opx_linkset_set_named_joint_positions, links, take_u8(in) < 248 ? names : NULL, positions, count,
              NULL);
}

static void read_joints(fuzz_api *api, const opx_linkset *links) {
    fuzz_input *in = &api->in;
    uint32_t found = 0;
    FUZZ_CALL(opx_linkset_find_joint, links, JOINT_NAMES[take_below(in, JOINT_NAME_COUNT)], &found);
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    info.struct_size = take_struct_size(in, sizeof info);
    FUZZ_CALL(opx_linkset_get_joint_info, links, (uint32_t)take_below(in, 10), &info);
    double positions[16];
    size_t count = 0;
    FUZZ_CALL(opx_linkset_get_joint_positions, links, positions, take_below(in, 17), &count);
    uint32_t pairs = 0, first = 0, second = 0;
    FUZZ_CALL(opx_linkset_get_disabled_pair_count, links, &pairs);
    FUZZ_CALL(opx_linkset_get_disabled_pair, links, (uint32_t)take_below(in, 2), &first, &second);
}

/* FK (all joints or named ones) or the joint getters, on any link set. */
void op_robot_joints(fuzz_api *api) {
    opx_linkset *links = take_linkset(api);
    uint32_t joint_count = 0;
    if (links != NULL) FUZZ_CALL(opx_linkset_get_joint_count, links, &joint_count);
    switch (take_u8(&api->in) % 3) {
    case 0: set_positions(api, links, joint_count); break;
    case 1: set_named_positions(api, links); break;
    default: read_joints(api, links);
    }
}
