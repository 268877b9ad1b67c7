// Plain-text tables for terminal output: columns padded to their widest cell (by display width,
// so Chinese labels line up), numbers right-aligned.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace semnav::cli {

class Table {
 public:
  explicit Table(std::vector<std::string> headers) : headers_(std::move(headers)) {}

  // Cells beyond the header count are dropped; missing cells are empty.
  void AddRow(std::vector<std::string> cells);
  bool empty() const { return rows_.empty(); }

  // Header line, then one line per row; columns separated by two spaces, no trailing blanks.
  std::string Render() const;

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

// Terminal columns taken by UTF-8 text: 2 for East Asian wide characters, else 1 per code point.
std::size_t DisplayWidth(std::string_view text);

// "TASK_STATUS_RUNNING" -> "RUNNING" for `prefix` "TASK_STATUS_"; other names unchanged.
std::string ShortEnumName(std::string_view name, std::string_view prefix);

// Fixed-point number with `decimals` digits, e.g. FormatFixed(1.23456, 2) == "1.23".
std::string FormatFixed(double value, int decimals);

}  // namespace semnav::cli
