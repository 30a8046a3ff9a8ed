// Isotropic elastic constants, the material model a body uses, and the wave speed that sets
// the explicit step.
#pragma once

#include <cmath>

#include <cstdint>

namespace lfem {

// The material models (the public Model, converted by the shim; lfem_types.h describes
// each).
enum class Model : int32_t { paper, corotational, neo_hookean, linear };

struct Lame {
    double mu = 0;      // shear modulus (Pa)
    double lambda = 0;  // first Lame parameter (Pa)
};

// What the element kernels need to know of a body's material.
struct Material {
    Model model = Model::paper;
    Lame lame;
};

inline Lame lame_from_young_poisson(double young, double poisson) {
    Lame l;
    l.mu = young / (2.0 * (1.0 + poisson));
    l.lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    return l;
}

// Dilatational (P-wave) speed c_d = sqrt((lambda + 2 mu) / rho): the fastest wave in the body.
inline double dilatational_wave_speed(const Lame& l, double density) {
    return std::sqrt((l.lambda + 2.0 * l.mu) / density);
}

}  // namespace lfem
