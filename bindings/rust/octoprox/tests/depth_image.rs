//! Depth frames: the hand-computed 4 x 3 frame of the C tests
//! (tests/c/opx_depth_test.h) gives the map of its points, u16 and f32
//! agree, strided rows are read, and bad images are refused.
mod common;
use common::*;
use octoprox::{camera_intrinsics, CellClass, CellClasses, DepthImage, ErrorKind, InsertMode, Octree};

/// Millimetres, row after row; 0 is no return.
const MM: [u16; 12] = [2000, 0, 2000, 1000, 2000, 2000, 0, 3000, 0, 2000, 0, 0];
/// ((u - 1.5) * z / 2, (v - 1) * z / 4, z) of the pixels with a return.
const POINTS: [[f64; 3]; 7] = [[-1.5, -0.5, 2.0], [0.5, -0.5, 2.0], [0.75, -0.25, 1.0],
                               [-1.5, 0.0, 2.0], [-0.5, 0.0, 2.0], [2.25, 0.0, 3.0],
                               [-0.5, 0.5, 2.0]];

fn metres() -> Vec<f32> {
    let mut m: Vec<f32> = MM.iter().map(|&d| f32::from(d) / 1000.0).collect();
    m[1] = f32::NAN;
    m[6] = f32::INFINITY;
    m[10] = -1.0;
    m[11] = f32::NEG_INFINITY;
    m
}

fn all_leaves(tree: &Octree) -> Vec<octoprox::Leaf> {
    tree.leaves(CellClasses::ALL_KNOWN).unwrap()
}

fn insert(image: &DepthImage<'_>) -> Octree {
    let options = sensor_at(C0, C0, C0, InsertMode::Raycast);
    let mut reference = new_tree(RES);
    let expected = reference.insert_points(&POINTS, &options).unwrap();
    let mut tree = new_tree(RES);
    let camera = camera_intrinsics(2.0, 4.0, 1.5, 1.0);
    let report = tree.insert_depth_image(image, &camera, &options).unwrap();
    assert_eq!((report.points_used, report.pixels_no_return), (7, 5));
    assert_eq!((report.cells_hit, report.cells_missed), (expected.cells_hit, expected.cells_missed));
    assert_eq!(all_leaves(&tree), all_leaves(&reference));
    tree
}

#[test]
fn the_tiny_frame_gives_the_map_of_its_points() {
    let tree = insert(&DepthImage::from_u16(&MM, 4, 3, 0, 1000.0).unwrap());
    for [x, y, z] in POINTS {
        let cell = tree.classify([C0 + x, C0 + y, C0 + z]).unwrap();
        assert_eq!(cell.cell_class, CellClass::Occupied);
    }
}

#[test]
fn u16_and_f32_agree() {
    let m = metres();
    let image = DepthImage::from_f32(&m, 4, 3, 0).unwrap();
    assert_eq!((image.width(), image.height()), (4, 3));
    insert(&image);
    // TUM RGB-D units: 1/5000 m.
    let tum: Vec<u16> = MM.iter().map(|&d| d * 5).collect();
    insert(&DepthImage::from_u16(&tum, 4, 3, 0, 5000.0).unwrap());
}

#[test]
fn strided_rows_are_read_in_place() {
    // Each row followed by 3 pixels of padding.
    let mut padded = vec![999u16; 3 * 7];
    for v in 0..3 {
        padded[v * 7..v * 7 + 4].copy_from_slice(&MM[v * 4..v * 4 + 4]);
    }
    insert(&DepthImage::from_u16(&padded[..2 * 7 + 4], 4, 3, 7, 1000.0).unwrap());
}

#[test]
fn bad_images_are_refused() {
    let short = DepthImage::from_u16(&MM[..11], 4, 3, 0, 1000.0).unwrap_err();
    assert_eq!(short.kind(), ErrorKind::InvalidArgument);
    assert!(short.message().contains("do not fit"), "{}", short.message());
    assert!(DepthImage::from_u16(&MM, 4, 3, 3, 1000.0).is_err()); // stride < width
    assert!(DepthImage::from_u16(&MM, 2, usize::MAX, usize::MAX / 2, 1000.0).is_err());
    assert!(DepthImage::from_f32(&[], 0, 5, 0).is_ok()); // empty
    let mut tree = new_tree(RES);
    let options = sensor_at(C0, C0, C0, InsertMode::Raycast);
    let image = DepthImage::from_u16(&MM, 4, 3, 0, 1000.0).unwrap();
    let error = tree.insert_depth_image(&image, &camera_intrinsics(0.0, 4.0, 1.5, 1.0), &options)
        .unwrap_err();
    assert!(error.message().contains("intrinsics.fx"), "{}", error.message());
    let no_scale = DepthImage::from_u16(&MM, 4, 3, 0, 0.0).unwrap();
    let camera = camera_intrinsics(2.0, 4.0, 1.5, 1.0);
    let error = tree.insert_depth_image(&no_scale, &camera, &options).unwrap_err();
    assert!(error.message().contains("depth_scale"), "{}", error.message());
    assert!(all_leaves(&tree).is_empty());
}
