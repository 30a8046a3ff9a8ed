//! The scene shared by the C, Rust, C# and Python examples: a soft box (0.3 x 0.2 x 0.1 m,
//! neo-Hookean rubber) dropped from rest with its bottom at z = 2 m, gravity only, stepped 0.5 s
//! in 0.01 s calls; every 0.1 s it prints the time, the lowest node z, the centre-of-mass
//! velocity along z and the kinetic energy. Run: cargo run --offline --example falling_block
use lfem::{BodyDef, Mesh, Model, World, WorldDef};

fn main() -> Result<(), lfem::Error> {
    let size = [0.3, 0.2, 0.1]; // m
    let density = 400.0; // kg/m^3
    let mass = density * (size[0] * size[1] * size[2]);

    let mut world = World::new(&WorldDef::default())?; // gravity (0, 0, -9.81) m/s^2
    let mut mesh = Mesh::new_box(size, [3, 2, 1])?;
    mesh.translate([0.0, 0.0, 2.0])?;

    let mut def = BodyDef::default();
    def.model = Model::NeoHookean;
    def.young_modulus = 2e5; // Pa: soft rubber
    def.poisson_ratio = 0.3;
    def.density = density;
    let block = world.create_body(&def)?;
    world.add_mesh(block, &mesh)?;
    drop(mesh);

    for call in 1..=50 {
        world.step(0.01)?;
        if call % 10 != 0 {
            continue;
        }
        let lowest = world.positions(block)?.iter().map(|p| p[2]).fold(f64::INFINITY, f64::min);
        let stats = world.stats()?;
        println!(
            "t = {:.6} s  lowest z = {:.6} m  com vz = {:.6} m/s  kinetic energy = {:.6} J",
            stats.time,
            lowest,
            stats.linear_momentum[2] / mass,
            stats.kinetic_energy
        );
    }
    Ok(())
}
