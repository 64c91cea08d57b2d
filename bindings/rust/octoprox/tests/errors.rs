//! Errors carry the C status and the message naming function and argument.
mod common;
use common::*;
use octoprox::consts::*;
use octoprox::{pose_at, status_name, CollisionRequest, ErrorKind, LinkSet, Octree, OctreeOptions,
               Pose, Query, QueryOptions, Shape};

#[test]
fn invalid_options_name_the_function_and_field() {
    let options = OctreeOptions { resolution: f64::NAN, ..Default::default() };
    let error = Octree::new(&options).unwrap_err();
    assert_eq!((error.kind(), error.status()), (ErrorKind::InvalidArgument, OPX_ERROR_INVALID_ARGUMENT));
    assert!(error.message().starts_with("opx_octree_create"), "{}", error);
    assert!(error.message().contains("resolution"), "{}", error);
    assert!(error.to_string().contains("OPX_ERROR_INVALID_ARGUMENT"));
    assert_eq!(status_name(OPX_ERROR_IO), "OPX_ERROR_IO");
    assert_eq!((ErrorKind::Io.name(), ErrorKind::Io.status()), ("OPX_ERROR_IO".to_string(), OPX_ERROR_IO));
    let number = (OPX_VERSION_MAJOR * 10000 + OPX_VERSION_MINOR * 100 + OPX_VERSION_PATCH) as u32;
    assert_eq!(octoprox::version_number(), number);
    assert!(octoprox::check_version().is_ok());
}

#[test]
fn files_and_bytes() {
    let missing = Octree::load_file("/nonexistent/map.bt", &OctreeOptions::default());
    let error = missing.unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Io);
    assert!(error.message().contains("/nonexistent/map.bt"), "{}", error);
    let garbage = Octree::load_memory(b"# Octomap OcTree binary file\nnonsense", &Default::default());
    assert_eq!(garbage.unwrap_err().kind(), ErrorKind::Corrupt);
    let nul = Octree::load_file("a\0b", &OctreeOptions::default()).unwrap_err();
    assert_eq!(nul.kind(), ErrorKind::InvalidArgument);
}

#[test]
fn bad_calls_leave_objects_usable() {
    let mut links = LinkSet::new().unwrap();
    assert!(links.add_link("bad\0name").is_err());
    let link = links.add_link("ball").unwrap();
    assert_eq!(links.add_shape(link, &Shape::sphere(-1.0)).unwrap_err().kind(),
               ErrorKind::InvalidArgument);
    assert_eq!(links.add_shape(7, &Shape::sphere(0.1)).unwrap_err().kind(),
               ErrorKind::InvalidArgument);
    links.add_shape(link, &Shape::sphere(0.1)).unwrap();
    let zero = Pose { orientation: [0.0; 4], ..Default::default() };
    let error = links.set_poses(&[zero]).unwrap_err();
    assert!(error.message().starts_with("opx_linkset_set_poses"), "{}", error);
    assert!(links.set_poses(&[pose_at(0.0, 0.0, 0.0); 2]).is_err()); // one link only
    assert!(links.set_padding(-0.1).is_err());
    assert!(links.find_link("nothing").is_err());
    let request = CollisionRequest { unknown_probability: 2.0, compute_cost: true, ..Default::default() };
    let mut query = Query::new(&QueryOptions::default()).unwrap();
    let error = query.collide(&one_cell_map(), &links, &request).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("unknown_probability"), "{}", error);
    assert!(query.contact(0).is_err());
    let path = query.path(&one_cell_map(), &LinkSet::new().unwrap(), &[], &Default::default());
    assert_eq!(path.unwrap_err().kind(), ErrorKind::InvalidArgument);
    let options = QueryOptions { morton_bits: 42, ..Default::default() };
    assert!(Query::new(&options).is_err());
}
