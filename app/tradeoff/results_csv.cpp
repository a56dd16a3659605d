#include "results_csv.h"

#include <sstream>
#include <stdexcept>

#include "base/csv_rows.h"

namespace whitted::tradeoff {

namespace {

constexpr const char* kHeader =
    "samples,depth,precision,scale,width,height,seconds,runs,rays,mrays_per_s,rmse_linear,"
    "psnr_linear,rmse_srgb8,psnr_srgb8,largest,pareto";

TradeoffPoint pointOf(const std::vector<std::string>& f) {
    TradeoffPoint p;
    p.settings.samplesPerPixel = std::stoi(f[0]);
    p.settings.maxDepth = std::stoi(f[1]);
    const auto precision = parsePrecision(f[2]);
    if (!precision) throw std::invalid_argument("precision");
    p.settings.precision = *precision;
    p.settings.resolutionScale = std::stod(f[3]);
    p.width = std::stoi(f[4]);
    p.height = std::stoi(f[5]);
    p.seconds = std::stod(f[6]);
    p.runs = std::stoi(f[7]);
    p.rays = std::stoull(f[8]);
    p.mraysPerSecond = std::stod(f[9]);
    p.error.rmseLinear = std::stod(f[10]);
    p.error.psnrLinear = std::stod(f[11]);
    p.error.rmseSrgb8 = std::stod(f[12]);
    p.error.psnrSrgb8 = std::stod(f[13]);
    p.error.largest = std::stod(f[14]);
    p.pareto = f[15] == "1";
    return p;
}

}  // namespace

std::string pointsCsv(const std::vector<TradeoffPoint>& points) {
    std::ostringstream out;
    out.precision(9);
    out << kHeader << "\n";
    for (const TradeoffPoint& p : points) {
        const TradeoffSettings& s = p.settings;
        out << s.samplesPerPixel << ',' << s.maxDepth << ',' << precisionName(s.precision) << ','
            << s.resolutionScale << ',' << p.width << ',' << p.height << ',' << p.seconds << ','
            << p.runs << ',' << p.rays << ',' << p.mraysPerSecond << ',' << p.error.rmseLinear
            << ',' << p.error.psnrLinear << ',' << p.error.rmseSrgb8 << ',' << p.error.psnrSrgb8
            << ',' << p.error.largest << ',' << (p.pareto ? 1 : 0) << "\n";
    }
    return out.str();
}

std::string progressiveCsv(const std::vector<ProgressiveSample>& curve) {
    std::ostringstream out;
    out.precision(9);
    out << "pass,samples,seconds,rmse_linear,psnr_linear,rmse_srgb8,psnr_srgb8,largest\n";
    for (const ProgressiveSample& c : curve)
        out << c.pass << ',' << c.samples << ',' << c.seconds << ',' << c.error.rmseLinear << ','
            << c.error.psnrLinear << ',' << c.error.rmseSrgb8 << ',' << c.error.psnrSrgb8 << ','
            << c.error.largest << "\n";
    return out.str();
}

std::vector<TradeoffPoint> readPointsCsv(const std::filesystem::path& file) {
    return readCsvValues(file, kHeader, "whitted-tradeoff points.csv", pointOf);
}

}  // namespace whitted::tradeoff
