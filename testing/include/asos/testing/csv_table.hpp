#pragma once
// A table written as CSV (RFC 4180: a field holding a comma, a quote or a line
// break is quoted, its quotes doubled; lines end in "\n"), as the benchmarks'
// figures are kept for plotting and spreadsheets.
#include <cstddef>
#include <string>
#include <vector>

namespace asos {

class CsvTable {
public:
    explicit CsvTable(std::vector<std::string> columns);
    // Throws std::invalid_argument when the row has not one field per column.
    void addRow(std::vector<std::string> fields);
    std::size_t rows() const { return rows_.size(); }
    // The header line, then one line per row.
    std::string text() const;
    // One field as CSV holds it.
    static std::string quoted(const std::string& field);

private:
    std::vector<std::string> columns_;
    std::vector<std::vector<std::string>> rows_;
};

}  // namespace asos
