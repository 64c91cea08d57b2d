/*
 * The demo on real data: see demo_real.h.  The real Kinect-class frame
 * (rgbd/, 640x480, optical frame) is placed as if the PR2's head camera
 * (link wide_stereo_optical_frame, head tilted down 0.82 rad, which puts
 * the frame's large flat surface level) had taken it;
 * the PR2 stands at the map origin; its right arm moves on a straight
 * joint-space line from MoveIt's "tuck_right_arm" state to reaching
 * forward into the scene.  Only the right arm's links are checked:
 * the rest of the robot stands still and the camera does not see it.
 * The frame holds no robot; the self-filter step puts the right arm into
 * it (demo_self_filter.h).
 */
#include "demo_real.h"

#include "demo_self_filter.h"
#include "demo_story.h"
#include "pcd_reader.h"
#include "shape_mesh.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#define FRAME_FILE "rgbd/frame_20121214T142255.814212_binary.pcd"
#define URDF_FILE "robots/pr2_description/urdf/robot.xml"
#define CAMERA_LINK "wide_stereo_optical_frame"
#define HEAD_TILT 0.82

static const char *const kArmJoints[7] = {"r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
                                          "r_elbow_flex_joint",   "r_forearm_roll_joint",  "r_wrist_flex_joint",
                                          "r_wrist_roll_joint"};
/* MoveIt's pr2.srdf "tuck_right_arm", then the arm stretched forward. */
static const double kTucked[7] = {-0.023593, 1.10728, -1.55669, -2.12441, -1.4175, -1.8417, 0.21436};
static const double kReach[7] = {-0.1, 0.1, 0.0, -0.35, 0.0, -0.4, 0.0};
/* The joints that stay still: the head tilted, the left arm (not checked)
 * in MoveIt's pr2.srdf "tuck_left_arm", out of the way. */
static const char *const kStillJoints[8] = {"head_tilt_joint",      "l_shoulder_pan_joint", "l_shoulder_lift_joint",
                                            "l_upper_arm_roll_joint", "l_elbow_flex_joint",  "l_forearm_roll_joint",
                                            "l_wrist_flex_joint",   "l_wrist_roll_joint"};
static const double kStillPositions[8] = {HEAD_TILT, 0.06024, 1.24853, 1.78907, -1.68339, -1.73434, -0.0962141, -0.0864407};

/* The arm in the camera's view for the self-filter step: stretched
 * forward, the forearm and gripper 10 to 20 cm above the table's height
 * (its top at about 0.5 m), the gripper short of its near edge, all in the
 * slice plane y = -0.19 m (pan and rolls 0).  At 5 cm no cell touching
 * the arm also holds a table point farther than the padding from it, so
 * the filtered map is collision-free at both of the demo's resolutions. */
static const double kReachingOut[7] = {0.0, 0.2, 0.0, -0.15, 0.0, -0.2, 0.0};
/* The self-filter's margin: the Kinect-class sensor's depth noise at
 * about a metre is a centimetre or two, and the PR2's meshes are a
 * little smaller than its arm; 2 cm takes the arm's own points and keeps
 * the table beneath it. */
#define ROBOT_PADDING 0.02

/* The right arm: shoulder to gripper (not r_torso_lift_side_plate_link). */
static int is_arm_link(const char *name) {
    static const char *const prefixes[6] = {"r_shoulder", "r_upper_arm", "r_elbow", "r_forearm", "r_wrist", "r_gripper"};
    int i;
    for (i = 0; i < 6; ++i)
        if (strncmp(name, prefixes[i], strlen(prefixes[i])) == 0) return 1;
    return 0;
}

static int is_body_link(const char *name) { return !is_arm_link(name); }

static int require_file(const char *path) {
    struct stat info;
    if (stat(path, &info) == 0) return 0;
    fprintf(stderr, "opx-demo --real: %s not found; set OPX_DATA_DIR (or --data) to the shared data folder\n", path);
    return -1;
}

static int load_pr2(const char *data_dir, opx_linkset **out) {
    char urdf[4096], package[4200];
    const char *dirs[1] = {package};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    snprintf(urdf, sizeof urdf, "%s/%s", data_dir, URDF_FILE);
    snprintf(package, sizeof package, "moveit_resources_pr2_description=%s/robots/pr2_description", data_dir);
    if (require_file(urdf) != 0) return -1;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    if (opx_linkset_load_urdf_file(urdf, &options, out) != OPX_OK) {
        fprintf(stderr, "opx-demo --real: %s\n", opx_last_error());
        return -1;
    }
    return 0;
}

/* Tilts the head, tucks the left arm, reads the camera's pose, and leaves
 * only the right arm's links on. */
static int place_camera_and_links(demo_story *s) {
    uint32_t camera, links = 0, l;
    if (opx_linkset_set_named_joint_positions(s->robot, kStillJoints, kStillPositions, 8, &s->base_pose) != OPX_OK ||
        opx_linkset_find_link(s->robot, CAMERA_LINK, &camera) != OPX_OK ||
        opx_linkset_get_pose(s->robot, camera, &s->sensor_pose) != OPX_OK ||
        opx_linkset_get_link_count(s->robot, &links) != OPX_OK) {
        fprintf(stderr, "opx-demo --real: %s\n", opx_last_error());
        return -1;
    }
    for (l = 0; l < links; ++l) {
        const char *name = "";
        opx_linkset_get_link_name(s->robot, l, &name);
        opx_linkset_set_link_enabled(s->robot, l, is_arm_link(name));
    }
    return 0;
}

/* Side view through the right shoulder: x forward, z up. */
static void side_view(demo_story *s, int quick) {
    static const double top[3] = {0.0, -240.0 / 525.0, 1.0}, bottom[3] = {0.0, 240.0 / 525.0, 1.0};
    picture_view *v = &s->picture.view;
    memset(v, 0, sizeof *v);
    v->origin[1] = -0.188; /* the right shoulder's y */
    v->u[0] = 1.0;
    v->v[2] = 1.0;
    /* The robot and the camera's wedge of seen space, no more. */
    v->u_min = -0.5;
    v->u_max = 2.0;
    v->v_min = -0.05;
    v->v_max = 1.6;
    v->pixels_per_metre = quick ? 240.0 : 400.0;
    v->title = "OCTOPROX DEMO --REAL: PR2 RIGHT ARM, REAL RGB-D FRAME, SLICE Y = -0.19 M";
    v->u_name = "X";
    v->v_name = "Z";
    memcpy(s->picture.sensor, s->sensor_pose.position, sizeof s->picture.sensor);
    pose_rotate(s->sensor_pose.orientation, top, s->picture.fov_edges[0]);
    pose_rotate(s->sensor_pose.orientation, bottom, s->picture.fov_edges[1]);
    s->picture.fov_edge_count = 2;
}

/* The arm over the table, seen by the head camera: filtered out or not. */
static int self_filter(const demo_story *story, const pcd_cloud *cloud, int quick) {
    self_filter_scene f;
    picture_view *v = &f.view;
    memset(&f, 0, sizeof f);
    f.robot = story->robot;
    f.is_robot_link = is_arm_link;
    f.base_pose = story->base_pose;
    f.joint_names = kArmJoints;
    f.positions = kReachingOut;
    f.joint_count = 7;
    f.pose_label = "the PR2's right arm reaching out toward the table in its head camera's view";
    f.points = cloud->xyz;
    f.camera.pose = story->sensor_pose;
    f.camera.fx = f.camera.fy = 525.0;
    f.camera.cx = 320.0;
    f.camera.cy = 240.0;
    f.camera.width = cloud->width;
    f.camera.height = cloud->height;
    f.resolution = story->resolution;
    f.robot_padding = ROBOT_PADDING;
    *v = story->picture.view;
    v->u_min = 0.0;
    v->u_max = 1.3;
    v->v_min = 0.25;
    v->v_max = 1.45; /* room for the scale bar above the camera */
    v->pixels_per_metre = quick ? 320.0 : 500.0;
    memcpy(f.fov_edges, story->picture.fov_edges, sizeof f.fov_edges);
    f.robot_label = "PR2 RIGHT ARM AT CAPTURE TIME (OUTLINE)";
    f.out_dir = story->out_dir;
    f.picture_name = "opx-demo-real-self-filter.png";
    return demo_self_filter_run(&f);
}

int demo_real_run(const char *data_dir, const char *out_dir, int quick) {
    static char frame_path[4096], frame_label[300];
    char error[600];
    pcd_cloud cloud;
    demo_story s;
    size_t j;
    int status;
    memset(&s, 0, sizeof s);
    snprintf(frame_path, sizeof frame_path, "%s/%s", data_dir, FRAME_FILE);
    if (require_file(frame_path) != 0 || load_pr2(data_dir, &s.robot) != 0) return -1;
    if (pcd_read_file(frame_path, &cloud, error, sizeof error) != 0) {
        fprintf(stderr, "opx-demo --real: %s\n", error);
        opx_linkset_destroy(s.robot);
        return -1;
    }
    s.base_pose = (opx_pose)OPX_POSE_IDENTITY;
    status = place_camera_and_links(&s);
    snprintf(frame_label, sizeof frame_label, "real %ux%u RGB-D frame (%s), %zu points with a return, seen from the "
             "PR2's head camera (%s, head tilted %.1f rad)", cloud.width, cloud.height, FRAME_FILE, cloud.finite_count,
             CAMERA_LINK, HEAD_TILT);
    s.frame_label = frame_label;
    s.points = cloud.xyz;
    s.point_count = cloud.count;
    s.resolution = quick ? 0.05 : 0.02;
    s.robot_label = "PR2 from the shared URDF (95 links, STL meshes); only the right arm (shoulder to gripper) is checked";
    s.joint_count = 7;
    for (j = 0; j < 7; ++j) {
        s.joint_names[j] = kArmJoints[j];
        s.start[j] = kTucked[j];
        s.goal[j] = kReach[j];
    }
    s.waypoint_count = quick ? 11 : 41;
    s.is_body_link = is_body_link;
    s.tool_link = "r_gripper_tool_frame";
    s.picture.tool_label = "GRIPPER";
    s.picture.body_label = "PR2 BODY (STILL, NOT CHECKED)";
    side_view(&s, quick);
    s.out_dir = out_dir;
    s.picture_name = "opx-demo-real.png";
    s.map_name = "opx-demo-real.bt";
    if (status == 0) {
        printf("OctoProx %s demo --real: the PR2 reaches into a real RGB-D frame\n\n", opx_version());
        status = demo_story_run(&s);
    }
    if (status == 0) status = self_filter(&s, &cloud, quick);
    pcd_free(&cloud);
    opx_linkset_destroy(s.robot);
    return status;
}
