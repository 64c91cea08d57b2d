//! Collision, distance, cost and path queries on the scenes of the C tests
//! (tests/c/test_query_collide.c, _distance.c, _cost.c, _path.c).
mod common;
use common::*;
use octoprox::{pose_at, CellClass, CollisionRequest, DistanceRequest, Engine, InsertMode, LinkSet, MapFormat,
               ObstacleGeometry, Octree, PathRequest, Query, QueryOptions, Shape, ShapeKind, UnknownPolicy};

fn new_query() -> Query {
    Query::new(&QueryOptions::default()).unwrap()
}

#[test]
fn a_touching_sphere_collides_and_reports_the_cell() {
    let tree = one_cell_map();
    // Sphere r 0.1 at x = 0.35: it touches the cell face x = 0.25.
    let links = sphere_at(0.1, 0.35, C0, C0);
    let mut query = new_query();
    let result = query.collide(&tree, &links, &CollisionRequest::default()).unwrap();
    assert_eq!((result.collided, result.contact_count), (true, 1));
    let contacts = query.contacts().unwrap();
    assert_eq!(contacts.len(), 1);
    assert_eq!((contacts[0].link, contacts[0].shape), (0, 0));
    assert_eq!(contacts[0].cell_center, [C0, C0, C0]);
    assert_eq!(contacts[0].cell_class, CellClass::Occupied);
    let apart = sphere_at(0.1, 0.5, C0, C0);
    assert!(!query.collide(&tree, &apart, &CollisionRequest::default()).unwrap().collided);
    assert!(query.contacts().unwrap().is_empty());
}

#[test]
fn unknown_space_is_an_obstacle_when_asked() {
    let tree = one_cell_map();
    let links = sphere_at(0.1, 2.0, 2.0, 2.0);
    let mut query = new_query();
    let request = CollisionRequest { unknown_policy: UnknownPolicy::Occupied, ..Default::default() };
    let result = query.collide(&tree, &links, &request).unwrap();
    assert!(result.collided);
    assert_eq!(query.contact(0).unwrap().cell_class, CellClass::Unknown);
}

#[test]
fn padding_and_penetration() {
    let tree = one_cell_map();
    let mut links = sphere_at(0.1, 0.4, C0, C0); // 0.05 m from the cell
    let mut query = new_query();
    let request = CollisionRequest { compute_penetration: true, ..Default::default() };
    assert!(!query.collide(&tree, &links, &request).unwrap().collided);
    links.set_padding(0.08).unwrap();
    assert!(query.collide(&tree, &links, &request).unwrap().collided);
    let contact = query.contact(0).unwrap();
    assert!((contact.depth - 0.03).abs() < 1e-6, "depth {}", contact.depth);
    assert!((contact.normal[0] + 1.0).abs() < 1e-6, "normal {:?}", contact.normal);
}

#[test]
fn distance_with_witnesses_and_per_link() {
    let tree = one_cell_map();
    let mut links = LinkSet::new().unwrap();
    let above = links.add_link("above").unwrap();
    let beside = links.add_link("beside").unwrap();
    links.add_shape(above, &Shape::sphere(0.1)).unwrap();
    links.add_shape(beside, &Shape::cuboid([0.1, 0.1, 0.1])).unwrap();
    links.set_poses(&[pose_at(C0, C0, 1.0), pose_at(C0, 1.0, C0)]).unwrap();
    let mut query = new_query();
    let request = DistanceRequest { per_link: true, ..Default::default() };
    let result = query.distance(&tree, &links, &request).unwrap();
    assert_eq!((result.found, result.collided, result.link), (true, false, above));
    assert!((result.distance - 0.65).abs() < 1e-9);
    assert!((result.point_on_cell[2] - 0.25).abs() < 1e-9);
    let per_link = query.link_distances().unwrap();
    assert_eq!(per_link.len(), 2);
    assert!((per_link[1] - 0.7).abs() < 1e-9);
    links.set_link_enabled(above, false).unwrap();
    let result = query.distance(&tree, &links, &DistanceRequest::default()).unwrap();
    assert_eq!(result.link, beside);
    assert!(query.link_distances().unwrap().is_empty());
}

#[test]
fn every_shape_kind_is_accepted() {
    let tetra = [[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.0, 0.1, 0.0], [0.0, 0.0, 0.1]];
    let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    let kinds = [
        ShapeKind::Cylinder { radius: 0.05, length: 0.2 },
        ShapeKind::Capsule { radius: 0.05, length: 0.2 },
        ShapeKind::Convex { vertices: &tetra },
        ShapeKind::Mesh { vertices: &tetra, triangles: &faces },
    ];
    let mut links = LinkSet::new().unwrap();
    let tool = links.add_link("tool").unwrap();
    for (i, kind) in kinds.iter().enumerate() {
        let shape = Shape::new(*kind).at(pose_at(0.0, 0.0, 0.01 * i as f64));
        assert_eq!(links.add_shape(tool, &shape).unwrap(), i as u32);
    }
    assert_eq!(links.shape_count(tool).unwrap(), 4);
    for (i, kind) in kinds.iter().enumerate().take(3) {
        let stored = links.shape(tool, i as u32).unwrap();
        assert_eq!(stored.kind, *kind);
        assert_eq!(stored.pose, pose_at(0.0, 0.0, 0.01 * i as f64));
    }
    // A stored mesh renumbers its vertices: compare the triangles' corners.
    let corners = |vertices: &[[f64; 3]], triangles: &[[u32; 3]]| -> Vec<[[f64; 3]; 3]> {
        triangles.iter().map(|t| t.map(|v| vertices[v as usize])).collect()
    };
    match links.shape(tool, 3).unwrap().kind {
        ShapeKind::Mesh { vertices, triangles } => {
            assert_eq!(corners(vertices, triangles), corners(&tetra, &faces))
        }
        other => panic!("a mesh was stored as {:?}", other),
    }
    assert!(links.shape(tool, 4).is_err());
    assert_eq!(links.find_link("tool").unwrap(), tool);
    assert_eq!(links.link_name(tool).unwrap(), "tool");
    let copy = links.try_clone().unwrap();
    assert_eq!(copy.shape_count(tool).unwrap(), 4);
}

/// tests/c/test_query_cost.c: a bar through free cells, an occupied cell
/// and unknown space behind it; the two unknown boxes, costliest first.
#[test]
fn cost_of_unknown_space_behind_an_obstacle() {
    let mut tree = new_tree(RES);
    tree.insert_points(&[[1.0f64, 0.0, 0.0]], &sensor_at(C0, C0, C0, InsertMode::Raycast))
        .unwrap();
    let mut links = LinkSet::new().unwrap();
    let bar = links.add_link("bar").unwrap();
    links.add_shape(bar, &Shape::cuboid([1.325, 0.15, 0.15])).unwrap();
    links.set_poses(&[pose_at(1.2125, C0, C0)]).unwrap();
    let request = CollisionRequest {
        compute_cost: true,
        region_max: [2.0, RES, RES],
        ..Default::default()
    };
    let mut query = new_query();
    let result = query.collide(&tree, &links, &request).unwrap();
    let (small, large) = (0.5 * 0.25 * 0.0225, 0.5 * 0.375 * 0.0225);
    assert_eq!((result.collided, result.cost_box_count, result.cost_boxes_found), (true, 2, 2));
    assert!((result.total_cost - (small + large)).abs() < 1e-9);
    let boxes = query.cost_boxes().unwrap();
    assert_eq!(boxes[0].cell_class, CellClass::Unknown);
    assert!((boxes[0].cost - large).abs() < 1e-9);
    assert!((boxes[1].cost - small).abs() < 1e-9);
    assert!((boxes[0].max[0] - 1.875).abs() < 1e-9);
}

#[test]
fn a_path_reports_its_first_colliding_waypoint() {
    let tree = one_cell_map();
    let links = sphere_at(0.1, 2.0, C0, C0);
    // The sphere moves in along x: 1.0, 0.6, 0.3 (touching), 0.2.
    let poses: Vec<_> = [1.0, 0.6, 0.3, 0.2].iter().map(|&x| pose_at(x, C0, C0)).collect();
    let mut query = new_query();
    let request = PathRequest { compute_distance: true, ..Default::default() };
    let result = query.path(&tree, &links, &poses, &request).unwrap();
    assert_eq!((result.collided, result.first_colliding_waypoint), (true, Some(2)));
    assert_eq!(result.min_distance_waypoint, Some(2));
    assert_eq!(links.pose(0).unwrap().position[0], 2.0); // not moved
    let free = query.path(&tree, &links, &poses[..2], &PathRequest::default()).unwrap();
    assert_eq!((free.collided, free.first_colliding_waypoint), (false, None));
}

#[test]
fn the_amortized_engine_gives_the_direct_answers() {
    let tree = one_cell_map();
    let links = sphere_at(0.1, C0, C0, 1.0);
    let options = QueryOptions { engine: Engine::Amortized, ..Default::default() };
    let mut amortized = Query::new(&options).unwrap();
    let result = amortized.distance(&tree, &links, &DistanceRequest::default()).unwrap();
    assert!((result.distance - 0.65).abs() < 1e-9);
    let stats = amortized.stats().unwrap();
    assert_eq!((stats.engine, stats.builds, stats.boxes), (Engine::Amortized, 1, 1));
}

#[test]
fn caller_boxes_answer_like_the_cell_they_copy() {
    let options = QueryOptions { engine: Engine::Amortized, ..Default::default() };
    let mut query = Query::new(&options).unwrap();
    query.bind_boxes(&[[0.0, 0.0, 0.0, RES, RES, RES], [5.0, 5.0, 5.0, 6.0, 6.0, 6.0]]).unwrap();
    let far = sphere_at(0.1, C0, C0, 1.0);
    let expected = new_query().distance(&one_cell_map(), &far, &DistanceRequest::default()).unwrap();
    let result = query.distance_boxes(&far, &DistanceRequest::default()).unwrap();
    assert!((result.distance - expected.distance).abs() < 1e-12);
    assert_eq!(result.cell_center, [C0, C0, C0]);
    let touching = sphere_at(0.1, 0.35, C0, C0);
    let hit = query.collide_boxes(&touching, &CollisionRequest::default()).unwrap();
    assert_eq!((hit.collided, query.contacts().unwrap().len()), (true, 1));
    // A direct context refuses boxes; NaN is refused.
    assert!(new_query().bind_boxes(&[[0.0; 6]]).is_err());
    assert!(query.bind_boxes(&[[0.0, 0.0, 0.0, 1.0, f64::NAN, 1.0]]).is_err());
}

#[test]
fn point_extents_keep_the_space_between_a_point_and_its_cell_face() {
    // One point at the centre of the cell [0, RES]^3: the sphere 0.1 m past
    // the face touches the cube but not the point's box.
    let tree = one_cell_map();
    let links = sphere_at(0.05, RES + 0.049, C0, C0);
    let mut query = new_query();
    let cells = CollisionRequest::default();
    let extents = CollisionRequest { obstacle_geometry: ObstacleGeometry::PointExtents, ..Default::default() };
    assert!(query.collide(&tree, &links, &cells).unwrap().collided);
    assert!(!query.collide(&tree, &links, &extents).unwrap().collided);
    let near = DistanceRequest { obstacle_geometry: ObstacleGeometry::PointExtents, ..Default::default() };
    let d = query.distance(&tree, &links, &near).unwrap();
    // Never beyond the point, and short of it by at most the box's slack:
    // the box is the point's slots of 1/32 cell, rounded outward.
    let to_point = RES + 0.049 - 0.05 - C0;
    assert!(d.distance <= to_point && d.distance > to_point - 2.0 * RES / 32.0, "distance {}", d.distance);
    // An .opx image keeps the extent, an .ot image does not.
    let opx = Octree::load_memory(&tree.save_memory(MapFormat::Opx).unwrap(), &Default::default()).unwrap();
    assert_eq!(opx.stats().unwrap().leaves_with_extent, 1);
    assert!(!query.collide(&opx, &links, &extents).unwrap().collided);
    let ot = Octree::load_memory(&tree.save_memory(MapFormat::Ot).unwrap(), &Default::default()).unwrap();
    assert_eq!(ot.stats().unwrap().leaves_with_extent, 0);
    assert!(query.collide(&ot, &links, &extents).unwrap().collided);
}
