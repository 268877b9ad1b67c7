#include "services/reasoning/testing/fixture.h"

#include <fstream>
#include <sstream>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"

namespace semnav::reasoning::testing {
namespace {

absl::StatusOr<std::string> ReadFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot open ", path));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

absl::StatusOr<SceneGraph> LoadSceneGraph(const std::string& path) {
  absl::StatusOr<std::string> text = ReadFile(path);
  if (!text.ok()) return text.status();
  const nlohmann::json root = nlohmann::json::parse(*text, nullptr, false);
  if (root.is_discarded()) return absl::InvalidArgumentError(absl::StrCat(path, ": not JSON"));
  SceneGraph graph;
  graph.revision = 1;
  try {
    for (const nlohmann::json& item : root.at("objects")) {
      SceneObject object;
      object.id = item.at("id").get<int64_t>();
      object.label = item.at("label").get<std::string>();
      object.attributes = item.value("attributes", std::vector<std::string>{});
      const auto position = item.at("position").get<std::vector<double>>();
      object.position = Eigen::Vector3d(position.at(0), position.at(1), position.at(2));
      object.score = item.at("score").get<double>();
      object.detection_count = item.at("detections").get<int>();
      object.region_id = item.value("region", int64_t{-1});
      graph.objects.push_back(std::move(object));
    }
    for (const nlohmann::json& item : root.at("relations")) {
      graph.relations.push_back({item.at(0).get<int64_t>(), item.at(1).get<std::string>(),
                                 item.at(2).get<int64_t>(), item.at(3).get<double>()});
    }
    for (const nlohmann::json& item : root.at("regions")) {
      graph.regions.push_back({item.at("id").get<int64_t>(), item.at("name").get<std::string>(),
                               item.at("objects").get<std::vector<int64_t>>()});
    }
  } catch (const nlohmann::json::exception& error) {
    return absl::InvalidArgumentError(absl::StrCat(path, ": ", error.what()));
  }
  return graph;
}

absl::StatusOr<std::vector<InstructionCase>> LoadInstructionSet(const std::string& path) {
  absl::StatusOr<std::string> text = ReadFile(path);
  if (!text.ok()) return text.status();
  std::vector<InstructionCase> cases;
  std::istringstream lines(*text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line.front() == '#') continue;
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos)
      return absl::InvalidArgumentError(absl::StrCat(path, ": missing tab in '", line, "'"));
    InstructionCase c;
    c.instruction = line.substr(0, tab);
    const std::string expected = line.substr(tab + 1);
    if (expected != "-") {
      int64_t id = 0;
      if (!absl::SimpleAtoi(expected, &id))
        return absl::InvalidArgumentError(absl::StrCat(path, ": bad id '", expected, "'"));
      c.expected_object = id;
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

std::string FastPathScenePath() { return SEMNAV_REASONING_TESTING_DIR "/fast_path_scene.json"; }
std::string FastPathInstructionsPath() {
  return SEMNAV_REASONING_TESTING_DIR "/fast_path_instructions.tsv";
}

}  // namespace semnav::reasoning::testing
