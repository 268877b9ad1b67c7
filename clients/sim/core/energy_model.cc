#include "clients/sim/core/energy_model.h"

#include <cmath>

namespace semnav::sim {

double HoverPower(double mass_kg, double gravity, double air_density, double rotor_area_m2) {
  return std::pow(mass_kg * gravity, 1.5) / std::sqrt(2.0 * air_density * rotor_area_m2);
}

EnergyModel EnergyModel::FromPhysics(double mass_kg, double gravity, double rolling_coefficient,
                                     double hover_power_w, double fly_speed_mps) {
  return EnergyModel{rolling_coefficient * mass_kg * gravity, hover_power_w / fly_speed_mps};
}

}  // namespace semnav::sim
