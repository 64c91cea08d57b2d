//! Query::distance_spheres: signed distances, gradients and witnesses
//! against the one cell [0, 0.25]^3 and a world's ball, and bad input.
mod common;

use common::{one_cell_map, C0};
use octoprox::{pose_at, ErrorKind, Query, QueryOptions, SphereDistanceRequest, World};

#[test]
fn outside_inside_and_truncated() {
    let map = one_cell_map();
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let spheres = [[0.5, C0, C0, 0.1], [0.05, C0, C0, 0.0], [2.0, C0, C0, 0.1]];
    let request = SphereDistanceRequest { max_distance: 0.5, ..Default::default() };
    let got = query.distance_spheres(&map, &spheres, &request).unwrap();
    assert!((got.distance[0] - 0.15).abs() < 1e-12);
    assert_eq!(got.gradient[0], [1.0, 0.0, 0.0]);
    assert!((got.witness[0][0] - 0.25).abs() < 1e-12);
    assert!((got.distance[1] + 0.05).abs() < 1e-12);
    assert_eq!(got.gradient[1], [-1.0, 0.0, 0.0]);
    assert_eq!(got.distance[2], 0.5);
    assert_eq!(got.gradient[2], [0.0; 3]);
    assert!(got.witness[2][0].is_nan());
    let threads = SphereDistanceRequest { max_threads: 0, ..request };
    assert_eq!(query.distance_spheres(&map, &spheres, &threads).unwrap().distance, got.distance);
}

#[test]
fn with_a_world() {
    let mut world = World::new().unwrap();
    world.add_sphere("ball", 0.2, &pose_at(1.0, C0, C0)).unwrap();
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let request = SphereDistanceRequest { max_distance: 1.0, ..Default::default() };
    let got = query.distance_spheres_with_world(None, &world, &[[1.5, C0, C0, 0.1]], &request).unwrap();
    assert!((got.distance[0] - 0.2).abs() < 1e-9);
    let map = one_cell_map();
    let got = query.distance_spheres_with_world(Some(&map), &world, &[[0.6, C0, C0, 0.0]], &request).unwrap();
    assert!((got.distance[0] - 0.2).abs() < 1e-9);
}

#[test]
fn bad_input_is_an_error() {
    let map = one_cell_map();
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let error = query.distance_spheres(&map, &[[0.0, 0.0, f64::NAN, 0.1]], &Default::default()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("row 0"));
    let bad = SphereDistanceRequest { max_distance: -1.0, ..Default::default() };
    let error = query.distance_spheres(&map, &[[0.0, 0.0, 0.0, 0.1]], &bad).unwrap_err();
    assert!(error.message().contains("max_distance"));
    assert!(query.distance_spheres(&map, &[], &Default::default()).unwrap().distance.is_empty());
}

const ARM: &str = "<robot name='arm'>\
<link name='base'><collision><geometry><sphere radius='0.05'/></geometry></collision></link>\
<link name='l1'><collision><origin xyz='0.3 0 0'/><geometry><sphere radius='0.05'/></geometry></collision></link>\
<joint name='j1' type='revolute'><parent link='base'/><child link='l1'/><origin xyz='0 0 0.1'/>\
<axis xyz='0 0 1'/><limit lower='-3' upper='3' effort='1' velocity='1'/></joint></robot>";

#[test]
fn trajectory_cost_and_its_gradient() {
    use octoprox::{LinkSet, TrajectoryCostRequest, UrdfOptions};
    let mut map = common::new_tree(0.04);
    map.insert_points(&[[0.0f64, 0.35, 0.1]], &common::sensor_at(0.0, 0.0, 0.0, octoprox::InsertMode::Endpoints))
        .unwrap();
    let arm = LinkSet::from_urdf_string(ARM, &UrdfOptions::default()).unwrap();
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let request = TrajectoryCostRequest { activation: 0.1, ..Default::default() };
    let q = [1.4, 1.5];
    let got = query.trajectory_cost(&map, &arm, &q, None, &request).unwrap();
    assert!(got.cost > 0.0);
    let h = 1e-6;
    for w in 0..2 {
        let (mut plus, mut minus) = (q, q);
        plus[w] += h;
        minus[w] -= h;
        let fd = (query.trajectory_cost(&map, &arm, &plus, None, &request).unwrap().cost
            - query.trajectory_cost(&map, &arm, &minus, None, &request).unwrap().cost)
            / (2.0 * h);
        assert!((fd - got.gradient[w]).abs() <= 1e-6 * fd.abs().max(1e-3), "{fd} vs {}", got.gradient[w]);
    }
    assert!(query.trajectory_cost(&map, &arm, &[], None, &request).is_err());
}
