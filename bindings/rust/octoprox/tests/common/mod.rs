//! Scenes shared by the integration tests, the same as the C tests'
//! (tests/c/opx_test.h): 25 cm cells, the sensor at the centre C0 of the
//! cell [0, RES)^3; and the generated arm's URDF, a map scattered around
//! it and the random generator of the arm tests.
#![allow(dead_code)]
use octoprox::{pose_at, InsertMode, InsertOptions, LinkSet, Octree, OctreeOptions, Shape};

pub const RES: f64 = 0.25;
pub const C0: f64 = 0.125;

pub fn new_tree(resolution: f64) -> Octree {
    Octree::new(&OctreeOptions { resolution, ..Default::default() }).unwrap()
}

pub fn sensor_at(x: f64, y: f64, z: f64, mode: InsertMode) -> InsertOptions<'static> {
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

/// A reproducible uniform generator (64-bit LCG).
pub struct Lcg(pub u64);

impl Lcg {
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// The opening of a generated arm's URDF: links l0..l`joints`, each a
/// cylinder from 0.04 to 0.2 m along its z, and revolute joints j1..
/// alternating z and y axes 0.24 m apart (the first 0.1 m up).  The caller
/// adds what else it needs and "</robot>".
pub fn arm_urdf_links(joints: usize) -> String {
    use std::fmt::Write;
    let mut xml = String::from("<robot name=\"arm\">");
    for k in 0..=joints {
        write!(xml, "<link name=\"l{k}\"><collision><origin xyz=\"0 0 0.12\"/><geometry>\
                     <cylinder radius=\"0.035\" length=\"0.16\"/></geometry></collision></link>").unwrap();
        if k > 0 {
            let axis = if k % 2 == 1 { "0 0 1" } else { "0 1 0" };
            let z = if k == 1 { 0.1 } else { 0.24 };
            write!(xml, "<joint name=\"j{k}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{k}\"/>\
                         <origin xyz=\"0 0 {z}\"/><axis xyz=\"{axis}\"/>\
                         <limit lower=\"-3.14\" upper=\"3.14\" effort=\"1\" velocity=\"1\"/></joint>", k - 1).unwrap();
        }
    }
    xml
}

/// 90 occupied cells of 5 cm scattered around the generated arm (x and y
/// within 1.1 m, z 0.15-1.9 m), from `seed`.
pub fn scatter_map(seed: u64) -> Octree {
    let mut rng = Lcg(seed);
    let points: Vec<[f64; 3]> = (0..90)
        .map(|_| [rng.uniform(-1.1, 1.1), rng.uniform(-1.1, 1.1), rng.uniform(0.15, 1.9)])
        .collect();
    let mut tree = new_tree(0.05);
    tree.insert_points(&points[..], &sensor_at(0.0, 0.0, 0.0, InsertMode::Endpoints)).unwrap();
    tree
}

/// Ends a test whose shared data is absent: a note on stderr (the test
/// passes as skipped), or a panic when OPX_REQUIRE_DATA=1 (CI sets it).
pub fn skip_without_data(message: &str) {
    if std::env::var("OPX_REQUIRE_DATA").map(|v| v == "1").unwrap_or(false) {
        panic!("{message} and OPX_REQUIRE_DATA=1: the shared data is required");
    }
    eprintln!("skipped: {message}");
}
