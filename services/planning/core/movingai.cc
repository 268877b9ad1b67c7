#include "services/planning/core/movingai.h"

#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"

namespace semnav::planning {
namespace {

bool Passable(char c) { return c == '.' || c == 'G' || c == 'S'; }

}  // namespace

absl::StatusOr<PassabilityGrid> LoadMovingAiMap(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot open map file ", path));
  std::string word;
  int width = -1;
  int height = -1;
  while (in >> word && word != "map") {
    if (word == "height") in >> height;
    if (word == "width") in >> width;
  }
  if (word != "map" || width <= 0 || height <= 0) {
    return absl::InvalidArgumentError(absl::StrCat(path, ": missing width/height/map header"));
  }
  PassabilityGrid grid(width, height, 0);
  std::string row;
  for (int y = 0; y < height; ++y) {
    if (!(in >> row) || static_cast<int>(row.size()) != width) {
      return absl::InvalidArgumentError(
          absl::StrCat(path, ": map row ", y, " is not ", width, " characters"));
    }
    for (int x = 0; x < width; ++x) grid.at(x, y) = Passable(row[x]) ? 1 : 0;
  }
  return grid;
}

absl::StatusOr<std::vector<MovingAiScenario>> LoadMovingAiScenarios(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot open scenario file ", path));
  std::string line;
  std::getline(in, line);
  if (line.rfind("version", 0) != 0) {
    return absl::InvalidArgumentError(absl::StrCat(path, ": missing 'version' header"));
  }
  std::vector<MovingAiScenario> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    MovingAiScenario row;
    std::string map_name;
    int map_w = 0;
    int map_h = 0;
    if (!(fields >> row.bucket >> map_name >> map_w >> map_h >> row.start.x >> row.start.y >>
          row.goal.x >> row.goal.y >> row.optimal_length)) {
      return absl::InvalidArgumentError(
          absl::StrCat(path, ": malformed scenario row ", rows.size() + 1));
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace semnav::planning
