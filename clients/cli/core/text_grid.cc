#include "clients/cli/core/text_grid.h"

#include <string>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"

namespace semnav::cli {
namespace {

constexpr uint8_t kStructure = 100;
constexpr uint8_t kUnknown = 255;

absl::StatusOr<uint8_t> CellValue(char c) {
  switch (c) {
    case '.':
    case 'G':
    case 'S':
      return 0;
    case '@':
    case 'O':
    case 'T':
    case 'W':
    case '#':
      return kStructure;
    case '?':
      return kUnknown;
    default:
      if (c >= '1' && c <= '9') return static_cast<uint8_t>(c - '0');
      return absl::InvalidArgumentError(
          absl::StrCat("unknown cell character '", std::string(1, c), "'"));
  }
}

// Reads "height H" / "width W" header lines; returns the lines after "map".
absl::StatusOr<std::vector<absl::string_view>> SkipHeader(std::vector<absl::string_view> lines,
                                                          int* height, int* width) {
  std::size_t i = 0;
  for (; i < lines.size() && lines[i] != "map"; ++i) {
    std::vector<absl::string_view> words = absl::StrSplit(lines[i], ' ', absl::SkipEmpty());
    if (words.size() == 2 && words[0] == "height" && !absl::SimpleAtoi(words[1], height)) {
      return absl::InvalidArgumentError("bad 'height' line");
    }
    if (words.size() == 2 && words[0] == "width" && !absl::SimpleAtoi(words[1], width)) {
      return absl::InvalidArgumentError("bad 'width' line");
    }
  }
  if (i == lines.size()) return absl::InvalidArgumentError("Moving AI header without a 'map' line");
  return std::vector<absl::string_view>(lines.begin() + i + 1, lines.end());
}

}  // namespace

absl::StatusOr<TextGrid> ParseTextGrid(std::string_view text) {
  std::vector<absl::string_view> lines;
  for (absl::string_view line : absl::StrSplit(absl::string_view(text.data(), text.size()), '\n')) {
    line = absl::StripSuffix(line, "\r");
    if (!line.empty()) lines.push_back(line);
  }
  int header_height = -1;
  int header_width = -1;
  if (!lines.empty() && absl::StartsWith(lines[0], "type")) {
    absl::StatusOr<std::vector<absl::string_view>> rows =
        SkipHeader(lines, &header_height, &header_width);
    if (!rows.ok()) return rows.status();
    lines = *std::move(rows);
  }
  if (lines.empty()) return absl::InvalidArgumentError("the grid has no rows");
  TextGrid grid;
  grid.height = static_cast<int>(lines.size());
  grid.width = static_cast<int>(lines[0].size());
  for (int row = 0; row < grid.height; ++row) {
    if (static_cast<int>(lines[row].size()) != grid.width) {
      return absl::InvalidArgumentError(
          absl::StrCat("row ", row, " has ", lines[row].size(), " cells, row 0 has ", grid.width));
    }
    for (int col = 0; col < grid.width; ++col) {
      absl::StatusOr<uint8_t> value = CellValue(lines[row][col]);
      if (!value.ok()) {
        return absl::InvalidArgumentError(
            absl::StrCat("row ", row, " column ", col, ": ", value.status().message()));
      }
      grid.cells.push_back(*value);
    }
  }
  if ((header_height >= 0 && header_height != grid.height) ||
      (header_width >= 0 && header_width != grid.width)) {
    return absl::InvalidArgumentError(absl::StrCat("header says ", header_width, "x", header_height,
                                                   ", rows are ", grid.width, "x", grid.height));
  }
  return grid;
}

}  // namespace semnav::cli
