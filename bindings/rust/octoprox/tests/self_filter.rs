//! Self-filtering at ingest (`InsertOptions::robot`), as the C tests
//! (tests/c/test_self_filter.c) and the Python ones: a ball in front of
//! the sensor sorts points into robot, shadowed and kept ones; the robot's
//! volume is cleared when asked; a URDF robot filters too; depth images
//! are filtered; bad options are refused and name the field.
mod common;
use common::*;
use octoprox::{camera_intrinsics, pose_at, CellClass, DepthImage, ErrorKind, InsertOptions,
               LinkSet, Octree, UrdfOptions};

/// Robot, shadowed and kept: on the ball's near side, behind it, elsewhere.
const FRAME: [[f64; 3]; 3] = [[1.81, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, 1.0, 0.0]];

/// A ball of radius 0.2 at (2, 0, 0), map frame; the sensor at the origin.
fn ball() -> LinkSet {
    sphere_at(0.2, 2.0, 0.0, 0.0)
}

fn class_at(tree: &Octree, x: f64, y: f64, z: f64) -> CellClass {
    tree.classify([x, y, z]).unwrap().cell_class
}

#[test]
fn sorts_points_into_robot_shadowed_and_kept() {
    let robot = ball();
    let mut tree = new_tree(0.05);
    let options = InsertOptions { robot: Some(&robot), ..Default::default() };
    let report = tree.insert_points(&FRAME, &options).unwrap();
    assert_eq!((report.points_used, report.points_on_robot, report.points_shadowed), (1, 1, 1));
    assert_eq!((report.cells_hit, report.cells_cleared), (1, 0));
    assert_eq!(class_at(&tree, 1.0, 1.0, 0.0), CellClass::Occupied);
    assert_eq!(class_at(&tree, 1.81, 0.0, 0.0), CellClass::Unknown);
    assert_eq!(class_at(&tree, 3.0, 0.0, 0.0), CellClass::Unknown);
    // The rays still carve up to the ball.
    assert_eq!(class_at(&tree, 1.0, 0.0, 0.0), CellClass::Free);
}

#[test]
fn robot_padding_widens_the_band() {
    let robot = ball();
    let near = [[1.7, 0.0, 0.0]]; // 0.1 m in front of the ball
    for (padding, on_robot) in [(0.0, 0), (0.15, 1)] {
        let mut tree = new_tree(0.05);
        let options = InsertOptions { robot: Some(&robot), robot_padding: padding, ..Default::default() };
        assert_eq!(tree.insert_points(&near, &options).unwrap().points_on_robot, on_robot);
    }
}

#[test]
fn without_a_robot_every_point_counts() {
    let mut tree = new_tree(0.05);
    let report = tree.insert_points(&FRAME, &InsertOptions::default()).unwrap();
    assert_eq!(report.points_used, 3);
    assert_eq!(report.points_on_robot + report.points_shadowed + report.cells_cleared, 0);
}

#[test]
fn clear_robot_volume_clears_a_ghost() {
    for clear in [false, true] {
        let mut tree = new_tree(0.05);
        tree.insert_points(&[[2.0, 0.0, 0.0]], &InsertOptions::default()).unwrap();
        assert_eq!(class_at(&tree, 2.0, 0.0, 0.0), CellClass::Occupied);
        let robot = ball();
        let options = InsertOptions { robot: Some(&robot), clear_robot_volume: clear, ..Default::default() };
        let report = tree.insert_points(&[[0.0, 3.0, 0.0]], &options).unwrap();
        let expected = if clear { CellClass::Free } else { CellClass::Occupied };
        assert_eq!((report.cells_cleared > 0, class_at(&tree, 2.0, 0.0, 0.0)), (clear, expected));
    }
}

#[test]
fn a_urdf_robot_filters_at_its_joint_positions() {
    // A ball on a prismatic joint along x: at 1 m it stands at (2, 0, 0).
    let urdf = r#"<robot name="slider">
      <link name="base"/>
      <link name="ball"><collision><geometry><sphere radius="0.2"/></geometry></collision></link>
      <joint name="slide" type="prismatic"><parent link="base"/><child link="ball"/>
        <origin xyz="1 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="2" velocity="1" effort="1"/></joint>
    </robot>"#;
    let mut robot = LinkSet::from_urdf_string(urdf, &UrdfOptions::default()).unwrap();
    robot.set_joint_positions(&[1.0], None).unwrap();
    let mut tree = new_tree(0.05);
    let options = InsertOptions { robot: Some(&robot), ..Default::default() };
    let report = tree.insert_points(&FRAME, &options).unwrap();
    assert_eq!((report.points_used, report.points_on_robot, report.points_shadowed), (1, 1, 1));
}

#[test]
fn filters_depth_images() {
    let robot = sphere_at(0.3, 0.0, 0.0, 2.0); // 2 m along the optical axis
    let mut depth = [3000u16; 81]; // 3 m: behind the ball at the centre
    depth[4 * 9 + 4] = 1750; // on the ball's near side
    let image = DepthImage::from_u16(&depth, 9, 9, 0, 1000.0).unwrap();
    let camera = camera_intrinsics(10.0, 10.0, 4.0, 4.0);
    let mut tree = new_tree(0.05);
    let options = InsertOptions { robot: Some(&robot), ..Default::default() };
    let report = tree.insert_depth_image(&image, &camera, &options).unwrap();
    assert_eq!(report.points_on_robot, 1);
    assert!(report.points_shadowed > 0);
    assert_eq!(report.points_used + report.points_on_robot + report.points_shadowed, 81);
}

fn expect_invalid(options: &InsertOptions<'_>, field: &str) {
    let mut tree = one_cell_map();
    let before = tree.leaves(octoprox::CellClasses::ALL_KNOWN).unwrap();
    let error = tree.insert_points(&[[1.0, 0.0, 0.0]], options).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().starts_with("opx_octree_insert_points"), "{}", error);
    assert!(error.message().contains(field), "{}", error);
    assert_eq!(tree.leaves(octoprox::CellClasses::ALL_KNOWN).unwrap(), before);
}

#[test]
fn bad_robot_options_are_refused() {
    let robot = ball();
    for padding in [-0.01, f64::NAN, f64::INFINITY] {
        expect_invalid(&InsertOptions { robot: Some(&robot), robot_padding: padding, ..Default::default() },
                       "robot_padding");
    }
    expect_invalid(&InsertOptions { clear_robot_volume: true, ..Default::default() }, "clear_robot_volume");
    let mut unposed = LinkSet::new().unwrap();
    let link = unposed.add_link("body").unwrap();
    unposed.add_shape(link, &octoprox::Shape::sphere(0.2)).unwrap();
    expect_invalid(&InsertOptions { robot: Some(&unposed), ..Default::default() }, "options.robot");
}

#[test]
fn options_compare_the_robot_by_identity() {
    let (a, b) = (ball(), ball());
    let with = |robot| InsertOptions { robot: Some(robot), sensor_pose: pose_at(0.0, 0.0, 1.0), ..Default::default() };
    assert_eq!(with(&a), with(&a));
    assert_ne!(with(&a), with(&b));
    assert_ne!(with(&a), InsertOptions { robot: None, ..with(&a) });
}
