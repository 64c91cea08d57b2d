//! read_point_cloud: small PCD (ascii, LZF binary_compressed) and PLY
//! files written here, the shared RGB-D frame when present, and errors.
mod common;

use octoprox::{read_point_cloud, CloudEncoding, CloudFormat, ErrorKind};
use std::path::PathBuf;

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("opx-rust-clouds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

const XYZ: &str = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

#[test]
fn an_organized_ascii_pcd_with_its_viewpoint() {
    let text = format!("{}WIDTH 2\nHEIGHT 2\nVIEWPOINT 1 2 3 0 1 0 0\nDATA ascii\n1 2 3\n4 5 6\nnan nan nan\n7 8 9\n", XYZ);
    let cloud = read_point_cloud(write("grid.pcd", text.as_bytes())).unwrap();
    assert_eq!((cloud.info.width, cloud.info.height, cloud.info.finite_count), (2, 2, 3));
    assert_eq!(cloud.info.format, CloudFormat::Pcd);
    assert_eq!(cloud.points[3], [7.0, 8.0, 9.0]);
    assert!(cloud.points[2][0].is_nan());
    let viewpoint = cloud.viewpoint().unwrap();
    assert_eq!(viewpoint.position, [1.0, 2.0, 3.0]);
    assert_eq!(viewpoint.orientation, [1.0, 0.0, 0.0, 0.0]); // qx qy qz qw
}

#[test]
fn a_compressed_pcd_of_one_literal_run() {
    // LZF: a control byte (length - 1), then the bytes; the fields one after another.
    let fields: Vec<u8> = [1.0f32, 4.0, 2.0, 5.0, 3.0, 6.0].iter().flat_map(|v| v.to_le_bytes()).collect();
    let mut file = format!("{}WIDTH 2\nDATA binary_compressed\n", XYZ).into_bytes();
    file.extend_from_slice(&(fields.len() as u32 + 1).to_le_bytes());
    file.extend_from_slice(&(fields.len() as u32).to_le_bytes());
    file.push(fields.len() as u8 - 1);
    file.extend_from_slice(&fields);
    let cloud = read_point_cloud(write("lzf.pcd", &file)).unwrap();
    assert_eq!(cloud.info.encoding, CloudEncoding::BinaryCompressed);
    assert_eq!(cloud.points, vec![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
    assert!(cloud.viewpoint().is_none());
}

#[test]
fn ply_vertices() {
    let text = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 1 2\n3 4 5\n";
    let cloud = read_point_cloud(write("v.ply", text.as_bytes())).unwrap();
    assert_eq!(cloud.info.format, CloudFormat::Ply);
    assert_eq!(cloud.points, vec![[0.0, 1.0, 2.0], [3.0, 4.0, 5.0]]);
}

#[test]
fn bad_files_are_errors_naming_the_file() {
    let missing = read_point_cloud("/nonexistent/frame.pcd").unwrap_err();
    assert_eq!(missing.kind(), ErrorKind::Io);
    assert!(missing.message().contains("/nonexistent/frame.pcd"));
    let cut = format!("{}WIDTH 3\nDATA ascii\n1 2 3\n", XYZ);
    let error = read_point_cloud(write("cut.pcd", cut.as_bytes())).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Corrupt);
    assert!(error.message().contains("opx_point_cloud_read_file"));
}

#[test]
fn the_shared_rgbd_frame_when_present() {
    let dir = std::env::var("OPX_DATA_DIR").map(PathBuf::from).unwrap_or_else(|_| {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../../shared/data")
    });
    let path = dir.join("rgbd/frame_20121214T142255.814212.pcd");
    if !path.exists() {
        common::skip_without_data(&format!("{} not found (set OPX_DATA_DIR)", path.display()));
        return;
    }
    let cloud = read_point_cloud(&path).unwrap();
    assert_eq!((cloud.info.width, cloud.info.height), (640, 480));
    assert_eq!(cloud.info.finite_count, 271_575);
    assert_eq!(cloud.points.len(), 307_200);
}
