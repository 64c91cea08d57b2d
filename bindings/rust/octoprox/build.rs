//! The rpath octoprox-sys chose for a liboctoprox outside the system's
//! library directories (DEP_OCTOPROX_RPATH), for this crate's tests and
//! examples: Cargo applies a link argument only to the package whose build
//! script prints it.  A binary crate of yours does the same in its build.rs,
//! with octoprox-sys among its dependencies.
fn main() {
    println!("cargo:rerun-if-env-changed=DEP_OCTOPROX_RPATH");
    if let Ok(dir) = std::env::var("DEP_OCTOPROX_RPATH") {
        println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir);
    }
}
