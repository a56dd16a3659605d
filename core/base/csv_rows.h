// Reading back the CSV files the project writes itself: whitted-tradeoff's
// points and bench_quality's measurements. No line breaks within a cell.
#pragma once

#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted {

struct CsvRow {
    std::string where;  // "FILE: line N", for messages
    std::vector<std::string> cells;
};

// `text` as a CSV cell: in double quotes if it holds a comma or a quote.
std::string csvCell(const std::string& text);

// The rows after the header line. Throws std::runtime_error naming the file
// and line when the file cannot be opened, its first line is not `header`
// ("not a `what`"), or a row has not as many cells as the header.
std::vector<CsvRow> readCsvRows(const std::filesystem::path& file, const std::string& header,
                                const std::string& what);

// readCsvRows(), each row's cells made into a value by `valueOf`; a row it
// throws on is a "malformed value" at that row's line.
template <typename ValueOf>
auto readCsvValues(const std::filesystem::path& file, const std::string& header,
                   const std::string& what, ValueOf valueOf) {
    std::vector<decltype(valueOf(std::vector<std::string>{}))> values;
    for (const CsvRow& row : readCsvRows(file, header, what)) try {
            values.push_back(valueOf(row.cells));
        } catch (const std::exception&) {
            throw std::runtime_error(row.where + ": malformed value");
        }
    return values;
}

}  // namespace whitted
