//! Real simulations through the safe API, checked against closed forms, plus error handling,
//! handle invalidation, buffers and contacts.
use lfem::{
    AttachTo, Body, BodyDef, BodyType, Contact, EventType, Mesh, Model, QueryFilter, ShapeDef, ShapeType, Status,
    WarningKind, World, WorldDef,
};

const G: f64 = 9.81;

/// A block of `size` (m) and `density`, lifted to z = 2 m, in a fresh default world.
fn block_world(model: Model, size: [f64; 3], density: f64) -> (World, Body) {
    let mut world = World::new(&WorldDef::default()).unwrap();
    let mut mesh = Mesh::new_box(size, [3, 2, 1]).unwrap();
    mesh.translate([0.0, 0.0, 2.0]).unwrap();
    let mut def = BodyDef::default();
    def.model = model;
    def.young_modulus = 2e5;
    def.density = density;
    let body = world.create_body(&def).unwrap();
    world.add_mesh(body, &mesh).unwrap();
    (world, body)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn falling_block_follows_free_fall() {
    // Uniform gravity on an unstressed body at rest accelerates every node by exactly g: no
    // deformation ever appears, so each node follows z0 - g t^2/2, each velocity is -g t, the
    // momentum is -m g t and the kinetic energy m (g t)^2 / 2, with m = rho V (lumped masses sum
    // to the body's mass). The central-difference update is exact for a quadratic trajectory,
    // so only round-off remains: ~1e-16 relative per sub-step, over at most a few thousand
    // sub-steps of values of order 1, far below the tolerances 1e-11 (positions, velocities)
    // and 1e-10 relative (momentum, energy) used here.
    let size = [0.3, 0.2, 0.1];
    let density = 400.0;
    let mass = density * size[0] * size[1] * size[2];
    for &model in &[Model::Paper, Model::Corotational, Model::NeoHookean, Model::Linear] {
        let (mut world, block) = block_world(model, size, density);
        let start = world.positions(block).unwrap();
        assert_eq!(start.len(), 4 * 3 * 2);
        assert!(close(world.mass(block).unwrap(), mass, 1e-12 * mass), "{:?}: mass", model);
        for call in 1..=50 {
            world.step(0.01).unwrap();
            if call % 10 != 0 {
                continue;
            }
            let stats = world.stats().unwrap();
            let t = stats.time;
            assert!(close(t, 0.01 * call as f64, 1e-12), "{:?}: t = {}", model, t);
            let x = world.positions(block).unwrap();
            let v = world.velocities(block).unwrap();
            for (i, (p, p0)) in x.iter().zip(&start).enumerate() {
                assert!(close(p[0], p0[0], 1e-11) && close(p[1], p0[1], 1e-11), "{:?} node {} drifted", model, i);
                assert!(
                    close(p[2], p0[2] - 0.5 * G * t * t, 1e-11),
                    "{:?} node {}: z = {}, closed form {}",
                    model,
                    i,
                    p[2],
                    p0[2] - 0.5 * G * t * t
                );
                assert!(close(v[i][2], -G * t, 1e-11), "{:?} node {}: vz = {}", model, i, v[i][2]);
                assert!(close(v[i][0], 0.0, 1e-11) && close(v[i][1], 0.0, 1e-11));
            }
            let p = stats.linear_momentum;
            assert!(close(p[2], -mass * G * t, 1e-10 * mass * G * t), "{:?}: pz = {}", model, p[2]);
            assert!(close(p[0], 0.0, 1e-10) && close(p[1], 0.0, 1e-10));
            let ke = 0.5 * mass * (G * t) * (G * t);
            assert!(close(stats.kinetic_energy, ke, 1e-10 * ke), "{:?}: ke = {}", model, stats.kinetic_energy);
            assert!(stats.strain_energy.abs() <= 1e-10 * ke, "{:?}: strain {}", model, stats.strain_energy);
            let (body_p, _) = world.momentum(block).unwrap();
            assert!(close(body_p[2], -mass * G * t, 1e-10 * mass * G * t), "{:?}: body pz", model);
        }
        assert_eq!(world.stats().unwrap().body_count, 1);
    }
}

#[test]
fn lowest_point_and_centre_of_mass_of_the_example_scene() {
    // The scene of examples/falling_block.rs: the lowest nodes start at z = 2 m.
    let (mut world, block) = block_world(Model::NeoHookean, [0.3, 0.2, 0.1], 400.0);
    for _ in 0..50 {
        world.step(0.01).unwrap();
    }
    let t = world.stats().unwrap().time;
    let lowest = world.positions(block).unwrap().iter().map(|p| p[2]).fold(f64::INFINITY, f64::min);
    assert!(close(lowest, 2.0 - 0.5 * G * t * t, 1e-11));
    assert!(close(t, 0.5, 1e-12));
}

#[test]
fn defaults_come_from_the_c_library() {
    let w = WorldDef::default();
    assert_eq!(w.gravity, [0.0, 0.0, -9.81]);
    assert_eq!(w.time_step, 0.0);
    assert_eq!(w.step_safety, 0.9);
    assert_eq!(w.contact_iterations, 200);
    assert_eq!(w.thread_count, 1);
    assert_eq!(w.max_substeps, 1_000_000);
    assert!(!w.allow_unstable_step);
    let b = BodyDef::default();
    assert_eq!(b.body_type, BodyType::Deformable);
    assert_eq!(b.model, Model::Paper);
    assert_eq!(b.young_modulus, 1e6);
    assert_eq!(b.poisson_ratio, 0.3);
    assert_eq!(b.density, 1000.0);
    assert_eq!(b.friction, 0.5);
    assert_eq!(b.category_bits, 1);
    assert_eq!(b.mask_bits, u32::MAX);
}

#[test]
fn bad_arguments_give_the_status_and_the_message() {
    let (mut world, _block) = block_world(Model::Paper, [0.3, 0.2, 0.1], 400.0);
    let before = world.stats().unwrap();

    let err = world.step(-1.0).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().starts_with("lfem_world_step"), "message: {}", err.message());
    assert!(err.message().contains("dt"), "message: {}", err.message());
    assert!(err.to_string().contains("LFEM_INVALID_ARGUMENT"), "display: {}", err);
    assert_eq!(world.stats().unwrap(), before, "a failed call changed the world");

    let err = world.step(f64::NAN).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);

    let mut def = BodyDef::default();
    def.poisson_ratio = 0.5;
    let err = world.create_body(&def).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().starts_with("lfem_body_create"), "message: {}", err.message());

    let mut bad = WorldDef::default();
    bad.step_safety = 1.5;
    let err = World::new(&bad).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().contains("step_safety"), "message: {}", err.message());

    // An inverted tet (negative volume) is an invalid mesh.
    let body = world.create_body(&BodyDef::default()).unwrap();
    let nodes = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
    let err = world.add_mesh_data(body, &nodes, &[[0, 1, 2, 3]]).unwrap_err();
    assert_eq!(err.status(), Status::InvalidMesh);
    assert!(err.message().starts_with("lfem_body_add_mesh"), "message: {}", err.message());
    assert_eq!(world.node_count(body).unwrap(), 0);
    // The same tet correctly oriented is accepted.
    world.add_mesh_data(body, &nodes, &[[0, 2, 1, 3]]).unwrap();
    assert_eq!(world.node_count(body).unwrap(), 4);
    assert_eq!(world.tet_count(body).unwrap(), 1);

    let err = Mesh::load_gmsh("/nonexistent/lfem/mesh.msh").unwrap_err();
    assert_eq!(err.status(), Status::IoError);
}

#[test]
fn destroyed_and_foreign_handles_are_refused() {
    let (mut world, block) = block_world(Model::Paper, [0.3, 0.2, 0.1], 400.0);
    let copy = block;
    assert!(world.is_valid(block));
    world.destroy_body(block).unwrap();
    assert!(!world.is_valid(copy));
    // Each error names the call made, not the count asked inside it first.
    let calls: [(&str, lfem::Result<usize>); 4] = [
        ("lfem_body_get_positions", world.positions(copy).map(|v| v.len())),
        ("lfem_body_get_velocities", world.velocities(copy).map(|v| v.len())),
        ("lfem_body_get_von_mises_stress", world.von_mises_stress(copy).map(|v| v.len())),
        ("lfem_body_get_boundary_triangles", world.boundary_triangles(copy).map(|v| v.len())),
    ];
    for (name, result) in calls {
        let err = result.unwrap_err();
        assert_eq!(err.status(), Status::InvalidHandle);
        assert!(err.message().starts_with(&format!("{}:", name)), "message: {}", err.message());
    }
    assert_eq!(world.destroy_body(copy).unwrap_err().status(), Status::InvalidHandle);
    assert_eq!(world.stats().unwrap().body_count, 0);

    // A new body may reuse the slot, never the generation.
    let fresh = world.create_body(&BodyDef::default()).unwrap();
    assert!(world.is_valid(fresh));
    assert!(!world.is_valid(copy));
    assert_ne!(fresh, copy);

    assert_eq!(world.node_count(Body::NULL).unwrap_err().status(), Status::InvalidHandle);
    assert!(!world.is_valid(Body::NULL));

    // A handle of another world.
    let (other, other_block) = block_world(Model::Paper, [0.3, 0.2, 0.1], 400.0);
    assert!(other.is_valid(other_block));
    let mut third = World::new(&WorldDef::default()).unwrap();
    assert_eq!(third.positions(other_block).unwrap_err().status(), Status::InvalidHandle);
    assert_eq!(third.destroy_body(other_block).unwrap_err().status(), Status::InvalidHandle);
}

#[test]
fn short_buffers_are_refused_untouched() {
    let (world, block) = block_world(Model::Paper, [0.3, 0.2, 0.1], 400.0);
    let n = world.node_count(block).unwrap();
    let mut short = vec![[7.0; 3]; n - 1];
    let err = world.positions_into(block, &mut short).unwrap_err();
    assert_eq!(err.status(), Status::BufferTooSmall);
    assert!(short.iter().all(|p| *p == [7.0; 3]));
    let mut long = vec![[7.0; 3]; n + 2];
    world.positions_into(block, &mut long).unwrap();
    assert_eq!(long[n], [7.0; 3]);
    assert_eq!(&long[..n], &world.positions(block).unwrap()[..]);
}

#[test]
fn contact_query_of_a_single_body_is_empty() {
    // A lone falling block touches nothing: the query gives a count of 0, an empty list, and
    // leaves a caller's buffer alone.
    let (mut world, _block) = block_world(Model::NeoHookean, [0.3, 0.2, 0.1], 400.0);
    world.step(0.05).unwrap();
    assert_eq!(world.contact_count().unwrap(), 0);
    assert!(world.contacts().unwrap().is_empty());
    assert_eq!(world.contacts_into(&mut []).unwrap(), 0);
    let mut sentinel = Contact::default();
    sentinel.node = 12345;
    let mut buffer = [sentinel; 4];
    assert_eq!(world.contacts_into(&mut buffer).unwrap(), 0);
    assert!(buffer.iter().all(|c| *c == sentinel));
    assert_eq!(world.stats().unwrap().contact_count, 0);
}

#[test]
fn mesh_views_and_gravity_change() {
    let mesh = Mesh::new_box([0.3, 0.2, 0.1], [3, 2, 1]).unwrap();
    assert_eq!(mesh.node_count(), 24);
    assert_eq!(mesh.tet_count(), 36);
    assert_eq!(mesh.positions().len(), 24);
    assert!(mesh.positions().iter().all(|p| p[0] >= 0.0 && p[0] <= 0.3 && p[1] <= 0.2 && p[2] <= 0.1));
    assert!(mesh.tets().iter().flatten().all(|&i| i < 24));
    assert_eq!(Mesh::new_box([0.3, 0.2, 0.1], [0, 2, 1]).unwrap_err().status(), Status::InvalidArgument);

    // Sideways gravity: x0 + a t^2/2 along x, nothing along z.
    let (mut world, block) = block_world(Model::Corotational, [0.3, 0.2, 0.1], 400.0);
    world.set_gravity([2.0, 0.0, 0.0]).unwrap();
    let start = world.positions(block).unwrap();
    world.step(0.3).unwrap();
    let t = world.stats().unwrap().time;
    for (p, p0) in world.positions(block).unwrap().iter().zip(&start) {
        assert!(close(p[0], p0[0] + t * t, 1e-11));
        assert!(close(p[2], p0[2], 1e-11));
    }
    assert_eq!(world.set_gravity([f64::NAN, 0.0, 0.0]).unwrap_err().status(), Status::InvalidArgument);
    assert!(world.stable_step().unwrap() > 0.0);
}

#[test]
fn version_of_the_loaded_library() {
    let (major, minor, patch) = lfem::version();
    assert_eq!((major, minor, patch), (lfem::sys::LFEM_VERSION_MAJOR, lfem::sys::LFEM_VERSION_MINOR, lfem::sys::LFEM_VERSION_PATCH));
    assert_eq!(lfem::version_string(), format!("{}.{}.{}", major, minor, patch));
    // The crate's version is the library's it was written for.
    assert_eq!(lfem::version_string(), env!("CARGO_PKG_VERSION"));
    assert!(Status::InvalidMesh.to_string().starts_with("LFEM_INVALID_MESH"));
}

#[test]
fn two_bar_impact_matches_the_one_dimensional_wave_solution() {
    // The paper's Fig. 3: steel bars of L = 0.254 m, sections 0.0254 x 0.0254 and
    // 0.0254 x 0.0224 m, approaching at 5.1359 m/s each across a gap of 2.54e-4 m, nu = 0,
    // no gravity, no friction. 1-D wave solution: c = sqrt(E/rho) = 5134.85 m/s; the contact
    // lasts 2L/c = 98.93 us; the force plateau Z1 Z2/(Z1 + Z2) 2v (Z = rho c A) gives an
    // impulse of 12.375 N s; final velocities -4.491 and +5.781 m/s. Tolerances as in the C++
    // test (tests/physics/test_two_bar_impact.cpp): 2 % on the impulse (mesh dispersion over 40
    // elements per bar), 3 % on the velocities; contact forces and momentum changes are the same
    // multipliers seen twice, so they agree to round-off (1e-9 relative).
    let (l, b, h1, h2, gap) = (0.254, 0.0254, 0.0254, 0.0224, 2.54e-4);
    let (v0, rho, e) = (5.1359, 7844.0, 206.82e9);
    let mut def = WorldDef::default();
    def.gravity = [0.0; 3];
    let mut world = World::new(&def).unwrap();
    let mut bar = |size: [f64; 3], offset: [f64; 3], v: f64| {
        let mut mesh = Mesh::new_box(size, [40, 4, 4]).unwrap();
        mesh.translate(offset).unwrap();
        let mut d = BodyDef::default();
        d.model = Model::Paper;
        d.young_modulus = e;
        d.poisson_ratio = 0.0;
        d.density = rho;
        d.friction = 0.0;
        d.linear_velocity = [v, 0.0, 0.0];
        let body = world.create_body(&d).unwrap();
        world.add_mesh(body, &mesh).unwrap();
        body
    };
    let bar1 = bar([l, b, h1], [-l - gap / 2.0, -b / 2.0, -h1 / 2.0], v0);
    let bar2 = bar([l, b, h2], [gap / 2.0, -b / 2.0, -h2 / 2.0], -v0);
    let (m1, m2) = (world.mass(bar1).unwrap(), world.mass(bar2).unwrap());
    assert!(close(m1, rho * l * b * h1, 1e-12 * m1) && close(m2, rho * l * b * h2, 1e-12 * m2));
    let (p10, _) = world.momentum(bar1).unwrap();
    let (p20, _) = world.momentum(bar2).unwrap();

    let h = 0.9 * world.stable_step().unwrap();
    let mut impulse = 0.0; // N s, contact forces on bar 2 along +x, summed over time
    let mut contacts = Vec::new();
    let mut seen = 0usize;
    while world.stats().unwrap().time < 200e-6 {
        world.step(h).unwrap();
        let n = world.contact_count().unwrap();
        contacts.resize(n, Contact::default());
        assert_eq!(world.contacts_into(&mut contacts).unwrap(), n);
        if n > 0 {
            // A buffer one short is refused and left alone.
            let mut short = vec![Contact::default(); n - 1];
            assert_eq!(world.contacts_into(&mut short).unwrap_err().status(), Status::BufferTooSmall);
            assert!(short.iter().all(|c| *c == Contact::default()));
        }
        seen = seen.max(n);
        for c in &contacts {
            assert!(c.body_a == bar1 || c.body_a == bar2);
            assert!(c.body_b == bar1 || c.body_b == bar2);
            assert_ne!(c.body_a, c.body_b);
            assert_eq!(c.shape(), None);
            let sign = if c.body_a == bar2 { 1.0 } else { -1.0 };
            impulse += sign * c.force[0] * h;
        }
    }
    assert!(seen > 0, "the bars never touched");
    let (p1, _) = world.momentum(bar1).unwrap();
    let (p2, _) = world.momentum(bar2).unwrap();
    assert!(close(impulse, 12.375, 0.02 * 12.375), "impulse {} N s", impulse);
    assert!(close(impulse, p2[0] - p20[0], 1e-9 * 12.375), "impulse vs bar 2's momentum");
    assert!(close(impulse, p10[0] - p1[0], 1e-9 * 12.375), "impulse vs bar 1's momentum");
    assert!(close(p1[0] / m1, -4.491, 0.03 * 4.491), "v1 = {}", p1[0] / m1);
    assert!(close(p2[0] / m2, 5.781, 0.03 * 5.781), "v2 = {}", p2[0] / m2);
    assert!((p1[0] + p2[0] - p10[0] - p20[0]).abs() < 1e-10 * (m1 + m2) * v0, "momentum not conserved");
}

#[test]
fn block_on_a_static_plane_touches_the_shape() {
    // A block released 1 mm above a static plane (z = 0, normal +z): after 0.1 s it has landed;
    // every contact names the floor's shape 0, its normal is +z and its force pushes up
    // (frictionless, so the force is along the normal).
    let mut world = World::new(&WorldDef::default()).unwrap();
    let mut floor_def = BodyDef::default();
    floor_def.body_type = BodyType::Static;
    let floor = world.create_body(&floor_def).unwrap();
    let plane = ShapeDef::default();
    assert_eq!(plane.shape_type, ShapeType::Plane);
    assert_eq!(plane.rotation, [1.0, 0.0, 0.0, 0.0]);
    world.add_shape(floor, &plane).unwrap();

    let mut mesh = Mesh::new_box([0.3, 0.2, 0.1], [3, 2, 1]).unwrap();
    mesh.translate([0.0, 0.0, 0.001]).unwrap();
    let mut d = BodyDef::default();
    d.young_modulus = 2e5;
    d.density = 400.0;
    d.friction = 0.0;
    d.damping = 5.0;
    let block = world.create_body(&d).unwrap();
    world.add_mesh(block, &mesh).unwrap();
    world.step(0.1).unwrap();

    let contacts = world.contacts().unwrap();
    assert!(!contacts.is_empty(), "the block did not land");
    for c in &contacts {
        assert_eq!(c.body_a, block);
        assert_eq!(c.body_b, floor);
        assert_eq!(c.shape(), Some(0));
        assert!(close(c.normal[2], 1.0, 1e-12) && close(c.normal[0], 0.0, 1e-12));
        assert!(c.force[2] >= 0.0 && close(c.force[0], 0.0, 1e-9) && close(c.force[1], 0.0, 1e-9));
    }
    // A plane on a deformable body is refused.
    let err = world.add_shape(block, &plane).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().starts_with("lfem_body_add_shape"), "message: {}", err.message());
}

#[test]
fn checkpoint_continues_bit_for_bit() {
    // A saved and reloaded world is the same world: the same handles read the same positions,
    // and both go on to bitwise identical states (lfem's checkpoint contract).
    let (mut world, block) = block_world(Model::Corotational, [0.3, 0.2, 0.1], 400.0);
    world.step(0.05).unwrap();
    let path = std::env::temp_dir().join(format!("lfem_rust_{}.ckpt", std::process::id()));
    world.save(&path).unwrap();
    let mut loaded = World::load(&path).unwrap();
    assert_eq!(world.positions(block).unwrap(), loaded.positions(block).unwrap());
    world.step(0.05).unwrap();
    loaded.step(0.05).unwrap();
    assert_eq!(world.positions(block).unwrap(), loaded.positions(block).unwrap());
    std::fs::remove_file(&path).unwrap();
    let err = World::load(&path).unwrap_err();
    assert_eq!(err.status(), Status::IoError);
    assert!(err.message().contains("checkpoint"), "message: {}", err.message());
}

#[test]
fn profile_counts_the_phases_a_lone_body_runs() {
    // A lone falling block: one predictor, one elastic-force pass and one commit per sub-step;
    // no contact, so no detection and no solve.
    let (mut world, _block) = block_world(Model::Paper, [0.3, 0.2, 0.1], 400.0);
    world.step(0.01).unwrap();
    let steps = world.stats().unwrap().steps;
    let p = world.profile().unwrap();
    assert_eq!(p.substeps, steps);
    assert_eq!(p.predictor.calls, steps);
    assert_eq!(p.internal_forces.calls, steps);
    assert_eq!(p.global_rotation.calls, steps);
    assert_eq!(p.narrow_phase.calls, 0);
    assert_eq!(p.friction.calls, 0);
    world.reset_profile().unwrap();
    assert_eq!(world.profile().unwrap().predictor.calls, 0);
    assert_eq!(Status::Unsupported.raw(), 9);
}

#[test]
fn ten_node_box_falls_freely_and_shows_its_six_node_faces() {
    // make_quadratic adds one node per edge (the distinct corner pairs of the 4-node tets,
    // counted here); the body weighs rho V and falls as z0 - g t^2 / 2 exactly (every lumped
    // mass is positive, so every node takes g); its 6-node faces have their mid-edge nodes at
    // the middles of their edges, and contact sees 4 flat triangles per face.
    let size = [0.3, 0.2, 0.1];
    let density = 400.0;
    let mut mesh = Mesh::new_box(size, [3, 2, 1]).unwrap();
    let mut edges = std::collections::BTreeSet::new();
    for t in mesh.tets() {
        for &(i, j) in &[(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)] {
            edges.insert((t[i].min(t[j]), t[i].max(t[j])));
        }
    }
    mesh.make_quadratic().unwrap();
    assert_eq!(mesh.nodes_per_tet(), 10);
    assert_eq!(mesh.quadratic_tets().len(), 36);
    assert!(mesh.tets().is_empty());
    assert_eq!(mesh.node_count(), 24 + edges.len());
    assert_eq!(mesh.make_quadratic().unwrap_err().status(), Status::InvalidArgument);
    mesh.translate([0.0, 0.0, 2.0]).unwrap();
    let mut world = World::new(&WorldDef::default()).unwrap();
    let mut def = BodyDef::default();
    def.model = Model::Corotational;
    def.young_modulus = 2e5;
    def.density = density;
    let body = world.create_body(&def).unwrap();
    world.add_mesh(body, &mesh).unwrap();
    assert_eq!(world.nodes_per_tet(body).unwrap(), 10);
    let mass = density * size[0] * size[1] * size[2];
    assert!(close(world.mass(body).unwrap(), mass, 1e-12 * mass));
    let start = world.positions(body).unwrap();
    world.step(0.3).unwrap();
    let t = world.stats().unwrap().time;
    let x = world.positions(body).unwrap();
    for (p, p0) in x.iter().zip(&start) {
        assert!(close(p[2], p0[2] - 0.5 * G * t * t, 1e-11), "z = {}, closed form {}", p[2], p0[2] - 0.5 * G * t * t);
    }
    let faces = world.quadratic_boundary_faces(body).unwrap();
    assert_eq!(world.boundary_triangles(body).unwrap().len(), 4 * faces.len());
    for f in &faces {
        for i in 0..3 {
            let (a, b, m) = (x[f[i] as usize], x[f[(i + 1) % 3] as usize], x[f[3 + i] as usize]);
            for k in 0..3 {
                assert!(close(m[k], 0.5 * (a[k] + b[k]), 1e-12));
            }
        }
    }
    // A body of 4-node tets has no 6-node faces.
    let (linear_world, linear) = block_world(Model::Paper, size, density);
    assert_eq!(linear_world.quadratic_boundary_faces(linear).unwrap_err().status(), Status::InvalidArgument);
}

#[test]
fn a_block_held_inside_out_is_reported_once_per_spell() {
    // A 10 cm cube of one cell: its bottom nodes fixed, its top ones driven down at 0.5 m/s
    // through the bottom for 0.3 s (to z = -0.05) and held. Every tet then has F = diag(1, 1,
    // -0.5): all inverted, J = -0.5 exactly. After 1 s held it is reported as staying inverted,
    // once.
    let mut def = WorldDef::default();
    def.gravity = [0.0; 3];
    let mut world = World::new(&def).unwrap();
    let mesh = Mesh::new_box([0.1, 0.1, 0.1], [1, 1, 1]).unwrap();
    let mut d = BodyDef::default();
    d.young_modulus = 1e4;
    d.damping = 20.0;
    let body = world.create_body(&d).unwrap();
    world.add_mesh(body, &mesh).unwrap();
    let at_rest = world.inversion(body).unwrap();
    assert_eq!((at_rest.inverted_tets, at_rest.min_jacobian, at_rest.inverted_for), (0, 1.0, 0.0));
    let bottom = world.find_nodes_in_box(body, [-1.0, -1.0, -0.01], [1.0, 1.0, 0.01]).unwrap();
    let top = world.find_nodes_in_box(body, [-1.0, -1.0, 0.09], [1.0, 1.0, 0.11]).unwrap();
    world.fix_nodes(body, &bottom).unwrap();
    world.prescribe_node_velocity(body, &top, [0.0, 0.0, -0.5]).unwrap();
    for _ in 0..30 {
        world.step(0.01).unwrap();
    }
    world.fix_nodes(body, &top).unwrap();
    for _ in 0..100 {
        world.step(0.01).unwrap();
    }
    let held = world.inversion(body).unwrap();
    assert_eq!(held.inverted_tets as usize, world.tet_count(body).unwrap());
    assert!(close(held.min_jacobian, -0.5, 1e-12), "J {}", held.min_jacobian);
    assert!(close(held.inverted_for, 1.1, 2e-3), "inverted for {} s", held.inverted_for);
    let stats = world.stats().unwrap();
    assert_eq!(stats.inverted_tets, held.inverted_tets);
    let stays = world.warning(WarningKind::StaysInverted).unwrap();
    assert_eq!(stays.count, 1);
    assert_eq!(stays.last_body, body);
    assert_eq!(world.warning(WarningKind::FallenIn).unwrap().count, 0);
    world.clear_warnings().unwrap();
    for kind in WarningKind::ALL {
        let w = world.warning(kind).unwrap();
        assert_eq!((w.count, w.last_time, w.last_body), (0, 0.0, Body::NULL));
    }
}

#[test]
fn self_contact_is_for_deformable_bodies_only() {
    // The flag reaches lfem: a static body asking for it is refused, a deformable one keeps it.
    let mut world = World::new(&WorldDef::default()).unwrap();
    let mut d = BodyDef::default();
    assert!(!d.self_contact);
    d.self_contact = true;
    d.body_type = BodyType::Static;
    let err = world.create_body(&d).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().contains("self_contact"), "message: {}", err.message());
    d.body_type = BodyType::Deformable;
    world.create_body(&d).unwrap();
}

#[test]
fn a_skin_falls_with_its_body() {
    // A render mesh inside a falling block: free fall moves every tet by -g t^2 / 2 exactly (up
    // to round-off, as the block's own nodes), so every skin vertex follows p - g t^2 / 2, the
    // flat box skin's normals stay the face normals, and the float buffer holds the same
    // numbers rounded to f32.
    let (mut world, block) = block_world(Model::Corotational, [0.3, 0.2, 0.1], 400.0);
    let (lo, hi) = ([0.05, 0.05, 2.02], [0.25, 0.15, 2.08]);
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for axis in 0..3 {
        for side in 0..2 {
            // One square per face (two triangles), vertices of its own: flat normals.
            let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
            let first = positions.len() as u32;
            for (i, j) in [(0, 0), (1, 0), (1, 1), (0, 1)] {
                let mut p = [0.0; 3];
                p[axis] = if side == 1 { hi[axis] } else { lo[axis] };
                p[u] = if i == 1 { hi[u] } else { lo[u] };
                p[w] = if j == 1 { hi[w] } else { lo[w] };
                positions.push(p);
            }
            let (a, b, c, d) = (first, first + 1, first + 2, first + 3);
            if side == 1 {
                triangles.extend_from_slice(&[[a, b, c], [a, c, d]]);
            } else {
                triangles.extend_from_slice(&[[a, c, b], [a, d, c]]);
            }
        }
    }
    assert_eq!(world.add_skin(block, &positions, &triangles).unwrap(), 0);
    assert_eq!(world.skin_count(block).unwrap(), 1);
    assert_eq!(world.skin_sizes(block, 0).unwrap(), (24, 12));
    assert_eq!(world.skin_triangles(block, 0).unwrap(), triangles);
    world.step(0.1).unwrap();
    let t = world.stats().unwrap().time;
    let skin = world.skin_vertices(block, 0).unwrap();
    for (v, (p, p0)) in skin.positions.iter().zip(&positions).enumerate() {
        assert!(close(p[0], p0[0], 1e-11) && close(p[1], p0[1], 1e-11), "vertex {} drifted", v);
        assert!(close(p[2], p0[2] - 0.5 * G * t * t, 1e-11), "vertex {}: z = {}", v, p[2]);
        let n = skin.normals[v];
        let axis = (v / 8) as usize; // 8 vertices per axis (two faces)
        let sign = if (v / 4) % 2 == 1 { 1.0 } else { -1.0 };
        for k in 0..3 {
            let expected = if k == axis { sign } else { 0.0 };
            assert!(close(n[k], expected, 1e-12), "vertex {} normal {:?}", v, n);
        }
    }
    let mut buffer = vec![-1.0f32; 24 * 8];
    world.skin_vertex_buffer(block, 0, &mut buffer, 8, true).unwrap();
    for v in 0..24 {
        for k in 0..3 {
            assert_eq!(buffer[8 * v + k], skin.positions[v][k] as f32);
            assert_eq!(buffer[8 * v + 3 + k], skin.normals[v][k] as f32);
        }
        assert_eq!(buffer[8 * v + 6], -1.0);
    }
    let err = world.skin_vertex_buffer(block, 0, &mut buffer[..100], 8, true).unwrap_err();
    assert_eq!(err.status(), Status::BufferTooSmall);
    let err = world.skin_vertices(block, 1).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().starts_with("lfem_body_get_skin_vertices:"), "message: {}", err.message());
    let far = [[5.0, 5.0, 5.0], [5.1, 5.0, 5.0], [5.0, 5.1, 5.0]];
    assert_eq!(world.add_skin(block, &far, &[[0, 1, 2]]).unwrap_err().status(), Status::InvalidArgument);
    assert_eq!(world.skin_count(block).unwrap(), 1);
    // Settings after creation, and the skin removed.
    world.set_friction(block, 0.2).unwrap();
    world.set_damping(block, 1.0).unwrap();
    world.set_sleep_allowed(block, false).unwrap();
    world.set_material(block, 3e5, 0.25).unwrap();
    assert_eq!(world.set_material(block, 3e5, 0.5).unwrap_err().status(), Status::InvalidArgument);
    world.set_filter(block, 1, u32::MAX).unwrap();
    assert_eq!(world.set_damping(block, -1.0).unwrap_err().status(), Status::InvalidArgument);
    assert_eq!(world.remove_skin(block, 1).unwrap_err().status(), Status::InvalidArgument);
    world.remove_skin(block, 0).unwrap();
    assert_eq!(world.skin_count(block).unwrap(), 0);
}

#[test]
fn rays_and_boxes_find_what_is_there() {
    // A static sphere of radius 0.5 about (2, 0, 0) and a cube [0, 0.2]^3: a ray along +x at
    // height z = 0.3 misses the cube and meets the sphere where its chord starts,
    // 2 - sqrt(0.25 - 0.09) = 1.6 from the origin, with normal (p - c) / r.
    let mut def = WorldDef::default();
    def.gravity = [0.0; 3];
    let mut world = World::new(&def).unwrap();
    let mut sd = BodyDef::default();
    sd.body_type = BodyType::Static;
    let ground = world.create_body(&sd).unwrap();
    let mut shape = ShapeDef::default();
    shape.shape_type = ShapeType::Sphere;
    shape.center = [2.0, 0.0, 0.0];
    shape.radius = 0.5;
    assert_eq!(world.add_shape(ground, &shape).unwrap(), 0);
    let cube = world.create_body(&BodyDef::default()).unwrap();
    world.add_mesh(cube, &Mesh::new_box([0.2, 0.2, 0.2], [2, 2, 2]).unwrap()).unwrap();
    let filter = QueryFilter::default();
    assert_eq!(filter, QueryFilter { category_bits: 1, mask_bits: u32::MAX });
    // A sphere 0.3 above the static sphere's top (radius 0.31) meets it at its top, 0.3 away;
    // one of radius 0.06 over the cube's top face (0.05 above it) meets the cube straight below.
    let o = world.overlap_sphere([2.0, 0.0, 0.8], 0.31, filter).unwrap();
    assert_eq!(o.len(), 1);
    assert_eq!((o[0].body, o[0].shape, o[0].triangle), (ground, 0, u32::MAX));
    assert!(close(o[0].point[2], 0.5, 1e-12) && close(o[0].distance, 0.3, 1e-12), "{:?}", o[0]);
    let o = world.overlap_capsule([0.07, 0.13, 0.25], [0.07, 0.13, 0.25], 0.06, filter).unwrap();
    assert_eq!(o.len(), 1);
    assert_eq!(o[0].body, cube);
    assert!(close(o[0].point[2], 0.2, 1e-12) && close(o[0].distance, 0.05, 1e-12), "{:?}", o[0]);
    assert!(world.overlap_sphere([2.0, 0.0, 0.8], 0.29, filter).unwrap().is_empty());
    // A sphere of 0.1 cast along -x from x = 4 at the static sphere: it stops 4 - 2 - 0.5 - 0.1
    // away, touching it at x = 2.5.
    let h = world.cast_sphere([4.0, 0.0, 0.0], [-1.0, 0.0, 0.0], 0.1, f64::INFINITY, filter).unwrap().unwrap();
    assert!(close(h.distance, 1.4, 1e-12) && close(h.point[0], 2.5, 1e-12), "{:?}", h);
    assert_eq!(world.overlap_sphere([2.0, 0.0, 0.8], -1.0, filter).unwrap_err().status(), Status::InvalidArgument);
    let hit = world.cast_ray([0.0, 0.0, 0.3], [2.0, 0.0, 0.0], f64::INFINITY, filter).unwrap().unwrap();
    assert_eq!(hit.body, ground);
    assert_eq!((hit.shape(), hit.triangle()), (Some(0), None));
    assert!(close(hit.distance, 1.6, 1e-12), "distance {}", hit.distance);
    for (k, n) in [-0.4 / 0.5, 0.0, 0.3 / 0.5].iter().enumerate() {
        assert!(close(hit.normal[k], *n, 1e-12), "normal {:?}", hit.normal);
    }
    // Through the cube (x = 0 and 0.2) and then the sphere (1.5 and 2.5), nearest first.
    let all = world.cast_ray_all([-1.0, 0.07, 0.03], [1.0, 0.0, 0.0], f64::INFINITY, filter).unwrap();
    let d: Vec<f64> = all.iter().map(|h| h.distance).collect();
    assert_eq!(all.len(), 4, "{:?}", d);
    let expected = [1.0, 1.2, 3.0 - (0.25f64 - 0.07 * 0.07 - 0.03 * 0.03).sqrt(), 3.0 + (0.25f64 - 0.0058).sqrt()];
    for (got, want) in d.iter().zip(&expected) {
        assert!(close(*got, *want, 1e-12), "{:?} against {:?}", d, expected);
    }
    assert_eq!((all[0].body, all[0].shape()), (cube, None));
    assert!(world.cast_ray([-1.0, 0.07, 0.03], [1.0, 0.0, 0.0], 0.99, filter).unwrap().is_none());
    let blind = QueryFilter { category_bits: 1, mask_bits: 2 };
    assert!(world.cast_ray([0.0, 0.0, 0.3], [1.0, 0.0, 0.0], f64::INFINITY, blind).unwrap().is_none());
    assert_eq!(world.overlap_box([0.1, 0.1, 0.1], [0.12, 0.12, 0.12], filter).unwrap(), vec![cube]);
    assert_eq!(world.overlap_box([1.9, -0.1, -0.1], [2.1, 0.1, 0.1], filter).unwrap(), vec![ground]);
    assert_eq!(world.overlap_box([-5.0, -5.0, -5.0], [5.0, 5.0, 5.0], filter).unwrap(), vec![ground, cube]);
    assert!(world.overlap_box([0.5, 0.5, 0.5], [0.6, 0.6, 0.6], filter).unwrap().is_empty());
    let err = world.cast_ray([0.0; 3], [0.0; 3], 1.0, filter).unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    assert!(err.message().contains("direction"), "message: {}", err.message());
    assert_eq!(world.overlap_box([1.0; 3], [0.0; 3], filter).unwrap_err().status(), Status::InvalidArgument);
    assert!(world.profile().unwrap().queries >= 10);
}

#[test]
fn a_bar_hangs_from_a_frame_and_a_resting_block_sleeps_with_events() {
    // A bar held at its top nodes by a frame that never moves carries its weight (the
    // attachment's force is m g at rest); a block settling on a plane begins one contact, then
    // falls asleep (events), and stepping it asleep changes no position.
    let mut def = WorldDef::default();
    def.enable_sleep = true;
    let mut world = World::new(&def).unwrap();
    let mut mesh = Mesh::new_box([0.03, 0.03, 0.3], [1, 1, 10]).unwrap();
    mesh.translate([-0.015, -0.015, 0.2]).unwrap();
    let mut d = BodyDef::default();
    d.young_modulus = 2e5;
    d.damping = 10.0;
    d.enable_sleep = false;
    let bar = world.create_body(&d).unwrap();
    world.add_mesh(bar, &mesh).unwrap();
    let top = world.find_nodes_in_box(bar, [-1.0, -1.0, 0.4999], [1.0, 1.0, 0.5001]).unwrap();
    let held = world.create_attachment(bar, &top, AttachTo::Frame([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]), 0.0).unwrap();
    let mut floor_def = BodyDef::default();
    floor_def.body_type = BodyType::Static;
    let floor = world.create_body(&floor_def).unwrap();
    world.add_shape(floor, &ShapeDef::default()).unwrap();
    let mut block_mesh = Mesh::new_box([0.1, 0.1, 0.1], [2, 2, 2]).unwrap();
    block_mesh.translate([0.3, 0.0, 0.0005]).unwrap();
    let mut bd = BodyDef::default();
    bd.damping = 20.0;
    let block = world.create_body(&bd).unwrap();
    world.add_mesh(block, &block_mesh).unwrap();
    let (mut begins, mut sleeps) = (0, 0);
    for _ in 0..180 {
        world.step(1.0 / 60.0).unwrap();
        for e in world.events().unwrap() {
            match e.event_type {
                EventType::ContactBegin => begins += 1,
                EventType::Sleep => {
                    assert_eq!(e.body_a, block);
                    sleeps += 1
                }
                _ => {}
            }
        }
    }
    assert_eq!((begins, sleeps), (1, 1));
    assert!(!world.is_awake(block).unwrap());
    assert!(world.is_awake(bar).unwrap());
    let mass = world.mass(bar).unwrap();
    let f = world.attachment_force(held).unwrap();
    // At rest (damping 10 for 3 s) the held nodes carry the weight to well within 1e-6.
    assert!(close(f[2], mass * G, 1e-6 * mass * G), "force {:?}, m g {}", f, mass * G);
    assert_eq!(world.attachment_frame(held).unwrap(), [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    let x = world.positions(block).unwrap();
    world.step(1.0 / 60.0).unwrap();
    assert_eq!(world.positions(block).unwrap(), x);
    world.wake(block).unwrap();
    assert!(world.is_awake(block).unwrap());
    world.destroy_attachment(held).unwrap();
    assert!(!world.is_attachment_valid(held));
    assert_eq!(world.attachment_force(held).unwrap_err().status(), Status::InvalidHandle);
    // Held instead by a point inside its top on a critically damped spring (k 2000 N/m): 1 s
    // later it carries the weight (to the solve's 1e-3 of it).
    let c = world.center_of_mass(bar).unwrap();
    let top_z = world.positions(bar).unwrap().iter().map(|p| p[2]).fold(f64::NEG_INFINITY, f64::max);
    let k = 2000.0;
    let frame = AttachTo::Frame([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    let spring = world.create_point_attachment(bar, &[[c[0], c[1], top_z - 0.001]], frame, k, 2.0 * (k * mass).sqrt(), 0.0).unwrap();
    for _ in 0..60 {
        world.step(1.0 / 60.0).unwrap();
    }
    let f = world.attachment_force(spring).unwrap();
    assert!(close(f[2], mass * G, 1e-3 * mass * G), "force {:?}, m g {}", f, mass * G);
}

#[test]
fn a_teleported_block_lands_with_its_approach_speed() {
    // A soft block put 0.2 m above a plane by its transform (x = X + t) falls and lands at
    // sqrt(2 g H): the begin event's approach speed is within g h / 2 of it (the impact
    // sub-step's predicted mid-step velocity), its normal +z from the plane toward the block.
    let mut world = World::new(&WorldDef::default()).unwrap();
    let mut floor_def = BodyDef::default();
    floor_def.body_type = BodyType::Static;
    let floor = world.create_body(&floor_def).unwrap();
    world.add_shape(floor, &ShapeDef::default()).unwrap();
    let mesh = Mesh::new_box([0.1, 0.1, 0.1], [2, 2, 2]).unwrap();
    let block = world.create_body(&BodyDef::default()).unwrap();
    world.add_mesh(block, &mesh).unwrap();
    let mut pose = world.transform(block).unwrap();
    pose[2] += 0.2;
    world.set_transform(block, pose).unwrap();
    let t = world.transform(block).unwrap();
    assert!(close(t[2], pose[2], 1e-12) && close(t[3], 1.0, 1e-12), "{:?}", t);
    let c0 = world.center_of_mass(block).unwrap();
    let height = world.positions(block).unwrap().iter().map(|p| p[2]).fold(f64::INFINITY, f64::min);
    assert!(close(height, 0.2, 1e-12), "lowest node {}", height);
    let v_impact = (2.0 * G * height).sqrt();
    let mut landed = false;
    for _ in 0..30 {
        world.step(1.0 / 60.0).unwrap();
        for e in world.events().unwrap() {
            if e.event_type != EventType::ContactBegin {
                continue;
            }
            let h = world.stats().unwrap().step_size;
            assert!(close(e.approach_speed, v_impact, 0.5 * G * h * (1.0 + 1e-9)), "approach {} vs {}", e.approach_speed, v_impact);
            assert!(close(e.normal[2], 1.0, 1e-12), "normal {:?}", e.normal);
            assert!(e.point[2].abs() < 1e-3 * v_impact * h, "point {:?}", e.point);
            landed = true;
        }
        if landed {
            break;
        }
    }
    assert!(landed);
    assert!(world.center_of_mass(block).unwrap()[2] < c0[2]);
    // The nearest point of the block's surface to a point above it: straight below, on its top.
    let top = world.positions(block).unwrap().iter().map(|p| p[2]).fold(f64::NEG_INFINITY, f64::max);
    let c = world.center_of_mass(block).unwrap();
    let (q, _, d) = world.closest_point(block, [c[0], c[1], top + 1.0]).unwrap();
    assert!(close(q[2], top, 1e-12) && close(d, 1.0, 1e-12), "{:?} {}", q, d);
    // An impulse at its centre of mass: its momentum grows by exactly that (round-off).
    let (p0, _) = world.momentum(block).unwrap();
    let c = world.center_of_mass(block).unwrap();
    world.apply_impulse(block, c, [0.5, 0.0, 0.2]).unwrap();
    let (p1, _) = world.momentum(block).unwrap();
    assert!(close(p1[0] - p0[0], 0.5, 1e-12) && close(p1[2] - p0[2], 0.2, 1e-12), "{:?} -> {:?}", p0, p1);
    // A static body does not move.
    assert_eq!(world.set_transform(floor, pose).unwrap_err().status(), Status::InvalidArgument);
}

#[test]
fn a_force_acts_for_one_call_and_a_user_id_is_kept() {
    // Weightless: a force F at the cube's centre for one call of dt gives it F dt of momentum
    // exactly (central differences; round-off of sums over its nodes), the next call nothing.
    let mut def = WorldDef::default();
    def.gravity = [0.0, 0.0, 0.0];
    let mut world = World::new(&def).unwrap();
    let cube = world.create_body(&BodyDef::default()).unwrap();
    world.add_mesh(cube, &Mesh::new_box([0.2, 0.2, 0.2], [2, 2, 2]).unwrap()).unwrap();
    assert_eq!(world.user_id(cube).unwrap(), 0);
    assert_eq!(world.body_type(cube).unwrap(), BodyType::Deformable);
    assert_eq!(world.set_type(cube, BodyType::Rigid).unwrap_err().status(), Status::InvalidArgument);
    world.set_user_id(cube, u64::MAX).unwrap();
    assert_eq!(world.user_id(cube).unwrap(), u64::MAX);
    let dt = 1.0 / 60.0;
    let c = world.center_of_mass(cube).unwrap();
    world.apply_force(cube, c, [3.0, 0.0, -1.0]).unwrap();
    world.step(dt).unwrap();
    let (p1, _) = world.momentum(cube).unwrap();
    assert!(close(p1[0], 3.0 * dt, 1e-12) && close(p1[2], -dt, 1e-12), "{:?}", p1);
    world.step(dt).unwrap();
    let (p2, _) = world.momentum(cube).unwrap();
    assert!(close(p2[0], p1[0], 1e-12), "{:?} -> {:?}", p1, p2);
    assert_eq!(world.apply_force(cube, [9.0, 9.0, 9.0], [1.0, 0.0, 0.0]).unwrap_err().status(), Status::InvalidArgument);
}
