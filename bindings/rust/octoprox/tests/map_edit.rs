//! Clearing boxes and shapes, decay, cropping and bounded inserts through
//! the safe API, and their bad input (an invalid argument, the map as it
//! was).
use octoprox::{pose_at, CellClass, ErrorKind, InsertMode, InsertOptions, MapFormat, Octree, OctreeOptions,
               Shape, World};

/// Eight occupied cells of 0.25 m in a row along x, from x = 0 to 2.
fn row_map() -> Octree {
    let mut map = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() }).unwrap();
    let points: Vec<[f64; 3]> = (0..8).map(|i| [(f64::from(i) + 0.5) * 0.25, 0.125, 0.125]).collect();
    let options = InsertOptions { mode: InsertMode::Endpoints, ..Default::default() };
    map.insert_points(&points[..], &options).unwrap();
    map
}

fn classes(map: &Octree) -> Vec<CellClass> {
    (0..8).map(|i| map.classify([(f64::from(i) + 0.5) * 0.25, 0.125, 0.125]).unwrap().cell_class).collect()
}

use CellClass::{Free as F, Occupied as O, Unknown as U};

/// The call failed with `kind`, its message naming `argument`.
fn expect_error<T: std::fmt::Debug>(result: octoprox::Result<T>, kind: ErrorKind, argument: &str) {
    let error = result.unwrap_err();
    assert_eq!(error.kind(), kind, "{error}");
    assert!(error.message().contains(argument), "{error}");
}

#[test]
fn clear_region_takes_the_cell_above_a_face() {
    let mut map = row_map();
    map.clear_region([0.5, 0.0, 0.0], [1.0, 0.0, 0.0], CellClass::Unknown).unwrap();
    assert_eq!(classes(&map), [O, O, U, U, U, O, O, O]);
    map.clear_region([1.5 + 1e-9, 0.0, 0.0], [1.75 - 1e-9, 0.0, 0.0], CellClass::Free).unwrap();
    assert_eq!(classes(&map)[5..], [O, F, O]);
}

#[test]
fn clear_shapes_of_a_world_object() {
    let mut map = row_map();
    let mut world = World::new().unwrap();
    let block = world.add_box("block", [0.2, 0.2, 0.2], &pose_at(1.875, 0.125, 0.125)).unwrap();
    let shape = world.shape(block, 0).unwrap();
    map.clear_shapes(&[shape], &world.pose(block).unwrap(), CellClass::Unknown).unwrap();
    assert_eq!(classes(&map), [O, O, O, O, O, O, O, U]);
    map.clear_shapes(&[Shape::sphere(0.2)], &pose_at(1.0, 0.0, 0.0), CellClass::Free).unwrap();
    assert_eq!(classes(&map)[2..6], [O, F, F, O]);
}

#[test]
fn decay_crop_and_bounds() {
    let mut map = row_map();
    map.decay(0.3).unwrap();
    let p = map.classify([0.125, 0.125, 0.125]).unwrap().probability;
    let expected = 1.0 / (1.0 + (-((0.7f64 / 0.3).ln() - 0.3)).exp());
    assert!((p - expected).abs() < 1e-6, "{p} vs {expected}");
    map.crop([0.25, -1.0, -1.0], [1.0, 1.0, 1.0]).unwrap();
    assert_eq!(classes(&map), [U, O, O, O, O, U, U, U]);
    let mut bounded = Octree::new(&OctreeOptions { resolution: 0.25, ..Default::default() }).unwrap();
    let points: Vec<[f64; 3]> = (0..8).map(|i| [(f64::from(i) + 0.5) * 0.25, 0.125, 0.125]).collect();
    let options = InsertOptions {
        mode: InsertMode::Endpoints,
        bounds: Some(([0.25, -1.0, -1.0], [1.0, 1.0, 1.0])),
        ..Default::default()
    };
    assert_eq!(bounded.insert_points(&points[..], &options).unwrap().cells_hit, 4);
    assert_eq!(classes(&bounded), [U, O, O, O, O, U, U, U]);
}

#[test]
fn bad_input_names_the_argument() {
    let mut map = row_map();
    let before = map.save_memory(MapFormat::Ot).unwrap();
    expect_error(map.clear_region([0.0; 3], [1.0, f64::NAN, 1.0], CellClass::Free), ErrorKind::InvalidArgument,
                 "box_max");
    expect_error(map.clear_region([0.0; 3], [1.0; 3], CellClass::Occupied), ErrorKind::InvalidArgument, "to");
    expect_error(map.crop([1.0, 0.0, 0.0], [0.0, 1.0, 1.0]), ErrorKind::InvalidArgument, "inverted");
    expect_error(map.decay(-1.0), ErrorKind::InvalidArgument, "amount");
    expect_error(map.decay(f64::NAN), ErrorKind::InvalidArgument, "amount");
    let options = InsertOptions { bounds: Some(([1.0; 3], [0.0; 3])), ..Default::default() };
    expect_error(map.insert_points(&[[1.0f64, 0.0, 0.0]][..], &options), ErrorKind::InvalidArgument,
                 "bounds_min");
    assert_eq!(map.save_memory(MapFormat::Ot).unwrap(), before);
}
