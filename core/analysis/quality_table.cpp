#include "analysis/quality_table.h"

#include <sstream>
#include <stdexcept>

#include "base/csv_rows.h"

namespace whitted {

namespace {

constexpr const char* kHeader =
    "date,scene,width,height,target,target_psnr_db,target_max_error_codes,depth,depth_short,"
    "mean_spp,psnr_db,max_error_codes,met,preset_psnr_db,preset_max_error_codes,preset_met,"
    "time_against_preset,fixed_meeting,time_against_fixed_meeting";

bool yesOrNo(const std::string& cell) {
    if (cell != "yes" && cell != "no") throw std::invalid_argument(cell);
    return cell == "yes";
}

QualityRow rowOf(const std::vector<std::string>& f) {
    QualityRow r;
    r.date = f[0];
    r.scene = f[1];
    r.width = std::stoi(f[2]);
    r.height = std::stoi(f[3]);
    r.target = f[4];
    r.targetPsnrDb = std::stod(f[5]);
    if (!f[6].empty()) r.targetLargestCodes = std::stod(f[6]);
    r.depth = std::stoi(f[7]);
    r.depthShort = yesOrNo(f[8]);
    r.meanSamples = std::stod(f[9]);
    r.psnrDb = std::stod(f[10]);
    r.largestCodes = std::stod(f[11]);
    r.met = yesOrNo(f[12]);
    r.presetPsnrDb = std::stod(f[13]);
    r.presetLargestCodes = std::stod(f[14]);
    r.presetMet = yesOrNo(f[15]);
    r.timeAgainstPreset = std::stod(f[16]);
    r.fixedMeeting = f[17];
    if (!f[18].empty()) r.timeAgainstFixedMeeting = std::stod(f[18]);
    return r;
}

}  // namespace

std::string qualityCsvHeader() {
    return kHeader;
}

std::string qualityCsvLine(const QualityRow& r) {
    std::ostringstream out;
    out.precision(6);
    auto yes = [](bool b) { return b ? "yes" : "no"; };
    out << r.date << ',' << csvCell(r.scene) << ',' << r.width << ',' << r.height << ','
        << csvCell(r.target) << ',' << r.targetPsnrDb << ',';
    if (r.targetLargestCodes) out << *r.targetLargestCodes;
    out << ',' << r.depth << ',' << yes(r.depthShort) << ',' << r.meanSamples << ',' << r.psnrDb
        << ',' << r.largestCodes << ',' << yes(r.met) << ',' << r.presetPsnrDb << ','
        << r.presetLargestCodes << ',' << yes(r.presetMet) << ',' << r.timeAgainstPreset << ','
        << csvCell(r.fixedMeeting) << ',';
    if (r.timeAgainstFixedMeeting) out << *r.timeAgainstFixedMeeting;
    return out.str();
}

std::vector<QualityRow> readQualityCsv(const std::filesystem::path& file) {
    return readCsvValues(file, kHeader, "bench_quality CSV", rowOf);
}

}  // namespace whitted
