//! Scenes shared by the integration tests, the same as the C tests'
//! (tests/c/opx_test.h): 25 cm cells, the sensor at the centre C0 of the
//! cell [0, RES)^3.
#![allow(dead_code)]
use octoprox::{pose_at, InsertMode, InsertOptions, LinkSet, Octree, OctreeOptions, Shape};

pub const RES: f64 = 0.25;
pub const C0: f64 = 0.125;

pub fn new_tree(resolution: f64) -> Octree {
    Octree::new(&OctreeOptions { resolution, ..Default::default() }).unwrap()
}

pub fn sensor_at(x: f64, y: f64, z: f64, mode: InsertMode) -> InsertOptions {
    InsertOptions { mode, sensor_pose: pose_at(x, y, z), ..Default::default() }
}

/// One occupied cell [0, RES]^3 (p = 0.7); the rest unknown.
pub fn one_cell_map() -> Octree {
    let mut tree = new_tree(RES);
    let point = [[C0, C0, C0]];
    tree.insert_points(&point, &sensor_at(0.0, 0.0, 0.0, InsertMode::Endpoints)).unwrap();
    assert_eq!(tree.stats().unwrap().leaves_occupied, 1);
    tree
}

/// One link "ball": a sphere of `radius` at (x, y, z), map frame.
pub fn sphere_at(radius: f64, x: f64, y: f64, z: f64) -> LinkSet {
    let mut links = LinkSet::new().unwrap();
    let link = links.add_link("ball").unwrap();
    links.add_shape(link, &Shape::sphere(radius)).unwrap();
    links.set_poses(&[pose_at(x, y, z)]).unwrap();
    links
}
