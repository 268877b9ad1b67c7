#pragma once
// Open vocabulary for the offline backend (issue 15): targets neither the lexicon nor the
// ConceptNet prior knows ("fire extinguisher cabinet", "coffee machine", "wifi router", 灭火器箱,
// 咖啡机, 路由器) get a stand-in: a class the robot's detector knows (the target is found as that
// class) and/or the place such a thing is kept (the search goes there). A hand-made table, the
// offline answer to what a vision-language model would say; real models need none.
#include <optional>
#include <string>

namespace semnav::modelproxy::offline {

struct StandIn {
  std::string phrase;       // the phrase matched, as in the table
  std::string known_class;  // canonical detector class; "" when there is none
  std::string place;        // canonical place; "" when none is typical
};

// The stand-in of `target` (as said, or canonical): the longest table phrase it contains;
// nullopt when none.
std::optional<StandIn> OpenVocabularyStandIn(const std::string& target);

}  // namespace semnav::modelproxy::offline
