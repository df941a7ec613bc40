#pragma once
// Aligned text tables for `rs4sim archive`: a header row, then one row per item, columns
// separated by two spaces, numbers right-aligned.

#include <string>
#include <vector>

namespace rs4sim::app::archive {

class Table {
 public:
  struct Column {
    std::string title;
    bool right = false;  // right-aligned (numbers)
  };
  explicit Table(std::vector<Column> columns) : columns_(std::move(columns)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  [[nodiscard]] bool empty() const { return rows_.empty(); }
  // Trailing spaces are trimmed from every line.
  [[nodiscard]] std::string render() const;

 private:
  std::vector<Column> columns_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace rs4sim::app::archive
