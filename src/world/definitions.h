// What the caller defines, in the world's own words: the world's and a body's settings, the
// handles of bodies and attachments, the kinds of event. The shim converts the public structs
// of lfem_types.h (which document every field) to these and back (api/conversions.*), so no
// file below src/api includes the public header.
#pragma once

#include <cstdint>

#include "common/body_kind.h"
#include "fem/material.h"

namespace lfem {

struct WorldDef {
    double gravity[3] = {0, 0, -9.81};  // m/s^2
    double time_step = 0;               // s; 0 = automatic (step_safety of the stable limit)
    double step_safety = 0.9;
    uint32_t contact_iterations = 200;  // cap of the contact solve's sweeps
    uint32_t thread_count = 1;
    double contact_tolerance = 1e-3;    // relative stopping tolerance of the contact solve
    uint32_t max_substeps = 1000000;
    bool allow_unstable_step = false;
    bool enable_sleep = false;
    double mass_scaling_step = 0;       // s; 0 = no mass scaling
    double sleep_velocity = 0.01;       // m/s
    double sleep_time = 0.5;            // s
};

struct BodyDef {
    BodyKind type = BodyKind::deformable;
    Model model = Model::paper;
    double young_modulus = 1e6;  // Pa
    double poisson_ratio = 0.3;
    double density = 1000;       // kg/m^3
    double damping = 0;          // 1/s, mass-proportional
    double friction = 0.5;       // Coulomb coefficient
    double linear_velocity[3] = {0, 0, 0};   // m/s (kinematic bodies: their velocity)
    double angular_velocity[3] = {0, 0, 0};  // rad/s
    uint32_t category_bits = 1, mask_bits = ~0u;
    void* user_data = nullptr;   // the caller's, never read
    uint64_t user_id = 0;        // the caller's, never read; kept by checkpoints
    bool enable_sleep = true;
    bool self_contact = false;
    bool composite_tets = false;
    bool report_contacts = false;  // every call reports its pairs that stay in touch
    bool edge_contacts = true;     // its sharp edges meet other bodies' (contact/edge_edge.h)
};

// Generation-checked handles (body_registry.h): {0, 0} is the null handle.
struct BodyHandle {
    uint32_t index = 0, generation = 0;
    bool is_null() const { return index == 0 && generation == 0; }
};
struct AttachmentHandle {
    uint32_t index = 0, generation = 0;
};

enum class EventType : int32_t { contact_begin, contact_end, sleep, wake, attachment_broken, contact_persist };

}  // namespace lfem
