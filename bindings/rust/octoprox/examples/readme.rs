use octoprox::{pose_at, CollisionRequest, InsertOptions, LinkSet, Octree, Query, Shape};

fn main() -> Result<(), octoprox::Error> {
    let mut map = Octree::new(&Default::default())?; // 5 cm cells
    let frame = [[1.0f32, 0.0, 0.0], [1.0, 0.5, 0.0]]; // sensor frame, metres
    let sensor = InsertOptions { sensor_pose: pose_at(0.0, 0.0, 1.2), ..Default::default() };
    map.insert_points(&frame, &sensor)?;
    let mut robot = LinkSet::new()?;
    let hand = robot.add_link("hand")?;
    robot.add_shape(hand, &Shape::sphere(0.08))?;
    robot.set_poses(&[pose_at(0.95, 0.0, 1.2)])?; // map frame
    let hit = Query::new(&Default::default())?.collide(&map, &robot, &CollisionRequest::default())?;
    println!("collided: {}", hit.collided);
    Ok(())
}
