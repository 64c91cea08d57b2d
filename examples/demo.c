/*
 * opx-demo: the library's whole story on data it makes itself.  A
 * synthetic depth frame of a furnished room, seen from a head-height
 * camera, is ray-cast into an occupancy map; a built-in 7-joint arm
 * (primitives and two meshes, from a URDF string) plans a straight-line
 * joint-space path from above the table down into the table's shadow,
 * space the camera never saw; the table is also known as a world object,
 * read from a MoveIt scene file; every waypoint is checked for collision
 * and distance (the map and the table) and unknown-space cost with both
 * engines, timed; a picture (PNG) shows a slice of the map, the known
 * table, the arm at a few waypoints, the cells and the table points it
 * hits and the unknown-space cost boxes of the path, as in the paper's
 * Fig. 3.  With --real, the same story runs on the real RGB-D frame and
 * the PR2 of the shared data folder, and then the PR2's arm, rendered into
 * its head camera's frame, is ingested without and with self-filtering
 * (a before/after picture).
 *
 *   opx-demo [--out DIR] [--quick] [--real [--data DIR]]
 */
#define _POSIX_C_SOURCE 200809L

#include "support/demo_arm.h"
#include "support/demo_real.h"
#include "support/demo_story.h"
#include "support/room_frame.h"

#include <octoprox/octoprox.h>
#include <octoprox/robot.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char kUsage[] =
    "usage: opx-demo [--out DIR] [--quick] [--real [--data DIR]]\n"
    "\n"
    "  --out DIR    where the picture, the map and the arm's meshes go (default .)\n"
    "  --quick      a coarse map and fewer waypoints (a smoke test)\n"
    "  --real       the real RGB-D frame and the PR2 from the shared data folder\n"
    "  --data DIR   the shared data folder (default $OPX_DATA_DIR, else ../shared/data)\n";

typedef struct demo_args {
    const char *out_dir, *data_dir;
    int quick, real;
} demo_args;

static int parse_args(int argc, char **argv, demo_args *a) {
    int i;
    const char *env = getenv("OPX_DATA_DIR");
    a->out_dir = ".";
    a->data_dir = env != NULL && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
    a->quick = a->real = 0;
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(kUsage, stdout);
            exit(EXIT_SUCCESS);
        } else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            a->out_dir = argv[++i];
        } else if (strcmp(argv[i], "--data") == 0 && i + 1 < argc) {
            a->data_dir = argv[++i];
        } else if (strcmp(argv[i], "--quick") == 0) {
            a->quick = 1;
        } else if (strcmp(argv[i], "--real") == 0) {
            a->real = 1;
        } else {
            fprintf(stderr, "opx-demo: unknown argument '%s'\n%s", argv[i], kUsage);
            return -1;
        }
    }
    return 0;
}

/* The arm stands behind the table (room_frame.h), facing the camera:
 * base at x = 2.75 m on the floor, turned 180 degrees about z. */
static const opx_pose kArmBase = {{2.75, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}};
/* From raised above the table's far edge to reaching under the table. */
static const double kStart[DEMO_ARM_JOINTS] = {0.0, -0.3, 0.0, 1.0, 0.0, 0.8, 0.0};
static const double kGoal[DEMO_ARM_JOINTS] = {0.0, 1.75, 0.0, 0.2, 0.0, -0.3, 1.57};

static int is_pedestal(const char *name) { return strcmp(name, "pedestal") == 0; }

/* The room's table as the robot knows it, a MoveIt scene exported from
 * RViz (.scene text, MoveIt 1.1 and later): the object's pose, then per
 * shape its sizes, its pose in the object frame and a colour.  A 1 x 1.2 m
 * top 3 cm thick at 0.70-0.73 m and four 5 cm legs (room_frame.h). */
static const char kTableScene[] =
    "opx-demo room\n"
    "* table\n1.7 0 0\n0 0 0 1\n5\n"
    "box\n1 1.2 0.03\n0 0 0.715\n0 0 0 1\n0.6 0.4 0.2 1\n"
    "box\n0.05 0.05 0.7\n-0.455 -0.555 0.35\n0 0 0 1\n0.6 0.4 0.2 1\n"
    "box\n0.05 0.05 0.7\n-0.455 0.555 0.35\n0 0 0 1\n0.6 0.4 0.2 1\n"
    "box\n0.05 0.05 0.7\n0.455 -0.555 0.35\n0 0 0 1\n0.6 0.4 0.2 1\n"
    "box\n0.05 0.05 0.7\n0.455 0.555 0.35\n0 0 0 1\n0.6 0.4 0.2 1\n"
    "0\n.\n";

static int load_arm(const char *out_dir, opx_linkset **out) {
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    uint32_t pedestal;
    opx_status status;
    if (demo_arm_write_meshes(out_dir) != 0) {
        fprintf(stderr, "opx-demo: cannot write the arm's meshes into %s\n", out_dir);
        return -1;
    }
    options.base_dir = out_dir;
    status = opx_linkset_load_urdf_string(demo_arm_urdf(), &options, out);
    /* The pedestal is bolted to the floor: it need not be checked. */
    if (status == OPX_OK) status = opx_linkset_find_link(*out, "pedestal", &pedestal);
    if (status == OPX_OK) status = opx_linkset_set_link_enabled(*out, pedestal, 0);
    if (status != OPX_OK) {
        fprintf(stderr, "opx-demo: loading the arm failed: %s\n", opx_last_error());
        return -1;
    }
    return 0;
}

static void add_note(picture_input *p, const char *text, double x, double z) {
    p->notes[p->note_count] = text;
    p->note_at[p->note_count][0] = x;
    p->note_at[p->note_count][1] = 0.0;
    p->note_at[p->note_count][2] = z;
    ++p->note_count;
}

/* The view: the vertical plane y = 0 through the camera, the table and the
 * arm, seen from the side (x to the right, z up). */
static void side_view(demo_story *s, const room_frame *frame, int quick) {
    static const double half_fov = 0.4281; /* atan(239.5 / 525): half the vertical field of view */
    static const double pitch = 10.0 * 3.14159265358979323846 / 180.0;
    picture_view *v = &s->picture.view;
    const double below = pitch + half_fov, above = pitch - half_fov;
    memset(v, 0, sizeof *v);
    v->origin[1] = 0.005; /* just off the cell faces at y = 0 */
    v->u[0] = 1.0;
    v->v[2] = 1.0;
    v->u_min = -1.1;
    v->u_max = 5.1;
    v->v_min = -0.1;
    v->v_max = 2.9;
    v->pixels_per_metre = quick ? 140.0 : 160.0;
    v->title = "OCTOPROX DEMO: SIDE VIEW, SLICE Y = 0 M, ARM PATH THROUGH THE TABLE'S SHADOW";
    v->u_name = "X";
    v->v_name = "Z";
    memcpy(s->picture.sensor, frame->sensor_position, sizeof s->picture.sensor);
    s->picture.fov_edges[0][0] = cos(below);
    s->picture.fov_edges[0][2] = -sin(below);
    s->picture.fov_edges[1][0] = cos(above);
    s->picture.fov_edges[1][2] = -sin(above);
    s->picture.fov_edge_count = 2;
    add_note(&s->picture, "TABLE", 1.45, 0.86);
    add_note(&s->picture, "TABLE'S SHADOW", 3.75, 0.32);
    add_note(&s->picture, "WINDOW: NO RETURNS", 4.0, 1.62);
    add_note(&s->picture, "FLOOR", 1.7, 0.08);
    add_note(&s->picture, "WALL", 4.72, 0.5);
}

static int run_room(const demo_args *a) {
    static char frame_label[160];
    room_frame frame;
    demo_story s;
    size_t j;
    int status;
    memset(&s, 0, sizeof s);
    if (room_frame_generate(1, &frame) != 0 || load_arm(a->out_dir, &s.robot) != 0) return -1;
    snprintf(frame_label, sizeof frame_label,
             "synthetic %ux%u depth frame of a furnished room, camera at 1.4 m, %zu points with a return", frame.width,
             frame.height, frame.finite_count);
    s.frame_label = frame_label;
    s.points = frame.xyz;
    s.point_count = frame.count;
    memcpy(s.sensor_pose.position, frame.sensor_position, sizeof s.sensor_pose.position);
    memcpy(s.sensor_pose.orientation, frame.sensor_orientation, sizeof s.sensor_pose.orientation);
    s.resolution = a->quick ? 0.08 : 0.03;
    s.robot_label = "built-in 7-joint arm from a URDF string: cylinders, spheres, an OBJ forearm and an STL hand "
                    "(pedestal at x 2.75 m, not checked)";
    s.base_pose = kArmBase;
    s.joint_count = DEMO_ARM_JOINTS;
    for (j = 0; j < DEMO_ARM_JOINTS; ++j) {
        s.joint_names[j] = kDemoArmJointNames[j];
        s.start[j] = kStart[j];
        s.goal[j] = kGoal[j];
    }
    s.waypoint_count = a->quick ? 11 : 41;
    s.is_body_link = is_pedestal;
    s.tool_link = "hand";
    s.picture.tool_label = "HAND";
    s.picture.body_label = "PEDESTAL (STILL, NOT CHECKED)";
    s.scene_name = "opx-demo-table.scene";
    s.scene_text = kTableScene;
    s.known_name = "table";
    s.picture.known_label = "KNOWN TABLE: A WORLD OBJECT FROM A MOVEIT .SCENE";
    side_view(&s, &frame, a->quick);
    s.out_dir = a->out_dir;
    s.picture_name = "opx-demo.png";
    s.map_name = "opx-demo-room.bt";
    printf("OctoProx %s demo: a 7-joint arm, one depth frame, a path into space the camera never saw\n\n", opx_version());
    status = demo_story_run(&s);
    opx_linkset_destroy(s.robot);
    room_frame_free(&frame);
    return status;
}

int main(int argc, char **argv) {
    demo_args a;
    if (parse_args(argc, argv, &a) != 0) return 2;
    if (a.real) return demo_real_run(a.data_dir, a.out_dir, a.quick) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
    return run_room(&a) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
