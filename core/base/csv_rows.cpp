#include "base/csv_rows.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace whitted {

namespace {

// A cell in double quotes may hold commas, and a quote as two.
std::vector<std::string> cellsOf(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            cells.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            cells.emplace_back();
        } else {
            cells.back() += c;
        }
    }
    return cells;
}

}  // namespace

std::string csvCell(const std::string& text) {
    if (text.find_first_of(",\"") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + '"';
}

std::vector<CsvRow> readCsvRows(const std::filesystem::path& file, const std::string& header,
                                const std::string& what) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open file");
    std::string line;
    if (!std::getline(in, line) || line != header)
        throw std::runtime_error(file.string() + ": line 1: not a " + what);
    const std::size_t columns = std::size_t(std::count(header.begin(), header.end(), ',')) + 1;
    std::vector<CsvRow> rows;
    for (int number = 2; std::getline(in, line); ++number) {
        CsvRow row{file.string() + ": line " + std::to_string(number), cellsOf(line)};
        if (row.cells.size() != columns)
            throw std::runtime_error(row.where + ": expected " + std::to_string(columns) +
                                     " columns");
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace whitted
