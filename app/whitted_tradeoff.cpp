// whitted-tradeoff: measures the speed/accuracy trade of one scene.
//   whitted-tradeoff SCENE.json [--out-dir DIR] [grid flags] [--quick]
// renders a reference, then every point of the grid, and writes into DIR
// points.csv, table.md, plot.png (error against time, Pareto front marked),
// progressive.csv, progressive.png, truncation.png, reference.png, summary.md
// and summary.json.
//   whitted-tradeoff --report OUT.md --dirs DIR... [--quality-csv FILE]
//                    [--sampler-csv FILE]
// writes docs/tradeoff.md from the summaries of earlier runs, presets included,
// and rewrites each directory's summary.md in the same words; with
// bench_quality's CSV, its section on rendering to a quality too, and with
// bench_whitted1980's, its section on Whitted's 1980 sampling and a plot a
// scene beside the report (tradeoff/whitted1980/).
// Exit codes as whitted-render: 0 success, 2 bad input, 1 any other failure.
#include <unistd.h>

#include <QGuiApplication>
#include <QImage>

#include <atomic>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "analysis/depth_truncation.h"
#include "analysis/quality_table.h"
#include "analysis/tradeoff.h"
#include "base/atomic_file.h"
#include "base/utc_date.h"
#include "cli_input.h"
#include "cli_main.h"
#include "image/image_io.h"
#include "scene/scene_io.h"
#include "tradeoff/plots.h"
#include "tradeoff/progress.h"
#include "tradeoff/quality_section.h"
#include "tradeoff/results_csv.h"
#include "tradeoff/sampler_section.h"
#include "tradeoff/tradeoff_report.h"

namespace fs = std::filesystem;
using namespace whitted;
using json = nlohmann::json;

namespace {

std::atomic<bool> interrupted{false};
extern "C" void onInterrupt(int) {
    interrupted = true;
}

// "0-8" or "0,2,5".
std::vector<int> parseIntList(const std::string& text) {
    std::vector<int> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        const auto dash = item.find('-', 1);
        if (dash == std::string::npos) {
            out.push_back(std::stoi(item));
        } else {
            for (int v = std::stoi(item.substr(0, dash)); v <= std::stoi(item.substr(dash + 1));
                 ++v)
                out.push_back(v);
        }
    }
    if (out.empty()) throw std::invalid_argument("empty list");
    return out;
}

void writePng(const QImage& image, const fs::path& file) {
    if (!image.save(QString::fromStdString(file.string()), "PNG"))
        throw std::runtime_error(file.string() + ": cannot write image");
}

std::string fixed(double v, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

// The command line as a reader would type it in the repository root: the
// program as build/bin/whitted-tradeoff whatever path started it.
std::string commandLine(int argc, char** argv) {
    std::string command = "build/bin/whitted-tradeoff";
    for (int i = 1; i < argc; ++i) command.append(" ").append(argv[i]);
    return command;
}

std::size_t gridSize(const TradeoffGrid& g) {
    return g.samples.size() * g.depths.size() * g.precisions.size() * g.scales.size();
}

// The truncation map scaled so that its largest weight is white: the weights
// are products of reflectivities, often an eighth or less, and would otherwise
// be too dark to tell from the black of pixels where nothing is cut off.
Image normalised(Image map, float largest) {
    if (largest > 0.0f)
        for (float& v : map.rgb) v /= largest;
    return map;
}

json summaryJson(const tradeoff::SceneSummary& s) {
    json curve = json::array();
    for (const ProgressiveSample& c : s.curve)
        curve.push_back({{"pass", c.pass},
                         {"samples", c.samples},
                         {"seconds", c.seconds},
                         {"rmse_srgb8", c.error.rmseSrgb8},
                         {"psnr_srgb8", c.error.psnrSrgb8},  // null: no error (psnrFromMse)
                         {"psnr_linear", c.error.psnrLinear}});
    return {{"name", s.name},
            {"command", s.command},
            {"date", s.date},
            {"reference", json::parse(sceneToJson(s.reference))},
            {"reference_seconds", s.referenceSeconds},
            {"scene_depth", s.sceneDepth},
            {"scene_precision", std::string(precisionName(s.scenePrecision))},
            {"truncation", s.truncation},
            {"depth_within_tolerance", s.depthWithinTolerance},
            {"progressive", curve}};
}

// A PSNR as summaryJson wrote it: null for no error at all.
double psnrFromJson(const json& db) {
    return db.is_null() ? std::numeric_limits<double>::infinity() : db.get<double>();
}

tradeoff::SceneSummary readSummary(const fs::path& dir) {
    std::ifstream in(dir / "summary.json");
    if (!in) throw std::runtime_error((dir / "summary.json").string() + ": cannot open file");
    const json j = json::parse(in);
    tradeoff::SceneSummary s;
    s.name = j.at("name").get<std::string>();
    s.command = j.value("command", std::string());
    s.date = j.value("date", std::string());
    s.reference = parseScene(j.at("reference").dump(), (dir / "summary.json").string());
    s.referenceSeconds = j.at("reference_seconds").get<double>();
    s.sceneDepth = j.at("scene_depth").get<int>();
    s.scenePrecision =
        parsePrecision(j.value("scene_precision", std::string("float"))).value_or(Precision::Float);
    s.truncation = j.at("truncation").get<float>();
    s.depthWithinTolerance = j.at("depth_within_tolerance").get<int>();
    for (const json& c : j.at("progressive")) {
        ProgressiveSample p;
        p.pass = c.at("pass");
        p.samples = c.at("samples");
        p.seconds = c.at("seconds");
        p.error.rmseSrgb8 = c.at("rmse_srgb8");
        p.error.psnrSrgb8 = psnrFromJson(c.at("psnr_srgb8"));
        p.error.psnrLinear = psnrFromJson(c.at("psnr_linear"));
        s.curve.push_back(p);
    }
    s.points = tradeoff::readPointsCsv(dir / "points.csv");
    return s;
}

// Plots are painted with Qt; no display needed. `argc` must outlive it.
std::unique_ptr<QGuiApplication> qtForPlots(int& argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    return std::make_unique<QGuiApplication>(argc, argv);
}

// The 1980 sampler's section, its plots written beside the report at `base`.
std::string samplerSectionWithPlots(const std::vector<tradeoff::SamplerRow>& rows,
                                    const std::string& csvFile, const fs::path& base) {
    int argc = 1;
    char name[] = "whitted-tradeoff";
    char* argv[] = {name, nullptr};
    const auto qt = qtForPlots(argc, argv);
    std::vector<std::string> plots;
    fs::create_directories(base / "tradeoff" / "whitted1980");
    for (const std::string& scene : tradeoff::samplerScenes(rows)) {
        std::string slug = scene;
        for (char& c : slug)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
        const std::string stem = "tradeoff/whitted1980/" + slug;
        const std::vector<tradeoff::SamplerRow> mine = tradeoff::samplerRowsOf(rows, scene);
        for (const auto& [axis, ending] : {std::pair{tradeoff::SamplerAxis::Time, ".png"},
                                           {tradeoff::SamplerAxis::CameraRays, "-rays.png"}})
            writePng(
                ui::renderPlot(tradeoff::samplerPlot(QString::fromStdString(scene), mine, axis),
                               QSize(560, 400)),
                base / (stem + ending));
        plots.push_back(stem);
    }
    return tradeoff::samplerSection(rows, csvFile, plots);
}

int writeReport(const std::string& output, const std::vector<std::string>& dirs,
                const std::string& qualityCsv, const std::string& samplerCsv,
                const std::string& command) {
    std::vector<QualityRow> qualityRows;
    std::vector<tradeoff::SamplerRow> samplerRows;
    try {
        if (!qualityCsv.empty()) qualityRows = readQualityCsv(qualityCsv);
        if (!samplerCsv.empty()) samplerRows = tradeoff::readSamplerCsv(samplerCsv);
    } catch (const std::runtime_error& e) {
        std::cerr << "whitted-tradeoff: " << e.what() << "\n";
        return kExitBadInput;
    }
    std::vector<tradeoff::SceneSummary> scenes;
    const fs::path base = fs::absolute(output).parent_path();
    for (const std::string& d : dirs) {
        tradeoff::SceneSummary s = readSummary(d);
        // Each directory's own summary follows the report's wording too.
        s.directory = ".";
        replaceFileWithText(fs::path(d) / "summary.md", tradeoff::sceneSection(s));
        s.directory = fs::relative(fs::absolute(d), base).generic_string();
        scenes.push_back(std::move(s));
    }
    const std::string quality =
        (qualityCsv.empty() ? "" : tradeoff::qualitySection(qualityRows, qualityCsv)) +
        (samplerCsv.empty() ? "" : samplerSectionWithPlots(samplerRows, samplerCsv, base));
    replaceFileWithText(output, tradeoff::report(scenes, command, quality));
    for (const tradeoff::PresetChoice& p : tradeoff::choosePresets(scenes))
        std::cout << p.name << ": " << p.samplesPerPixel << " spp, depth " << p.maxDepth << ", "
                  << precisionName(p.precision) << "\n";
    return kExitOk;
}

// What the command line asks for.
struct Flags {
    std::string scenePath, outDir, samples = "1,2,4,8,16,32,64,128,256", depths = "0-8",
                                   precisions = "float,double", scales = "0.25,0.5,1", report,
                                   qualityCsv, samplerCsv;
    // One run for slow points, up to 9 for fast ones until they have taken
    // 0.3 s: the median tames the noise where it is largest (short renders), and
    // a full default run of the seed at 640x480 stays under ten minutes on two
    // cores (its 256-spp points alone take about four).
    int referenceSpp = 0, progressiveSpp = 256, maxSize = 0, minRuns = 1;
    std::optional<int> width, height;
    double minSeconds = 0.3;
    bool quick = false;
    std::vector<std::string> reportDirs;
};

void addFlags(CLI::App& app, Flags& f) {
    app.add_option("scene", f.scenePath, "Scene file (JSON, whitted-scene v1)");
    app.add_option("--out-dir", f.outDir, "Where to write (default docs/tradeoff/<scene name>)");
    app.add_option("--samples", f.samples, "Samples per pixel, e.g. 1,2,4,8");
    app.add_option("--depths", f.depths, "Max depths, e.g. 0-8 or 0,2,5");
    app.add_option("--precisions", f.precisions, "float,double or one of them");
    app.add_option("--scales", f.scales, "Resolution scales, e.g. 0.25,0.5,1");
    app.add_option("--reference-spp", f.referenceSpp,
                   "Samples per pixel of the reference (default: 4 times the grid's largest)")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--progressive-spp", f.progressiveSpp, "Samples of the progressive curve")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--width", f.width, "Image width in pixels (default: the scene's)")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--height", f.height, "Image height in pixels (default: the scene's)")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--max-size", f.maxSize, "Render at most this many pixels on the long side")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--runs", f.minRuns, "Runs per point, at least")->check(CLI::Range(1, 99));
    app.add_option("--min-seconds", f.minSeconds, "Run a point until it has taken this long")
        ->check(CLI::Range(0.0, 60.0));
    app.add_flag("--quick", f.quick,
                 "A small grid (tests): 1,4 spp; depths 0,2; scales 0.5,1; one run");
    app.add_option("--report", f.report, "Write the report from earlier runs' directories");
    app.add_option("--dirs", f.reportDirs, "With --report: the result directories");
    app.add_option("--quality-csv", f.qualityCsv,
                   "With --report: bench_quality's measurements of rendering to a quality "
                   "(WHITTED_QUALITY_CSV)");
    app.add_option("--sampler-csv", f.samplerCsv,
                   "With --report: bench_whitted1980's measurements of Whitted's 1980 sampling "
                   "against ours");
}

// The grid the flags ask for, or nothing, having said what is wrong.
std::optional<TradeoffGrid> gridOrSay(const Flags& f) {
    TradeoffGrid grid;
    try {
        grid.samples = parseIntList(f.samples);
        grid.depths = parseIntList(f.depths);
        grid.precisions.clear();
        std::stringstream p(f.precisions);
        for (std::string name; std::getline(p, name, ',');) {
            const auto precision = parsePrecision(name);
            if (!precision) throw std::invalid_argument("precision " + name);
            grid.precisions.push_back(*precision);
        }
        grid.scales.clear();
        std::stringstream sc(f.scales);
        for (std::string v; std::getline(sc, v, ',');) grid.scales.push_back(std::stod(v));
    } catch (const std::exception& e) {
        std::cerr << "whitted-tradeoff: bad grid flag: " << e.what() << "\n";
        return std::nullopt;
    }
    grid.minRuns = f.minRuns;
    grid.minSeconds = f.minSeconds;
    if (f.quick) {
        grid.samples = {1, 4};
        grid.depths = {0, 2};
        grid.scales = {0.5, 1.0};
        grid.minRuns = grid.maxRuns = 1;
    }
    for (int d : grid.depths)
        if (d < 0 || d > kMaxDepth) {
            std::cerr << "whitted-tradeoff: --depths: " << d << " is outside [0, 64]\n";
            return std::nullopt;
        }
    for (double s : grid.scales)
        if (!(s > 0 && s <= 1)) {
            std::cerr << "whitted-tradeoff: --scales: " << s << " is outside (0, 1]\n";
            return std::nullopt;
        }
    return grid;
}

// The reference's samples: the flag's, or 4x the grid's largest. The
// reference must be far less noisy than the grid's best points, or they would
// be measured against their own noise: 4x the samples halves it.
int referenceSamples(const Flags& f, const TradeoffGrid& grid) {
    const int largest = *std::max_element(grid.samples.begin(), grid.samples.end());
    const int spp =
        f.referenceSpp > 0 ? f.referenceSpp : std::min(kMaxSamplesPerPixel, 4 * largest);
    if (spp <= largest)
        std::cerr << "whitted-tradeoff: warning: --reference-spp " << spp
                  << " is not above the grid's " << largest
                  << " samples; their errors will be mostly the reference's noise\n";
    return spp;
}

// The scene at the size the flags ask for.
void fitSize(Scene& scene, const Flags& f) {
    if (f.width) scene.render.width = *f.width;
    if (f.height) scene.render.height = *f.height;
    const int longest = std::max(scene.render.width, scene.render.height);
    if (f.maxSize > 0 && longest > f.maxSize) {
        scene.render.width = std::max(1, scene.render.width * f.maxSize / longest);
        scene.render.height = std::max(1, scene.render.height * f.maxSize / longest);
    }
}

// Every file of a scene's directory: images, tables, plots, the summary.
void writeResults(const fs::path& dir, tradeoff::SceneSummary& summary, const ReferenceRender& ref,
                  const Image& truncation) {
    const ImageMetadata meta = makeImageMetadata(ref.scene.render, ref.seconds, "whitted-tradeoff");
    writeImage(ref.image, dir / "reference.png", meta);
    writeImage(normalised(truncation, summary.truncation), dir / "truncation.png", meta);
    replaceFileWithText(dir / "points.csv", tradeoff::pointsCsv(summary.points));
    replaceFileWithText(dir / "progressive.csv", tradeoff::progressiveCsv(summary.curve));
    replaceFileWithText(dir / "table.md", "# " + summary.name + ": every point\n\n" +
                                              tradeoff::pointsTable(summary.points));
    const QString name = QString::fromStdString(summary.name);
    writePng(ui::renderPlot(tradeoff::errorAgainstTimePlot(name, summary.points), QSize(900, 600)),
             dir / "plot.png");
    if (!summary.curve.empty())
        writePng(ui::renderPlot(tradeoff::progressivePlot(name, summary.curve), QSize(700, 450)),
                 dir / "progressive.png");
    summary.directory = ".";
    replaceFileWithText(dir / "summary.md", tradeoff::sceneSection(summary));
    replaceFileWithText(dir / "summary.json", summaryJson(summary).dump(2) + "\n");
}

// Measures one scene: the reference, the grid, the progressive curve; then
// writes them. Ctrl+C stops it, keeping what was measured (exit 1).
int measureScene(Scene scene, const Flags& f, const TradeoffGrid& grid, int argc, char** argv) {
    fitSize(scene, f);
    const int referenceSpp = referenceSamples(f, grid);
    const std::string name = fs::path(f.scenePath).stem().string();
    const fs::path dir = f.outDir.empty() ? fs::path("docs/tradeoff") / name : fs::path(f.outDir);
    fs::create_directories(dir);
    const auto qt = qtForPlots(argc, argv);
    const auto stop = [] { return interrupted.load(); };

    std::cerr << "whitted-tradeoff: " << name << " at " << scene.render.width << "x"
              << scene.render.height << ": reference (double, " << referenceSpp << " spp)...\n";
    tradeoff::SceneSummary summary;
    summary.name = name;
    summary.command = commandLine(argc, argv);
    summary.date = todayUtc();
    const ReferenceRender ref = renderReference(scene, referenceSpp, stop);
    if (interrupted) return kExitFailure;
    summary.reference = ref.scene;
    summary.referenceSeconds = ref.seconds;
    summary.sceneDepth = scene.render.maxDepth;
    summary.scenePrecision = scene.render.precision;
    summary.depthWithinTolerance = depthWithinTolerance(scene);
    const Image truncation = depthTruncationMap(scene);
    summary.truncation = largestTruncation(truncation);
    std::cerr << "whitted-tradeoff: reference took " << fixed(ref.seconds, 1) << " s; the grid's "
              << gridSize(grid) << " points will take about "
              << fixed(tradeoff::estimateGridSeconds(grid, ref) / 60, 1) << " min\n";

    tradeoff::Progress progress(grid, ::isatty(STDERR_FILENO));
    summary.points = runTradeoff(
        scene, ref.image, grid, [&](const TradeoffProgress& p) { progress.point(p); }, stop);
    Scene progressiveScene = scene;
    progressiveScene.render.samplesPerPixel =
        f.quick ? std::min(f.progressiveSpp, 4) : f.progressiveSpp;
    if (!interrupted) summary.curve = progressiveCurve(progressiveScene, ref.image, stop);

    writeResults(dir, summary, ref, truncation);
    std::cerr << "whitted-tradeoff: " << summary.points.size() << " points written to "
              << dir.string() << (interrupted ? " (interrupted)" : "") << "\n";
    return interrupted ? kExitFailure : kExitOk;
}

int run(const Flags& f, int argc, char** argv) {
    if (!f.report.empty()) {
        if (f.reportDirs.empty()) {
            std::cerr << "whitted-tradeoff: --report needs --dirs\n";
            return kExitBadInput;
        }
        return writeReport(f.report, f.reportDirs, f.qualityCsv, f.samplerCsv,
                           commandLine(argc, argv));
    }
    if (f.scenePath.empty()) {
        std::cerr << "whitted-tradeoff: a scene file is required\n";
        return kExitBadInput;
    }
    const std::optional<Scene> scene = sceneOrSay("whitted-tradeoff", f.scenePath);
    if (!scene) return kExitBadInput;
    const std::optional<TradeoffGrid> grid = gridOrSay(f);
    if (!grid) return kExitBadInput;
    return measureScene(*scene, f, *grid, argc, argv);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Measures the speed/accuracy trade of a scene (docs/tradeoff.md)."};
    Flags flags;
    addFlags(app, flags);
    if (const auto code = parseFlags(app, "whitted-tradeoff", argc, argv)) return *code;
    std::signal(SIGINT, onInterrupt);
    return runOrSay("whitted-tradeoff", [&] { return run(flags, argc, argv); });
}
