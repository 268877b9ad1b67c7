#pragma once

#include <cmath>

namespace semnav::planning {

// Energy per metre of the flying-rolling robot (seed 003, sec. 3.1).
// Defaults: Table 1 (m = 6 kg, g = 9.81, P_hover = 800 W, v = 1 m/s) and the
// experiment's 400 J/m rolling, 800 J/m flying.
struct EnergyModel {
  // Eq. 10: E1(d) = C_r m g d. The seed sets C_r m g empirically to half the
  // flying energy (400 J/m) rather than from a measured C_r.
  double rolling_j_per_m = 400.0;
  // Eq. 11: P_hover = (m g)^1.5 / sqrt(2 rho A_r); Table 1 gives 800 W.
  double hover_power_w = 800.0;
  // Table 1: constant flight speed v.
  double flight_speed_mps = 1.0;

  // Eq. 12: E2(d) = P_hover / v * d.
  double FlyingJPerM() const { return hover_power_w / flight_speed_mps; }

  // Joules to roll / fly `metres`.
  double Roll(double metres) const { return rolling_j_per_m * metres; }
  double Fly(double metres) const { return FlyingJPerM() * metres; }
};

// Eq. 11: ideal hover power of a rotorcraft, P = (m g)^(3/2) / sqrt(2 rho A_r).
inline double HoverPower(double mass_kg, double gravity, double air_density, double rotor_area_m2) {
  return std::pow(mass_kg * gravity, 1.5) / std::sqrt(2.0 * air_density * rotor_area_m2);
}

}  // namespace semnav::planning
