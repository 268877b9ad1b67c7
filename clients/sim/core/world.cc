#include "clients/sim/core/world.h"

namespace semnav::sim {

std::string_view ModalityName(Modality modality) {
  switch (modality) {
    case Modality::kGround:
      return "ground";
    case Modality::kUav:
      return "uav";
    case Modality::kFlyRoll:
      return "fly_roll";
  }
  return "ground";
}

std::optional<Modality> ParseModality(std::string_view name) {
  for (Modality m : {Modality::kGround, Modality::kUav, Modality::kFlyRoll}) {
    if (ModalityName(m) == name) return m;
  }
  return std::nullopt;
}

double ShapeTop(const Shape& shape) {
  return std::visit([](const auto& s) { return s.top_z(); }, shape);
}

bool IsStructure(std::string_view kind) { return kind == "wall" || kind == "building"; }

}  // namespace semnav::sim
