//! Field offsets of the #[repr(C)] structs against the C ones (the numbers asserted by
//! bindings/abi_layout.c), and the C default functions returning what lfem.h documents.
use lfem_sys::*;
use std::mem::{align_of, size_of, MaybeUninit};
use std::ptr::addr_of;

macro_rules! offset {
    ($t:ty, $f:ident) => {{
        let v = MaybeUninit::<$t>::uninit();
        let base = v.as_ptr();
        // SAFETY: addr_of! takes the field's address without reading it.
        let field = unsafe { addr_of!((*base).$f) };
        field as usize - base as usize
    }};
}

#[test]
fn sizes_match_c() {
    assert_eq!(size_of::<lfem_body>(), 8);
    assert_eq!(size_of::<lfem_world_def>(), 96);
    assert_eq!(size_of::<lfem_world_stats>(), 184);
    assert_eq!(size_of::<lfem_warning>(), 24);
    assert_eq!(size_of::<lfem_body_def>(), 128);
    assert_eq!(size_of::<lfem_contact>(), 168);
    assert_eq!(size_of::<lfem_shape_def>(), 120);
    assert_eq!(size_of::<lfem_phase_time>(), 16);
    assert_eq!(size_of::<lfem_profile>(), 240);
    assert_eq!(size_of::<lfem_query_filter>(), 8);
    assert_eq!(size_of::<lfem_ray_hit>(), 88);
    assert_eq!(align_of::<lfem_world_def>(), 8);
    assert_eq!(align_of::<lfem_body>(), 4);
}

#[test]
fn offsets_match_c() {
    assert_eq!(offset!(lfem_body, generation), 4);

    assert_eq!(offset!(lfem_world_def, time_step), 24);
    assert_eq!(offset!(lfem_world_def, step_safety), 32);
    assert_eq!(offset!(lfem_world_def, contact_iterations), 40);
    assert_eq!(offset!(lfem_world_def, thread_count), 44);
    assert_eq!(offset!(lfem_world_def, contact_tolerance), 48);
    assert_eq!(offset!(lfem_world_def, max_substeps), 56);
    assert_eq!(offset!(lfem_world_def, allow_unstable_step), 60);
    assert_eq!(offset!(lfem_world_def, internal_value), 64);
    assert_eq!(offset!(lfem_world_def, mass_scaling_step), 72);

    assert_eq!(offset!(lfem_world_stats, steps), 8);
    assert_eq!(offset!(lfem_world_stats, substeps_last_call), 32);
    assert_eq!(offset!(lfem_world_stats, body_count), 36);
    assert_eq!(offset!(lfem_world_stats, kinetic_energy), 40);
    assert_eq!(offset!(lfem_world_stats, energy_error), 72);
    assert_eq!(offset!(lfem_world_stats, linear_momentum), 80);
    assert_eq!(offset!(lfem_world_stats, angular_momentum), 104);
    assert_eq!(offset!(lfem_world_stats, contact_count), 128);
    assert_eq!(offset!(lfem_world_stats, solver_iterations), 132);
    assert_eq!(offset!(lfem_world_stats, solver_residual), 136);
    assert_eq!(offset!(lfem_world_stats, rotation_drift), 152);
    assert_eq!(offset!(lfem_world_stats, added_mass), 160);
    assert_eq!(offset!(lfem_world_stats, inverted_tets), 168);
    assert_eq!(offset!(lfem_world_stats, min_jacobian), 176);
    assert_eq!(offset!(lfem_warning, count), 0);
    assert_eq!(offset!(lfem_warning, last_time), 8);
    assert_eq!(offset!(lfem_warning, last_body), 16);

    assert_eq!(offset!(lfem_phase_time, calls), 8);
    assert_eq!(offset!(lfem_profile, internal_forces), 8);
    assert_eq!(offset!(lfem_profile, predictor), 24);
    assert_eq!(offset!(lfem_profile, kinematic_motion), 40);
    assert_eq!(offset!(lfem_profile, broad_phase), 56);
    assert_eq!(offset!(lfem_profile, narrow_phase), 72);
    assert_eq!(offset!(lfem_profile, shape_queries), 88);
    assert_eq!(offset!(lfem_profile, shape_tests), 104);
    assert_eq!(offset!(lfem_profile, ccd_queries), 112);
    assert_eq!(offset!(lfem_profile, normal_solve), 120);
    assert_eq!(offset!(lfem_profile, friction), 136);
    assert_eq!(offset!(lfem_profile, global_rotation), 152);
    assert_eq!(offset!(lfem_profile, commit), 168);
    assert_eq!(offset!(lfem_profile, candidate_searches), 184);
    assert_eq!(offset!(lfem_profile, queries), 192);
    assert_eq!(offset!(lfem_profile, query_bodies), 200);
    assert_eq!(offset!(lfem_profile, query_primitives), 208);
    assert_eq!(offset!(lfem_profile, query_refits), 216);
    assert_eq!(offset!(lfem_profile, contact_sweeps), 224);
    assert_eq!(offset!(lfem_profile, constraint_updates), 232);

    assert_eq!(offset!(lfem_query_filter, mask_bits), 4);
    assert_eq!(offset!(lfem_ray_hit, triangle), 8);
    assert_eq!(offset!(lfem_ray_hit, shape), 12);
    assert_eq!(offset!(lfem_ray_hit, barycentric), 16);
    assert_eq!(offset!(lfem_ray_hit, point), 32);
    assert_eq!(offset!(lfem_ray_hit, normal), 56);
    assert_eq!(offset!(lfem_ray_hit, distance), 80);
    assert_eq!(size_of::<lfem_overlap>(), 48);
    assert_eq!(offset!(lfem_overlap, triangle), 8);
    assert_eq!(offset!(lfem_overlap, shape), 12);
    assert_eq!(offset!(lfem_overlap, point), 16);
    assert_eq!(offset!(lfem_overlap, distance), 40);

    assert_eq!(offset!(lfem_body_def, model), 4);
    assert_eq!(offset!(lfem_body_def, young_modulus), 8);
    assert_eq!(offset!(lfem_body_def, friction), 40);
    assert_eq!(offset!(lfem_body_def, linear_velocity), 48);
    assert_eq!(offset!(lfem_body_def, angular_velocity), 72);
    assert_eq!(offset!(lfem_body_def, category_bits), 96);
    assert_eq!(offset!(lfem_body_def, mask_bits), 100);
    assert_eq!(offset!(lfem_body_def, enable_sleep), 116);
    assert_eq!(offset!(lfem_body_def, self_contact), 117);
    assert_eq!(offset!(lfem_body_def, edge_contacts), 120);
    assert_eq!(offset!(lfem_body_def, composite_tets), 118);
    assert_eq!(offset!(lfem_world_def, enable_sleep), 61);
    assert_eq!(offset!(lfem_world_def, sleep_velocity), 80);
    assert_eq!(offset!(lfem_world_def, sleep_time), 88);
    assert_eq!(offset!(lfem_attachment_def, target), 8);
    assert_eq!(offset!(lfem_attachment_def, nodes), 16);
    assert_eq!(offset!(lfem_attachment_def, frame), 32);
    assert_eq!(offset!(lfem_attachment_def, break_force), 88);
    assert_eq!(offset!(lfem_attachment_def, points), 96);
    assert_eq!(offset!(lfem_attachment_def, point_count), 104);
    assert_eq!(offset!(lfem_attachment_def, stiffness), 112);
    assert_eq!(offset!(lfem_attachment_def, damping), 120);
    assert_eq!(offset!(lfem_event, body_a), 8);
    assert_eq!(offset!(lfem_event, attachment), 24);
    assert_eq!(offset!(lfem_event, normal_impulse), 32);
    assert_eq!(offset!(lfem_event, max_force), 40);
    assert_eq!(offset!(lfem_event, approach_speed), 48);
    assert_eq!(offset!(lfem_event, point), 56);
    assert_eq!(offset!(lfem_event, normal), 80);
    assert_eq!(offset!(lfem_body_def, user_data), 104);
    assert_eq!(offset!(lfem_body_def, internal_value), 112);

    assert_eq!(offset!(lfem_contact, body_b), 8);
    assert_eq!(offset!(lfem_contact, node), 16);
    assert_eq!(offset!(lfem_contact, triangle), 20);
    assert_eq!(offset!(lfem_contact, barycentric), 32);
    assert_eq!(offset!(lfem_contact, position), 48);
    assert_eq!(offset!(lfem_contact, normal), 72);
    assert_eq!(offset!(lfem_contact, force), 96);
    assert_eq!(offset!(lfem_contact, sliding), 120);
    assert_eq!(offset!(lfem_contact, kind), 121);
    assert_eq!(offset!(lfem_contact, shape), 124);
    assert_eq!(offset!(lfem_contact, weights_a), 128);
    assert_eq!(offset!(lfem_contact, nodes_a), 152);

    assert_eq!(offset!(lfem_shape_def, point_count), 4);
    assert_eq!(offset!(lfem_shape_def, center), 8);
    assert_eq!(offset!(lfem_shape_def, rotation), 32);
    assert_eq!(offset!(lfem_shape_def, half_extents), 64);
    assert_eq!(offset!(lfem_shape_def, radius), 88);
    assert_eq!(offset!(lfem_shape_def, half_length), 96);
    assert_eq!(offset!(lfem_shape_def, points), 104);
    assert_eq!(offset!(lfem_shape_def, internal_value), 112);
}

#[test]
fn defaults_are_the_documented_ones() {
    // SAFETY: plain value-returning C functions, callable from any thread.
    let (w, b) = unsafe { (lfem_world_def_default(), lfem_body_def_default()) };
    assert_eq!(w.gravity, [0.0, 0.0, -9.81]);
    assert_eq!(w.time_step, 0.0);
    assert_eq!(w.step_safety, 0.9);
    assert_eq!(w.contact_iterations, 200);
    assert_eq!(w.thread_count, 1);
    assert_eq!(w.contact_tolerance, 1e-3);
    assert_eq!(w.max_substeps, 1_000_000);
    assert_eq!(w.allow_unstable_step, 0);
    assert_eq!(b.type_, LFEM_BODY_DEFORMABLE);
    assert_eq!(b.model, LFEM_MODEL_PAPER);
    assert_eq!(b.young_modulus, 1e6);
    assert_eq!(b.poisson_ratio, 0.3);
    assert_eq!(b.density, 1000.0);
    assert_eq!(b.damping, 0.0);
    assert_eq!(b.friction, 0.5);
    assert_eq!(b.category_bits, 1);
    assert_eq!(b.mask_bits, u32::MAX);
    assert!(b.user_data.is_null());
    // SAFETY: returns a value.
    let s = unsafe { lfem_shape_def_default() };
    assert_eq!(s.type_, LFEM_SHAPE_PLANE);
    assert_eq!(s.center, [0.0; 3]);
    assert_eq!(s.rotation, [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(s.half_extents, [0.5; 3]);
    assert_eq!(s.radius, 0.5);
    assert_eq!(s.half_length, 0.5);
    assert!(s.points.is_null());
    // SAFETY: returns a value.
    let f = unsafe { lfem_query_filter_default() };
    assert_eq!(f, lfem_query_filter { category_bits: 1, mask_bits: u32::MAX });
}

#[test]
fn version_matches_header() {
    // SAFETY: no arguments; the returned string is static and NUL-terminated.
    let (v, s) = unsafe { (lfem_version(), std::ffi::CStr::from_ptr(lfem_version_string())) };
    assert_eq!(v, (LFEM_VERSION_MAJOR << 16) | (LFEM_VERSION_MINOR << 8) | LFEM_VERSION_PATCH);
    assert_eq!(
        s.to_str().unwrap(),
        format!("{}.{}.{}", LFEM_VERSION_MAJOR, LFEM_VERSION_MINOR, LFEM_VERSION_PATCH)
    );
}
