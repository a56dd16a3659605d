#include "results_csv.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace whitted::tradeoff {

namespace {

constexpr const char* kHeader =
    "samples,depth,precision,scale,width,height,seconds,runs,rays,mrays_per_s,rmse_linear,"
    "psnr_linear,rmse_srgb8,psnr_srgb8,largest,pareto";

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
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open file");
    std::string line;
    if (!std::getline(in, line) || line != kHeader)
        throw std::runtime_error(file.string() + ": line 1: not a whitted-tradeoff points.csv");
    std::vector<TradeoffPoint> points;
    for (int number = 2; std::getline(in, line); ++number) {
        std::istringstream row(line);
        std::vector<std::string> f;
        for (std::string cell; std::getline(row, cell, ',');) f.push_back(cell);
        if (f.size() != 16)
            throw std::runtime_error(file.string() + ": line " + std::to_string(number) +
                                     ": expected 16 columns");
        try {
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
            points.push_back(p);
        } catch (const std::exception&) {
            throw std::runtime_error(file.string() + ": line " + std::to_string(number) +
                                     ": malformed value");
        }
    }
    return points;
}

}  // namespace whitted::tradeoff
