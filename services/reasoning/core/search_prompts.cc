#include "services/reasoning/core/search_prompts.h"

#include <cctype>

#include "absl/strings/str_cat.h"

namespace semnav::reasoning {

std::string BuildSearchPrompt(std::string_view target) {
  const std::string t(target);
  return absl::StrCat(
      "Task: you analyse the forward camera image of a robot. Target = [", t,
      "]. Work in a recognition-evaluation loop to find where the [", t,
      "] most likely is, or where the robot should move to search further.\n"
      "Question A (recognition): What type of scene is this? Does it match the [",
      t, "]? Are there clues related to the [", t,
      "]? Are there passages (doors, windows, roads) to other areas?\n",
      "Question B (evaluation: go to a clue or transfer): if there is a clue related to the [", t,
      "], choose it; if the scene type does not match the [", t,
      "], choose a passage to transfer through.\n",
      "Output constraint: the image is labelled with position codes (letter-digits-letter). Output "
      "the code "
      "printed nearest to the chosen place and a short description, exactly as\n"
      "Code: <code>, Description: <description>\n"
      "Output nothing if there is neither a clue nor a passage.\n"
      "Example: a garage shelf holds an object shaped like a [",
      t,
      "]. Expected output: Code: F6A, "
      "Description: [",
      t, "] on the garage shelf");
}

std::string BuildRegionScorePrompt(std::string_view target,
                                   const std::vector<std::string>& descriptions) {
  std::string listed;
  for (const std::string& description : descriptions)
    absl::StrAppend(&listed, "- ", description, "\n");
  return absl::StrCat(
      "A robot searching for [", std::string(target),
      "] observed these places inside one region of the map:\n", listed, "How likely is the [",
      std::string(target),
      "] to be in this region? Answer with one integer from -5 (certainly not) to 5 (certainly).");
}

absl::StatusOr<int> ParseRegionScore(std::string_view answer) {
  for (std::size_t i = 0; i < answer.size(); ++i) {
    const bool negative = answer[i] == '-' && i + 1 < answer.size() &&
                          std::isdigit(static_cast<unsigned char>(answer[i + 1]));
    if (!negative && !std::isdigit(static_cast<unsigned char>(answer[i]))) continue;
    std::size_t j = negative ? i + 1 : i;
    int value = 0;
    while (j < answer.size() && std::isdigit(static_cast<unsigned char>(answer[j])) &&
           value < 100) {
      value = value * 10 + (answer[j++] - '0');
    }
    if (negative) value = -value;
    if (value < -5 || value > 5) {
      return absl::InvalidArgumentError(
          absl::StrCat("region score: ", value, " is outside [-5, 5]"));
    }
    return value;
  }
  return absl::InvalidArgumentError("region score: no integer in the answer");
}

}  // namespace semnav::reasoning
