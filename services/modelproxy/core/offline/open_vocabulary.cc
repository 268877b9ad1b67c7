#include "services/modelproxy/core/offline/open_vocabulary.h"

#include <cctype>

#include "absl/strings/ascii.h"

namespace semnav::modelproxy::offline {
namespace {

struct Entry {
  const char* phrase;  // lower case English, or Chinese
  const char* known_class;
  const char* place;
};

// Places are the ConceptNet terms the prior and the simulator's rooms use.
constexpr Entry kStandIns[] = {
    {"fire extinguisher cabinet", "fire extinguisher", "corridor"},
    {"fire extinguisher box", "fire extinguisher", "corridor"},
    {"extinguisher", "fire extinguisher", "corridor"},
    {"灭火器箱", "fire extinguisher", "corridor"},
    {"消防箱", "fire extinguisher", "corridor"},
    {"灭火器", "fire extinguisher", "corridor"},
    {"coffee machine", "", "kitchen"},
    {"coffee maker", "", "kitchen"},
    {"espresso machine", "", "kitchen"},
    {"咖啡机", "", "kitchen"},
    {"kettle", "", "kitchen"},
    {"水壶", "", "kitchen"},
    {"wifi router", "", "office"},
    {"wi fi router", "", "office"},
    {"wireless router", "", "office"},
    {"router", "", "office"},
    {"modem", "", "office"},
    {"路由器", "", "office"},
    {"photocopier", "printer", "office"},
    {"复印机", "printer", "office"},
    {"fridge magnet", "refrigerator", "kitchen"},
    {"冰箱贴", "refrigerator", "kitchen"},
};

}  // namespace

std::optional<StandIn> OpenVocabularyStandIn(const std::string& target) {
  std::string text = absl::AsciiStrToLower(target);
  for (char& c : text) {
    if (c == '-' || c == '_') c = ' ';
  }
  const Entry* best = nullptr;
  for (const Entry& entry : kStandIns) {
    const std::string phrase = entry.phrase;
    const size_t at = text.find(phrase);
    if (at == std::string::npos) continue;
    // English phrases match whole words ("router" not in "routers'" is fine, not in "prerouter").
    const bool ascii = static_cast<unsigned char>(phrase[0]) < 0x80;
    if (ascii && ((at > 0 && std::isalpha(static_cast<unsigned char>(text[at - 1]))) ||
                  (at + phrase.size() < text.size() &&
                   std::isalpha(static_cast<unsigned char>(text[at + phrase.size()])) &&
                   text[at + phrase.size()] != 's'))) {
      continue;
    }
    if (best == nullptr || phrase.size() > std::string(best->phrase).size()) best = &entry;
  }
  if (best == nullptr) return std::nullopt;
  return StandIn{best->phrase, best->known_class, best->place};
}

}  // namespace semnav::modelproxy::offline
