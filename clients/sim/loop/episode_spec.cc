#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::loop {

SensorConfig LoopSensorConfig() {
  SensorConfig sensors;
  sensors.intrinsics = CameraIntrinsics{160, 120, 131.25, 131.25, 79.5, 59.5};
  sensors.detector.min_pixels = 10;  // 150 / 16
  return sensors;
}

}  // namespace semnav::sim::loop
