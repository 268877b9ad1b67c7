#include "clients/sim/bench/target_names.h"

#include <map>

namespace semnav::sim::bench {

std::optional<std::string> ChineseName(std::string_view label) {
  // Labels of the room-object table, the fly-roll halls and the outdoor scenes.
  static const std::map<std::string, std::string, std::less<>> kNames = {
      {"backpack", "背包"},      {"bed", "床"},           {"bench", "长椅"},
      {"book", "书"},            {"bottle", "瓶子"},      {"bowl", "碗"},
      {"boat", "船"},            {"car", "汽车"},         {"chair", "椅子"},
      {"clock", "时钟"},         {"couch", "沙发"},       {"cup", "杯子"},
      {"desk", "书桌"},          {"dining table", "餐桌"}, {"fire extinguisher", "灭火器"},
      {"laptop", "笔记本电脑"},  {"microwave", "微波炉"}, {"oven", "烤箱"},
      {"potted plant", "盆栽"},  {"printer", "打印机"},   {"refrigerator", "冰箱"},
      {"remote", "遥控器"},      {"sink", "水槽"},        {"sports ball", "球"},
      {"suitcase", "行李箱"},    {"teddy bear", "泰迪熊"}, {"toilet", "马桶"},
      {"toothbrush", "牙刷"},    {"tv", "电视"},          {"vase", "花瓶"},
  };
  const auto it = kNames.find(label);
  if (it == kNames.end()) return std::nullopt;
  return it->second;
}

}  // namespace semnav::sim::bench
