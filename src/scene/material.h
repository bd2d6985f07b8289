#pragma once
#include <string>

#include "math/types.h"

namespace lightpath {

// The classic material of Szymczak's illumination formula
//   I = sum_l I_l / (c0 + c1 d + c2 d^2) * (kd (N.L) + ks (H.N)^n) + ka Ia
// extended with Whitted's mirror (kr) and refraction (kt, ior) weights. Per-channel RGB.
struct PhongMaterial {
    std::string name;
    Rgb ka{0.0f};        // ambient reflectance
    Rgb kd{0.0f};        // diffuse reflectance
    Rgb ks{0.0f};        // specular (highlight) reflectance
    float n = 20.0f;     // specular exponent, >= 0
    Rgb kr{0.0f};        // mirror reflection weight
    Rgb kt{0.0f};        // transmission (refraction) weight
    float ior = 1.5f;    // index of refraction of the inside, > 0
    // Fresnel glass: the mirror ray gains kt F and the refracted ray keeps kt (1 - F), F the
    // dielectric's reflectance at the angle of incidence; off, the weights are kr and kt exactly.
    bool fresnel = false;
    Rgb emission{0.0f};  // emitted radiance: makes the surface an area light (an L event)

    bool isSpecular() const { return !isBlack(kr) || !isBlack(kt); }
};

}  // namespace lightpath
