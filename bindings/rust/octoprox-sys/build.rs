//! Links liboctoprox: from OPX_LIB_DIR (a build tree, as ctest sets it),
//! else from the directories pkg-config reports, else from the system's
//! default library path.
//!
//! A library found outside the system's library directories (a build tree,
//! /usr/local, /opt, a home prefix) gets an rpath, so programs start without
//! LD_LIBRARY_PATH.  Cargo applies link arguments only to the package that
//! prints them: this crate's own targets get the rpath here, and the
//! directory goes to the build scripts of crates depending on this one as
//! DEP_OCTOPROX_RPATH (the `octoprox` crate's build script passes it on to
//! its tests and examples; a binary crate does the same in its build.rs).
use std::env;
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-env-changed=OPX_LIB_DIR");
    println!("cargo:rerun-if-env-changed=PKG_CONFIG_PATH");
    let dirs = match env::var("OPX_LIB_DIR") {
        Ok(dir) => vec![dir],
        Err(_) => pkg_config_lib_dirs(),
    };
    for dir in &dirs {
        println!("cargo:rustc-link-search=native={}", dir);
    }
    println!("cargo:rustc-link-lib=dylib=octoprox");
    if let Some(dir) = dirs.iter().find_map(|dir| rpath_dir(Path::new(dir))) {
        println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir.display());
        println!("cargo:rpath={}", dir.display());
    }
}

/// The `-L` directories of `pkg-config --libs octoprox`; none when
/// pkg-config or the package is missing.
fn pkg_config_lib_dirs() -> Vec<String> {
    let output = match Command::new("pkg-config").args(["--libs-only-L", "octoprox"]).output() {
        Ok(output) if output.status.success() => output.stdout,
        _ => return Vec::new(),
    };
    String::from_utf8_lossy(&output)
        .split_whitespace()
        .filter_map(|flag| flag.strip_prefix("-L"))
        .map(str::to_owned)
        .collect()
}

/// `dir` made absolute, when it holds liboctoprox and is not one of the
/// directories the dynamic loader searches without being told.
fn rpath_dir(dir: &Path) -> Option<PathBuf> {
    let dir = dir.canonicalize().ok()?;
    let has_library = dir.join("liboctoprox.so").exists() || dir.join("liboctoprox.dylib").exists();
    (has_library && !is_system_dir(&dir)).then_some(dir)
}

/// /lib, /usr/lib, their lib64 and multiarch (e.g. x86_64-linux-gnu)
/// folders.  /usr/local/lib is not among them: it is found only through
/// the loader's cache, which an install does not refresh.
fn is_system_dir(dir: &Path) -> bool {
    let system = ["/lib", "/lib64", "/usr/lib", "/usr/lib64"];
    let is_system = |path: &Path| system.iter().any(|s| path == Path::new(s));
    let multiarch = dir.file_name().map_or(false, |name| name.to_string_lossy().contains("-linux-"));
    is_system(dir) || (multiarch && dir.parent().map_or(false, is_system))
}
