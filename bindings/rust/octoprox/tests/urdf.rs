//! Link sets from URDF: links, joints, FK, named positions, SRDF-less
//! options, errors, and a collision check at a pose set by FK.
mod common;
use common::*;
use octoprox::{pose_at, CollisionRequest, ErrorKind, JointType, LinkSet, Query, QueryOptions,
               UrdfOptions};
use std::f64::consts::FRAC_PI_2;

/// base --shoulder (revolute z, 0.2 up)--> arm --slide (prismatic x, 0.5
/// along the arm)--> finger.
const ARM: &str = r#"<robot name="arm">
  <link name="base"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0.25 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="finger"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" velocity="1" effort="10"/></joint>
  <joint name="slide" type="prismatic"><parent link="arm"/><child link="finger"/>
    <origin xyz="0.5 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.2" velocity="2" effort="5"/></joint>
</robot>"#;

fn arm() -> LinkSet {
    LinkSet::from_urdf_string(ARM, &UrdfOptions::default()).unwrap()
}

fn assert_position(links: &LinkSet, link: u32, expected: [f64; 3]) {
    let position = links.pose(link).unwrap().position;
    for axis in 0..3 {
        assert!((position[axis] - expected[axis]).abs() < 1e-12, "{:?}", position);
    }
}

#[test]
fn links_shapes_and_joints_come_from_the_urdf() {
    let links = arm();
    assert_eq!(links.link_count().unwrap(), 3);
    assert_eq!(links.link_name(2).unwrap(), "finger");
    assert_eq!(links.shape_count(0).unwrap(), 1);
    assert_eq!(links.joint_count().unwrap(), 2);
    let shoulder = links.joint_info(links.find_joint("shoulder").unwrap()).unwrap();
    assert_eq!((shoulder.name.as_str(), shoulder.joint_type), ("shoulder", JointType::Revolute));
    assert_eq!((shoulder.parent_link, shoulder.child_link), (Some(0), Some(1)));
    assert_eq!((shoulder.axis, shoulder.limits), ([0.0, 0.0, 1.0], Some((-1.5, 1.5))));
    assert_eq!(shoulder.origin.position, [0.0, 0.0, 0.2]);
    assert_eq!(shoulder.mimic, None);
    let slide = links.joint_info(1).unwrap();
    assert_eq!((slide.joint_type, slide.velocity, slide.effort), (JointType::Prismatic, 2.0, 5.0));
    assert!(links.disabled_pairs().unwrap().is_empty());
    assert_position(&links, 2, [0.5, 0.0, 0.2]); // every joint at 0
}

#[test]
fn forward_kinematics_and_named_positions() {
    let mut links = arm();
    links.set_joint_positions(&[FRAC_PI_2, 0.1], None).unwrap();
    assert_position(&links, 2, [0.0, 0.6, 0.2]);
    links.set_joint_positions(&[FRAC_PI_2, 0.1], Some(&pose_at(1.0, 0.0, 0.0))).unwrap();
    assert_position(&links, 2, [1.0, 0.6, 0.2]);
    links.set_named_joint_positions(&[("slide", 0.0)], None).unwrap();
    assert_position(&links, 2, [0.0, 0.5, 0.2]);
    let positions = links.joint_positions().unwrap();
    assert_eq!(positions, vec![FRAC_PI_2, 0.0]);
}

#[test]
fn a_check_after_fk() {
    // One occupied cell [0, 0.25]^3; the robot's base placed so that, at
    // every joint 0, the finger sits at the cell's centre.
    let tree = one_cell_map();
    let mut links = arm();
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let request = CollisionRequest { max_contacts: 10, ..Default::default() };
    links.set_joint_positions(&[0.0, 0.0], Some(&pose_at(2.0, 2.0, 0.0))).unwrap();
    assert!(!query.collide(&tree, &links, &request).unwrap().collided);
    links.set_joint_positions(&[0.0, 0.0], Some(&pose_at(-0.5 + C0, C0, -0.2 + C0))).unwrap();
    assert!(query.collide(&tree, &links, &request).unwrap().collided);
    let finger = links.find_link("finger").unwrap();
    assert!(query.contacts().unwrap().iter().any(|c| c.link == finger));
}

#[test]
fn urdf_errors() {
    let options = UrdfOptions::default();
    let error = LinkSet::from_urdf_file("/nonexistent/robot.urdf", &options).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Io);
    assert!(error.message().contains("/nonexistent/robot.urdf"), "{}", error);
    let error = LinkSet::from_urdf_string("<robot name=", &options).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Corrupt);
    let mut links = arm();
    let error = links.set_joint_positions(&[0.0], None).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    let error = links.set_named_joint_positions(&[("elbow", 1.0)], None).unwrap_err();
    assert!(error.message().contains("elbow"), "{}", error);
    assert!(links.find_joint("elbow").is_err());
    let mut by_hand = sphere_at(0.1, 0.0, 0.0, 0.0);
    assert_eq!(by_hand.joint_count().unwrap(), 0);
    let error = by_hand.set_joint_positions(&[], None).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Unsupported);
    let bad = UrdfOptions { package_dirs: vec!["a\0b".into()], ..Default::default() };
    assert!(LinkSet::from_urdf_string(ARM, &bad).is_err());
}
