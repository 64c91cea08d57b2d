//! Self-collision: the scenarios of tests/c/test_self_collision.c and the
//! Python test_self_collision.py (two cubes 1 cm apart, padding, a disabled
//! pair, contacts, signed distance, an SRDF's pair, pair sampling, errors).
use octoprox::{pose_at, ErrorKind, LinkSet, PairSamplingOptions, Query, QueryOptions,
               SelfCollisionRequest, SelfDistanceRequest, Shape, UrdfOptions};
use std::io::Write;

const ARM: &str = r#"<robot name="arm">
  <link name="base"><collision><origin xyz="0 0 0.1"/><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0.3 0 0" rpy="0 1.5707963267948966 0"/>
    <geometry><cylinder radius="0.05" length="0.6"/></geometry></collision></link>
  <link name="hand"><collision><origin xyz="0 0 0.3"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" velocity="1" effort="10"/></joint>
  <joint name="slide" type="prismatic"><parent link="arm"/><child link="hand"/>
    <origin xyz="0.6 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.2" velocity="2" effort="5"/></joint>
</robot>"#;

/// Two links holding a 0.1 m cube each, `gap` metres apart along x.
fn two_cubes(gap: f64) -> LinkSet {
    let mut links = LinkSet::new().unwrap();
    for name in ["left", "right"] {
        let link = links.add_link(name).unwrap();
        links.add_shape(link, &Shape::cuboid([0.1, 0.1, 0.1])).unwrap();
    }
    links.set_poses(&[pose_at(0.0, 0.0, 0.0), pose_at(0.1 + gap, 0.0, 0.0)]).unwrap();
    links
}

fn new_query() -> Query {
    Query::new(&QueryOptions::default()).unwrap()
}

#[test]
fn links_one_centimetre_apart() {
    let mut links = two_cubes(0.01);
    let mut query = new_query();
    let yes_no = SelfCollisionRequest::default();
    assert!(!query.self_collide(&links, &yes_no).unwrap().collided);
    let d = query.self_distance(&links, &SelfDistanceRequest::default()).unwrap();
    assert_eq!((d.found, d.link_a, d.link_b), (true, 0, 1));
    assert!((d.distance - 0.01).abs() < 1e-12);
    assert!((d.point_on_a[0] - 0.05).abs() < 1e-12 && (d.point_on_b[0] - 0.06).abs() < 1e-12);
    links.set_padding(0.005).unwrap();
    assert!(query.self_collide(&links, &yes_no).unwrap().collided);
    links.set_pair_enabled(1, 0, false).unwrap();
    assert!(!links.pair_enabled(0, 1).unwrap());
    assert!(!query.self_collide(&links, &yes_no).unwrap().collided);
    let none = query.self_distance(&links, &SelfDistanceRequest::default()).unwrap();
    assert!(!none.found);
    assert!(none.distance.is_infinite());
}

#[test]
fn contacts_carry_both_links_and_the_depth() {
    let links = two_cubes(-0.02);
    let mut query = new_query();
    let all = SelfCollisionRequest { max_contacts: u32::MAX, compute_penetration: true };
    let result = query.self_collide(&links, &all).unwrap();
    assert_eq!((result.collided, result.contact_count, result.truncated), (true, 1, false));
    let contacts = query.self_contacts().unwrap();
    let c = contacts[0];
    assert_eq!((c.link_a, c.shape_a, c.link_b, c.shape_b), (0, 0, 1, 0));
    assert!((c.depth - 0.02).abs() < 1e-12 && (c.normal[0] - 1.0).abs() < 1e-12);
    let signed = SelfDistanceRequest { signed_distance: true, ..Default::default() };
    assert!((query.self_distance(&links, &signed).unwrap().distance + 0.02).abs() < 1e-12);
}

#[test]
fn srdf_pairs_start_disabled_and_sampling_disables_more() {
    let folder = std::env::temp_dir().join(format!("opx_self_rust_{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let srdf = folder.join("arm.srdf");
    std::fs::File::create(&srdf).unwrap()
        .write_all(br#"<robot name="arm"><disable_collisions link1="base" link2="arm"/></robot>"#)
        .unwrap();
    let options = UrdfOptions { srdf_path: Some(srdf), ..Default::default() };
    let mut robot = LinkSet::from_urdf_string(ARM, &options).unwrap();
    std::fs::remove_dir_all(&folder).unwrap();
    assert!(!robot.pair_enabled(0, 1).unwrap());
    assert!(robot.pair_enabled(1, 2).unwrap());
    let mut query = new_query();
    assert!(!query.self_collide(&robot, &SelfCollisionRequest::default()).unwrap().collided);
    // The hand (z >= 0.45) never meets the base (z <= 0.2) nor the arm (z <= 0.25).
    let sampling = PairSamplingOptions { samples: 200, ..Default::default() };
    let result = robot.disable_never_colliding_pairs(&sampling).unwrap();
    assert_eq!((result.now, result.never, result.always), (0, 2, 0));
    assert!(!robot.pair_enabled(0, 2).unwrap() && !robot.pair_enabled(1, 2).unwrap());
}

#[test]
fn bad_arguments_name_the_function_and_the_argument() {
    let mut links = two_cubes(0.01);
    let error = links.set_pair_enabled(0, 5, false).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("opx_linkset_set_pair_enabled: b: link 5"), "{}", error);
    assert!(links.pair_enabled(1, 1).is_err());
    let cutoff = SelfDistanceRequest { cutoff: -1.0, ..Default::default() };
    let error = new_query().self_distance(&links, &cutoff).unwrap_err();
    assert!(error.message().contains("opx_query_self_distance: request->cutoff"), "{}", error);
    let error = links.disable_never_colliding_pairs(&PairSamplingOptions::default()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Unsupported);
}
