//! The time of one tiny collision query called from Rust through the safe
//! crate, beside opx-bench-call-overhead's from C and the Python calls
//! (bench/call_overhead/python_overhead.py runs all three).
//!
//! The scene of the C, Python and Rust tests: one occupied 25 cm cell
//! [0, 0.25]^3 and one link holding a 10 cm sphere that touches the cell's
//! face x = 0.25; every call is `Query::collide` with a default request
//! (stop at the first contact), as a caller writes it.  Times are CPU time
//! of the calling thread, so other programs' load on the machine counts
//! only through the caches.  Prints the median of the rounds in nanoseconds
//! per call, as the C program does:
//!     ns_per_call 563.2
//!
//!   cargo run --release --example call_overhead -- [--calls N] [--rounds R]
use octoprox::{pose_at, CollisionRequest, InsertMode, InsertOptions, LinkSet, Octree,
               OctreeOptions, Query, Shape};
use std::process::ExitCode;

const CELL: f64 = 0.25;
const CENTRE: f64 = 0.125;

/// One cell hit by one endpoint; a sphere of radius 0.1 at x = 0.35.
fn scene() -> Result<(Octree, LinkSet), octoprox::Error> {
    let mut map = Octree::new(&OctreeOptions { resolution: CELL, ..Default::default() })?;
    let endpoints = InsertOptions { mode: InsertMode::Endpoints, ..Default::default() };
    map.insert_points(&[[CENTRE, CENTRE, CENTRE]], &endpoints)?;
    let mut links = LinkSet::new()?;
    let ball = links.add_link("ball")?;
    links.add_shape(ball, &Shape::sphere(0.1))?;
    links.set_poses(&[pose_at(0.35, CENTRE, CENTRE)])?;
    Ok((map, links))
}

#[repr(C)]
struct Timespec {
    seconds: std::os::raw::c_long,
    nanoseconds: std::os::raw::c_long,
}

extern "C" {
    fn clock_gettime(clock: i32, out: *mut Timespec) -> i32;
}

/// CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID), seconds.
fn thread_seconds() -> f64 {
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut now = Timespec { seconds: 0, nanoseconds: 0 };
    // SAFETY: clock_gettime writes one timespec, which `now` is.
    let status = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut now) };
    assert_eq!(status, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    now.seconds as f64 + 1e-9 * now.nanoseconds as f64
}

/// ns per call over `calls` calls; an error when a call fails or misses
/// the cell.
fn time_round(query: &mut Query, map: &Octree, links: &LinkSet, calls: u64)
              -> Result<f64, String> {
    let mut collided = 0u64;
    let start = thread_seconds();
    for _ in 0..calls {
        let hit = query.collide(map, links, &CollisionRequest::default()).map_err(|e| e.to_string())?;
        collided += u64::from(hit.collided);
    }
    let seconds = thread_seconds() - start;
    if collided != calls {
        return Err(format!("{} of {} calls missed the cell", calls - collided, calls));
    }
    Ok(1e9 * seconds / calls as f64)
}

/// --calls N (1..1e8) and --rounds R (1..101), defaults 200,000 and 5.
fn parse(mut args: impl Iterator<Item = String>) -> Option<(u64, usize)> {
    let (mut calls, mut rounds) = (200_000u64, 5usize);
    while let Some(flag) = args.next() {
        let value = args.next()?;
        match flag.as_str() {
            "--calls" => calls = value.parse().ok()?,
            "--rounds" => rounds = value.parse().ok()?,
            _ => return None,
        }
    }
    ((1..=100_000_000).contains(&calls) && (1..=101).contains(&rounds)).then_some((calls, rounds))
}

fn run(calls: u64, rounds: usize) -> Result<f64, String> {
    let (map, links) = scene().map_err(|e| format!("scene: {}", e))?;
    let mut query = Query::new(&Default::default()).map_err(|e| format!("query: {}", e))?;
    time_round(&mut query, &map, &links, calls / 10 + 1)?; // warm-up
    let mut times = (0..rounds)
        .map(|_| time_round(&mut query, &map, &links, calls))
        .collect::<Result<Vec<f64>, String>>()?;
    times.sort_by(f64::total_cmp);
    Ok(times[rounds / 2])
}

fn main() -> ExitCode {
    let (calls, rounds) = match parse(std::env::args().skip(1)) {
        Some(parsed) => parsed,
        None => {
            eprintln!("usage: call_overhead [--calls N (1..1e8)] [--rounds R (1..101)]");
            return ExitCode::from(2);
        }
    };
    match run(calls, rounds) {
        Ok(median) => {
            println!("ns_per_call {:.1}", median);
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("call_overhead: {}", message);
            ExitCode::FAILURE
        }
    }
}
