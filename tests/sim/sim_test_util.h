// Shared truths of the simulation tests: reference coefficients and the closed-form mean
// forces of a cylindrical end mill, written once so every test checks the same formula.
#pragma once

#include <cmath>

#include "swarf/core/vec.h"
#include "swarf/sim/force.h"

namespace swarf::sim::testing {

// Altintas' Al7075 coefficients: the axial terms are large enough to be checked.
inline CuttingCoefficients al7075() {
  CuttingCoefficients k;
  k.ktc_n_mm2 = 796.0;
  k.krc_n_mm2 = 168.0;
  k.kac_n_mm2 = 222.0;
  k.kte_n_mm = 27.7;
  k.kre_n_mm = 30.8;
  k.kae_n_mm = 2.3;
  return k;
}

// Closed-form mean forces of a cylindrical end mill (Altintas, Manufacturing Automation,
// Eq. 2.31 with edge forces), feed along +x, tooth in cut from start_rad to exit_rad.
// F_z is -F_a in the seed's element frame.
inline Vec3 altintas_mean(const CuttingCoefficients& k, int flutes, double axial, double ft,
                          double start_rad, double exit_rad) {
  const double n = flutes;
  auto f = [&](double t) {
    return Vec3{n * axial * ft / (8 * kPi) *
                        (k.ktc_n_mm2 * std::cos(2 * t) - k.krc_n_mm2 * (2 * t - std::sin(2 * t))) +
                    n * axial / (2 * kPi) * (-k.kte_n_mm * std::sin(t) + k.kre_n_mm * std::cos(t)),
                n * axial * ft / (8 * kPi) *
                        (k.ktc_n_mm2 * (2 * t - std::sin(2 * t)) + k.krc_n_mm2 * std::cos(2 * t)) -
                    n * axial / (2 * kPi) * (k.kte_n_mm * std::cos(t) + k.kre_n_mm * std::sin(t)),
                -n * axial / (2 * kPi) * (-k.kac_n_mm2 * ft * std::cos(t) + k.kae_n_mm * t)};
  };
  return f(exit_rad) - f(start_rad);
}

}  // namespace swarf::sim::testing
