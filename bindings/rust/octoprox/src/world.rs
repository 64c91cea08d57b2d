//! Known objects beside the sensed map (`opx_world`): tables, shelves,
//! walls and bins, as MoveIt keeps them in its planning scene.
//!
//! An object has a name, a pose in the map frame, an enabled flag and
//! [`Shape`]s (the link-set kinds: a box's FULL edges, a cylinder's FULL
//! length along z), each at a pose in the object frame.  Objects have no
//! padding (a link's padding is the margin); a mesh is a surface.  Indices
//! are positions: removing an object moves every later one down by one.
//! [`Query::collide_with_world`], [`Query::distance_with_world`],
//! [`Query::path_with_world`], [`Query::check_configurations_with_world`],
//! [`Query::check_motion_with_world`] and
//! [`Query::check_motions_with_world`] check a world's enabled objects,
//! with or without an octree (the world is set for the call alone);
//! contacts and distances name the object ([`crate::Contact::object`],
//! [`crate::DistanceResult::object`]).  [`LinkSet::attach_world_object`]
//! attaches a copy of an object to a link.
//!
//! ```
//! use octoprox::{pose_at, CollisionRequest, LinkSet, Query, Shape, World};
//!
//! let mut world = World::new()?;
//! let table = world.add_box("table", [1.0, 0.6, 0.04], &pose_at(1.0, 0.0, 0.72))?; // map frame
//! world.add_sphere("ball", 0.1, &pose_at(0.0, 2.0, 0.5))?;
//! assert_eq!((world.len(), world.find("table")?), (2, table));
//!
//! let mut robot = LinkSet::new()?;
//! let hand = robot.add_link("hand")?;
//! robot.add_shape(hand, &Shape::sphere(0.05))?;
//! robot.set_poses(&[pose_at(1.2, 0.1, 0.78)])?; // resting on the table top
//! let mut query = Query::new(&Default::default())?;
//! let request = CollisionRequest { max_contacts: 8, ..Default::default() };
//! let hit = query.collide_with_world(None, &world, &robot, &request)?; // no map: objects alone
//! assert!(hit.collided);
//! assert_eq!(query.contacts()?[0].object, Some(table));
//! world.set_enabled(table, false)?;
//! assert!(!query.collide_with_world(None, &world, &robot, &request)?.collided);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::c_enum;
use crate::error::{c_string, check, to_c_string, Result};
use crate::{check_version, sys, CollisionRequest, CollisionResult, DistanceRequest, DistanceResult, LinkSet,
            Octree, PathRequest, PathResult, Pose, Query, Shape, ShapeKind};
use std::path::Path;
use std::ptr;

c_enum! {
    /// The text formats of MoveIt planning scenes
    /// ([`World::from_scene_str`]).
    SceneFormat {
        /// A `moveit_msgs/PlanningScene` (or `PlanningSceneWorld`) as YAML,
        /// as `ros2 topic echo` and `rostopic echo` print it: ADD, APPEND,
        /// REMOVE and MOVE in order; BOX, SPHERE and CYLINDER primitives and
        /// meshes.  `header.frame_id` is taken as the map frame.
        Yaml = sys::OPX_SCENE_FORMAT_YAML,
        /// MoveIt's `.scene` text (`PlanningScene::saveGeometryToStream`,
        /// the RViz panel's export), with or without object poses.
        Text = sys::OPX_SCENE_FORMAT_TEXT,
    }
}

/// Named objects of shapes with poses in the map frame (see the module).
/// Reading methods take `&self` and may run on many threads at once, as
/// may queries using the world; changing methods take `&mut self`, so no
/// query can run with the world meanwhile.  The library copies what it is
/// given (names, vertices, poses).  An unknown object index, a bad size or
/// a zero quaternion is an [`crate::ErrorKind::InvalidArgument`] that
/// changes nothing.
#[derive(Debug)]
pub struct World {
    raw: *mut sys::opx_world,
}

// SAFETY: a world may move between threads, and functions taking a const
// handle (reads and queries) may run concurrently; only those are
// reachable through `&`.
unsafe impl Send for World {}
unsafe impl Sync for World {}

impl Drop for World {
    fn drop(&mut self) {
        // SAFETY: raw is a live handle, destroyed once; no query keeps it
        // (queries set a world for one call only).
        unsafe { sys::opx_world_destroy(self.raw) }
    }
}

fn create(f: impl FnOnce(*mut *mut sys::opx_world) -> sys::opx_status) -> Result<World> {
    check_version()?;
    let mut raw = ptr::null_mut();
    check(f(&mut raw))?;
    Ok(World { raw })
}

impl World {
    /// An empty world.
    pub fn new() -> Result<World> {
        // SAFETY: out is valid.
        create(|out| unsafe { sys::opx_world_create(out) })
    }

    /// The objects of a MoveIt planning scene file, in the format of its
    /// extension: `.yaml` or `.yml` ([`SceneFormat::Yaml`]), `.scene`
    /// ([`SceneFormat::Text`]); the YAML in MoveIt's message form or in
    /// robowflex's dialect (MotionBenchMaker's scenes: poses as lists,
    /// primitive types and operations as words), the robot state and the
    /// allowed collision matrix ignored.  An unreadable file is an
    /// [`crate::ErrorKind::Io`] error; a malformed one
    /// [`crate::ErrorKind::Corrupt`], the message naming the file, the line
    /// and the field; cones, planes and mesh files
    /// [`crate::ErrorKind::Unsupported`].
    pub fn from_scene_file(path: impl AsRef<Path>) -> Result<World> {
        let text = path.as_ref().to_string_lossy().into_owned();
        let path = to_c_string(&text, "World::from_scene_file: path")?;
        // SAFETY: path and out are valid for the call.
        create(|out| unsafe { sys::opx_world_load_scene_file(path.as_ptr(), out) })
    }

    /// As [`World::from_scene_file`], from a scene's text; errors name
    /// `data` for the file.
    pub fn from_scene_str(text: &str, format: SceneFormat) -> Result<World> {
        World::from_scene_bytes(text.as_bytes(), format)
    }

    /// As [`World::from_scene_str`], from bytes (UTF-8 text).
    pub fn from_scene_bytes(data: &[u8], format: SceneFormat) -> Result<World> {
        // SAFETY: data holds data.len() bytes for the call.
        create(|out| unsafe {
            sys::opx_world_load_scene_memory(data.as_ptr().cast(), data.len(), format.raw(), out)
        })
    }

    /// Adds an object named `name` (names need not be unique:
    /// [`World::find`] returns the first) at `pose` (the object frame in
    /// the map frame), enabled and without shapes; returns its index.
    /// [`World::add_shape`] gives it shapes.
    pub fn add_object(&mut self, name: &str, pose: &Pose) -> Result<u32> {
        let name = to_c_string(name, "World::add_object: name")?;
        let mut index = 0;
        // SAFETY: name is a C string, pose a valid pose; exclusive access.
        check(unsafe { sys::opx_world_add_object(self.raw, name.as_ptr(), pose, &mut index) })?;
        Ok(index)
    }

    /// Adds a shape of any kind to `object`, at `shape.pose` in the object
    /// frame; returns its index within the object.  A mesh gets its
    /// triangle tree here, once.
    pub fn add_shape(&mut self, object: u32, shape: &Shape<'_>) -> Result<u32> {
        let c = shape.to_c();
        let mut index = 0;
        // SAFETY: c borrows slices that outlive the call (the library copies
        // them); exclusive access.
        check(unsafe { sys::opx_world_add_shape(self.raw, object, &c, &mut index) })?;
        Ok(index)
    }

    /// Adds an object of one shape, centred on the object's origin, at
    /// `pose` (map frame); an object is never left without its shape.
    fn add_one(&mut self, name: &str, kind: ShapeKind<'_>, pose: &Pose) -> Result<u32> {
        let object = self.add_object(name, pose)?;
        if let Err(error) = self.add_shape(object, &Shape::new(kind)) {
            // SAFETY: exclusive access; the object was just added.
            unsafe { sys::opx_world_remove_object(self.raw, object) };
            return Err(error);
        }
        Ok(object)
    }

    /// Adds an object of one box of FULL edge lengths `size` (x, y, z;
    /// metres), centred at `pose` (map frame); returns its index.
    pub fn add_box(&mut self, name: &str, size: [f64; 3], pose: &Pose) -> Result<u32> {
        self.add_one(name, ShapeKind::Box { size }, pose)
    }

    /// Adds an object of one sphere of `radius` metres centred at `pose`.
    pub fn add_sphere(&mut self, name: &str, radius: f64, pose: &Pose) -> Result<u32> {
        self.add_one(name, ShapeKind::Sphere { radius }, pose)
    }

    /// Adds an object of one cylinder of `radius` and FULL `length` along
    /// its z axis (metres), centred at `pose` (map frame).  MoveIt gives
    /// `[height, radius]`: `length` is the height.
    pub fn add_cylinder(&mut self, name: &str, radius: f64, length: f64, pose: &Pose) -> Result<u32> {
        self.add_one(name, ShapeKind::Cylinder { radius, length }, pose)
    }

    /// Adds an object of one triangle surface: `vertices` in the object
    /// frame (metres), three vertex indices per triangle, the object at
    /// `pose` (map frame).
    pub fn add_mesh(&mut self, name: &str, vertices: &[[f64; 3]], triangles: &[[u32; 3]], pose: &Pose)
        -> Result<u32> {
        self.add_one(name, ShapeKind::Mesh { vertices, triangles }, pose)
    }

    /// Removes `object`; every later object moves down by one index.
    pub fn remove(&mut self, object: u32) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe { sys::opx_world_remove_object(self.raw, object) })
    }

    /// Moves `object`: `pose` is its frame in the map frame.
    pub fn set_pose(&mut self, object: u32, pose: &Pose) -> Result<()> {
        // SAFETY: pose is valid; exclusive access.
        check(unsafe { sys::opx_world_set_object_pose(self.raw, object, pose) })
    }

    /// The object's pose in the map frame.
    pub fn pose(&self, object: u32) -> Result<Pose> {
        let mut pose = Pose::default();
        // SAFETY: const call.
        check(unsafe { sys::opx_world_get_object_pose(self.raw, object, &mut pose) })?;
        Ok(pose)
    }

    /// Enables or disables `object`: disabled objects take part in no
    /// query.  Objects start enabled.
    pub fn set_enabled(&mut self, object: u32, enabled: bool) -> Result<()> {
        // SAFETY: exclusive access.
        check(unsafe { sys::opx_world_set_object_enabled(self.raw, object, i32::from(enabled)) })
    }

    /// Whether `object` takes part in queries.
    pub fn enabled(&self, object: u32) -> Result<bool> {
        let mut enabled = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_world_get_object_enabled(self.raw, object, &mut enabled) })?;
        Ok(enabled != 0)
    }

    /// The index of the first object named `name`; an
    /// [`crate::ErrorKind::InvalidArgument`] when none is.
    pub fn find(&self, name: &str) -> Result<u32> {
        let name = to_c_string(name, "World::find: name")?;
        let mut index = 0;
        // SAFETY: const call; name is a C string.
        check(unsafe { sys::opx_world_find_object(self.raw, name.as_ptr(), &mut index) })?;
        Ok(index)
    }

    /// The name of `object` (copied).
    pub fn name(&self, object: u32) -> Result<String> {
        let mut name = ptr::null();
        // SAFETY: const call; the name stays valid while we hold &self and
        // is copied at once.
        check(unsafe { sys::opx_world_get_object_name(self.raw, object, &mut name) })?;
        Ok(unsafe { c_string(name) })
    }

    /// Every object's name, in index order.
    pub fn names(&self) -> Result<Vec<String>> {
        (0..self.len() as u32).map(|object| self.name(object)).collect()
    }

    /// The number of objects.
    pub fn len(&self) -> usize {
        let mut count = 0u32;
        // SAFETY: const call on a live handle, which cannot fail.
        unsafe { sys::opx_world_get_object_count(self.raw, &mut count) };
        count as usize
    }

    /// Whether the world holds no object.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of shapes of `object`.
    pub fn shape_count(&self, object: u32) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_world_get_shape_count(self.raw, object, &mut count) })?;
        Ok(count)
    }

    /// Shape `shape` of `object` as stored (its pose in the object frame);
    /// convex and mesh vertices and triangles are borrowed from the world
    /// (a mesh keeps only the vertices its triangles use).
    pub fn shape(&self, object: u32, shape: u32) -> Result<Shape<'_>> {
        let mut c = sys::opx_shape::default();
        // SAFETY: const call; the returned arrays stay valid while the
        // world is unchanged, which the borrow of self guarantees.
        unsafe {
            check(sys::opx_world_get_shape(self.raw, object, shape, &mut c))?;
            Shape::from_c(&c, "World::shape")
        }
    }

    pub(crate) fn as_raw(&self) -> *const sys::opx_world {
        self.raw
    }
}

impl Query {
    /// Runs `call` with `world` set on this context, and detaches it again
    /// whatever the call returns, so the context never keeps a pointer to
    /// a world that Rust may drop.
    pub(crate) fn with_world<T>(&mut self, world: &World, call: impl FnOnce(&mut Query) -> Result<T>) -> Result<T> {
        // SAFETY: both handles are live; the world stays borrowed until it
        // is detached below.
        check(unsafe { sys::opx_query_set_world(self.as_raw_mut(), world.as_raw()) })?;
        let answer = call(self);
        // SAFETY: detaching (NULL) cannot fail on a live context.
        unsafe { sys::opx_query_set_world(self.as_raw_mut(), ptr::null()) };
        answer
    }

    /// [`Query::collide`] against the octree (`None`: no map) and the
    /// enabled objects of `world` together: the robot collides when a link
    /// touches a cell or an object.  [`Query::contacts`] then holds both,
    /// the octree's first, up to `max_contacts` together; an object
    /// contact has [`crate::Contact::object`] set and zero cell fields, and
    /// with `compute_penetration` the depth, normal and point of the shape
    /// pair.  Cost boxes come from the octree alone: `compute_cost` without
    /// an octree is an invalid argument.
    pub fn collide_with_world(&mut self, tree: Option<&Octree>, world: &World, links: &LinkSet,
                              request: &CollisionRequest) -> Result<CollisionResult> {
        self.with_world(world, |query| query.collide_tree(tree.map_or(ptr::null(), Octree::as_raw), links, request))
    }

    /// [`Query::distance`] to the octree (`None`: no map) and the enabled
    /// objects of `world`: the least of both.
    /// [`crate::DistanceResult::object`] names the nearest object (`None`
    /// for a cell), `point_on_cell` then lying on it; per-link distances
    /// are the least per link.  Objects are measured exactly (`abs_err` and
    /// `rel_err` apply to the octree).
    pub fn distance_with_world(&mut self, tree: Option<&Octree>, world: &World, links: &LinkSet,
                               request: &DistanceRequest) -> Result<DistanceResult> {
        self.with_world(world, |query| query.distance_tree(tree.map_or(ptr::null(), Octree::as_raw), links, request))
    }

    /// [`Query::path`] against the octree (`None`: no map) and the enabled
    /// objects of `world` together: a waypoint collides when it touches
    /// either, distances are the least of both.  Objects have no cost: the
    /// path's cost comes from the octree alone (`compute_cost` needs one).
    pub fn path_with_world(&mut self, tree: Option<&Octree>, world: &World, links: &LinkSet, poses: &[Pose],
                           request: &PathRequest) -> Result<PathResult> {
        self.with_world(world, |query| query.path_tree(tree.map_or(ptr::null(), Octree::as_raw), links, poses, request))
    }
}
