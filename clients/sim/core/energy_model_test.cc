#include "clients/sim/core/energy_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::sim {
namespace {

TEST(SimEnergyModelTest, SeedThreeExperimentNumbers) {
  const EnergyModel model;
  EXPECT_DOUBLE_EQ(model.Roll(10.0), 4000.0);
  EXPECT_DOUBLE_EQ(model.Fly(10.0), 8000.0);
  // Table 1: P_hover 800 W at v = 1 m/s gives 800 J/m (eq. 12); eq. 10 with m = 6 kg,
  // g = 9.81 and C_r = 0.1 gives 5.886 J/m.
  const EnergyModel physics = EnergyModel::FromPhysics(6.0, 9.81, 0.1, 800.0, 1.0);
  EXPECT_DOUBLE_EQ(physics.fly_j_per_m, 800.0);
  EXPECT_NEAR(physics.roll_j_per_m, 5.886, 1e-9);
}

TEST(SimEnergyModelTest, HoverPowerEquationEleven) {
  // (m g)^1.5 / sqrt(2 rho A): m = 6, g = 9.81, rho = 1.225, A = 0.2 -> 58.86^1.5 / 0.7 = 645.1 W.
  EXPECT_NEAR(HoverPower(6.0, 9.81, 1.225, 0.2), std::pow(58.86, 1.5) / std::sqrt(0.49), 1e-9);
  EXPECT_NEAR(HoverPower(6.0, 9.81, 1.225, 0.2), 645.1, 0.1);
}

}  // namespace
}  // namespace semnav::sim
