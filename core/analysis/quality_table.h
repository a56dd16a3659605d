// bench_quality's measurements as CSV: each render to a quality
// on one scene against the fixed preset of the same name. bench_quality
// writes them (WHITTED_QUALITY_CSV) and `whitted-tradeoff --report
// --quality-csv` turns them into docs/tradeoff.md's table of targets
// against what was measured.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace whitted {

struct QualityRow {
    std::string date;  // of the run, UTC, YYYY-MM-DD
    std::string scene;
    int width = 0, height = 0;
    std::string target;  // Draft, Preview or Final
    double targetPsnrDb = 0.0;
    std::optional<double> targetLargestCodes;
    int depth = 0;
    bool depthShort = false;  // the plan said beforehand it may miss the target
    double meanSamples = 0.0;
    double psnrDb = 0.0, largestCodes = 0.0;
    bool met = false;
    double presetPsnrDb = 0.0, presetLargestCodes = 0.0;
    bool presetMet = false;
    double timeAgainstPreset = 0.0;  // ours (planning too) over the preset's
    // The fixed setting the time is judged against: the preset where it meets
    // the target, else the fewest samples a pixel that meet it at our depth
    // ("32 spp"); empty where none up to 256 does.
    std::string fixedMeeting;
    std::optional<double> timeAgainstFixedMeeting;
};

std::string qualityCsvHeader();
std::string qualityCsvLine(const QualityRow& row);

// The rows of a file of qualityCsvHeader() and qualityCsvLine()s. Throws
// std::runtime_error naming the file and line on anything else.
std::vector<QualityRow> readQualityCsv(const std::filesystem::path& file);

}  // namespace whitted
