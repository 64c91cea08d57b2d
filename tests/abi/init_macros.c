/* Uses every OPX_*_INIT macro, compiled as C99 and as C++11 with -Wextra
 * -Werror: a macro missing a field (-Wmissing-field-initializers) or not
 * valid C++ (narrowing, designated initialisers) fails the build. */
#include <octoprox/octoprox.h>

int opx_init_macros_compile(void);

int opx_init_macros_compile(void) {
    const opx_pose pose = OPX_POSE_IDENTITY;
    const opx_octree_options octree_options = OPX_OCTREE_OPTIONS_INIT;
    const opx_insert_options insert_options = OPX_INSERT_OPTIONS_INIT;
    const opx_insert_report report = OPX_INSERT_REPORT_INIT;
    const opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    const opx_camera_intrinsics intrinsics = OPX_CAMERA_INTRINSICS_INIT;
    const opx_cell_info cell = OPX_CELL_INFO_INIT;
    const opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    const opx_shape shape = OPX_SHAPE_INIT;
    const opx_query_options query_options = OPX_QUERY_OPTIONS_INIT;
    const opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    const opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    const opx_contact contact = OPX_CONTACT_INIT;
    const opx_urdf_options urdf_options = OPX_URDF_OPTIONS_INIT;
    const opx_joint_info joint_info = OPX_JOINT_INFO_INIT;
    const opx_self_collision_request self_request = OPX_SELF_COLLISION_REQUEST_INIT;
    const opx_self_collision_result self_result = OPX_SELF_COLLISION_RESULT_INIT;
    const opx_self_contact self_contact = OPX_SELF_CONTACT_INIT;
    const opx_self_distance_request self_distance_request = OPX_SELF_DISTANCE_REQUEST_INIT;
    const opx_self_distance_result self_distance_result = OPX_SELF_DISTANCE_RESULT_INIT;
    const opx_pair_sampling_options pair_sampling = OPX_PAIR_SAMPLING_OPTIONS_INIT;
    const opx_pair_sampling_result pair_sampling_result = OPX_PAIR_SAMPLING_RESULT_INIT;
    const opx_batch_request batch_request = OPX_BATCH_REQUEST_INIT;
    const opx_motion_request motion_request = OPX_MOTION_REQUEST_INIT;
    const opx_motion_result motion_result = OPX_MOTION_RESULT_INIT;
    const opx_point_cloud_info cloud_info = OPX_POINT_CLOUD_INFO_INIT;
    const opx_sphere_request sphere_request = OPX_SPHERE_REQUEST_INIT;
    const opx_sphere_distance_request sphere_distance = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    const opx_trajectory_cost_request trajectory_cost = OPX_TRAJECTORY_COST_REQUEST_INIT;
    return pose.orientation[3] == 1.0 && octree_options.struct_size == sizeof octree_options &&
           insert_options.struct_size == sizeof insert_options &&
           report.struct_size == sizeof report && image.struct_size == sizeof image &&
           intrinsics.struct_size == sizeof intrinsics && cell.struct_size == sizeof cell &&
           stats.struct_size == sizeof stats && shape.struct_size == sizeof shape &&
           query_options.struct_size == sizeof query_options &&
           request.struct_size == sizeof request && result.struct_size == sizeof result &&
           contact.struct_size == sizeof contact &&
           urdf_options.struct_size == sizeof urdf_options &&
           joint_info.struct_size == sizeof joint_info &&
           self_request.struct_size == sizeof self_request &&
           self_result.struct_size == sizeof self_result &&
           self_contact.struct_size == sizeof self_contact &&
           self_distance_request.struct_size == sizeof self_distance_request &&
           self_distance_result.struct_size == sizeof self_distance_result &&
           pair_sampling.struct_size == sizeof pair_sampling &&
           sphere_request.struct_size == sizeof sphere_request &&
           sphere_distance.struct_size == sizeof sphere_distance &&
           trajectory_cost.struct_size == sizeof trajectory_cost &&
           pair_sampling_result.struct_size == sizeof pair_sampling_result &&
           batch_request.struct_size == sizeof batch_request &&
           motion_request.struct_size == sizeof motion_request &&
           motion_result.struct_size == sizeof motion_result &&
           cloud_info.struct_size == sizeof cloud_info;
}
