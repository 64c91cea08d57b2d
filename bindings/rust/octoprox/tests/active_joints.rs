//! Active joints and every pose at once (as
//! bindings/python/tests/test_active_joints.py): on a generated arm with a
//! mimic finger and a fixed tool, FK from active vectors equals FK from
//! the model-order vectors holding them, bit for bit; poses() equals pose()
//! link by link; batch queries answer active rows as model rows; bad input
//! is an error naming the argument.  The PR2 of the shared data too, when
//! present.
mod common;
use common::*;
use octoprox::{pose_at, BasePoses, BatchRequest, ErrorKind, JointOrder, LinkSet, MotionRequest, Pose,
               Query, QueryOptions, UrdfOptions};
use std::fmt::Write;
use std::path::PathBuf;

const ACTIVE: usize = 8; // j1..j7, finger_l
const JOINTS: usize = 10; // and finger_r (mimic), tool (fixed)

fn gripper_arm() -> LinkSet {
    let mut xml = arm_urdf_links(7);
    for name in ["finger_l", "finger_r", "tool"] {
        write!(xml, "<link name=\"{name}\"><collision><geometry><box size=\"0.02 0.02 0.06\"/>\
                     </geometry></collision></link>").unwrap();
    }
    let limit = "<limit lower=\"0\" upper=\"0.04\" effort=\"1\" velocity=\"1\"/>";
    write!(xml, "<joint name=\"finger_l\" type=\"prismatic\"><parent link=\"l7\"/><child link=\"finger_l\"/>\
                 <origin xyz=\"0 0 0.27\"/><axis xyz=\"0 1 0\"/>{limit}</joint>\
                 <joint name=\"finger_r\" type=\"prismatic\"><parent link=\"l7\"/><child link=\"finger_r\"/>\
                 <origin xyz=\"0 0 0.27\"/><axis xyz=\"0 -1 0\"/>{limit}<mimic joint=\"finger_l\"/></joint>\
                 <joint name=\"tool\" type=\"fixed\"><parent link=\"l7\"/><child link=\"tool\"/>\
                 <origin xyz=\"0 0 0.33\"/></joint></robot>").unwrap();
    LinkSet::from_urdf_string(&xml, &UrdfOptions::default()).unwrap()
}

/// `rows` active vectors of the arm, packed.
fn random_active(rows: usize, seed: u64) -> Vec<f64> {
    let mut rng = Lcg(seed);
    let mut values = Vec::with_capacity(rows * ACTIVE);
    for _ in 0..rows {
        values.extend((0..7).map(|_| rng.uniform(-3.1, 3.1)));
        values.push(rng.uniform(0.0, 0.04));
    }
    values
}

/// The model-order rows holding `active` rows, other joints at `filler`.
fn in_model_order(robot: &LinkSet, active: &[f64], filler: f64) -> Vec<f64> {
    let indices = robot.active_joints().unwrap();
    let joints = robot.joint_count().unwrap() as usize;
    let mut model = Vec::new();
    for row in active.chunks(indices.len()) {
        let mut full = vec![filler; joints];
        for (value, &j) in row.iter().zip(&indices) {
            full[j as usize] = *value;
        }
        model.extend(full);
    }
    model
}

fn turned_base() -> Pose {
    let half = std::f64::consts::FRAC_PI_8; // half the angle of an eighth of a turn about z
    Pose { position: [0.3, -0.1, 0.2], orientation: [0.0, 0.0, half.sin(), half.cos()] }
}

#[test]
fn the_active_joints_are_the_moving_joints_that_mimic_none() {
    let arm = gripper_arm();
    assert_eq!((arm.joint_count().unwrap(), arm.active_joint_count().unwrap()), (JOINTS as u32, ACTIVE as u32));
    assert_eq!(arm.active_joints().unwrap(), (0..ACTIVE as u32).collect::<Vec<_>>());
    let names = arm.active_joint_names().unwrap();
    assert_eq!((names[0].as_str(), names[7].as_str()), ("j1", "finger_l"));
    assert_eq!(LinkSet::new().unwrap().active_joint_count().unwrap(), 0);
    assert!(LinkSet::new().unwrap().active_joints().unwrap().is_empty());
}

#[test]
fn active_named_and_model_vectors_pose_alike() {
    let (mut by_active, mut by_model, mut by_name) = (gripper_arm(), gripper_arm(), gripper_arm());
    let names = by_name.active_joint_names().unwrap();
    let base = turned_base();
    let rows = random_active(10, 3);
    for q in rows.chunks(ACTIVE) {
        by_active.set_active_joint_positions(q, Some(&base)).unwrap();
        by_model.set_joint_positions(&in_model_order(&by_model, q, 0.5), Some(&base)).unwrap();
        let named: Vec<(&str, f64)> = names.iter().map(|n| n.as_str()).zip(q.iter().copied()).collect();
        by_name.set_named_joint_positions(&named, Some(&base)).unwrap();
        assert_eq!(by_active.poses().unwrap(), by_model.poses().unwrap());
        assert_eq!(by_name.poses().unwrap(), by_model.poses().unwrap());
        assert_eq!(by_active.active_joint_positions().unwrap(), q);
        assert_eq!(by_active.joint_positions().unwrap()[8], q[7]); // the mimic finger
    }
}

#[test]
fn poses_equal_pose_link_by_link() {
    let mut arm = gripper_arm();
    arm.set_active_joint_positions(&random_active(1, 5), Some(&pose_at(1.0, 2.0, 0.0))).unwrap();
    let poses = arm.poses().unwrap();
    assert_eq!(poses.len(), arm.link_count().unwrap() as usize);
    for (i, pose) in poses.iter().enumerate() {
        assert_eq!(*pose, arm.pose(i as u32).unwrap());
    }
    assert!(LinkSet::new().unwrap().poses().unwrap().is_empty());
}

#[test]
fn bad_active_vectors_are_errors_that_change_nothing() {
    let mut arm = gripper_arm();
    arm.set_active_joint_positions(&[0.2; ACTIVE], None).unwrap();
    let before = arm.poses().unwrap();
    let error = arm.set_active_joint_positions(&[0.0; JOINTS], None).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("opx_linkset_set_active_joint_positions"), "{}", error.message());
    assert!(error.message().contains("count 10"), "{}", error.message());
    let mut bad = [0.0; ACTIVE];
    bad[3] = f64::NAN;
    let error = arm.set_active_joint_positions(&bad, None).unwrap_err();
    assert!(error.message().contains("positions[3]"), "{}", error.message());
    assert_eq!(arm.poses().unwrap(), before);
    let error = LinkSet::new().unwrap().set_active_joint_positions(&[], None).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Unsupported);
}

#[test]
fn batches_of_active_rows_answer_as_model_rows() {
    let (arm, tree) = (gripper_arm(), scatter_map(7));
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let active = random_active(60, 11);
    let model = in_model_order(&arm, &active, 7.0);
    let by_model = BatchRequest { compute_distance: true, ..Default::default() };
    let by_active = BatchRequest { joint_order: JointOrder::Active, ..by_model };
    let m = query.check_configurations(&tree, &arm, &model, BasePoses::Origin, &by_model).unwrap();
    let a = query.check_configurations(&tree, &arm, &active, BasePoses::Origin, &by_active).unwrap();
    assert_eq!(a, m);
    let hits = m.collided.iter().filter(|&&c| c).count();
    assert!(hits > 0 && hits < m.collided.len());
    // A flat slice of active rows under the default order is read as model rows.
    let error = query.check_configurations(&tree, &arm, &active[..ACTIVE * 3], BasePoses::Origin, &by_model);
    assert_eq!(error.unwrap_err().kind(), ErrorKind::InvalidArgument);

    let motion = MotionRequest { resolution: 0.05, ..Default::default() };
    let active_motion = MotionRequest { joint_order: JointOrder::Active, ..motion };
    let (m_starts, m_goals) = (&model[..30 * JOINTS], &model[30 * JOINTS..]);
    let (a_starts, a_goals) = (&active[..30 * ACTIVE], &active[30 * ACTIVE..]);
    let m = query.check_motions(&tree, &arm, m_starts, m_goals, BasePoses::Origin, &motion).unwrap();
    let a = query.check_motions(&tree, &arm, a_starts, a_goals, BasePoses::Origin, &active_motion).unwrap();
    assert_eq!(a, m);
    // One motion tells its order by its length.
    let one = query.check_motion(&tree, &arm, &a_starts[..ACTIVE], &a_goals[..ACTIVE], None, &motion).unwrap();
    let full = query.check_motion(&tree, &arm, &m_starts[..JOINTS], &m_goals[..JOINTS], None, &motion).unwrap();
    assert_eq!(one, full);
}

fn pr2_paths() -> Option<(PathBuf, PathBuf, String)> {
    let data = std::env::var("OPX_DATA_DIR").ok().filter(|d| !d.is_empty()).map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../../shared/data"));
    let robot = data.join("robots/pr2_description");
    let urdf = robot.join("urdf/robot.xml");
    if !urdf.exists() {
        common::skip_without_data("the PR2 of the shared data is absent (set OPX_DATA_DIR)");
        return None;
    }
    let package = format!("moveit_resources_pr2_description={}", robot.display());
    Some((urdf, robot.join("srdf/pr2.srdf"), package))
}

#[test]
fn the_pr2_poses_alike_from_active_and_model_vectors() {
    let (urdf, srdf, package) = match pr2_paths() {
        Some(paths) => paths,
        None => return,
    };
    let options = UrdfOptions { package_dirs: vec![package], srdf_path: Some(srdf), ..Default::default() };
    let mut by_active = LinkSet::from_urdf_file(&urdf, &options).unwrap();
    let mut by_model = LinkSet::from_urdf_file(&urdf, &options).unwrap();
    let indices = by_active.active_joints().unwrap();
    assert!(indices.len() > 30 && indices.len() < by_active.joint_count().unwrap() as usize);
    let mut rng = Lcg(21);
    for _ in 0..5 {
        let q: Vec<f64> = indices
            .iter()
            .map(|&j| match by_active.joint_info(j).unwrap().limits {
                Some((lo, hi)) if lo.is_finite() && hi.is_finite() => rng.uniform(lo, hi),
                _ => rng.uniform(-3.1, 3.1),
            })
            .collect();
        by_active.set_active_joint_positions(&q, None).unwrap();
        by_model.set_joint_positions(&in_model_order(&by_model, &q, -0.25), None).unwrap();
        assert_eq!(by_active.poses().unwrap(), by_model.poses().unwrap());
    }
}
