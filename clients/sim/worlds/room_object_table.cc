#include "clients/sim/worlds/room_object_table.h"

#include <map>

namespace semnav::sim {
namespace {

using P = Placement;

ItemSpec Item(const char* label, bool findable, double l, double d, double h, Rgb colour,
              int min_count, int max_count, Placement placement, const char* on = "") {
  return ItemSpec{label,     findable, Eigen::Vector3d(l, d, h), colour, min_count, max_count,
                  placement, on};
}

// Colours are fixed per label so the RGB image is consistent across worlds.
constexpr Rgb kWood{150, 105, 60}, kWhite{235, 235, 230}, kGrey{120, 120, 125}, kBlack{30, 30, 35},
    kGreen{60, 140, 60}, kRed{190, 50, 45}, kBlue{60, 90, 170}, kBeige{210, 190, 150},
    kBrown{110, 75, 45}, kYellow{220, 190, 60};

const std::map<std::string, std::vector<ItemSpec>, std::less<>>& Table() {
  static const auto* table = [] {
    auto* t = new std::map<std::string, std::vector<ItemSpec>, std::less<>>{
        {"bedroom",
         {Item("bed", true, 2.0, 1.6, 0.55, kBlue, 1, 1, P::kAgainstWall),
          Item("nightstand", false, 0.45, 0.45, 0.55, kWood, 1, 2, P::kAgainstWall),
          Item("wardrobe", false, 1.2, 0.6, 2.0, kWood, 0, 1, P::kAgainstWall),
          Item("chair", true, 0.5, 0.5, 0.9, kBrown, 0, 1, P::kFree),
          Item("potted plant", true, 0.4, 0.4, 0.8, kGreen, 0, 1, P::kFree),
          Item("clock", true, 0.25, 0.1, 0.25, kWhite, 0, 1, P::kOnTop, "nightstand"),
          Item("book", true, 0.25, 0.18, 0.05, kRed, 0, 1, P::kOnTop, "nightstand"),
          Item("teddy bear", true, 0.35, 0.25, 0.35, kBeige, 0, 1, P::kOnTop, "bed")}},
        {"living_room",
         {Item("couch", true, 2.0, 0.9, 0.85, kGrey, 1, 1, P::kAgainstWall),
          Item("tv stand", false, 1.5, 0.45, 0.5, kWood, 1, 1, P::kAgainstWall),
          Item("tv", true, 1.2, 0.15, 0.7, kBlack, 1, 1, P::kOnTop, "tv stand"),
          Item("coffee table", false, 1.0, 0.6, 0.45, kWood, 0, 1, P::kFree),
          Item("potted plant", true, 0.45, 0.45, 1.0, kGreen, 1, 2, P::kFree),
          Item("chair", true, 0.6, 0.6, 0.9, kBrown, 0, 2, P::kFree),
          Item("vase", true, 0.2, 0.2, 0.35, kBlue, 0, 1, P::kOnTop, "coffee table"),
          Item("remote", true, 0.2, 0.06, 0.03, kBlack, 0, 1, P::kOnTop, "coffee table")}},
        {"kitchen",
         {Item("refrigerator", true, 0.8, 0.7, 1.8, kWhite, 1, 1, P::kAgainstWall),
          Item("counter", false, 2.0, 0.6, 0.9, kBeige, 1, 1, P::kAgainstWall),
          Item("oven", true, 0.6, 0.6, 0.9, kGrey, 1, 1, P::kAgainstWall),
          Item("sink", true, 0.8, 0.55, 0.9, kWhite, 1, 1, P::kAgainstWall),
          Item("microwave", true, 0.5, 0.35, 0.3, kGrey, 0, 1, P::kOnTop, "counter"),
          Item("bottle", true, 0.08, 0.08, 0.3, kGreen, 0, 2, P::kOnTop, "counter"),
          Item("cup", true, 0.1, 0.1, 0.12, kWhite, 0, 1, P::kOnTop, "counter"),
          Item("dining table", true, 1.2, 0.8, 0.75, kWood, 0, 1, P::kFree),
          Item("chair", true, 0.5, 0.5, 0.9, kBrown, 0, 2, P::kFree)}},
        {"bathroom",
         {Item("toilet", true, 0.45, 0.7, 0.75, kWhite, 1, 1, P::kAgainstWall),
          Item("sink", true, 0.6, 0.45, 0.85, kWhite, 1, 1, P::kAgainstWall),
          Item("bathtub", false, 1.7, 0.75, 0.55, kWhite, 0, 1, P::kAgainstWall),
          Item("toothbrush", true, 0.2, 0.03, 0.03, kBlue, 0, 1, P::kOnTop, "sink"),
          Item("bottle", true, 0.08, 0.08, 0.2, kYellow, 0, 1, P::kOnTop, "sink")}},
        {"dining_room",
         {Item("dining table", true, 1.8, 0.9, 0.75, kWood, 1, 1, P::kFree),
          Item("chair", true, 0.5, 0.5, 0.9, kBrown, 2, 4, P::kFree),
          Item("cabinet", false, 1.2, 0.45, 1.0, kWood, 0, 1, P::kAgainstWall),
          Item("potted plant", true, 0.45, 0.45, 1.0, kGreen, 0, 1, P::kFree),
          Item("vase", true, 0.2, 0.2, 0.35, kRed, 0, 1, P::kOnTop, "dining table"),
          Item("bowl", true, 0.25, 0.25, 0.1, kWhite, 0, 1, P::kOnTop, "dining table")}},
        {"study",
         {Item("desk", true, 1.4, 0.7, 0.75, kWood, 1, 1, P::kAgainstWall),
          Item("chair", true, 0.55, 0.55, 0.95, kBlack, 1, 1, P::kFree),
          Item("bookshelf", false, 1.0, 0.35, 1.9, kWood, 1, 2, P::kAgainstWall),
          Item("laptop", true, 0.35, 0.25, 0.03, kGrey, 0, 1, P::kOnTop, "desk"),
          Item("book", true, 0.25, 0.18, 0.05, kRed, 0, 1, P::kOnTop, "desk"),
          Item("potted plant", true, 0.4, 0.4, 0.8, kGreen, 0, 1, P::kFree)}},
        {"office",
         {Item("desk", true, 1.4, 0.7, 0.75, kWhite, 2, 4, P::kAgainstWall),
          Item("chair", true, 0.55, 0.55, 0.95, kBlack, 2, 4, P::kFree),
          Item("cabinet", false, 0.8, 0.5, 1.2, kGrey, 0, 2, P::kAgainstWall),
          Item("tv", true, 0.6, 0.15, 0.4, kBlack, 0, 2, P::kOnTop, "desk"),
          Item("laptop", true, 0.35, 0.25, 0.03, kGrey, 0, 2, P::kOnTop, "desk"),
          Item("potted plant", true, 0.45, 0.45, 1.1, kGreen, 0, 1, P::kFree),
          Item("printer", true, 0.5, 0.45, 0.35, kGrey, 0, 1, P::kOnTop, "cabinet")}},
        {"meeting_room",
         {Item("table", true, 3.0, 1.2, 0.75, kWood, 1, 1, P::kFree),
          Item("chair", true, 0.55, 0.55, 0.95, kBlack, 3, 6, P::kFree),
          Item("tv", true, 1.5, 0.15, 0.9, kBlack, 0, 1, P::kOnTop, "tv stand"),
          Item("tv stand", false, 1.6, 0.45, 0.6, kGrey, 0, 1, P::kAgainstWall),
          Item("potted plant", true, 0.45, 0.45, 1.1, kGreen, 0, 1, P::kFree)}},
        {"pantry",
         {Item("refrigerator", true, 0.8, 0.7, 1.8, kWhite, 1, 1, P::kAgainstWall),
          Item("counter", false, 1.8, 0.6, 0.9, kBeige, 1, 1, P::kAgainstWall),
          Item("sink", true, 0.8, 0.55, 0.9, kWhite, 0, 1, P::kAgainstWall),
          Item("microwave", true, 0.5, 0.35, 0.3, kGrey, 1, 1, P::kOnTop, "counter"),
          Item("cup", true, 0.1, 0.1, 0.12, kWhite, 0, 2, P::kOnTop, "counter"),
          Item("bottle", true, 0.08, 0.08, 0.3, kGreen, 0, 1, P::kOnTop, "counter")}},
        // HouseExpo's generic and utility rooms.
        {"room",
         {Item("cabinet", false, 1.0, 0.45, 1.0, kWood, 0, 1, P::kAgainstWall),
          Item("chair", true, 0.5, 0.5, 0.9, kBrown, 1, 2, P::kFree),
          Item("potted plant", true, 0.45, 0.45, 1.0, kGreen, 0, 1, P::kFree),
          Item("clock", true, 0.25, 0.1, 0.25, kWhite, 0, 1, P::kOnTop, "cabinet")}},
        {"storage",
         {Item("shelf", false, 1.2, 0.4, 1.8, kGrey, 1, 2, P::kAgainstWall),
          Item("suitcase", true, 0.5, 0.3, 0.7, kBlue, 0, 1, P::kFree),
          Item("backpack", true, 0.35, 0.25, 0.5, kRed, 0, 1, P::kFree)}},
        {"gym",
         {Item("bench", true, 1.2, 0.4, 0.45, kBlack, 1, 1, P::kFree),
          Item("sports ball", true, 0.25, 0.25, 0.25, kYellow, 0, 2, P::kFree)}},
    };
    (*t)["restroom"] = (*t)["bathroom"];  // an office restroom holds what a bathroom does
    return t;
  }();
  return *table;
}

}  // namespace

const std::vector<ItemSpec>& RoomItems(std::string_view room_type) {
  static const std::vector<ItemSpec> kNone;
  const auto& table = Table();
  const auto it = table.find(room_type);
  return it == table.end() ? kNone : it->second;
}

}  // namespace semnav::sim
