//! Link sets from URDF, their joints and forward kinematics
//! (`include/octoprox/robot.h`).  Joint positions are in radians (revolute,
//! continuous) or metres (prismatic), in the URDF's joint order ("model
//! order", fixed joints included), or the active joints' alone
//! ([`LinkSet::set_active_joint_positions`]: the moving joints that mimic
//! none).
//!
//! ```
//! use octoprox::{JointType, LinkSet, UrdfOptions};
//!
//! let urdf = r#"<robot name="arm">
//!   <link name="base"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
//!   <link name="arm"><collision><origin xyz="0.25 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
//!   <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
//!     <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" velocity="1" effort="10"/></joint>
//! </robot>"#;
//! let mut robot = LinkSet::from_urdf_string(urdf, &UrdfOptions::default())?;
//! let shoulder = robot.joint_info(robot.find_joint("shoulder")?)?;
//! assert_eq!((shoulder.joint_type, shoulder.limits), (JointType::Revolute, Some((-1.5, 1.5))));
//! robot.set_joint_positions(&[std::f64::consts::FRAC_PI_2], None)?; // the root at the origin
//! let arm = robot.find_link("arm")?;
//! assert_eq!(robot.pose(arm)?.position, [0.0, 0.0, 0.2]); // the link frame, map frame
//! assert_eq!(robot.joint_positions()?, [std::f64::consts::FRAC_PI_2]);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::enums::{c_enum, known};
use crate::error::{c_string, check, to_c_string, Result};
use crate::{check_version, sys, LinkSet, Pose};
use std::ffi::CString;
use std::os::raw::c_char;
use std::path::{Path, PathBuf};
use std::ptr;

/// How a URDF's mesh files are found, and an optional SRDF.
#[derive(Debug, Clone, Default)]
pub struct UrdfOptions {
    /// Resolve `package://NAME/rest`: each entry is a folder (tried as
    /// `DIR/NAME/rest`, then `DIR/rest` when DIR ends in NAME) or
    /// `"NAME=DIR"` (`DIR/rest`).
    pub package_dirs: Vec<String>,
    /// Base of relative mesh paths (default: the URDF file's folder, or the
    /// current directory for a string).
    pub base_dir: Option<PathBuf>,
    /// An SRDF whose `<disable_collisions>` pairs are read: self-collision
    /// queries skip them.
    pub srdf_path: Option<PathBuf>,
}

c_enum! {
    /// The type of a URDF joint.  Floating and planar joints are not moved
    /// by forward kinematics: they stay at their origin, as if fixed.
    JointType {
        /// No motion.
        Fixed = sys::OPX_JOINT_FIXED,
        /// A rotation about the axis within limits, radians.
        Revolute = sys::OPX_JOINT_REVOLUTE,
        /// A rotation about the axis without limits, radians.
        Continuous = sys::OPX_JOINT_CONTINUOUS,
        /// A translation along the axis, metres.
        Prismatic = sys::OPX_JOINT_PRISMATIC,
        /// Six degrees of freedom; held at its origin.
        Floating = sys::OPX_JOINT_FLOATING,
        /// Motion in a plane; held at its origin.
        Planar = sys::OPX_JOINT_PLANAR,
    }
}

/// One URDF joint, from [`LinkSet::joint_info`].
#[derive(Debug, Clone, PartialEq)]
pub struct JointInfo {
    /// The joint's name in the URDF.
    pub name: String,
    /// Its type.
    pub joint_type: JointType,
    /// The parent link's index in the link set.
    pub parent_link: Option<u32>,
    /// The child link's index in the link set.
    pub child_link: Option<u32>,
    /// Unit axis in the child link frame.
    pub axis: [f64; 3],
    /// The child link frame in the parent link frame at position 0.
    pub origin: Pose,
    /// Lower and upper position limits (metres or radians) when the URDF
    /// has `<limit>`; continuous joints: -infinity, +infinity.
    pub limits: Option<(f64, f64)>,
    /// Velocity limit as in the URDF (m/s or rad/s); 0 when absent.
    pub velocity: f64,
    /// Effort limit as in the URDF (N or N m); 0 when absent.
    pub effort: f64,
    /// The joint this one mimics, the multiplier and the offset: position =
    /// multiplier * master + offset.
    pub mimic: Option<(u32, f64, f64)>,
}

/// The C strings and pointer array an `opx_urdf_options` borrows.
struct CUrdfOptions {
    _strings: Vec<CString>,
    _dirs: Vec<*const c_char>,
    raw: sys::opx_urdf_options,
}

fn path_c_string(path: &Path, what: &str) -> Result<CString> {
    to_c_string(&path.to_string_lossy(), what)
}

impl UrdfOptions {
    fn to_c(&self) -> Result<CUrdfOptions> {
        let mut strings = Vec::new();
        for dir in &self.package_dirs {
            strings.push(to_c_string(dir, "UrdfOptions::package_dirs")?);
        }
        let dirs: Vec<*const c_char> = strings.iter().map(|s| s.as_ptr()).collect();
        let mut raw = sys::opx_urdf_options {
            package_dirs: if dirs.is_empty() { ptr::null() } else { dirs.as_ptr() },
            package_dir_count: dirs.len(),
            ..Default::default()
        };
        if let Some(dir) = &self.base_dir {
            strings.push(path_c_string(dir, "UrdfOptions::base_dir")?);
            raw.base_dir = strings.last().map_or(ptr::null(), |s| s.as_ptr());
        }
        if let Some(srdf) = &self.srdf_path {
            strings.push(path_c_string(srdf, "UrdfOptions::srdf_path")?);
            raw.srdf_path = strings.last().map_or(ptr::null(), |s| s.as_ptr());
        }
        // Moving a CString into the Vec moves its handle, not its heap
        // buffer, so the pointers taken above stay valid.
        Ok(CUrdfOptions { _strings: strings, _dirs: dirs, raw })
    }
}

fn index_or_none(index: u32) -> Option<u32> {
    if i64::from(index) == sys::OPX_JOINT_NONE {
        None
    } else {
        Some(index)
    }
}

impl LinkSet {
    /// A link set from a URDF file: one link per `<link>` (same names, file
    /// order), one shape per `<collision>` (box, sphere, cylinder, mesh read
    /// with assimp), poses at every joint 0 with the root at the map
    /// origin.  Errors: [`crate::ErrorKind::Io`] (the file or a mesh cannot
    /// be read, an unknown package), [`crate::ErrorKind::Corrupt`]
    /// (malformed XML, URDF or SRDF, bad geometry),
    /// [`crate::ErrorKind::Unsupported`] (other collision geometry).
    pub fn from_urdf_file(path: impl AsRef<Path>, options: &UrdfOptions) -> Result<LinkSet> {
        let path = path_c_string(path.as_ref(), "LinkSet::from_urdf_file: path")?;
        let options = options.to_c()?;
        // SAFETY: path and the options' strings live across the call.
        LinkSet::create(|out| unsafe {
            sys::opx_linkset_load_urdf_file(path.as_ptr(), &options.raw, out)
        })
    }

    /// A link set from URDF XML text, as [`LinkSet::from_urdf_file`];
    /// relative mesh paths start at `options.base_dir` or the current
    /// directory.
    pub fn from_urdf_string(xml: &str, options: &UrdfOptions) -> Result<LinkSet> {
        let xml = to_c_string(xml, "LinkSet::from_urdf_string: xml")?;
        let options = options.to_c()?;
        // SAFETY: as above.
        LinkSet::create(|out| unsafe {
            sys::opx_linkset_load_urdf_string(xml.as_ptr(), &options.raw, out)
        })
    }

    fn create(f: impl FnOnce(*mut *mut sys::opx_linkset) -> sys::opx_status) -> Result<LinkSet> {
        check_version()?;
        let mut raw = ptr::null_mut();
        check(f(&mut raw))?;
        Ok(LinkSet::from_raw(raw))
    }

    /// Number of URDF joints (0 for a hand-built set).
    pub fn joint_count(&self) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_joint_count(self.as_raw(), &mut count) })?;
        Ok(count)
    }

    /// The joint named `name`; an invalid argument when none.
    pub fn find_joint(&self, name: &str) -> Result<u32> {
        let name = to_c_string(name, "LinkSet::find_joint: name")?;
        let mut index = 0;
        // SAFETY: const call; name is a C string.
        check(unsafe { sys::opx_linkset_find_joint(self.as_raw(), name.as_ptr(), &mut index) })?;
        Ok(index)
    }

    /// A joint's type, links, axis, origin, limits and mimic.
    pub fn joint_info(&self, joint: u32) -> Result<JointInfo> {
        let mut j = sys::opx_joint_info::default();
        // SAFETY: const call; the name is copied while we hold &self.
        check(unsafe { sys::opx_linkset_get_joint_info(self.as_raw(), joint, &mut j) })?;
        Ok(JointInfo {
            name: unsafe { c_string(j.name) },
            joint_type: known(JointType::from_raw(j.type_), j.type_, "joint type")?,
            parent_link: index_or_none(j.parent_link),
            child_link: index_or_none(j.child_link),
            axis: j.axis,
            origin: j.origin,
            limits: if j.has_limits != 0 { Some((j.lower, j.upper)) } else { None },
            velocity: j.velocity,
            effort: j.effort,
            mimic: index_or_none(j.mimic_joint).map(|m| (m, j.mimic_multiplier, j.mimic_offset)),
        })
    }

    /// FK: every joint position in model order (`positions.len()` = the
    /// joint count), the root link at `base` in the map frame (None:
    /// identity); then every link pose is set.  Values of fixed, floating
    /// and planar joints are ignored, a mimic joint follows its master;
    /// values must be finite and within +-1e6.  A vector of the active
    /// joints alone goes to [`LinkSet::set_active_joint_positions`].  A set not made from URDF:
    /// [`crate::ErrorKind::Unsupported`].  On error nothing changes.
    pub fn set_joint_positions(&mut self, positions: &[f64], base: Option<&Pose>) -> Result<()> {
        let base = base.map_or(ptr::null(), |pose| pose as *const Pose);
        // SAFETY: positions holds len values; exclusive access.
        check(unsafe {
            sys::opx_linkset_set_joint_positions(self.as_raw_mut(), positions.as_ptr(),
                                                 positions.len(), base)
        })
    }

    /// FK with only the named joints changed (any subset; the others keep
    /// their values, initially 0): naming the active joints alone sets
    /// every pose, values of mimic, fixed, floating and planar joints are
    /// ignored.  An unknown name is an invalid argument naming it.
    pub fn set_named_joint_positions(&mut self, named: &[(&str, f64)], base: Option<&Pose>)
        -> Result<()> {
        let mut names = Vec::with_capacity(named.len());
        for (name, _) in named {
            names.push(to_c_string(name, "LinkSet::set_named_joint_positions: name")?);
        }
        let pointers: Vec<*const c_char> = names.iter().map(|n| n.as_ptr()).collect();
        let positions: Vec<f64> = named.iter().map(|(_, value)| *value).collect();
        let base = base.map_or(ptr::null(), |pose| pose as *const Pose);
        // SAFETY: names, pointers and positions live across the call.
        check(unsafe {
            sys::opx_linkset_set_named_joint_positions(self.as_raw_mut(), pointers.as_ptr(),
                                                       positions.as_ptr(), named.len(), base)
        })
    }

    /// The joint positions in model order, as FK uses them (mimic joints:
    /// their computed value; fixed, floating, planar: 0).
    pub fn joint_positions(&self) -> Result<Vec<f64>> {
        let mut count = 0usize;
        // SAFETY: capacity 0 with NULL asks for the count.
        let status = unsafe {
            sys::opx_linkset_get_joint_positions(self.as_raw(), ptr::null_mut(), 0, &mut count)
        };
        if status != sys::OPX_ERROR_BUFFER_TOO_SMALL {
            check(status)?;
        }
        let mut positions = vec![0.0; count];
        // SAFETY: positions holds `count` doubles.
        check(unsafe {
            sys::opx_linkset_get_joint_positions(self.as_raw(), positions.as_mut_ptr(), count,
                                                 &mut count)
        })?;
        Ok(positions)
    }

    /// The SRDF `<disable_collisions>` pairs as the file lists them, as
    /// link indices (later [`LinkSet::set_pair_enabled`] calls change the
    /// checked pairs, not this list).
    pub fn disabled_pairs(&self) -> Result<Vec<(u32, u32)>> {
        let mut count = 0;
        // SAFETY: const calls.
        check(unsafe { sys::opx_linkset_get_disabled_pair_count(self.as_raw(), &mut count) })?;
        (0..count)
            .map(|pair| {
                let (mut a, mut b) = (0, 0);
                let raw = self.as_raw();
                check(unsafe { sys::opx_linkset_get_disabled_pair(raw, pair, &mut a, &mut b) })
                    .map(|_| (a, b))
            })
            .collect()
    }
}
