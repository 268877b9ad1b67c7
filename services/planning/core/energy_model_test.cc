#include "services/planning/core/energy_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::planning {
namespace {

TEST(EnergyModelTest, SeedThreeExperimentNumbers) {
  const EnergyModel model;
  EXPECT_DOUBLE_EQ(model.Roll(10.0), 4000.0);
  EXPECT_DOUBLE_EQ(model.Fly(10.0), 8000.0);  // Table 1: 800 W at 1 m/s (eq. 12)
  const EnergyModel slower{400.0, 800.0, 0.5};
  EXPECT_DOUBLE_EQ(slower.FlyingJPerM(), 1600.0);
}

TEST(EnergyModelTest, HoverPowerEquationEleven) {
  // (m g)^1.5 / sqrt(2 rho A): m = 6, g = 9.81, rho = 1.225, A = 0.2 -> 58.86^1.5 / 0.7 = 645.1 W.
  EXPECT_NEAR(HoverPower(6.0, 9.81, 1.225, 0.2), std::pow(58.86, 1.5) / std::sqrt(0.49), 1e-9);
  EXPECT_NEAR(HoverPower(6.0, 9.81, 1.225, 0.2), 645.1, 0.1);
}

}  // namespace
}  // namespace semnav::planning
