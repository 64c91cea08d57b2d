//! Getting started in Rust: a map from a file, a robot from URDF, one
//! query, then a batch of configurations.  Uses the shared data
//! ($OPX_DATA_DIR, else ../shared/data): the geb079 map and the PR2; exits
//! 77 without it.
use octoprox::{BasePoses, BatchRequest, LinkSet, Octree, Query, UrdfOptions};
use std::path::Path;

fn main() -> Result<(), octoprox::Error> {
    let data = std::env::var("OPX_DATA_DIR").unwrap_or_else(|_| "../shared/data".into());
    let data = Path::new(&data);
    let map_path = data.join("maps/geb079.bt");
    if !map_path.exists() {
        println!("skipped: no {} (set OPX_DATA_DIR)", map_path.display());
        std::process::exit(77);
    }
    // A map from a .bt file (the resolution comes from the file) and a robot
    // from URDF (package:// meshes resolved through NAME=DIR).
    let map = Octree::load_file(&map_path, &Default::default())?;
    let pr2 = data.join("robots/pr2_description");
    let urdf = UrdfOptions {
        package_dirs: vec![format!("moveit_resources_pr2_description={}", pr2.display())],
        ..Default::default()
    };
    let robot = LinkSet::from_urdf_file(pr2.join("urdf/robot.xml"), &urdf)?;

    // One query: every joint at 0, the root at the map origin.
    let mut query = Query::new(&Default::default())?;
    let hit = query.collide(&map, &robot, &Default::default())?;
    let near = query.distance(&map, &robot, &Default::default())?;
    println!("collided: {}, distance {:.3} m", hit.collided, near.distance);

    // A batch: 100 rows of every joint (model order), the right shoulder
    // swept from -2 to 0.5 rad, two threads, with distances.
    let joints = robot.joint_count()? as usize;
    let shoulder = robot.find_joint("r_shoulder_pan_joint")? as usize;
    let mut rows = vec![0.0; 100 * joints];
    for (i, row) in rows.chunks_mut(joints).enumerate() {
        row[shoulder] = -2.0 + 2.5 * i as f64 / 99.0;
    }
    let request = BatchRequest { compute_distance: true, max_threads: 2, ..Default::default() };
    let answers = query.check_configurations(&map, &robot, &rows, BasePoses::Origin, &request)?;
    let count = answers.collided.iter().filter(|&&c| c).count();
    let least = answers.distances.iter().copied().fold(f64::INFINITY, f64::min);
    println!("batch: {count} of 100 configurations collide, least distance {least:.3} m");
    Ok(())
}
