#include "sampler_section.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "tradeoff_report.h"

#include "base/csv_rows.h"

namespace whitted::tradeoff {

namespace {

const char* const kSamplerCsvHeader =
    "scene,sampler,setting,width,height,camera_rays_per_pixel,rays_per_pixel,seconds,psnr_db,"
    "largest_codes";

SamplerRow rowOf(const std::vector<std::string>& c) {
    return {c[0],
            c[1],
            c[2],
            std::stoi(c[3]),
            std::stoi(c[4]),
            std::stod(c[5]),
            std::stod(c[6]),
            std::stod(c[7]),
            std::stod(c[8]),
            std::stod(c[9])};
}

// The fastest of ours (fixed or adaptive) at least as good as `row`, if any.
const SamplerRow* fastestAsGood(const std::vector<SamplerRow>& rows, const SamplerRow& row) {
    const SamplerRow* best = nullptr;
    for (const SamplerRow& other : rows)
        if (other.sampler != "whitted1980" && other.psnrDb >= row.psnrDb &&
            (!best || other.seconds < best->seconds))
            best = &other;
    return best;
}

struct Tally {
    int settings = 0, wins = 0, unmatched = 0;
    std::vector<std::string> won;  // "field (threshold 16, 1 cut)"
};

void sceneTable(std::ostream& md, const std::vector<SamplerRow>& rows, Tally& tally) {
    md << "| 1980 setting | camera rays a pixel | ms | PSNR dB | largest codes | the fastest of "
          "ours as good | its ms | 1980's time over it |\n|---|---|---|---|---|---|---|---|\n";
    for (const SamplerRow& r : rows) {
        if (r.sampler != "whitted1980") continue;
        ++tally.settings;
        md << "| " << r.setting << " | " << printed("%.2f", r.cameraRaysPerPixel) << " | "
           << printed("%.1f", r.seconds * 1e3) << " | " << printed("%.1f", r.psnrDb) << " | "
           << printed("%.0f", r.largestCodes) << " | ";
        const SamplerRow* ours = fastestAsGood(rows, r);
        if (!ours) {
            ++tally.unmatched;
            md << "none of ours reaches it | | |\n";
            continue;
        }
        const double ratio = r.seconds / ours->seconds;
        if (ratio < 1.0) {
            ++tally.wins;
            tally.won.push_back(r.scene + " (" + r.setting + ")");
        }
        md << ours->sampler << " " << ours->setting << printed(" (%.1f dB)", ours->psnrDb) << " | "
           << printed("%.1f", ours->seconds * 1e3) << " | "
           << (ratio < 1.0 ? printed("**%.2f**", ratio) : printed("%.2f", ratio)) << " |\n";
    }
}

void why(std::ostream& md) {
    md << "### Why it stops short\n\n"
          "![The seed at 160x120: the 1980 sampler's render (threshold 8, 2 cuts), the "
          "converged reference, each pixel's error, and how deep each pixel was cut]"
          "(tradeoff/whitted1980/why-seed.png)\n\n"
          "Left to right, twice their size: the seed rendered with threshold 8 and 2 cuts, the "
          "reference, each pixel's error on the Precision Check's ramp (black none, pale yellow "
          "8 codes or more), and how deep each pixel was cut (black not at all, pale yellow "
          "twice). Three things keep its error up, however deep it cuts:\n\n"
          "- **Its rays lie on a regular lattice.** Where the floor's checkers are smaller "
          "than the lattice, near the horizon, the corners sample the pattern at a fixed "
          "stride and show moiré: the pixels there are cut as deep as allowed and still err "
          "by the most. Stratified samples, jittered within the pixel, average such a pattern "
          "out.\n"
          "- **What lies between four corners that agree is never seen.** A ball or a checker "
          "square smaller than a pixel and between its corners leaves them alike, and the "
          "pixel is not cut: the largest error of a pixel stays where it was with no cuts.\n"
          "- **A cell is the mean of its corners.** A pixel not cut is the mean of four "
          "points on its border, shared with its neighbours, and a cut one weighs its points "
          "as a tent does, the middle most; the reference averages the pixel's square evenly. "
          "An edge inside a pixel so comes out a little off what the pixel covers, which the "
          "error map shows along the checker edges.\n\n"
          "So ours renders to a quality with stratified samples where the picture needs them, "
          "and the quality planner does not choose the 1980 sampler; it stays in the editor "
          "and `whitted-render --sampler whitted1980` for what it shows: where Whitted's "
          "paper spent its rays.\n\n";
}

}  // namespace

std::vector<SamplerRow> readSamplerCsv(const std::filesystem::path& file) {
    return readCsvValues(file, kSamplerCsvHeader, "bench_whitted1980 CSV", rowOf);
}

std::vector<SamplerRow> samplerRowsOf(const std::vector<SamplerRow>& rows,
                                      const std::string& scene) {
    std::vector<SamplerRow> found;
    for (const SamplerRow& r : rows)
        if (r.scene == scene) found.push_back(r);
    return found;
}

std::vector<std::string> samplerScenes(const std::vector<SamplerRow>& rows) {
    std::vector<std::string> scenes;
    for (const SamplerRow& r : rows)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end())
            scenes.push_back(r.scene);
    return scenes;
}

ui::PlotSpec samplerPlot(const QString& scene, const std::vector<SamplerRow>& rows,
                         SamplerAxis axis) {
    const bool time = axis == SamplerAxis::Time;
    const auto xOf = [time](const SamplerRow& r) {
        return time ? r.seconds * 1e3 : r.cameraRaysPerPixel;
    };
    ui::PlotSpec spec;
    spec.title = QStringLiteral("%1: error against %2 by sampler")
                     .arg(scene, time ? QStringLiteral("time") : QStringLiteral("camera rays"));
    spec.xLabel = time ? QStringLiteral("render time (ms), two threads")
                       : QStringLiteral("camera rays a pixel");
    spec.yLabel = QStringLiteral("PSNR of the 8-bit picture (dB)");
    spec.logX = true;
    spec.highlightName.clear();
    const char* const samplers[] = {"fixed", "adaptive", "whitted1980"};
    const QString names[] = {QStringLiteral("fixed samples (1 to 64 a pixel)"),
                             QStringLiteral("adaptive to a PSNR (30 to 50 dB)"),
                             QStringLiteral("Whitted 1980 (threshold, cuts)")};
    for (int k = 0; k < 3; ++k) {
        spec.series.push_back({names[k], ui::plotPaletteColour(k)});
        std::vector<SamplerRow> mine;
        for (const SamplerRow& r : rows)
            if (r.sampler == samplers[k]) mine.push_back(r);
        std::sort(mine.begin(), mine.end(),
                  [&](const SamplerRow& a, const SamplerRow& b) { return xOf(a) < xOf(b); });
        ui::PlotLine line;
        line.colour = ui::plotPaletteColour(k);
        line.dashed = k == 2;
        for (const SamplerRow& r : mine) {
            const double x = xOf(r), y = std::min(r.psnrDb, 99.0);
            line.points.emplace_back(x, y);
            spec.points.push_back({x, y, QString::fromStdString(r.setting), false, k, 0});
        }
        spec.lines.push_back(line);
    }
    return spec;
}

std::string samplerSection(const std::vector<SamplerRow>& rows, const std::string& csvFile,
                           const std::vector<std::string>& plots) {
    std::ostringstream md;
    md << "## Whitted's 1980 sampling against ours\n\n"
          "`whitted-render --sampler whitted1980` (and Antialiasing in the editor's Render tab) "
          "samples as Whitted's paper does: a ray through every pixel corner, shared by the "
          "four pixels that meet there; a pixel whose corners differ by more than a threshold "
          "(in 8-bit codes) is cut in four, its new corners traced and shared likewise, down to "
          "a number of cuts. A cell is the mean of its corners.\n\n";
    if (rows.empty()) return md.str();
    md << "Measured at " << rows.front().width << "x" << rows.front().height
       << ", float, two threads, the best of three runs, each against a converged render at "
          "the scene's own depth (double, 256 samples a pixel), so that only the sampling "
          "differs: `build/bin/bench_whitted1980 "
       << rows.front().width << " " << csvFile << " docs/tradeoff/whitted1980/why-seed.png"
       << "`. For each 1980 setting: the fastest of our fixed or adaptive renders whose PSNR is "
          "at least as high, and 1980's time over its time (under 1, in bold: 1980 wins).\n\n";
    Tally tally;
    const std::vector<std::string> scenes = samplerScenes(rows);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        md << "### " << scenes[i] << "\n\n";
        if (i < plots.size())
            md << "![" << scenes[i] << ": error against time](" << plots[i] << ".png) !["
               << scenes[i] << ": error against camera rays](" << plots[i] << "-rays.png)\n\n";
        sceneTable(md, samplerRowsOf(rows, scenes[i]), tally);
        md << "\n";
    }
    md << "In all, " << tally.wins << " of " << tally.settings
       << " settings of the 1980 sampler were faster than the fastest of ours as good, and "
       << tally.unmatched << " reached a PSNR none of ours measured here reached.";
    for (std::size_t i = 0; i < tally.won.size(); ++i)
        md << (i == 0                      ? " It won on "
               : i + 1 == tally.won.size() ? " and "
                                           : ", ")
           << tally.won[i] << (i + 1 == tally.won.size() ? "." : "");
    md << "\n\n";
    why(md);
    return md.str();
}

}  // namespace whitted::tradeoff
