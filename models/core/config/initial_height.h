#pragma once
// The ground's initial height field as the scene describes it, and which
// material lies where.

#include "models/core/geometry/height_field.h"
#include "models/core/config/scene.h"

namespace repose {

// Flat, seeded noise, or read from the scene's .npy / 16-bit .png file.
// Noise: white noise per cell from std::mt19937_64 seeded with scene.seed,
// smoothed by three passes of a box filter (close to a Gaussian of standard
// deviation correlation_m), then shifted and scaled so that its mean is
// mean_m and its largest deviation from the mean is amplitude_m. The same
// scene and seed give a bit-identical field on every run.
HeightField make_initial_height(const Scene& scene);

// The material at a point: the last region containing it (edges included),
// else the ground's material.
const std::string& material_at(const GroundSpec& ground, double x_m, double y_m);

}  // namespace repose
