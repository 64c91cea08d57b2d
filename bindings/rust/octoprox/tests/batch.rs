//! Many configurations and motions per call on a generated 7-joint arm
//! (as bindings/python/tests/test_batch.py): the answers equal single calls
//! for 1, 2 and 3 threads, motions equal a walk over their samples, bad
//! input is an error naming the argument.
mod common;
use common::*;
use octoprox::{pose_at, BasePoses, BatchRequest, CollisionRequest, DistanceRequest, ErrorKind,
               LinkSet, MotionRequest, ObstacleGeometry, Octree, Query, QueryOptions,
               UrdfOptions};

const JOINTS: usize = 7;

/// Links l0..l7, each a cylinder from 0.04 to 0.2 m along its z, joints
/// alternating z and y axes 0.24 m apart.
fn arm() -> LinkSet {
    let xml = arm_urdf_links(JOINTS) + "</robot>";
    LinkSet::from_urdf_string(&xml, &UrdfOptions::default()).unwrap()
}

fn rows(n: usize, seed: u64) -> Vec<f64> {
    let mut rng = Lcg(seed);
    (0..n * JOINTS).map(|_| rng.uniform(-3.1, 3.1)).collect()
}

fn new_query() -> Query {
    Query::new(&QueryOptions::default()).unwrap()
}

fn single(query: &mut Query, tree: &Octree, robot: &mut LinkSet, q: &[f64]) -> bool {
    robot.set_joint_positions(q, None).unwrap();
    let request = CollisionRequest { max_contacts: 0, ..Default::default() };
    query.collide(tree, robot, &request).unwrap().collided
}

#[test]
fn configurations_equal_single_calls_for_every_thread_count() {
    let (mut robot, tree, q) = (arm(), scatter_map(7), rows(120, 11));
    let mut reference = new_query();
    let expected: Vec<bool> = q.chunks(JOINTS).map(|row| single(&mut reference, &tree, &mut robot, row)).collect();
    assert!(expected.iter().any(|&c| c) && expected.iter().any(|&c| !c));
    for threads in 1..=3 {
        let request = BatchRequest { max_threads: threads, compute_distance: true, ..Default::default() };
        let answers = new_query().check_configurations(&tree, &robot, &q, BasePoses::Origin, &request).unwrap();
        assert_eq!(answers.collided, expected);
        for (row, distance) in q.chunks(JOINTS).zip(&answers.distances) {
            robot.set_joint_positions(row, None).unwrap();
            assert_eq!(*distance, reference.distance(&tree, &robot, &DistanceRequest::default()).unwrap().distance);
        }
    }
}

#[test]
fn base_poses_and_self_collision() {
    let (mut robot, tree, q) = (arm(), scatter_map(7), rows(40, 13));
    let bases: Vec<_> = (0..40).map(|i| pose_at(-0.3 + 0.015 * i as f64, 0.0, 0.0)).collect();
    let mut query = new_query();
    let answers = query.check_configurations(&tree, &robot, &q, BasePoses::PerRow(&bases),
                                             &BatchRequest::default()).unwrap();
    let mut reference = new_query();
    for (i, row) in q.chunks(JOINTS).enumerate() {
        robot.set_joint_positions(row, Some(&bases[i])).unwrap();
        let request = CollisionRequest { max_contacts: 0, ..Default::default() };
        assert_eq!(answers.collided[i], reference.collide(&tree, &robot, &request).unwrap().collided);
    }
    let shared = query.check_configurations(&tree, &robot, &q, BasePoses::Shared(bases[0]),
                                            &BatchRequest::default()).unwrap();
    assert_eq!(shared.collided.len(), 40);
    let with_self = BatchRequest { self_collision: true, max_threads: 2, ..Default::default() };
    let world = query.check_configurations(&tree, &robot, &q, BasePoses::Origin, &BatchRequest::default()).unwrap();
    let both = query.check_configurations(&tree, &robot, &q, BasePoses::Origin, &with_self).unwrap();
    assert!(world.collided.iter().zip(&both.collided).all(|(w, b)| !w || *b));
}

#[test]
fn motions_equal_a_walk_over_their_samples() {
    let (mut robot, tree, starts) = (arm(), scatter_map(7), rows(20, 3));
    let mut rng = Lcg(5);
    let goals: Vec<f64> = starts.iter().map(|v| v + rng.uniform(-0.4, 0.4)).collect();
    let request = MotionRequest { resolution: 0.05, max_threads: 2, ..Default::default() };
    let mut query = new_query();
    let batch = query.check_motions(&tree, &robot, &starts, &goals, BasePoses::Origin, &request).unwrap();
    let mut reference = new_query();
    for (m, (a, b)) in starts.chunks(JOINTS).zip(goals.chunks(JOINTS)).enumerate() {
        let result = query.check_motion(&tree, &robot, a, b, None, &request).unwrap();
        let n = result.steps;
        let first = (0..=n).find(|&i| {
            let q: Vec<f64> = if i == n { b.to_vec() } else {
                a.iter().zip(b).map(|(x, y)| x + (i as f64 / n as f64) * (y - x)).collect()
            };
            single(&mut reference, &tree, &mut robot, &q)
        });
        let fraction = first.map(|i| i as f64 / n as f64);
        assert_eq!(result.first_collision_fraction, fraction);
        assert_eq!((batch.collided[m], batch.first_fractions[m]), (first.is_some(), fraction));
    }
}

/// A certified check calls a motion free only when every configuration of
/// a walk at 1e-3 of it is free, and collides whenever a sampled check does.
#[test]
fn certified_motions_are_free_only_when_a_walk_is() {
    let (mut robot, tree, starts) = (arm(), scatter_map(7), rows(8, 3));
    let mut rng = Lcg(5);
    let goals: Vec<f64> = starts.iter().map(|v| v + rng.uniform(-0.4, 0.4)).collect();
    let certified = MotionRequest { certified: true, max_threads: 2, ..Default::default() };
    let sampled = MotionRequest { resolution: 0.05, ..Default::default() };
    let mut query = new_query();
    let batch = query.check_motions(&tree, &robot, &starts, &goals, BasePoses::Origin, &certified).unwrap();
    let mut reference = new_query();
    for (m, (a, b)) in starts.chunks(JOINTS).zip(goals.chunks(JOINTS)).enumerate() {
        let result = query.check_motion(&tree, &robot, a, b, None, &certified).unwrap();
        assert_eq!((batch.collided[m], batch.first_fractions[m]), (result.collided, result.first_collision_fraction));
        let end = result.first_collision_fraction.map_or(2.0, |f| f - certified.tolerance);
        for i in (0..=1000).take_while(|&i| (i as f64 / 1000.0) < end) {
            let q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + (i as f64 / 1000.0) * (y - x)).collect();
            assert!(!single(&mut reference, &tree, &mut robot, &q));
        }
        if query.check_motion(&tree, &robot, a, b, None, &sampled).unwrap().collided {
            assert!(result.collided);
        }
    }
    let bad = MotionRequest { tolerance: -1.0, ..certified };
    let error = query.check_motion(&tree, &robot, &starts[..7], &goals[..7], None, &bad).unwrap_err();
    assert!(error.message().contains("request->tolerance"), "{}", error.message());
}

#[test]
fn bad_input_is_an_error_naming_the_argument() {
    let (robot, tree) = (arm(), scatter_map(7));
    let mut query = new_query();
    let error = query.check_configurations(&tree, &robot, &[0.0; 10], BasePoses::Origin, &BatchRequest::default())
        .unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    let mut q = rows(2, 1);
    q[9] = f64::NAN;
    let error = query.check_configurations(&tree, &robot, &q, BasePoses::Origin, &BatchRequest::default())
        .unwrap_err();
    assert!(error.message().contains("positions[row 1][joint 2]"), "{}", error.message());
    let bad = MotionRequest { resolution: 0.0, ..Default::default() };
    let error = query.check_motion(&tree, &robot, &q[..7], &q[..7], None, &bad).unwrap_err();
    assert!(error.message().contains("request->resolution"), "{}", error.message());
    let none = query.check_configurations(&tree, &robot, &[], BasePoses::Origin, &BatchRequest::default()).unwrap();
    assert!(none.collided.is_empty());
}

/// Point extents shrink obstacles to their points' boxes, so a batch with
/// them finds no collision the cell cubes do not, and the same answers as
/// single calls with the same geometry.
#[test]
fn obstacle_geometry_reaches_batch_and_motion_checks() {
    let (mut robot, tree, q) = (arm(), scatter_map(7), rows(60, 17));
    let extents = ObstacleGeometry::PointExtents;
    let mut query = new_query();
    let cubes = query.check_configurations(&tree, &robot, &q, BasePoses::Origin, &BatchRequest::default()).unwrap();
    let request = BatchRequest { obstacle_geometry: extents, ..Default::default() };
    let boxes = query.check_configurations(&tree, &robot, &q, BasePoses::Origin, &request).unwrap();
    assert!(cubes.collided.iter().zip(&boxes.collided).all(|(c, b)| *c || !*b));
    let mut reference = new_query();
    for (i, row) in q.chunks(JOINTS).enumerate() {
        robot.set_joint_positions(row, None).unwrap();
        let single = CollisionRequest { max_contacts: 0, obstacle_geometry: extents, ..Default::default() };
        assert_eq!(boxes.collided[i], reference.collide(&tree, &robot, &single).unwrap().collided);
    }
    let motion = MotionRequest { resolution: 0.05, obstacle_geometry: extents, ..Default::default() };
    let (start, goal) = (&q[..JOINTS], &q[JOINTS..2 * JOINTS]);
    let one = query.check_motion(&tree, &robot, start, goal, None, &motion).unwrap();
    let many = query.check_motions(&tree, &robot, start, goal, BasePoses::Origin, &motion).unwrap();
    assert_eq!((many.collided[0], many.first_fractions[0]), (one.collided, one.first_collision_fraction));
}
