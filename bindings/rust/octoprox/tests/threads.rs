//! Many threads query one octree and one link set at once, each with its
//! own Query: Octree and LinkSet are Sync, Query is Send.
mod common;
use common::*;
use octoprox::{pose_at, CollisionRequest, DistanceRequest, LinkSet, Query, QueryOptions, Shape};

fn assert_send<T: Send>() {}
fn assert_sync<T: Sync>() {}

#[test]
fn queries_from_several_threads_on_one_octree() {
    assert_send::<octoprox::Octree>();
    assert_sync::<octoprox::Octree>();
    assert_sync::<LinkSet>();
    assert_send::<Query>();
    let tree = one_cell_map();
    // One link per height: link i is a sphere 0.1 m above the cell plus i cm.
    let mut links = LinkSet::new().unwrap();
    let mut poses = Vec::new();
    for i in 0..8 {
        let link = links.add_link(&format!("link{}", i)).unwrap();
        links.add_shape(link, &Shape::sphere(0.1)).unwrap();
        poses.push(pose_at(C0, C0, 0.45 + 0.01 * i as f64));
    }
    links.set_poses(&poses).unwrap();
    let (tree, links) = (&tree, &links);
    std::thread::scope(|scope| {
        let workers: Vec<_> = (0..4)
            .map(|_| {
                scope.spawn(move || {
                    let mut query = Query::new(&QueryOptions::default()).unwrap();
                    let request = DistanceRequest { per_link: true, ..Default::default() };
                    let mut answers = Vec::new();
                    for _ in 0..50 {
                        let near = query.distance(tree, links, &request).unwrap();
                        let hit = query.collide(tree, links, &CollisionRequest::default());
                        answers.push((near.distance, hit.unwrap().collided));
                        assert_eq!(query.link_distances().unwrap().len(), 8);
                    }
                    answers
                })
            })
            .collect();
        for worker in workers {
            for (distance, collided) in worker.join().unwrap() {
                assert!((distance - 0.1).abs() < 1e-9, "distance {}", distance);
                assert!(!collided);
            }
        }
    });
}
