//! Inserting sensor frames from every point layout, classifying, leaves
//! and files (the scenarios of tests/c/test_octree_insert.c and _io.c).
mod common;
use common::*;
use octoprox::{CellClass, CellClasses, InsertMode, MapFormat, Octree, OctreeOptions, Points};

/// Two rays from (C0, C0, C0) to (1, 0, 0) and (0, 1, 0), sensor frame:
/// 2 occupied and 7 free cells, whatever the layout of the points.
fn assert_sample_map(tree: &Octree) {
    let stats = tree.stats().unwrap();
    assert_eq!(stats.leaves_occupied, 2);
    assert_eq!(stats.leaves_free, 7);
    let hit = tree.classify([1.0 + C0, C0, C0]).unwrap();
    assert_eq!(hit.cell_class, CellClass::Occupied);
    assert!((hit.probability - 0.7).abs() < 1e-4);
    assert_eq!(tree.classify([0.5 + C0, C0, C0]).unwrap().cell_class, CellClass::Free);
    assert_eq!(tree.classify([-3.0, -3.0, -3.0]).unwrap().cell_class, CellClass::Unknown);
}

fn insert(points: Points<'_>) -> Octree {
    let mut tree = new_tree(RES);
    let report = tree.insert_points(points, &sensor_at(C0, C0, C0, InsertMode::Raycast)).unwrap();
    assert_eq!((report.points_used, report.cells_hit, report.cells_missed), (2, 2, 7));
    tree
}

#[test]
fn packed_f32_and_f64_points() {
    assert_sample_map(&insert((&[[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0]]).into()));
    assert_sample_map(&insert((&[[1.0f64, 0.0, 0.0], [0.0, 1.0, 0.0]]).into()));
    let with_intensity = [[1.0f32, 0.0, 0.0, 9.0], [0.0, 1.0, 0.0, 9.0]];
    assert_sample_map(&insert((&with_intensity).into()));
}

#[test]
fn strided_points_are_read_in_place() {
    // Every other row of a 4-column array: a strided view, not a copy.
    let rows = [1.0f64, 0.0, 0.0, 5.0, 7.0, 7.0, 7.0, 7.0, 0.0, 1.0, 0.0, 5.0];
    let points = Points::from_f64_rows(&rows, 8).unwrap();
    assert_eq!((points.len(), points.stride()), (2, 64));
    assert_eq!(points.as_ptr(), rows.as_ptr().cast());
    assert_sample_map(&insert(points));
}

#[test]
fn pointcloud2_buffer_with_point_step() {
    // x y z float32 at offsets 0, 4, 8, then rgb: point_step 16.
    let mut data = Vec::new();
    for xyz in [[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0]] {
        xyz.iter().for_each(|v| data.extend_from_slice(&v.to_ne_bytes()));
        data.extend_from_slice(&0xff00ffu32.to_ne_bytes());
    }
    let points = Points::strided_f32(&data, 2, 16).unwrap();
    assert_eq!(points.as_ptr(), data.as_ptr());
    assert_sample_map(&insert(points));
    assert!(Points::strided_f32(&data, 3, 16).is_err()); // past the end
    assert!(Points::strided_f32(&data, 2, 8).is_err()); // overlapping points
}

#[test]
fn leaves_and_memory_round_trip() {
    let tree = insert((&[[1.0f64, 0.0, 0.0], [0.0, 1.0, 0.0]]).into());
    let occupied = tree.leaves(CellClass::Occupied).unwrap();
    assert_eq!(occupied.len(), 2);
    assert!(occupied.iter().all(|leaf| leaf.cell_class == CellClass::Occupied));
    assert_eq!(tree.leaves(CellClasses::ALL_KNOWN).unwrap().len(), 9);
    assert_eq!(tree.leaves([CellClass::Free, CellClass::Occupied]).unwrap().len(), 9);
    assert_eq!(tree.leaves(CellClass::Free | CellClass::Uncertain).unwrap().len(), 7);
    assert!(tree.leaves(CellClass::Unknown).is_err()); // unknown space has no leaves
    let bytes = tree.save_memory(MapFormat::Ot).unwrap();
    let loaded = Octree::load_memory(&bytes, &OctreeOptions::default()).unwrap();
    assert_eq!(loaded.options().unwrap().resolution, RES);
    assert_sample_map(&loaded);
    let path = std::env::temp_dir().join(format!("opx_rust_{}.bt", std::process::id()));
    tree.save_file(&path, MapFormat::Auto).unwrap();
    let from_file = Octree::load_file(&path, &OctreeOptions::default()).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(from_file.stats().unwrap().leaves_occupied, 2);
}

#[test]
fn clear_empties_the_map() {
    let mut tree = one_cell_map();
    tree.clear().unwrap();
    assert_eq!(tree.stats().unwrap().leaves_occupied, 0);
}
