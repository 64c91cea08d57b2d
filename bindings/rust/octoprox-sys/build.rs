//! Links liboctoprox: from OPX_LIB_DIR (a build tree, as ctest sets it),
//! else from the directories pkg-config reports, else from the system's
//! default library path.
use std::env;
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-env-changed=OPX_LIB_DIR");
    println!("cargo:rerun-if-env-changed=PKG_CONFIG_PATH");
    if let Ok(dir) = env::var("OPX_LIB_DIR") {
        println!("cargo:rustc-link-search=native={}", dir);
    } else {
        for dir in pkg_config_lib_dirs() {
            println!("cargo:rustc-link-search=native={}", dir);
        }
    }
    println!("cargo:rustc-link-lib=dylib=octoprox");
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
