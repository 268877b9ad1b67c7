#ifndef SEMNAV_CLIENTS_SIM_CORE_ENERGY_MODEL_H_
#define SEMNAV_CLIENTS_SIM_CORE_ENERGY_MODEL_H_

// Energy per metre for rolling and flying, seed 003 section 3 (eq. 10-12).
namespace semnav::sim {

// Eq. 11: ideal hover power of a rotorcraft, P = (m g)^(3/2) / sqrt(2 rho A_r).
double HoverPower(double mass_kg, double gravity, double air_density, double rotor_area_m2);

struct EnergyModel {
  // Seed 003's experiment (Table 1): 800 J per metre flying (P_hover 800 W at v = 1 m/s) and
  // rolling set to half of that, 400 J per metre.
  double roll_j_per_m = 400.0;
  double fly_j_per_m = 800.0;

  // Eq. 10: E_roll = C_r m g d; eq. 12: E_fly = (P_hover / v) d.
  static EnergyModel FromPhysics(double mass_kg, double gravity, double rolling_coefficient,
                                 double hover_power_w, double fly_speed_mps);
  double Roll(double metres) const { return roll_j_per_m * metres; }
  double Fly(double metres) const { return fly_j_per_m * metres; }
};

}  // namespace semnav::sim

#endif  // SEMNAV_CLIENTS_SIM_CORE_ENERGY_MODEL_H_
