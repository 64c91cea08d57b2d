//! Link sets from URDF, their joints and forward kinematics
//! (`include/octoprox/robot.h`).
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

/// One URDF joint (see `opx_joint_info`).
#[derive(Debug, Clone, PartialEq)]
pub struct JointInfo {
    pub name: String,
    /// `consts::OPX_JOINT_*`.
    pub joint_type: i32,
    pub parent_link: Option<u32>,
    pub child_link: Option<u32>,
    /// Unit axis in the child link frame.
    pub axis: [f64; 3],
    /// The child link frame in the parent link frame at position 0.
    pub origin: Pose,
    /// Position limits (metres or radians) when the URDF has `<limit>`.
    pub limits: Option<(f64, f64)>,
    pub velocity: f64,
    pub effort: f64,
    /// The joint this one mimics: position = multiplier * master + offset.
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
    /// A link set from a URDF file: one link per `<link>`, one shape per
    /// `<collision>`, poses at every joint 0 with the root at the origin.
    pub fn from_urdf_file(path: impl AsRef<Path>, options: &UrdfOptions) -> Result<LinkSet> {
        let path = path_c_string(path.as_ref(), "LinkSet::from_urdf_file: path")?;
        let options = options.to_c()?;
        // SAFETY: path and the options' strings live across the call.
        LinkSet::create(|out| unsafe {
            sys::opx_linkset_load_urdf_file(path.as_ptr(), &options.raw, out)
        })
    }

    /// A link set from URDF XML text.
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

    /// The joint named `name`.
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
            joint_type: j.type_,
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
    /// identity); then every link pose is set.
    pub fn set_joint_positions(&mut self, positions: &[f64], base: Option<&Pose>) -> Result<()> {
        let base = base.map_or(ptr::null(), |pose| pose as *const Pose);
        // SAFETY: positions holds len values; exclusive access.
        check(unsafe {
            sys::opx_linkset_set_joint_positions(self.as_raw_mut(), positions.as_ptr(),
                                                 positions.len(), base)
        })
    }

    /// FK with only the named joints changed (the others keep their values).
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

    /// The joint positions in model order, as FK uses them.
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

    /// The SRDF `<disable_collisions>` pairs, as link indices.
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
