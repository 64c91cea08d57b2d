//! World objects: a `World` built by hand (every shape kind, with poses)
//! and read from MoveIt scene files (tests/data/scenes), its bookkeeping
//! (len, names, poses, enabled flags, removal), and collision and distance
//! with a world, with no map and beside the one-cell map.
mod common;
use common::*;
use octoprox::{pose_at, CellClass, CollisionRequest, DistanceRequest, ErrorKind, LinkSet, Pose, Query,
               QueryOptions, SceneFormat, Shape, ShapeKind, World};
use std::path::PathBuf;

const TETRA: [[f64; 3]; 4] = [[0.0, 0.0, 0.0], [0.2, 0.0, 0.0], [0.0, 0.2, 0.0], [0.0, 0.0, 0.2]];
const FACES: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];

fn scenes() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../tests/data/scenes")
}

fn new_query() -> Query {
    Query::new(&QueryOptions::default()).unwrap()
}

/// A box, a cylinder standing on z, a sphere and a tetrahedron surface,
/// each 2 m from the origin.
fn kitchen() -> World {
    let mut world = World::new().unwrap();
    world.add_box("crate", [0.2, 0.2, 0.2], &pose_at(2.0, 0.0, 0.0)).unwrap();
    world.add_cylinder("post", 0.05, 1.0, &pose_at(0.0, 2.0, 0.5)).unwrap();
    world.add_sphere("ball", 0.1, &pose_at(0.0, -2.0, 0.0)).unwrap();
    world.add_mesh("wedge", &TETRA, &FACES, &pose_at(-2.0, 0.0, 0.0)).unwrap();
    world
}

/// A quarter turn about z, at (x, y, z).
fn turned_at(x: f64, y: f64, z: f64) -> Pose {
    let half = std::f64::consts::FRAC_1_SQRT_2;
    Pose { position: [x, y, z], orientation: [0.0, 0.0, half, half] }
}

#[test]
fn objects_by_index_and_name() {
    let mut world = kitchen();
    assert_eq!((world.len(), world.is_empty()), (4, false));
    assert_eq!(world.names().unwrap(), ["crate", "post", "ball", "wedge"]);
    assert_eq!(world.find("ball").unwrap(), 2);
    assert_eq!(world.pose(1).unwrap().position, [0.0, 2.0, 0.5]);
    assert_eq!(world.shape(1, 0).unwrap().kind, ShapeKind::Cylinder { radius: 0.05, length: 1.0 });
    match world.shape(3, 0).unwrap().kind {
        ShapeKind::Mesh { vertices, triangles } => assert_eq!((vertices.len(), triangles.len()), (4, 4)),
        other => panic!("the wedge is a {:?}", other),
    }
    world.remove(1).unwrap(); // later objects move down by one
    assert_eq!(world.names().unwrap(), ["crate", "ball", "wedge"]);
    assert_eq!(world.find("wedge").unwrap(), 2);
    world.set_enabled(0, false).unwrap();
    assert!(!world.enabled(0).unwrap() && world.enabled(1).unwrap());
    world.set_pose(1, &pose_at(0.0, -3.0, 0.0)).unwrap();
    assert_eq!(world.pose(1).unwrap().position, [0.0, -3.0, 0.0]);
    assert!(World::new().unwrap().is_empty());
}

#[test]
fn an_object_of_every_shape_kind_at_its_poses() {
    let mut world = World::new().unwrap();
    let table = world.add_object("table", &turned_at(1.0, 0.0, 0.0)).unwrap();
    let top = Shape::cuboid([1.2, 0.8, 0.05]).at(pose_at(0.0, 0.0, 0.725));
    let leg = Shape::new(ShapeKind::Cylinder { radius: 0.03, length: 0.7 }).at(pose_at(0.55, 0.35, 0.35));
    let rail = Shape::new(ShapeKind::Capsule { radius: 0.02, length: 0.5 }).at(pose_at(0.0, -0.35, 0.3));
    let shapes = [top, leg, rail, Shape::sphere(0.05), Shape::new(ShapeKind::Convex { vertices: &TETRA }),
                  Shape::new(ShapeKind::Mesh { vertices: &TETRA, triangles: &FACES })];
    for (i, shape) in shapes.iter().enumerate() {
        assert_eq!(world.add_shape(table, shape).unwrap(), i as u32);
    }
    assert_eq!(world.shape_count(table).unwrap(), 6);
    assert_eq!(world.shape(table, 0).unwrap(), top);
    assert_eq!(world.shape(table, 2).unwrap().kind, ShapeKind::Capsule { radius: 0.02, length: 0.5 });
    // The top, in the map frame: turned a quarter, its 0.8 m side along x.
    let mut query = new_query();
    let on_top = sphere_at(0.05, 1.35, 0.0, 0.79);
    assert!(query.collide_with_world(None, &world, &on_top, &Default::default()).unwrap().collided);
    let past_the_edge = sphere_at(0.05, 1.5, 0.0, 0.8);
    assert!(!query.collide_with_world(None, &world, &past_the_edge, &Default::default()).unwrap().collided);
}

#[test]
fn bad_input_is_an_error_that_changes_nothing() {
    let mut world = kitchen();
    let error = world.add_sphere("bad", -1.0, &Pose::default()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("radius"), "{}", error.message());
    assert_eq!(world.len(), 4); // no object left without its shape
    let nan = pose_at(f64::NAN, 0.0, 0.0);
    assert_eq!(world.set_pose(0, &nan).unwrap_err().kind(), ErrorKind::InvalidArgument);
    assert!(world.remove(9).unwrap_err().message().contains('9'));
    assert!(world.find("chair").unwrap_err().message().contains("chair"));
    assert_eq!(world.add_object("a\0b", &Pose::default()).unwrap_err().kind(), ErrorKind::InvalidArgument);
}

#[test]
fn yaml_and_scene_text_give_the_same_world() {
    let yaml = World::from_scene_file(scenes().join("kitchen.yaml")).unwrap();
    let text = World::from_scene_file(scenes().join("kitchen.scene")).unwrap();
    assert_eq!(yaml.names().unwrap(), ["table", "ball", "wedge"]);
    assert_eq!(text.names().unwrap(), yaml.names().unwrap());
    for world in [&yaml, &text] {
        assert_eq!(world.shape_count(0).unwrap(), 3); // top, leg, knob
        assert_eq!(world.pose(1).unwrap().position, [0.0, 2.0, 0.5]);
        assert_eq!(world.shape(0, 1).unwrap().kind, ShapeKind::Cylinder { radius: 0.03, length: 0.7 });
    }
    let old = World::from_scene_file(scenes().join("kitchen_without_object_poses.scene")).unwrap();
    assert_eq!(old.names().unwrap(), ["ball", "wedge"]);
}

#[test]
fn robowflex_scenes_give_the_same_world() {
    let yaml = World::from_scene_file(scenes().join("kitchen.yaml")).unwrap();
    let benchmark = World::from_scene_file(scenes().join("kitchen_robowflex.yaml")).unwrap();
    assert_eq!(benchmark.names().unwrap(), yaml.names().unwrap());
    for object in 0..yaml.len() as u32 {
        let (a, b) = (yaml.pose(object).unwrap(), benchmark.pose(object).unwrap());
        for axis in 0..3 {
            assert!((a.position[axis] - b.position[axis]).abs() < 1e-12, "object {object}");
        }
        assert_eq!(benchmark.shape_count(object).unwrap(), yaml.shape_count(object).unwrap());
    }
    let error = World::from_scene_file(scenes().join("box_position_too_short.yaml")).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Corrupt);
    let field = "line 10: world.collision_objects[0].primitive_poses[0].position";
    assert!(error.message().contains(field), "{}", error.message());
}

#[test]
fn scenes_from_text_and_their_errors() {
    let text = "room\n* block\n0 0 0.5\n0 0 0 1\n1\nbox\n1 1 1\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n.\n";
    let world = World::from_scene_str(text, SceneFormat::Text).unwrap();
    assert_eq!((world.len(), world.name(0).unwrap()), (1, "block".to_string()));
    let bad = World::from_scene_file(scenes().join("cylinder_missing_radius.yaml")).unwrap_err();
    assert_eq!(bad.kind(), ErrorKind::Corrupt);
    assert!(bad.message().contains("line") && bad.message().contains("dimensions"), "{}", bad.message());
    let torus = World::from_scene_file(scenes().join("unknown_shape.scene")).unwrap_err();
    assert!(torus.message().contains("torus"), "{}", torus.message());
    assert_eq!(World::from_scene_file("/nonexistent/room.scene").unwrap_err().kind(), ErrorKind::Io);
    let cone = "world:\n  collision_objects:\n    - id: c\n      primitives:\n        - {type: 4, dimensions: [1, 1]}\n";
    assert_eq!(World::from_scene_bytes(cone.as_bytes(), SceneFormat::Yaml).unwrap_err().kind(),
               ErrorKind::Unsupported);
}

#[test]
fn contacts_name_the_object_and_its_shape() {
    let world = World::from_scene_file(scenes().join("kitchen.yaml")).unwrap();
    // A ball 2 cm into the knob (table shape 2, at (1, 0, 0.8), r 0.05).
    let robot = sphere_at(0.05, 1.0, 0.0, 0.88);
    let mut query = new_query();
    let request = CollisionRequest { max_contacts: 8, compute_penetration: true, ..Default::default() };
    let hit = query.collide_with_world(None, &world, &robot, &request).unwrap();
    assert!(hit.collided);
    let contacts = query.contacts().unwrap();
    assert_eq!(contacts.len(), 1);
    assert_eq!((contacts[0].object, contacts[0].object_shape), (Some(0), 2));
    assert_eq!((contacts[0].cell_class, contacts[0].cell_size), (CellClass::Unknown, 0.0));
    assert!((contacts[0].depth - 0.02).abs() < 1e-6, "depth {}", contacts[0].depth);
}

#[test]
fn the_map_and_the_objects_together() {
    let tree = one_cell_map(); // the cell [0, 0.25]^3
    let mut world = World::new().unwrap();
    let wall = world.add_box("wall", [0.1, 1.0, 1.0], &pose_at(0.6, C0, C0)).unwrap(); // x from 0.55
    let robot = sphere_at(0.1, 0.35, C0, C0); // touches the cell (x 0.25) and is 0.1 from the wall
    let mut query = new_query();
    let request = CollisionRequest { max_contacts: 8, ..Default::default() };
    let hit = query.collide_with_world(Some(&tree), &world, &robot, &request).unwrap();
    assert_eq!((hit.collided, hit.contact_count), (true, 1));
    assert_eq!(query.contacts().unwrap()[0].object, None); // a cell
    // The nearest obstacle: the cell at 0.0, the wall 0.1 m away.
    let near = query.distance_with_world(Some(&tree), &world, &robot, &DistanceRequest::default()).unwrap();
    assert_eq!((near.found, near.object), (true, None));
    let beside_wall = sphere_at(0.1, 0.55 - 0.1 - 0.02, C0, C0); // 2 cm from the wall, 8 cm from the cell
    let near = query.distance_with_world(Some(&tree), &world, &beside_wall, &DistanceRequest::default()).unwrap();
    assert_eq!((near.object, near.object_shape), (Some(wall), 0));
    assert!((near.distance - 0.02).abs() < 1e-9, "distance {}", near.distance);
    assert!((near.point_on_cell[0] - 0.55).abs() < 1e-9, "witness {:?}", near.point_on_cell);
    // Without the world the same context answers for the map alone.
    assert!(query.distance(&tree, &beside_wall, &DistanceRequest::default()).unwrap().object.is_none());
}

#[test]
fn distance_to_the_objects_alone_per_link() {
    let world = kitchen();
    let mut robot = LinkSet::new().unwrap();
    for name in ["near_crate", "near_ball"] {
        let link = robot.add_link(name).unwrap();
        robot.add_shape(link, &Shape::sphere(0.1)).unwrap();
    }
    robot.set_poses(&[pose_at(1.5, 0.0, 0.0), pose_at(0.0, -1.0, 0.0)]).unwrap();
    let mut query = new_query();
    let request = DistanceRequest { per_link: true, ..Default::default() };
    let near = query.distance_with_world(None, &world, &robot, &request).unwrap();
    assert_eq!((near.found, near.link, near.object), (true, 0, Some(0)));
    assert!((near.distance - 0.3).abs() < 1e-9, "distance {}", near.distance); // 1.9 - 1.5 - 0.1
    let per_link = query.link_distances().unwrap();
    assert!((per_link[0] - 0.3).abs() < 1e-9 && (per_link[1] - 0.8).abs() < 1e-9, "{:?}", per_link);
}

#[test]
fn a_world_may_be_dropped_after_its_query() {
    let robot = sphere_at(0.1, 2.0, 0.0, 0.15);
    let mut query = new_query();
    {
        let world = kitchen();
        assert!(query.collide_with_world(None, &world, &robot, &Default::default()).unwrap().collided);
    }
    // The context kept no pointer to the dropped world: a map query runs.
    let tree = one_cell_map();
    assert!(!query.collide(&tree, &robot, &Default::default()).unwrap().collided);
    let error = query.collide_with_world(None, &kitchen(), &robot,
                                         &CollisionRequest { compute_cost: true, ..Default::default() });
    assert_eq!(error.unwrap_err().kind(), ErrorKind::InvalidArgument); // cost needs an octree
}

#[test]
fn worlds_are_queried_from_many_threads() {
    let world = kitchen();
    let robot = sphere_at(0.1, 2.0, 0.0, 0.15);
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| {
                let mut query = new_query();
                assert!(query.collide_with_world(None, &world, &robot, &Default::default()).unwrap().collided);
            });
        }
    });
}
