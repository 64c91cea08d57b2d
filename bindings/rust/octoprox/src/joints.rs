//! The active joints of a link set made from URDF (`include/octoprox/robot.h`):
//! the revolute, continuous and prismatic joints that mimic no other joint,
//! in model order.  Their values decide every link pose: mimic joints follow
//! their leaders, fixed joints do not move, and floating and planar joints
//! are held at their origin (place a mobile base with the base pose).  For
//! a robot without floating or planar joints they are MoveIt's active
//! joints; MoveIt and Pinocchio order joints along the kinematic tree,
//! which may differ from the URDF's order, so match vectors by name
//! ([`LinkSet::active_joint_names`]).
//!
//! ```
//! use octoprox::{LinkSet, UrdfOptions};
//!
//! // A slider with two fingers (the right one mimics the left) and a fixed tool.
//! let urdf = r#"<robot name="gripper">
//!   <link name="base"/><link name="carriage"/><link name="left"/><link name="right"/><link name="tool"/>
//!   <joint name="slide" type="prismatic"><parent link="base"/><child link="carriage"/>
//!     <axis xyz="1 0 0"/><limit lower="0" upper="1" velocity="1" effort="1"/></joint>
//!   <joint name="left" type="prismatic"><parent link="carriage"/><child link="left"/>
//!     <axis xyz="0 1 0"/><limit lower="0" upper="0.04" velocity="1" effort="1"/></joint>
//!   <joint name="right" type="prismatic"><parent link="carriage"/><child link="right"/>
//!     <axis xyz="0 1 0"/><limit lower="-0.04" upper="0" velocity="1" effort="1"/>
//!     <mimic joint="left" multiplier="-1"/></joint>
//!   <joint name="tool" type="fixed"><parent link="carriage"/><child link="tool"/>
//!     <origin xyz="0 0 0.1"/></joint>
//! </robot>"#;
//! let mut robot = LinkSet::from_urdf_string(urdf, &UrdfOptions::default())?;
//! assert_eq!((robot.joint_count()?, robot.active_joint_count()?), (4, 2));
//! assert_eq!(robot.active_joints()?, [0, 1]);
//! assert_eq!(robot.active_joint_names()?, ["slide", "left"]);
//! robot.set_active_joint_positions(&[0.5, 0.03], None)?; // the root at the map origin
//! assert_eq!(robot.joint_positions()?, [0.5, 0.03, -0.03, 0.0]); // model order
//! assert_eq!(robot.active_joint_positions()?, [0.5, 0.03]);
//! let right = robot.find_link("right")?;
//! assert_eq!(robot.pose(right)?.position, [0.5, -0.03, 0.0]);
//! # Ok::<(), octoprox::Error>(())
//! ```
use crate::error::{check, Result};
use crate::{sys, LinkSet, Pose};
use std::ptr;

impl LinkSet {
    /// Number of active joints: the length of an active joint vector (0 for
    /// a set not made from URDF).
    pub fn active_joint_count(&self) -> Result<u32> {
        let mut count = 0;
        // SAFETY: const call.
        check(unsafe { sys::opx_linkset_get_active_joint_count(self.as_raw(), &mut count) })?;
        Ok(count)
    }

    /// The model indices of the active joints, in model order: value i of an
    /// active joint vector sets joint `active_joints()[i]`
    /// ([`LinkSet::joint_info`]).
    pub fn active_joints(&self) -> Result<Vec<u32>> {
        let mut joints = vec![0u32; self.active_joint_count()? as usize];
        let mut count = 0usize;
        // SAFETY: joints holds joints.len() values; const call.
        check(unsafe {
            sys::opx_linkset_get_active_joints(self.as_raw(), joints.as_mut_ptr(), joints.len(),
                                               &mut count)
        })?;
        joints.truncate(count);
        Ok(joints)
    }

    /// The active joints' names, in the order of an active joint vector.
    pub fn active_joint_names(&self) -> Result<Vec<String>> {
        self.active_joints()?.into_iter().map(|j| Ok(self.joint_info(j)?.name)).collect()
    }

    /// FK from the active joints alone: one value per active joint, in the
    /// order of [`LinkSet::active_joint_names`] (radians or metres, finite,
    /// within +-1e6), the root link at `base` in the map frame (None:
    /// identity).  Mimic joints follow their leaders; fixed, floating and
    /// planar joints need no value.  The poses equal those of
    /// [`LinkSet::set_joint_positions`] with the same values in model order.
    /// Another length is an invalid argument, a set not made from URDF
    /// [`crate::ErrorKind::Unsupported`]; on error nothing changes.
    pub fn set_active_joint_positions(&mut self, positions: &[f64], base: Option<&Pose>) -> Result<()> {
        let base = base.map_or(ptr::null(), |pose| pose as *const Pose);
        // SAFETY: positions holds len values; exclusive access.
        check(unsafe {
            sys::opx_linkset_set_active_joint_positions(self.as_raw_mut(), positions.as_ptr(),
                                                        positions.len(), base)
        })
    }

    /// The active joints' current positions, in the order of an active
    /// joint vector.
    pub fn active_joint_positions(&self) -> Result<Vec<f64>> {
        let positions = self.joint_positions()?;
        Ok(self.active_joints()?.into_iter().map(|j| positions[j as usize]).collect())
    }
}
