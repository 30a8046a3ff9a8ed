/* The C layout of every struct of lfem.h that the bindings mirror. The bindings hard-code these
 * numbers (Rust: const assertions on size_of plus offset tests; C#: Marshal.SizeOf/OffsetOf;
 * Python: ctypes.sizeof and field offsets); the static assertions below make the build fail if
 * the header ever changes a layout, so the numbers cannot go stale silently. Run, it prints the
 * table. Built as C11 (for _Static_assert), against the unchanged C99 header. */
#include <stddef.h>
#include <stdio.h>

#include "lfem.h"

#define CHECK_SIZE(type, n) _Static_assert(sizeof(type) == (n), "sizeof(" #type ") != " #n)
#define CHECK_OFFSET(type, field, n) \
    _Static_assert(offsetof(type, field) == (n), "offsetof(" #type ", " #field ") != " #n)

/* enums are 32-bit */
CHECK_SIZE(lfem_status, 4);
CHECK_SIZE(lfem_body_type, 4);
CHECK_SIZE(lfem_model, 4);
CHECK_SIZE(lfem_shape_type, 4);

CHECK_SIZE(lfem_body, 8);
CHECK_OFFSET(lfem_body, index, 0);
CHECK_OFFSET(lfem_body, generation, 4);

CHECK_SIZE(lfem_world_def, 96);
CHECK_OFFSET(lfem_world_def, gravity, 0);
CHECK_OFFSET(lfem_world_def, time_step, 24);
CHECK_OFFSET(lfem_world_def, step_safety, 32);
CHECK_OFFSET(lfem_world_def, contact_iterations, 40);
CHECK_OFFSET(lfem_world_def, thread_count, 44);
CHECK_OFFSET(lfem_world_def, contact_tolerance, 48);
CHECK_OFFSET(lfem_world_def, max_substeps, 56);
CHECK_OFFSET(lfem_world_def, allow_unstable_step, 60);
CHECK_OFFSET(lfem_world_def, internal_value, 64);
CHECK_OFFSET(lfem_world_def, enable_sleep, 61);
CHECK_OFFSET(lfem_world_def, mass_scaling_step, 72);
CHECK_OFFSET(lfem_world_def, sleep_velocity, 80);
CHECK_OFFSET(lfem_world_def, sleep_time, 88);

CHECK_SIZE(lfem_phase_time, 16);
CHECK_OFFSET(lfem_phase_time, seconds, 0);
CHECK_OFFSET(lfem_phase_time, calls, 8);

CHECK_SIZE(lfem_profile, 240);
CHECK_OFFSET(lfem_profile, substeps, 0);
CHECK_OFFSET(lfem_profile, internal_forces, 8);
CHECK_OFFSET(lfem_profile, predictor, 24);
CHECK_OFFSET(lfem_profile, kinematic_motion, 40);
CHECK_OFFSET(lfem_profile, broad_phase, 56);
CHECK_OFFSET(lfem_profile, narrow_phase, 72);
CHECK_OFFSET(lfem_profile, shape_queries, 88);
CHECK_OFFSET(lfem_profile, shape_tests, 104);
CHECK_OFFSET(lfem_profile, ccd_queries, 112);
CHECK_OFFSET(lfem_profile, normal_solve, 120);
CHECK_OFFSET(lfem_profile, friction, 136);
CHECK_OFFSET(lfem_profile, global_rotation, 152);
CHECK_OFFSET(lfem_profile, commit, 168);
CHECK_OFFSET(lfem_profile, candidate_searches, 184);
CHECK_OFFSET(lfem_profile, queries, 192);
CHECK_OFFSET(lfem_profile, query_bodies, 200);
CHECK_OFFSET(lfem_profile, query_primitives, 208);
CHECK_OFFSET(lfem_profile, query_refits, 216);
CHECK_OFFSET(lfem_profile, contact_sweeps, 224);
CHECK_OFFSET(lfem_profile, constraint_updates, 232);

CHECK_SIZE(lfem_world_stats, 184);
CHECK_OFFSET(lfem_world_stats, time, 0);
CHECK_OFFSET(lfem_world_stats, steps, 8);
CHECK_OFFSET(lfem_world_stats, step_size, 16);
CHECK_OFFSET(lfem_world_stats, stable_step, 24);
CHECK_OFFSET(lfem_world_stats, substeps_last_call, 32);
CHECK_OFFSET(lfem_world_stats, body_count, 36);
CHECK_OFFSET(lfem_world_stats, kinetic_energy, 40);
CHECK_OFFSET(lfem_world_stats, strain_energy, 48);
CHECK_OFFSET(lfem_world_stats, external_work, 56);
CHECK_OFFSET(lfem_world_stats, dissipated_energy, 64);
CHECK_OFFSET(lfem_world_stats, energy_error, 72);
CHECK_OFFSET(lfem_world_stats, linear_momentum, 80);
CHECK_OFFSET(lfem_world_stats, angular_momentum, 104);
CHECK_OFFSET(lfem_world_stats, contact_count, 128);
CHECK_OFFSET(lfem_world_stats, solver_iterations, 132);
CHECK_OFFSET(lfem_world_stats, solver_residual, 136);
CHECK_OFFSET(lfem_world_stats, max_penetration, 144);
CHECK_OFFSET(lfem_world_stats, rotation_drift, 152);
CHECK_OFFSET(lfem_world_stats, added_mass, 160);
CHECK_OFFSET(lfem_world_stats, inverted_tets, 168);
CHECK_OFFSET(lfem_world_stats, padding, 172);
CHECK_OFFSET(lfem_world_stats, min_jacobian, 176);

CHECK_SIZE(lfem_warning_kind, 4);
CHECK_SIZE(lfem_warning, 24);
CHECK_OFFSET(lfem_warning, count, 0);
CHECK_OFFSET(lfem_warning, last_time, 8);
CHECK_OFFSET(lfem_warning, last_body, 16);

CHECK_SIZE(lfem_query_filter, 8);
CHECK_OFFSET(lfem_query_filter, category_bits, 0);
CHECK_OFFSET(lfem_query_filter, mask_bits, 4);

CHECK_SIZE(lfem_ray_hit, 88);
CHECK_OFFSET(lfem_ray_hit, body, 0);
CHECK_OFFSET(lfem_ray_hit, triangle, 8);
CHECK_OFFSET(lfem_ray_hit, shape, 12);
CHECK_OFFSET(lfem_ray_hit, barycentric, 16);
CHECK_OFFSET(lfem_ray_hit, point, 32);
CHECK_OFFSET(lfem_ray_hit, normal, 56);
CHECK_OFFSET(lfem_ray_hit, distance, 80);
CHECK_SIZE(lfem_overlap, 48);
CHECK_OFFSET(lfem_overlap, body, 0);
CHECK_OFFSET(lfem_overlap, triangle, 8);
CHECK_OFFSET(lfem_overlap, shape, 12);
CHECK_OFFSET(lfem_overlap, point, 16);
CHECK_OFFSET(lfem_overlap, distance, 40);

CHECK_SIZE(lfem_event_type, 4);
CHECK_SIZE(lfem_attachment, 8);
CHECK_OFFSET(lfem_attachment, index, 0);
CHECK_OFFSET(lfem_attachment, generation, 4);
CHECK_SIZE(lfem_event, 104);
CHECK_OFFSET(lfem_event, type, 0);
CHECK_OFFSET(lfem_event, body_a, 8);
CHECK_OFFSET(lfem_event, body_b, 16);
CHECK_OFFSET(lfem_event, attachment, 24);
CHECK_OFFSET(lfem_event, normal_impulse, 32);
CHECK_OFFSET(lfem_event, max_force, 40);
CHECK_OFFSET(lfem_event, approach_speed, 48);
CHECK_OFFSET(lfem_event, point, 56);
CHECK_OFFSET(lfem_event, normal, 80);

/* 64-bit targets (8-byte pointers), which every binding test runs on */
CHECK_SIZE(void*, 8);
CHECK_SIZE(lfem_body_def, 128);
CHECK_OFFSET(lfem_body_def, type, 0);
CHECK_OFFSET(lfem_body_def, model, 4);
CHECK_OFFSET(lfem_body_def, young_modulus, 8);
CHECK_OFFSET(lfem_body_def, poisson_ratio, 16);
CHECK_OFFSET(lfem_body_def, density, 24);
CHECK_OFFSET(lfem_body_def, damping, 32);
CHECK_OFFSET(lfem_body_def, friction, 40);
CHECK_OFFSET(lfem_body_def, linear_velocity, 48);
CHECK_OFFSET(lfem_body_def, angular_velocity, 72);
CHECK_OFFSET(lfem_body_def, category_bits, 96);
CHECK_OFFSET(lfem_body_def, mask_bits, 100);
CHECK_OFFSET(lfem_body_def, user_data, 104);
CHECK_OFFSET(lfem_body_def, internal_value, 112);
CHECK_OFFSET(lfem_body_def, enable_sleep, 116);
CHECK_OFFSET(lfem_body_def, self_contact, 117);
CHECK_OFFSET(lfem_body_def, composite_tets, 118);
CHECK_OFFSET(lfem_body_def, report_contacts, 119);
CHECK_OFFSET(lfem_body_def, edge_contacts, 120);

CHECK_SIZE(lfem_contact, 168);
CHECK_OFFSET(lfem_contact, body_a, 0);
CHECK_OFFSET(lfem_contact, body_b, 8);
CHECK_OFFSET(lfem_contact, node, 16);
CHECK_OFFSET(lfem_contact, triangle, 20);
CHECK_OFFSET(lfem_contact, barycentric, 32);
CHECK_OFFSET(lfem_contact, position, 48);
CHECK_OFFSET(lfem_contact, normal, 72);
CHECK_OFFSET(lfem_contact, force, 96);
CHECK_OFFSET(lfem_contact, sliding, 120);
CHECK_OFFSET(lfem_contact, kind, 121);
CHECK_OFFSET(lfem_contact, padding, 122);
CHECK_OFFSET(lfem_contact, shape, 124);
CHECK_OFFSET(lfem_contact, weights_a, 128);
CHECK_OFFSET(lfem_contact, nodes_a, 152);

CHECK_SIZE(lfem_attachment_def, 128);
CHECK_OFFSET(lfem_attachment_def, body, 0);
CHECK_OFFSET(lfem_attachment_def, target, 8);
CHECK_OFFSET(lfem_attachment_def, nodes, 16);
CHECK_OFFSET(lfem_attachment_def, node_count, 24);
CHECK_OFFSET(lfem_attachment_def, internal_value, 28);
CHECK_OFFSET(lfem_attachment_def, frame, 32);
CHECK_OFFSET(lfem_attachment_def, break_force, 88);
CHECK_OFFSET(lfem_attachment_def, points, 96);
CHECK_OFFSET(lfem_attachment_def, point_count, 104);
CHECK_OFFSET(lfem_attachment_def, stiffness, 112);
CHECK_OFFSET(lfem_attachment_def, damping, 120);

CHECK_SIZE(lfem_shape_def, 120);
CHECK_OFFSET(lfem_shape_def, type, 0);
CHECK_OFFSET(lfem_shape_def, point_count, 4);
CHECK_OFFSET(lfem_shape_def, center, 8);
CHECK_OFFSET(lfem_shape_def, rotation, 32);
CHECK_OFFSET(lfem_shape_def, half_extents, 64);
CHECK_OFFSET(lfem_shape_def, radius, 88);
CHECK_OFFSET(lfem_shape_def, half_length, 96);
CHECK_OFFSET(lfem_shape_def, points, 104);
CHECK_OFFSET(lfem_shape_def, internal_value, 112);
CHECK_OFFSET(lfem_shape_def, padding, 116);

int main(void) {
    printf("lfem_status %zu\nlfem_body_type %zu\nlfem_model %zu\nlfem_shape_type %zu\n",
           sizeof(lfem_status), sizeof(lfem_body_type), sizeof(lfem_model), sizeof(lfem_shape_type));
    printf("lfem_body %zu\nlfem_world_def %zu\nlfem_world_stats %zu\n", sizeof(lfem_body),
           sizeof(lfem_world_def), sizeof(lfem_world_stats));
    printf("lfem_body_def %zu\nlfem_contact %zu\nlfem_shape_def %zu\n", sizeof(lfem_body_def),
           sizeof(lfem_contact), sizeof(lfem_shape_def));
    printf("lfem_warning_kind %zu\nlfem_warning %zu\n", sizeof(lfem_warning_kind), sizeof(lfem_warning));
    printf("lfem_profile %zu\nlfem_query_filter %zu\nlfem_ray_hit %zu\n", sizeof(lfem_profile),
           sizeof(lfem_query_filter), sizeof(lfem_ray_hit));
    return 0;
}
