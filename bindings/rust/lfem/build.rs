//! lfem-sys finds and links liblfem; a build script's rpath only reaches its own crate's
//! binaries, so this one repeats it (from DEP_LFEM_LIB_DIR) for this crate's tests and examples.
use std::env;

fn main() {
    println!("cargo:rerun-if-env-changed=DEP_LFEM_LIB_DIR");
    println!("cargo:rerun-if-changed=build.rs");
    let target_os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if let Some(dir) = env::var_os("DEP_LFEM_LIB_DIR") {
        if target_os != "windows" {
            println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir.to_string_lossy());
        }
    }
}
