#include "asos/testing/csv_table.hpp"

#include <stdexcept>
#include <utility>

namespace asos {

namespace {

std::string line(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + CsvTable::quoted(fields[i]);
    return out + "\n";
}

}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
    if (columns_.empty()) throw std::invalid_argument("CsvTable: at least one column");
}

void CsvTable::addRow(std::vector<std::string> fields) {
    if (fields.size() != columns_.size())
        throw std::invalid_argument("CsvTable: " + std::to_string(fields.size()) + " fields for " +
                                    std::to_string(columns_.size()) + " columns");
    rows_.push_back(std::move(fields));
}

std::string CsvTable::text() const {
    std::string out = line(columns_);
    for (const auto& row : rows_) out += line(row);
    return out;
}

std::string CsvTable::quoted(const std::string& field) {
    if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
    std::string out = "\"";
    for (const char c : field) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

}  // namespace asos
