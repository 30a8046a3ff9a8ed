#!/usr/bin/env bash
# ctest bindings_outside_rust: rust/ (a program depending on lfem = "0.5") built and run with
# cargo outside the repository, against the installed lfem. The crates come as a registry would
# give them: cargo package makes lfem-sys and lfem, and a local directory source stands in for
# crates.io (nothing is downloaded). The build script finds the library through PKG_CONFIG_PATH;
# cargo run and cargo test load it without LD_LIBRARY_PATH.
#
# usage: check_rust.sh PREFIX LIBDIR CARGO
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cargo=$3
command -v "$cargo" > /dev/null || die "cargo not found ('$cargo')"

mkdir -p "$tmp/crates" "$tmp/registry" "$tmp/.cargo"
cp "$bindings/rust/Cargo.toml" "$tmp/crates/"
cp -r "$bindings/rust/lfem-sys" "$bindings/rust/lfem" "$tmp/crates/"
rm -rf "$tmp/crates"/*/target
cat > "$tmp/.cargo/config.toml" <<CONFIG
# The test's stand-in for crates.io: the packages cargo package made, in a directory source.
[source.crates-io]
replace-with = "lfem-packages"
[source.lfem-packages]
directory = "$tmp/registry"
CONFIG
for crate in lfem-sys lfem; do  # lfem-sys first: packaging lfem resolves it from the registry
  step "cargo package -p $crate"
  (cd "$tmp/crates" && "$cargo" package --offline --no-verify --allow-dirty -p "$crate" \
     --target-dir "$tmp/package-target") > "$tmp/package.log" 2>&1 ||
    { cat "$tmp/package.log"; die "cargo package -p $crate failed"; }
  version=$(sed -n 's/^version = "\(.*\)"/\1/p' "$tmp/crates/$crate/Cargo.toml" | head -n 1)
  tar -xzf "$tmp/package-target/package/$crate-$version.crate" -C "$tmp/registry"
  mv "$tmp/registry/$crate-$version" "$tmp/registry/$crate"
  echo '{"files":{},"package":null}' > "$tmp/registry/$crate/.cargo-checksum.json"
done

cp -r "$outside/rust" "$tmp/app"
cd "$tmp/app"
step "PKG_CONFIG_PATH=$PKG_CONFIG_PATH cargo run --offline"
"$cargo" run --offline --quiet || die "cargo run failed"
found=$(sed -n 's/^cargo:lib_dir=//p' target/debug/build/lfem-sys-*/output)
echo "   lfem-sys found the library in $found"
[[ "$found" == "$prefix/$libdir" ]] || die "the build script did not take the installed library"
step "cargo test --offline"
"$cargo" test --offline --quiet 2>&1 | tee "$tmp/test.log"
grep -q "test result: ok. 1 passed" "$tmp/test.log" || die "cargo test of the program failed"
echo "OK: the Rust program built and ran against the installed lfem"
