#include "base/csv_rows.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace whitted {

namespace {

std::vector<std::string> cellsOf(const std::string& line) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();  // an empty last cell
    return cells;
}

}  // namespace

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
