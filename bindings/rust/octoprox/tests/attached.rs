//! Objects attached to links: a box grasped between two fingers collides
//! with them unless they are touch links (self-collision and
//! self-distance name the object); the getters, detaching and cloning; a
//! world object attached where it stands; an attached object against the
//! octree and world objects, and world objects on paths, batches and
//! motions.
mod common;
use common::*;
use octoprox::{pose_at, BasePoses, BatchRequest, CollisionRequest, DistanceRequest, ErrorKind, LinkSet,
               MotionRequest, PathRequest, Query, QueryOptions, SelfCollisionRequest, SelfDistanceRequest,
               Shape, ShapeKind, UrdfOptions, World};

const HAND: u32 = 0;
const FINGER_L: u32 = 1;
const FINGER_R: u32 = 2;
const FINGERS: [&str; 2] = ["finger_l", "finger_r"];

fn new_query() -> Query {
    Query::new(&QueryOptions::default()).unwrap()
}

/// A hand (a 2 cm ball at its origin) and two fingers, boxes 1 cm thick
/// centred 0.3 m ahead of it at y = +-0.025 (their inner faces 4 cm
/// apart), the hand at the map origin.
fn hand() -> LinkSet {
    let mut robot = LinkSet::new().unwrap();
    let hand = robot.add_link("hand").unwrap();
    robot.add_shape(hand, &Shape::sphere(0.02)).unwrap();
    for (name, y) in [("finger_l", 0.025), ("finger_r", -0.025)] {
        let finger = robot.add_link(name).unwrap();
        robot.add_shape(finger, &Shape::cuboid([0.02, 0.01, 0.06]).at(pose_at(0.0, y, 0.3))).unwrap();
    }
    robot
}

/// A box 4.2 cm wide between the fingers: 1 mm into each.
fn grasp_box(robot: &mut LinkSet, touch_links: &[&str]) -> u32 {
    let part = [Shape::cuboid([0.02, 0.042, 0.03])];
    robot.attach_object(HAND, "part", &part, &pose_at(0.0, 0.0, 0.3), touch_links).unwrap()
}

fn self_contacts(query: &mut Query, robot: &LinkSet) -> Vec<octoprox::SelfContact> {
    let all = SelfCollisionRequest { max_contacts: u32::MAX, ..Default::default() };
    query.self_collide(robot, &all).unwrap();
    query.self_contacts().unwrap()
}

#[test]
fn a_grasped_box_touches_its_fingers_only_when_they_are_not_touch_links() {
    let mut robot = hand();
    let mut query = new_query();
    assert!(self_contacts(&mut query, &robot).is_empty());

    let part = grasp_box(&mut robot, &[]);
    let contacts = self_contacts(&mut query, &robot);
    assert_eq!(contacts.len(), 2);
    for contact in &contacts {
        assert_eq!((contact.link_a, contact.attached_a, contact.shape_a), (HAND, Some(part), 0));
        assert!(contact.link_b == FINGER_L || contact.link_b == FINGER_R);
        assert_eq!(contact.attached_b, None);
    }
    let signed = SelfDistanceRequest { signed_distance: true, ..Default::default() };
    let nearest = query.self_distance(&robot, &signed).unwrap();
    assert!((nearest.distance + 0.001).abs() < 1e-9, "{}", nearest.distance);
    assert_eq!((nearest.attached_a, nearest.attached_b), (Some(part), None));

    robot.detach(part).unwrap();
    let part = grasp_box(&mut robot, &FINGERS);
    assert!(self_contacts(&mut query, &robot).is_empty());
    assert_eq!(robot.attached_touch_links(part).unwrap(), [FINGER_L, FINGER_R]);

    robot.detach(part).unwrap();
    grasp_box(&mut robot, &FINGERS[..1]);
    let contacts = self_contacts(&mut query, &robot);
    assert_eq!(contacts.len(), 1);
    assert_eq!(contacts[0].link_b, FINGER_R);
}

#[test]
fn getters_detaching_and_cloning() {
    let mut robot = hand();
    assert_eq!(robot.attached_count().unwrap(), 0);
    let tetra = [[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.0, 0.1, 0.0], [0.0, 0.0, 0.1]];
    let shapes = [Shape::sphere(0.05).at(pose_at(0.0, 0.0, 0.1)), Shape::new(ShapeKind::Convex { vertices: &tetra })];
    let tool = robot.attach_object(FINGER_L, "tool", &shapes, &pose_at(0.0, 0.0, 0.5), &["finger_r"]).unwrap();
    let part = grasp_box(&mut robot, &FINGERS);
    assert_eq!((tool, part, robot.attached_count().unwrap()), (0, 1, 2));
    assert_eq!(robot.attached_names().unwrap(), ["tool", "part"]);
    assert_eq!(robot.find_attached("part").unwrap(), part);
    assert_eq!(robot.attached_link(tool).unwrap(), FINGER_L);
    assert_eq!(robot.attached_pose(tool).unwrap().position, [0.0, 0.0, 0.5]);
    assert_eq!(robot.attached_shape_count(tool).unwrap(), 2);
    assert_eq!(robot.attached_shape(tool, 0).unwrap(), shapes[0]);
    match robot.attached_shape(tool, 1).unwrap().kind {
        ShapeKind::Convex { vertices } => assert_eq!(vertices.len(), 4),
        other => panic!("the tool's second shape is a {other:?}"),
    }
    assert_eq!(robot.attached_touch_links(tool).unwrap(), [FINGER_R]);
    assert_eq!(robot.attached_touch_links(part).unwrap(), [FINGER_L, FINGER_R]);

    let copy = robot.try_clone().unwrap();
    robot.detach(tool).unwrap(); // the part moves down to 0
    assert_eq!((robot.attached_count().unwrap(), robot.find_attached("part").unwrap()), (1, 0));
    assert_eq!(copy.attached_names().unwrap(), ["tool", "part"]);
}

#[test]
fn bad_input_is_an_invalid_argument_that_changes_nothing() {
    let mut robot = hand();
    let ball = [Shape::sphere(0.01)];
    let here = pose_at(0.0, 0.0, 0.0);
    let invalid = |error: octoprox::Error| assert_eq!(error.kind(), ErrorKind::InvalidArgument, "{error}");
    invalid(robot.attach_object(7, "x", &ball, &here, &[]).unwrap_err());
    invalid(robot.attach_object(HAND, "x", &[], &here, &[]).unwrap_err());
    invalid(robot.attach_object(HAND, "x", &ball, &here, &["no_such_link"]).unwrap_err());
    invalid(robot.attach_object(HAND, "x\0y", &ball, &here, &[]).unwrap_err());
    let nan = octoprox::Pose { position: [f64::NAN, 0.0, 0.0], ..here };
    invalid(robot.attach_object(HAND, "x", &ball, &nan, &[]).unwrap_err());
    assert_eq!(robot.attached_count().unwrap(), 0);
    invalid(robot.detach(0).unwrap_err());
    invalid(robot.attached_name(0).unwrap_err());
    invalid(robot.attached_touch_links(0).unwrap_err());
    invalid(robot.find_attached("x").unwrap_err());
    let mut world = World::new().unwrap();
    let empty = world.add_object("empty", &here).unwrap();
    invalid(robot.attach_world_object(HAND, &world, empty, &[]).unwrap_err());
    invalid(robot.attach_world_object(HAND, &world, 9, &[]).unwrap_err());
}

#[test]
fn a_world_object_attached_where_it_stands() {
    let mut robot = hand();
    robot.set_poses(&[pose_at(1.0, 0.0, 0.0); 3]).unwrap();
    let mut world = World::new().unwrap();
    let crate_ = world.add_box("crate", [0.2, 0.2, 0.2], &pose_at(1.0, 0.0, 0.5)).unwrap();
    let held = robot.attach_world_object(HAND, &world, crate_, &FINGERS).unwrap();
    assert_eq!(robot.attached_name(held).unwrap(), "crate");
    let pose = robot.attached_pose(held).unwrap().position;
    assert!((pose[2] - 0.5).abs() < 1e-12 && pose[0].abs() < 1e-12, "{pose:?}");
    assert_eq!(world.len(), 1); // the world does not change

    // The copy touches the original until the world's is disabled.
    let mut query = new_query();
    let request = CollisionRequest { max_contacts: 8, ..Default::default() };
    assert!(query.collide_with_world(None, &world, &robot, &request).unwrap().collided);
    let contact = query.contacts().unwrap()[0];
    assert_eq!((contact.link, contact.attached, contact.object), (HAND, Some(held), Some(crate_)));
    world.set_enabled(crate_, false).unwrap();
    assert!(!query.collide_with_world(None, &world, &robot, &request).unwrap().collided);
}

#[test]
fn an_attached_object_meets_the_octree_as_its_link() {
    // The one-cell map [0, 0.25]^3; the hand 1 m above it holds a ball
    // 0.8 m below the hand: 0.05 m above the cell.
    let map = one_cell_map();
    let mut robot = hand();
    robot.set_poses(&[pose_at(C0, C0, 1.0); 3]).unwrap();
    let mut query = new_query();
    let before = query.distance(&map, &robot, &DistanceRequest::default()).unwrap();
    assert_eq!(before.attached, None);
    let ball = robot.attach_object(HAND, "ball", &[Shape::sphere(0.1)], &pose_at(0.0, 0.0, -0.6), &[]).unwrap();
    let near = query.distance(&map, &robot, &DistanceRequest::default()).unwrap();
    assert!((near.distance - 0.05).abs() < 1e-9, "{}", near.distance);
    assert_eq!((near.link, near.attached, near.shape), (HAND, Some(ball), 0));
    robot.set_poses(&[pose_at(C0, C0, 0.9); 3]).unwrap(); // moves with its link
    assert!(query.collide(&map, &robot, &Default::default()).unwrap().collided);
    assert_eq!(query.contacts().unwrap()[0].attached, Some(ball));
}

/// A 1 m arm turning about z at the origin, its tip a 5 cm sphere at x = 1.
fn turning_arm() -> LinkSet {
    let urdf = r#"<robot name="arm">
      <link name="base"/>
      <link name="arm"><collision><origin xyz="1 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
      <joint name="turn" type="continuous"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/></joint>
    </robot>"#;
    LinkSet::from_urdf_string(urdf, &UrdfOptions::default()).unwrap()
}

#[test]
fn world_objects_on_paths_batches_and_motions() {
    let mut world = World::new().unwrap();
    world.add_sphere("post", 0.05, &pose_at(0.0, 1.0, 0.0)).unwrap(); // at +y, a quarter turn away
    let mut query = new_query();

    let ball = sphere_at(0.05, 1.0, 0.0, 0.0);
    let waypoints: Vec<_> = [0.0, 0.5, 1.0].iter().map(|&y| pose_at(1.0 - y, y, 0.0)).collect();
    let request = PathRequest { compute_distance: true, ..Default::default() };
    let path = query.path_with_world(None, &world, &ball, &waypoints, &request).unwrap();
    assert_eq!(path.first_colliding_waypoint, Some(2));
    let with_map = query.path_with_world(Some(&one_cell_map()), &world, &ball, &waypoints, &request).unwrap();
    assert!(with_map.collided);

    let arm = turning_arm();
    let quarter = std::f64::consts::FRAC_PI_2;
    let rows = [0.0, quarter, 2.0 * quarter];
    let batch = BatchRequest { compute_distance: true, max_threads: 2, ..Default::default() };
    let answers = query.check_configurations_with_world(None, &world, &arm, &rows, BasePoses::Origin, &batch)
        .unwrap();
    assert_eq!(answers.collided, [false, true, false]);
    assert_eq!(answers.distances[1], 0.0);

    let motion = MotionRequest::default();
    let one = query.check_motion_with_world(None, &world, &arm, &[0.0], &[2.0 * quarter], None, &motion)
        .unwrap();
    assert!(one.collided);
    let many = query.check_motions_with_world(None, &world, &arm, &[0.0, 0.0], &[2.0 * quarter, -quarter],
                                              BasePoses::Origin, &motion)
        .unwrap();
    assert_eq!(many.collided, [true, false]);
    assert!(many.first_fractions[0].is_some() && many.first_fractions[1].is_none());
}
