//! A user's program, run outside the repository against an installed lfem (bindings/outside/):
//! a 1 kg cube dropped 1 cm onto a static plane comes to rest on it, and the contact forces,
//! summed over the contacts and averaged over 0.5 s, carry its weight m g. Exits non-zero when
//! they do not; `cargo test` runs the same check.
use lfem::{BodyDef, BodyType, Mesh, Model, ShapeDef, ShapeType, World, WorldDef};
use std::process::ExitCode;

const H: f64 = 5e-4; // s, a fixed sub-step, about half the stable limit of this mesh
const SETTLE: usize = 1000; // steps (0.5 s) to land and come to rest
const WINDOW: usize = 1000; // steps (0.5 s) over which the contact forces are averaged

/// What the run measured.
struct Resting {
    mass: f64,         // kg
    weight: f64,       // N
    mean: [f64; 3],    // N, the summed contact force averaged over the window
    balance: f64,      // N, mean z - weight - change of momentum / window
    contacts: usize,   // at the end
    end: f64,          // s
}

fn drop_cube() -> Result<Resting, lfem::Error> {
    let mut world_def = WorldDef::default(); // gravity (0, 0, -9.81) m/s^2
    world_def.time_step = H;
    let mut world = World::new(&world_def)?;
    let mut floor_def = BodyDef::default();
    floor_def.body_type = BodyType::Static;
    let floor = world.create_body(&floor_def)?;
    let mut plane = ShapeDef::default();
    plane.shape_type = ShapeType::Plane; // z = 0, normal +z
    world.add_shape(floor, &plane)?;

    let mut mesh = Mesh::new_box([0.1, 0.1, 0.1], [2, 2, 2])?; // m, cells
    mesh.translate([-0.05, -0.05, 0.01])?; // bottom 1 cm above the plane
    let mut def = BodyDef::default();
    def.model = Model::NeoHookean;
    def.young_modulus = 1e6;
    def.density = 1000.0;
    def.damping = 0.0; // then gravity is the only force on the cube besides the contacts
    let cube = world.create_body(&def)?;
    world.add_mesh(cube, &mesh)?;
    let mass = world.mass(cube)?; // rho V = 1 kg
    let weight = mass * -world_def.gravity[2];

    for _ in 0..SETTLE {
        world.step(H)?;
    }
    let p0 = world.momentum(cube)?.0;
    let mut impulse = [0.0; 3];
    for _ in 0..WINDOW {
        world.step(H)?; // one sub-step: H is the fixed step
        for contact in world.contacts()? {
            for i in 0..3 {
                impulse[i] += contact.force[i] * H; // N s, summed over the contacts
            }
        }
    }
    let p1 = world.momentum(cube)?.0;
    let span = WINDOW as f64 * H;
    let mean = [impulse[0] / span, impulse[1] / span, impulse[2] / span];
    Ok(Resting {
        mass,
        weight,
        mean,
        balance: mean[2] - weight - (p1[2] - p0[2]) / span,
        contacts: world.contact_count()?,
        end: world.stats()?.time,
    })
}

/// What is wrong with the run (nothing when empty).
fn failures(r: &Resting) -> Vec<String> {
    let mut failed = Vec::new();
    // Newton's second law over the window: the momentum lfem reports changes in each sub-step by H
    // times the total force on the cube, the weight plus the contact forces (no damping; the tets'
    // elastic forces sum to zero), as long as the cube keeps touching the plane (a sub-step in
    // which it lands or lifts off entirely is off by m g H / 2, the half step of the synchronized
    // velocities). So the contact impulses equal the change of momentum plus the weight's impulse,
    // up to rounding (about 1e-15 of m g per step), and this fails if the cube bounces.
    if r.balance.abs() > 1e-9 * r.weight {
        failed.push(format!("contact impulses {:.3e} N off the momentum balance", r.balance));
    }
    // At rest the plane carries the weight. What is left of the drop is elastic vibration, whose
    // momentum is at most sqrt(2 m E_kin) (Cauchy-Schwarz over the lumped masses): about 0.017
    // kg m/s here (E_kin ~ 1.5e-4 J), so the mean over 0.5 s may differ from m g by up to
    // 2 * 0.017 / 0.5 = 0.07 N, 0.7 %; 1 % allows for that.
    if (r.mean[2] / r.weight - 1.0).abs() > 0.01 {
        failed.push(format!("mean contact force {:.6} N is not the weight {:.6} N", r.mean[2], r.weight));
    }
    // The scene is symmetric about x and y: the lateral (friction) forces cancel but for rounding.
    if r.mean[0].abs().max(r.mean[1].abs()) > 1e-6 * r.weight {
        failed.push(format!("lateral contact force ({:.3e}, {:.3e}) N", r.mean[0], r.mean[1]));
    }
    if r.contacts == 0 {
        failed.push("the cube does not touch the plane".into());
    }
    failed
}

fn main() -> ExitCode {
    let r = match drop_cube() {
        Ok(r) => r,
        Err(e) => {
            eprintln!("FAIL: {}", e);
            return ExitCode::FAILURE;
        }
    };
    let span = WINDOW as f64 * H;
    println!("lfem {}: cube of {:.6} kg dropped 0.01 m onto the plane z = 0", lfem::version_string(), r.mass);
    println!("resting from t = {:.6} s to t = {:.6} s: {} contacts at the end", r.end - span, r.end, r.contacts);
    println!("mean summed contact force z: {:.6} N (x, y below 1e-6 m g)", r.mean[2]);
    println!("weight m g: {:.6} N, ratio {:.6}", r.weight, r.mean[2] / r.weight);
    let failed = failures(&r);
    for failure in &failed {
        println!("FAIL: {}", failure);
    }
    if !failed.is_empty() {
        return ExitCode::FAILURE;
    }
    println!("OK: the plane carries the cube's weight and the contact impulses balance its momentum");
    ExitCode::SUCCESS
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_plane_carries_the_resting_cube() {
        let r = super::drop_cube().expect("the scene runs");
        let failed = super::failures(&r);
        assert!(failed.is_empty(), "{:?}", failed);
    }
}
