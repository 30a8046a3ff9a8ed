//! Finds liblfem and links it dynamically. The first place that has it wins:
//!
//! 1. `LFEM_LIB_DIR`, the folder that holds it (named explicitly, so it overrides the rest);
//! 2. pkg-config: the libdir of `lfem.pc` (`PKG_CONFIG_PATH=<prefix>/lib/pkgconfig` finds an lfem
//!    installed anywhere by `cmake --install`; one in /usr/local needs nothing);
//! 3. the CMake build folder of the source checkout these crates sit in (`build/` at its root).
//!
//! The library is then copied into this crate's build output (`OUT_DIR/lib`) and linked from
//! there: cargo puts the link folders that lie inside its target folder on the loader's path of
//! what it runs, so `cargo run` and `cargo test` of any program that depends on these crates
//! find the library without `LD_LIBRARY_PATH` (a link argument such as an rpath would reach only
//! this crate's own tests). A binary started by hand still needs the library on the loader's
//! path, as any dynamically linked program does. The folder found is passed on to dependent
//! build scripts as `DEP_LFEM_LIB_DIR` (the `links = "lfem"` key).
use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The library's file names, the versioned one (its SONAME, which the loader looks for) first.
fn file_names(target_os: &str, major: &str) -> Vec<String> {
    match target_os {
        "macos" => vec![format!("liblfem.{}.dylib", major), "liblfem.dylib".into()],
        "windows" => vec!["lfem.dll".into(), "lfem.lib".into()],
        _ => vec![format!("liblfem.so.{}", major), "liblfem.so".into()],
    }
}

fn library_in(dir: &Path, names: &[String]) -> Option<PathBuf> {
    names.iter().map(|name| dir.join(name)).find(|path| path.exists())
}

/// The libdir of lfem.pc, checked to be of this crate's version (0.x: the same minor).
fn pkg_config_libdir(major_minor: &str) -> Result<PathBuf, String> {
    let exe = env::var("PKG_CONFIG").unwrap_or_else(|_| "pkg-config".into());
    let run = |args: &[&str]| -> Result<String, String> {
        let out = Command::new(&exe).args(args).output().map_err(|e| format!("{}: {}", exe, e))?;
        if !out.status.success() {
            return Err(String::from_utf8_lossy(&out.stderr).trim().to_string());
        }
        Ok(String::from_utf8_lossy(&out.stdout).trim().to_string())
    };
    let version = run(&["--modversion", "lfem"])?;
    if !(version == major_minor || version.starts_with(&format!("{}.", major_minor))) {
        return Err(format!("lfem.pc is version {}, these bindings need {}.x", version, major_minor));
    }
    Ok(PathBuf::from(run(&["--variable=libdir", "lfem"])?))
}

/// Copies `from` (its target if a link) to `to`, replacing an older copy.
fn copy(from: &Path, to: &Path) {
    let _ = fs::remove_file(to);
    fs::copy(from, to).unwrap_or_else(|e| panic!("lfem-sys: copying {} to {}: {}", from.display(), to.display(), e));
}

fn main() {
    for var in ["LFEM_LIB_DIR", "PKG_CONFIG", "PKG_CONFIG_PATH", "PKG_CONFIG_LIBDIR", "PKG_CONFIG_SYSROOT_DIR"] {
        println!("cargo:rerun-if-env-changed={}", var);
    }
    println!("cargo:rerun-if-changed=build.rs");

    let version = env::var("CARGO_PKG_VERSION").expect("CARGO_PKG_VERSION");
    let mut parts = version.split('.');
    let major = parts.next().unwrap_or("0").to_string();
    let major_minor = format!("{}.{}", major, parts.next().unwrap_or("0"));
    let target_os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let names = file_names(&target_os, &major);

    let mut tried = Vec::new();
    let mut found = None;
    match env::var_os("LFEM_LIB_DIR").filter(|dir| !dir.is_empty()) {
        Some(dir) => {
            let dir = PathBuf::from(dir);
            match library_in(&dir, &names) {
                Some(lib) => found = Some(lib),
                None => tried.push(format!("LFEM_LIB_DIR={}: no {}", dir.display(), names.join(" or "))),
            }
        }
        None => {
            match pkg_config_libdir(&major_minor) {
                Ok(dir) => match library_in(&dir, &names) {
                    Some(lib) => found = Some(lib),
                    None => tried.push(format!("pkg-config lfem: no library in its libdir {}", dir.display())),
                },
                Err(why) => tried.push(format!("pkg-config lfem: {}", why)),
            }
            if found.is_none() {
                let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
                // bindings/rust/lfem-sys -> the checkout's root
                let root = manifest.join("..").join("..").join("..");
                if root.join("include_c").join("lfem.h").exists() {
                    let build = root.join("build");
                    match library_in(&build, &names) {
                        Some(lib) => found = Some(lib),
                        None => tried.push(format!("the checkout's build folder {}: not built", build.display())),
                    }
                }
            }
        }
    }
    let lib = found.unwrap_or_else(|| {
        panic!(
            "lfem-sys: liblfem not found. Tried:\n  {}\nInstall lfem (cmake --install <build> --prefix <prefix>) and set \
             PKG_CONFIG_PATH=<prefix>/lib/pkgconfig, or set LFEM_LIB_DIR to the folder that holds the library.",
            tried.join("\n  ")
        )
    });
    println!("cargo:rerun-if-changed={}", lib.display());
    let lib_dir = lib.parent().map(Path::to_path_buf).unwrap_or_default();
    let lib_dir = lib_dir.canonicalize().unwrap_or(lib_dir);

    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR")).join("lib");
    fs::create_dir_all(&out).expect("lfem-sys: creating OUT_DIR/lib");
    if target_os == "windows" {
        // The import library links; the DLL itself is found beside the program or on PATH.
        for name in &names {
            if let Some(file) = library_in(&lib_dir, std::slice::from_ref(name)) {
                copy(&file, &out.join(name));
            }
        }
    } else {
        // The soname for the loader, the plain name for the linker's -llfem: two copies of one
        // small file keep this free of symbolic links.
        for name in &names {
            copy(&lib, &out.join(name));
        }
    }
    println!("cargo:rustc-link-search=native={}", out.display());
    println!("cargo:rustc-link-lib=dylib=lfem");
    println!("cargo:lib_dir={}", lib_dir.display());
}
