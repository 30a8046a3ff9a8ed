//! Finds liblfem: the folder named by the LFEM_LIB_DIR environment variable if set, else the
//! CMake build folder at the repository root (`cmake -S . -B build`). Links it dynamically, with
//! an rpath to that folder so this crate's tests run without LD_LIBRARY_PATH, and passes the
//! folder on to dependent crates as DEP_LFEM_LIB_DIR (the `links = "lfem"` key).
use std::env;
use std::path::{Path, PathBuf};

fn library_present(dir: &Path) -> bool {
    ["liblfem.so", "liblfem.dylib", "lfem.lib", "liblfem.a"]
        .iter()
        .any(|name| dir.join(name).exists())
}

fn main() {
    println!("cargo:rerun-if-env-changed=LFEM_LIB_DIR");
    println!("cargo:rerun-if-changed=build.rs");

    let dir = match env::var_os("LFEM_LIB_DIR") {
        Some(dir) if !dir.is_empty() => PathBuf::from(dir),
        _ => {
            let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
            // bindings/rust/lfem-sys -> the repository root -> build
            manifest.join("..").join("..").join("..").join("build")
        }
    };
    let dir = dir.canonicalize().unwrap_or(dir);
    if !library_present(&dir) {
        panic!(
            "lfem-sys: liblfem not found in {}; build it first (cmake -S . -B build && cmake --build build) \
             or set LFEM_LIB_DIR to the folder that holds it",
            dir.display()
        );
    }
    println!("cargo:rustc-link-search=native={}", dir.display());
    println!("cargo:rustc-link-lib=dylib=lfem");
    let target_os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os != "windows" {
        println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir.display());
    }
    println!("cargo:lib_dir={}", dir.display());
}
